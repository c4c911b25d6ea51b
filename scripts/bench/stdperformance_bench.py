#!/usr/bin/python3
"""The reference's standard performance test (`yade --stdperformance 1`: 10 009 visco-elastic spheres
falling into a box of facets, 7 000 steps), its own script run unchanged here and in the reference
Yade, interleaved.

    /usr/bin/python3 scripts/bench/stdperformance_bench.py [--repeats 3] [--threads 1]
        [--script PATH] [--no-reference]

The script is the one the reference's launcher runs for --stdperformance (installed with it:
.../yade/tests/checks/performance/checkPerf.py); here `./yade --stdperformance 1 script` runs it
with yade.runtime.opts.stdperformance = 1, as the reference's launcher does. Each repeat runs it
here, then in the reference, each a fresh process pinned to CPU 0 (CPUs 0-1 with two threads),
and reads its "Performance ... iter/sec" line and the process's CPU time (/usr/bin/time: user +
system, which a busy machine inflates less than the wall clock). Printed: each pair, the medians,
and the ratios here/reference taken pair by pair (median of the per-pair ratios, with their range).
Exit status 0 when every run printed its figure.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

HERE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE_DIR))
LAUNCHER = os.path.join(REPO, "yade")
SCRIPT = "/usr/lib/x86_64-linux-gnu/yade-double/py/yade/tests/checks/performance/checkPerf.py"
PERF_RE = re.compile(r"^Performance\s+([0-9.eE+-]+)\s+iter/sec", re.M)
CPU_RE = re.compile(r"^CPU ([0-9.]+) ([0-9.]+)$", re.M)


def figures(text):
    perf, cpu = PERF_RE.search(text), CPU_RE.search(text)
    return (float(perf.group(1)) if perf else None, float(cpu.group(1)) + float(cpu.group(2)) if cpu else None)


def one(binary, script, threads, workdir):
    """One run: (iter/s as the script prints it, CPU seconds of the process; None where not printed)."""
    cpus = "0" if threads == 1 else "0-%d" % (threads - 1)
    cmd = ["/usr/bin/time", "-f", "CPU %U %S", "taskset", "-c", cpus, binary, "-n", "-x", "-j%d" % threads, "--stdperformance", "1"]
    if binary == LAUNCHER:
        cmd.append(script)
    p = subprocess.run(cmd, cwd=workdir, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return figures(p.stdout)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--script", default=SCRIPT)
    ap.add_argument("--no-reference", action="store_true")
    a = ap.parse_args(argv)
    if not os.path.isfile(a.script):
        print("stdperformance_bench: %s not found (it comes with the reference: apt-get install -y yade)" % a.script)
        return 2
    ok, here, ref = True, [], []
    with tempfile.TemporaryDirectory() as work:
        for r in range(a.repeats):
            h = one(LAUNCHER, a.script, a.threads, work)
            here.append(h)
            line = "pair %d: here %s iter/s, %s s CPU" % (r + 1, h[0], h[1])
            ok &= None not in h
            if not a.no_reference:
                f = one("yade", a.script, a.threads, work)
                ref.append(f)
                ok &= None not in f
                line += "; reference %s iter/s, %s s CPU" % f
            print(line, flush=True)
    good = [h for h in here if None not in h]
    if good:
        print("here: median %.1f iter/s, %.1f s CPU (%d threads, %s)" % (statistics.median(h[0] for h in good),
              statistics.median(h[1] for h in good), a.threads, a.script))
    pairs = [(h, f) for h, f in zip(here, ref) if None not in h and None not in f]
    if pairs:
        speed = [h[0] / f[0] for h, f in pairs]
        cpu = [f[1] / h[1] for h, f in pairs]
        print("reference: median %.1f iter/s, %.1f s CPU" % (statistics.median(f[0] for _, f in pairs), statistics.median(f[1] for _, f in pairs)))
        print("here/reference: %.2fx by iter/s (pairs %.2f-%.2f), %.2fx by CPU time (pairs %.2f-%.2f)"
              % (statistics.median(speed), min(speed), max(speed), statistics.median(cpu), min(cpu), max(cpu)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
