"""With several threads a thread that is done helps with the others' remaining work (the
interaction loop's pairs, the integrator's bodies; ChunkQueue.hpp), and the forces it computes
for another thread's pairs are added in the order that thread would have added them. A run must
therefore repeat to the last bit however fast each thread runs: here one of the two CPUs is kept
busy by another process during one of two identical runs (the simulation's second thread then
runs at about half speed and the first does part of its work)."""
import os
import pathlib
import shutil
import subprocess
import sys
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"

SCENE = r'''
import hashlib, struct, sys
from yade import pack
from yade.utils import *
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (.3, .3, .2), rMean=.01, rRelFuzz=.2, num=1500, seed=7)
sp.toSimulation()
O.bodies.append(wall((0, 0, 0), axis=2))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                             [Law2_ScGeom_FrictPhys_CundallStrack()]),
             NewtonIntegrator(gravity=(0, 0, -30), damping=0.4)]
O.dt = .5 * PWaveTimeStep()
O.trackEnergy = sys.argv[2] == 'energy'
O.run(int(sys.argv[1]), True)
h = hashlib.sha1()
for b in O.bodies:
    h.update(struct.pack('12d', *(tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel) + tuple(O.forces.f(b.id)))))
for name in sorted(O.energy.keys()):
    h.update(name.encode() + struct.pack('d', O.energy[name]))
print("STATE", h.hexdigest(), "contacts", O.interactions.countReal(), "energy terms", len(O.energy.keys()))
'''


def run(tmp_path, steps, variant, threads=2):
    script = tmp_path / "pile.py"
    script.write_text(SCENE)
    r = subprocess.run([sys.executable, str(LAUNCHER), "-n", "-x", "-j", str(threads), str(script), str(steps), variant],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    line = [l for l in r.stdout.splitlines() if l.startswith("STATE")][0].split()
    return line[1], int(line[3]), int(line[6])


@pytest.mark.skipif((os.cpu_count() or 1) < 2 or not shutil.which("taskset"), reason="needs 2 CPUs and taskset")
@pytest.mark.parametrize("variant", ["plain", "energy"])
def test_two_threads_give_the_same_bits_when_one_cpu_is_busy(tmp_path, variant):
    # with energy tracking the energy terms too (the functors' and the integrator's)
    plain, contacts, terms = run(tmp_path, 2500, variant)
    assert contacts > 1000  # a packing: the loop has real work
    assert terms == (5 if variant == "energy" else 0)
    cpus = sorted(os.sched_getaffinity(0))
    hog = subprocess.Popen(["taskset", "-c", str(cpus[1]), sys.executable, "-c", "while True: pass"])
    try:
        time.sleep(0.2)
        busy, _, _ = run(tmp_path, 2500, variant)
    finally:
        hog.kill()
        hog.wait()
    assert busy == plain
