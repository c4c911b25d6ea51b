#!/usr/bin/python3
"""Dense-lattice benchmark: scripts/bench/dense.py here and in the reference Yade, and the same
lattice in LAMMPS (dense.lammps), interleaved.

    /usr/bin/python3 scripts/bench/dense_bench.py [--sizes 5000[,50000]] [--steps S[,S]] [--repeats 3]
        [--threads 1[,2]] [--no-reference] [--no-lammps] [--no-shares]

Each repeat runs every (size, threads) once here, then in the reference (`yade` on PATH), then
in LAMMPS (`lmp` on PATH), each a fresh process pinned to CPU 0 (CPUs 0-1 with two threads), its
peak memory read from /usr/bin/time -v. Printed per scene: the medians of iter/s, particle-steps/s,
contacts and peak RSS of each engine, the ratios here/reference and here/LAMMPS taken pair by
pair (median of the per-repeat ratios), the 2-thread/1-thread ratio, and the share of each engine
of this one (yade.timing, from one more run with O.timingEnabled). Timing is noisy on shared
machines: quote the ratios of one invocation. Exit status 0 when every run printed its figures.
"""

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE_DIR))
LAUNCHER = os.path.join(REPO, "yade")
SCENE = os.path.join(HERE_DIR, "dense.py")         # verbatim copy of the shared scene
LAMMPS_IN = os.path.join(HERE_DIR, "dense.lammps")  # verbatim copy of the shared input
LINE_RE = re.compile(r"N=(\d+)\s+steps=(\d+)\s+contacts=(\d+)\s+iter_per_s=([0-9.eE+-]+)")
RSS_RE = re.compile(r"Maximum resident set size \(kbytes\):\s*(\d+)")
LAMMPS_RE = re.compile(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms")
SHARE_RE = re.compile(r"^(\w+)\s+\d+\s+\d+\s+[0-9.]+\s+([0-9.]+)%", re.M)


def lattice(n_spheres):
    n = max(2, int(round(n_spheres ** (1. / 3.))))
    return n, max(2, n_spheres // (n * n))


def timed(cmd, threads, cwd=None, timeout=1800):
    cpus = "0" if threads == 1 else "0-%d" % (threads - 1)
    full = ["/usr/bin/time", "-v", "taskset", "-c", cpus] + cmd
    p = subprocess.run(full, capture_output=True, text=True, cwd=cwd, timeout=timeout)
    rss = RSS_RE.search(p.stderr)
    return p.stdout + p.stderr, (int(rss.group(1)) / 1024 if rss else None)


def run_yade(binary, n, steps, threads):
    out, rss = timed([binary, "-n", "-x", "-j%d" % threads, SCENE, str(n), str(steps)], threads, cwd=tempfile.gettempdir())
    m = LINE_RE.search(out)
    if not m:
        return None
    spheres, contacts, ips = int(m.group(1)), int(m.group(3)), float(m.group(4))
    return {"iter_per_s": ips, "psps": ips * spheres, "contacts": contacts, "rss": rss}


def run_lammps(n, steps, threads):
    nx, nz = lattice(n)
    out, rss = timed(["lmp", "-log", "none", "-in", LAMMPS_IN, "-var", "n", str(nx), "-var", "nz", str(nz), "-var", "steps", str(steps)],
                     threads, cwd=tempfile.gettempdir())
    loops = LAMMPS_RE.findall(out)
    if len(loops) < 2:
        return None
    t, s, atoms = float(loops[-1][0]), int(loops[-1][1]), int(loops[-1][2])
    return {"iter_per_s": s / t, "psps": s / t * atoms, "contacts": None, "rss": rss}


def shares(n, steps, threads):
    script = ("import sys, runpy\nsys.argv = [%r, %r, %r]\nfrom yade import O, timing\nO.timingEnabled = True\n"
              "runpy.run_path(%r, init_globals=dict(globals()), run_name='__main__')\ntiming.stats()\n") % (SCENE, str(n), str(steps), SCENE)
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as f:
        f.write(script)
    try:
        out, _ = timed([LAUNCHER, "-n", "-x", "-j%d" % threads, f.name], threads)
    finally:
        os.unlink(f.name)
    return SHARE_RE.findall(out)


def median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def fmt(x, spec):
    return "-" if x is None else format(x, spec)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sizes", default="5000")
    ap.add_argument("--steps", default="", help="steps per size (default: 300 below 20 000 spheres, else 100)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--threads", default="1")
    ap.add_argument("--no-reference", action="store_true")
    ap.add_argument("--no-lammps", action="store_true")
    ap.add_argument("--no-shares", action="store_true")
    a = ap.parse_args(argv)
    sizes = [int(x) for x in a.sizes.split(",")]
    steps = [int(x) for x in a.steps.split(",")] if a.steps else [300 if n < 20000 else 100 for n in sizes]
    if len(steps) != len(sizes):
        ap.error("--steps needs one value per size")
    threads = [int(x) for x in a.threads.split(",")]
    ref = None if a.no_reference else (shutil.which("yade-double") or shutil.which("yade"))
    lmp = None if a.no_lammps else shutil.which("lmp")
    engines = [("here", lambda n, s, t: run_yade(LAUNCHER, n, s, t))]
    if ref:
        engines.append(("reference", lambda n, s, t: run_yade(ref, n, s, t)))
    if lmp:
        engines.append(("lammps", run_lammps))
    results, failed = {}, 0
    for r in range(a.repeats):
        for n, s in zip(sizes, steps):
            for t in threads:
                for name, run in engines:
                    res = run(n, s, t)
                    print("repeat %d  %-9s N=%-6d steps=%-4d -j%d  %s" % (r + 1, name, n, s, t,
                          "failed" if res is None else "%.1f iter/s, %.0f MB" % (res["iter_per_s"], res["rss"] or 0)), flush=True)
                    failed += res is None
                    results.setdefault((name, n, t), []).append(res)
    print("\n%-9s %7s %3s %10s %14s %9s %8s" % ("engine", "N", "-j", "iter/s", "particle-st/s", "contacts", "peak MB"))
    for (name, n, t), rs in sorted(results.items(), key=lambda kv: (kv[0][1], kv[0][2], kv[0][0])):
        ok = [x for x in rs if x]
        print("%-9s %7d %3d %10s %14s %9s %8s" % (name, n, t, fmt(median([x["iter_per_s"] for x in ok]), ".1f"),
              fmt(median([x["psps"] for x in ok]), ".3g"), fmt(median([x["contacts"] for x in ok]), ".0f"),
              fmt(median([x["rss"] for x in ok]), ".0f")))

    def ratio(a_key, b_key):  # median of the per-repeat ratios
        pairs = [x["iter_per_s"] / y["iter_per_s"] for x, y in zip(results.get(a_key, []), results.get(b_key, [])) if x and y]
        return (median(pairs), min(pairs), max(pairs)) if pairs else None

    print()
    for n in sizes:
        for t in threads:
            for other in ("reference", "lammps"):
                q = ratio(("here", n, t), (other, n, t))
                if q:
                    print("N=%d -j%d  here / %-9s  %.2fx  (pairs %.2f-%.2f)" % (n, t, other, q[0], q[1], q[2]))
        if len(threads) > 1:
            q = ratio(("here", n, threads[-1]), ("here", n, threads[0]))
            if q:
                print("N=%d  here -j%d / -j%d  %.2fx  (pairs %.2f-%.2f)" % (n, threads[-1], threads[0], q[0], q[1], q[2]))
    if not a.no_shares:
        for n, s in zip(sizes, steps):
            rows = shares(n, s, threads[0])
            print("\nN=%d -j%d shares of this engine's step: %s" % (n, threads[0], ", ".join("%s %s%%" % r for r in rows) or "(not measured)"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
