#!/usr/bin/python3
"""DEM8 rotating drum (Dosta et al., Comput. Phys. Commun. 2024): the reference's own example script
DEM2020Benchmark/Case2_rotating_drum_openmp.py, run unchanged here and in the reference Yade,
interleaved.

    /usr/bin/python3 scripts/bench/drum_bench.py [--repeats 3] [--threads 1,2] [--no-reference]
        [--script PATH] [--input DIR]

The script (package yade-doc: /usr/share/doc/yade/examples/DEM2020Benchmark/) reads its spheres
and facets from inputData/ (default: ../shared/bench/dem8/inputData beside this repository), runs
1 000 timed steps of 38 000 Hertz-Mindlin spheres in a drum of 1 200 facets turned by a
RotationEngine and prints its Cundall number (particle-steps per second); it would then go on to
simulate 5 s, so each run is stopped once that line is printed. Each repeat runs every thread
count here, then in the reference (`yade` on PATH), each a fresh process pinned to CPU 0 (CPUs
0-1 with two threads). Printed: the median Cundall numbers, the ratios here/reference taken pair
by pair (median of the per-repeat ratios), and two threads against one. Exit status 0 when every
run printed its figure.
"""

import argparse
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time

HERE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE_DIR))
LAUNCHER = os.path.join(REPO, "yade")
SCRIPT = "/usr/share/doc/yade/examples/DEM2020Benchmark/Case2_rotating_drum_openmp.py"
INPUT = os.path.join(os.path.dirname(REPO), "shared", "bench", "dem8", "inputData")
CUNDALL_RE = re.compile(r"Cundall number = ([0-9.eE+-]+)")


def cundall(binary, script, workdir, threads, timeout=1800):
    """Runs the script until it prints its Cundall number; returns it (None if it never did)."""
    cpus = "0" if threads == 1 else "0-%d" % (threads - 1)
    cmd = ["taskset", "-c", cpus, binary, "-n", "-x", "-j%d" % threads, script]
    p = subprocess.Popen(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    found, start = None, time.time()
    try:
        for line in p.stdout:
            m = CUNDALL_RE.search(line)
            if m:
                found = float(m.group(1))
                break
            if time.time() - start > timeout:
                break
    finally:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
    return found


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", default="1,2", help="thread counts, comma-separated")
    ap.add_argument("--no-reference", action="store_true", help="run this engine only")
    ap.add_argument("--script", default=SCRIPT, help="the reference's example script")
    ap.add_argument("--input", default=INPUT, help="folder holding the three input files")
    args = ap.parse_args(argv)
    if not os.path.exists(args.script):
        sys.exit("drum_bench: %s not found (apt-get install yade-doc, or give --script)" % args.script)
    if not os.path.isdir(args.input):
        sys.exit("drum_bench: input folder %s not found (give --input)" % args.input)
    threads = [int(t) for t in args.threads.split(",")]
    engines = [("here", LAUNCHER)] + ([] if args.no_reference else [("reference", "yade")])
    work = tempfile.mkdtemp(prefix="drum-")
    os.symlink(os.path.abspath(args.input), os.path.join(work, "inputData"))
    results = {}  # (engine, threads) -> [Cundall numbers]
    ok = True
    for r in range(args.repeats):
        for name, binary in engines:
            for t in threads:
                c = cundall(binary, args.script, work, t)
                ok &= c is not None
                results.setdefault((name, t), []).append(c)
                print("repeat %d  %-9s -j%d  Cundall %s" % (r + 1, name, t, "%.3g" % c if c else "(none)"), flush=True)
    print("\nDEM8 rotating drum, 38 000 spheres, Cundall number (particle-steps/s), medians of %d:" % args.repeats)
    for t in threads:
        here = [c for c in results[("here", t)] if c]
        line = "  -j%d  here %.3g" % (t, statistics.median(here)) if here else "  -j%d  here (none)" % t
        if not args.no_reference:
            ref = [c for c in results[("reference", t)] if c]
            pairs = [a / b for a, b in zip(results[("here", t)], results[("reference", t)]) if a and b]
            if ref:
                line += "  reference %.3g" % statistics.median(ref)
            if pairs:
                line += "  here/reference %.2fx [%.2f-%.2f]" % (statistics.median(pairs), min(pairs), max(pairs))
        print(line)
    if 1 in threads and 2 in threads:
        pairs = [a / b for a, b in zip(results[("here", 2)], results[("here", 1)]) if a and b]
        if pairs:
            print("  here -j2/-j1 %.2fx" % statistics.median(pairs))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
