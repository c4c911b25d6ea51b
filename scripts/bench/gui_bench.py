#!/usr/bin/python3
"""The 3D view's cost, under a display (Xvfb here):

    xvfb-run -a -s "-screen 0 1280x1024x24" /usr/bin/python3 scripts/bench/gui_bench.py [--draw 50000] [--run 5000]
        [--steps 2000] [--repeats 3] [--cpus 0]

1. drawing: N spheres on a lattice in a 550×550 view; frames drawn per second (each frame: the scene's arrays
   gathered by _displayFrame, uploaded, drawn, read back as an image), and _displayFrame's own time;
2. following a run: the dense lattice of scripts/bench/dense.py with M spheres, STEPS steps of O.run(STEPS, True),
   in separate processes pinned to --cpus, alternating: without a view, and with a view and the controller open
   (the view redraws every 100 ms while the run goes on). Prints iter/s of each and the ratio, median of the pairs,
   and the share of the time the frames held the run paused (an upper bound: it includes waiting for a step's end).
A report, not a test: it prints figures and exits 0."""
import argparse
import os
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

RUN = r"""
import sys, time
from yade import *
from yade import geom, qt
N, STEPS, gui = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3] == 'gui'
r = 0.01; a = 2 * r * 0.995
n = max(2, int(round(N ** (1. / 3.)))); nz = max(2, N // (n * n))
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
half = lambda m: ((m - 1) * a + 2 * r - 0.01 * r) / 2
c = lambda m: (m - 1) * a / 2
O.bodies.append(geom.facetBox((c(n), c(n), c(nz)), (half(n), half(n), half(nz)), wallMask=63))
O.bodies.append([utils.sphere((i * a, j * a, k * a), r) for k in range(nz) for j in range(n) for i in range(n)])
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                             [Law2_ScGeom_FrictPhys_CundallStrack()]),
             NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4)]
O.dt = .5 * utils.PWaveTimeStep()
spent = [0.0]
if gui:
    import yade.qt.glwidget as gw
    from yade import _yade
    def timed(*a, **k):  # how long the frames keep the run paused (at most: it includes waiting for the step's end)
        t = time.perf_counter(); r = _yade._displayFrame(*a, **k); spent[0] += time.perf_counter() - t; return r
    gw._yade = type('Timed', (), {'_displayFrame': staticmethod(timed), 'O': _yade.O})
    qt.View(); qt.Controller()
O.run(20, True)
spent[0] = 0.0
t0 = time.time()
O.run(STEPS, True)
wall = time.time() - t0
print('iter_per_s %.3f paused_percent %.2f' % (STEPS / wall, 100 * spent[0] / wall))
"""

DRAW = r"""
import sys, time
from yade import *
from yade import qt, _yade
N = int(sys.argv[1])
n = max(2, int(round(N ** (1. / 3.))))
O.bodies.append([utils.sphere((i, j, k), 0.45, color=(i / n, j / n, k / n)) for k in range(n) for j in range(n) for i in range(n)])
v = qt.View()
v.center()
w = v._widget
w.renderFrame()  # (shaders compiled, buffers made)
t0 = time.perf_counter(); reps = 20
for _ in range(reps):
    w.renderFrame()
draw = (time.perf_counter() - t0) / reps
t0 = time.perf_counter()
for _ in range(reps):
    _yade._displayFrame()
gather = (time.perf_counter() - t0) / reps
print('spheres %d frames_per_s %.2f ms_per_frame %.1f displayFrame_ms %.1f' % (len(O.bodies), 1 / draw, 1000 * draw, 1000 * gather))
"""


def python(code, args, cpus):
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build"), OMP_NUM_THREADS="1")
    cmd = ["/usr/bin/python3", "-c", code] + [str(a) for a in args]
    if cpus:
        cmd = ["taskset", "-c", cpus] + cmd
    out = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=1800)
    if out.returncode != 0:
        raise SystemExit("gui_bench: a run failed:\n" + out.stderr[-3000:])
    return out.stdout.strip().splitlines()[-1]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--draw", type=int, default=50000, help="spheres drawn (0: skip)")
    ap.add_argument("--run", type=int, default=5000, help="spheres of the run followed live (0: skip)")
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--cpus", default="0", help="CPUs the processes are pinned to (taskset -c), '' for none")
    a = ap.parse_args()
    if not os.environ.get("DISPLAY"):
        print("gui_bench: no display; run it under xvfb-run (see its docstring)")
        return 0
    if a.draw:
        print("draw  ", python(DRAW, [a.draw], a.cpus), flush=True)
    if a.run:
        ratios, paused = [], []
        for rep in range(a.repeats):
            plain = float(python(RUN, [a.run, a.steps, "none"], a.cpus).split()[1])
            out = python(RUN, [a.run, a.steps, "gui"], a.cpus).split()
            gui = float(out[1])
            ratios.append(gui / plain)
            paused.append(float(out[3]))
            print("run    pair %d: without a view %.1f iter/s, with a view and the controller %.1f iter/s: %.3f; the frames "
                  "held the run for at most %.2f %% of the time" % (rep + 1, plain, gui, gui / plain, paused[-1]), flush=True)
        print("run    median ratio (with / without) %.3f over %d pairs (range %.3f-%.3f), pinned to CPUs %s; paused at most "
              "%.2f %% (median)" % (statistics.median(ratios), len(ratios), min(ratios), max(ratios), a.cpus or "(any)",
                                    statistics.median(paused)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
