#!/usr/bin/python3
"""Free fall of spheres without contacts: what each engine costs per step with 1 and 2 threads.

    /usr/bin/python3 scripts/bench/freefall_bench.py [--bodies 20000] [--steps 1000] [--settle 50]
        [--repeats 3] [--threads 1,2] [--build DIR]

Spheres of radius 0.1 on a grid of spacing 0.3 (100 x 100 x ...), gravity, engines ForceResetter,
InsertionSortCollider([Bo1_Sphere_Aabb()]), InteractionLoop (sphere functors), NewtonIntegrator,
O.dt = 1e-4: no contact is ever made, so the step is the per-body work of each engine. Each run is a
fresh process, `taskset -c 0,1 ./yade -n -x -jT` (the threads pinned as the engine pins them), with
O.timingEnabled for the timed steps after `settle` untimed ones. The thread counts are interleaved
within each repeat. Prints each run's per-engine µs per step, then per engine and thread count the
median over the repeats (and min-max), and the ratio of the medians 1 thread / T threads.

Another process busy on CPU 0 or 1 spoils the -j2 figures (the OpenMP threads are pinned, one to each CPU: the
one sharing its CPU holds up every parallel region), so each run's line says how much of the two CPUs other
processes used meanwhile ("others=0.95 cpu": almost a whole CPU), and with --max-others X a run starts only
once others used less than X CPU over one second (waiting up to --wait seconds).

Run with `--child N STEPS SETTLE` inside yade, it is the scene itself (prints one `engine=... us=...` line
per engine).
"""

import argparse
import os
import resource
import time
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
LINE_RE = re.compile(r"^engine=(\w+) us=([0-9.eE+-]+)$", re.M)


def child(n, steps, settle):
    from yade import O, timing
    from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                              Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                              Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)
    from yade.utils import sphere
    O.bodies.append([sphere((i % 100 * 0.3, i // 100 % 100 * 0.3, i // 10000 * 0.3), 0.1) for i in range(n)])
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(gravity=(0, 0, -9.81)),
    ]
    O.dt = 1e-4
    O.run(settle, True)
    O.timingEnabled = True
    timing.reset()
    O.run(steps, True)
    total = 0
    for e in O.engines:
        us = e.execTime / 1e3 / max(1, e.execCount)
        total += us
        print("engine=%s us=%.2f" % (type(e).__name__, us))
    print("engine=total us=%.2f" % total)
    assert len([i for i in O.interactions if i.isReal]) == 0


def busy_jiffies(cpus=(0, 1)):
    """Busy (non-idle) time of the CPUs in /proc/stat [s]."""
    total = 0
    with open("/proc/stat") as f:
        for line in f:
            name, *v = line.split()
            if name in ["cpu%d" % c for c in cpus]:
                v = [int(x) for x in v]
                total += sum(v) - v[3] - v[4]  # (all but idle and iowait)
    return total / os.sysconf("SC_CLK_TCK")


def others_now(seconds=1.0):
    """CPUs 0-1 used by other processes over the next `seconds` [CPUs]."""
    b, t = busy_jiffies(), time.time()
    time.sleep(seconds)
    return (busy_jiffies() - b) / (time.time() - t)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bodies", type=int, default=20000)
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--settle", type=int, default=50)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--builds", default=None,
                    help="comma-separated folders of built yade packages (YADE_BUILD_DIR), run interleaved; default <repo>/build")
    ap.add_argument("--max-others", type=float, default=None, help="start a run only once other processes used less than this many CPUs")
    ap.add_argument("--wait", type=float, default=600, help="how long to wait for that [s]")
    a = ap.parse_args()
    threads = [int(t) for t in a.threads.split(",")]
    builds = [os.path.abspath(b) for b in a.builds.split(",")] if a.builds else [None]
    cmd = lambda t: ["taskset", "-c", "0,1", "/usr/bin/python3", os.path.join(REPO, "yade"), "-n", "-x", "-j%d" % t,
                     os.path.abspath(__file__), "--child", str(a.bodies), str(a.steps), str(a.settle)]
    print("command of a run:", " ".join(cmd(threads[0])))
    res = {}  # (build, threads, engine) -> [us]
    engines = []
    runs = [(b, t) for b in builds for t in threads]
    for r in range(a.repeats):
        for b, t in (runs if r % 2 == 0 else runs[::-1]):  # interleaved, the order alternating
            if a.max_others is not None:
                deadline = time.time() + a.wait
                while others_now() > a.max_others and time.time() < deadline:
                    time.sleep(5)
            env = dict(os.environ)
            if b:
                env["YADE_BUILD_DIR"] = b
            b0, t0, r0 = busy_jiffies(), time.time(), resource.getrusage(resource.RUSAGE_CHILDREN)
            p = subprocess.run(cmd(t), capture_output=True, text=True, env=env, cwd=REPO)
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            ours = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
            others = max(0.0, busy_jiffies() - b0 - ours) / (time.time() - t0)
            found = LINE_RE.findall(p.stdout)
            if p.returncode != 0 or not found:
                print("run failed (-j%d):\n%s%s" % (t, p.stdout, p.stderr))
                return 1
            print("repeat %d %s-j%d: %s  (others=%.2f cpu)" % (r, (b + " ") if b else "", t,
                  "  ".join("%s %s" % (e, us) for e, us in found), others), flush=True)
            for e, us in found:
                if e not in engines:
                    engines.append(e)
                res.setdefault((b, t, e), []).append(float(us))
    for b in builds:
        print("\nus per step, median [min-max] of %d runs, %d spheres, %d steps%s" % (a.repeats, a.bodies, a.steps, (", " + b) if b else ""))
        print("%-22s" % "engine" + "".join("%24s" % ("-j%d" % t) for t in threads)
              + "".join("%12s" % ("j%d/j%d" % (threads[0], t)) for t in threads[1:]))
        for e in engines:
            v = [res[(b, t, e)] for t in threads]
            meds = [statistics.median(x) for x in v]
            row = "%-22s" % e + "".join("%24s" % ("%.1f [%.1f-%.1f]" % (m, min(x), max(x))) for m, x in zip(meds, v))
            row += "".join("%12.2f" % (meds[0] / m if m > 0 else float("nan")) for m in meds[1:])
            print(row)
    return 0


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "--child":
        child(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]))
    else:
        sys.exit(main())
