#!/usr/bin/python3
"""Two builds of this engine run the DEM8 drum in turn, chunk by chunk, on one CPU: the way to see a
change of a few percent on a machine whose speed drifts by more than that between runs.

    /usr/bin/python3 scripts/bench/lockstep.py BUILD_A BUILD_B [--chunks 30] [--steps 40]
        [--script PATH] [--input DIR]

BUILD_A and BUILD_B are folders holding a built `yade` package (as `build/`; YADE_BUILD_DIR of the
launcher). Each build gets its own process, pinned to CPU 0, which sets up the drum (the reference's
example DEM2020Benchmark/Case2_rotating_drum_openmp.py, up to its timed part) and runs 20 steps;
then the two processes take turns: A runs `steps` steps while B waits, then B, then B again and A
(ABBA...), `chunks` times each. Both simulate the same steps, so chunk k of A and chunk k of B did the
same work, a fraction of a second apart. Printed: each build's median chunk time, the ratios A/B
chunk by chunk, their median and quartiles (B is the faster where the ratio is above 1). Two copies of
one build gave medians of 0.98-1.02 here; timing is never a test.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile

HERE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE_DIR))
LAUNCHER = os.path.join(REPO, "yade")
SCRIPT = "/usr/share/doc/yade/examples/DEM2020Benchmark/Case2_rotating_drum_openmp.py"
INPUT = os.path.join(os.path.dirname(REPO), "shared", "bench", "dem8", "inputData")

# What each process runs: the example up to its timed part, then chunks of steps on request.
CHILD = """
exec(open(%(script)r).read().split('rotation.dead = 0')[0])
rotation.dead = 0
O.run(20, True)
import sys as _sys, time as _time
print('ready', flush=True)
for _line in _sys.stdin:
    _n = int(_line)
    if _n <= 0:
        break
    _t0 = _time.time()
    O.run(_n, True)
    print('T %%.6f' %% (_time.time() - _t0), flush=True)
"""


def start(build, child, workdir):
    env = dict(os.environ, YADE_BUILD_DIR=os.path.abspath(build))
    p = subprocess.Popen(["taskset", "-c", "0", sys.executable, LAUNCHER, "-n", "-x", "-j1", child], env=env, cwd=workdir,
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    for line in p.stdout:
        if line.startswith("ready"):
            return p
    sys.exit("lockstep: the process of %s stopped before the scene was ready" % build)


def chunk(p, steps):
    p.stdin.write("%d\n" % steps)
    p.stdin.flush()
    for line in p.stdout:
        if line.startswith("T "):
            return float(line.split()[1])
    sys.exit("lockstep: a process stopped while running")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("a", help="folder of build A")
    ap.add_argument("b", help="folder of build B")
    ap.add_argument("--chunks", type=int, default=30)
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--script", default=SCRIPT)
    ap.add_argument("--input", default=INPUT, help="folder holding the drum's three input files")
    args = ap.parse_args(argv)
    for build in (args.a, args.b):
        if not os.path.isdir(os.path.join(build, "yade")):
            sys.exit("lockstep: %s holds no built 'yade' package" % build)
    if not os.path.isfile(args.script) or not os.path.isdir(args.input):
        sys.exit("lockstep: %s or %s not found (package yade-doc; give --script, --input)" % (args.script, args.input))
    with tempfile.TemporaryDirectory(prefix="lockstep-") as work:
        os.symlink(os.path.abspath(args.input), os.path.join(work, "inputData"))
        child = os.path.join(work, "child.py")
        with open(child, "w") as f:
            f.write(CHILD % {"script": os.path.abspath(args.script)})
        procs = [start(args.a, child, work), start(args.b, child, work)]
        times = ([], [])
        try:
            for k in range(args.chunks):
                for i in ((0, 1) if k % 2 == 0 else (1, 0)):
                    times[i].append(chunk(procs[i], args.steps))
        finally:
            for p in procs:
                p.kill()
                p.wait()
    ratios = [x / y for x, y in zip(*times)]
    q = statistics.quantiles(ratios, n=4)
    print("A %s: median %.4f s a chunk of %d steps" % (args.a, statistics.median(times[0]), args.steps))
    print("B %s: median %.4f s a chunk of %d steps" % (args.b, statistics.median(times[1]), args.steps))
    print("time A/B chunk by chunk: " + " ".join("%.3f" % r for r in ratios))
    print("median A/B %.3f, quartiles %.3f-%.3f (B faster where above 1)" % (statistics.median(ratios), q[0], q[2]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
