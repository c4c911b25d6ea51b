#!/usr/bin/python3
"""Dense-lattice benchmark: scripts/bench/dense.py here and in the reference Yade, and the same
lattice in LAMMPS (dense.lammps), interleaved.

    /usr/bin/python3 scripts/bench/dense_bench.py [--sizes 5000[,50000]] [--steps S[,S]] [--repeats 3]
        [--threads 1[,2]] [--law frict[,viscel,mindlin]] [--periodic] [--no-reference] [--no-lammps] [--no-shares]

Each repeat runs every (size, threads) once here, then in the reference (`yade` on PATH), then
in LAMMPS (`lmp` on PATH), each a fresh process pinned to CPU 0 (CPUs 0-1 with two threads), its
peak memory read from /usr/bin/time -v. Printed per scene: the medians of iter/s, particle-steps/s,
contacts and peak RSS of each engine, the ratios here/reference and here/LAMMPS taken pair by
pair (median of the per-repeat ratios), the 2-thread/1-thread ratio, and the share of each engine
of this one (yade.timing, from one more run with O.timingEnabled). Timing is noisy on shared
machines: quote the ratios of one invocation. Exit status 0 when every run printed its figures.

--law runs the same lattice with another contact law, in this engine and the reference, from a
copy of dense.py with its material, Ip2 and Law2 replaced (LAMMPS runs the Hooke lattice only):
  frict   FrictMat, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack (dense.py itself)
  viscel  ViscElMat(kn, ks, cn, cs) of the same stiffness as frict, Law2_ScGeom_ViscElPhys_Basic
  mindlin FrictMat, Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin
With several laws it prints each law's speed here over frict's, pair by pair.

--periodic runs scripts/bench/periodic_dense.py instead: the same lattice filling a periodic cell that
is slowly compressed (no facet box, no gravity), here and in the reference (LAMMPS not run).
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
PERIODIC_SCENE = os.path.join(HERE_DIR, "periodic_dense.py")
LAMMPS_IN = os.path.join(HERE_DIR, "dense.lammps")  # verbatim copy of the shared input
LINE_RE = re.compile(r"N=(\d+)\s+steps=(\d+)\s+contacts=(\d+)\s+iter_per_s=([0-9.eE+-]+)")
RSS_RE = re.compile(r"Maximum resident set size \(kbytes\):\s*(\d+)")
LAMMPS_RE = re.compile(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms")
SHARE_RE = re.compile(r"^(\w+)\s+\d+\s+\d+\s+[0-9.]+\s+([0-9.]+)%", re.M)


FRICT = ("FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='mat')",
         "Ip2_FrictMat_FrictMat_FrictPhys()", "Law2_ScGeom_FrictPhys_CundallStrack()")
LAWS = {
    "frict": FRICT,
    # kn = 2·E·r as FrictPhys gives two such spheres (the material's kn is halved in series), ks = poisson·kn
    "viscel": ("ViscElMat(young=1e7, poisson=.3, kn=2e5, ks=6e4, cn=10, cs=3, frictionAngle=.5, density=2600, label='mat')",
               "Ip2_ViscElMat_ViscElMat_ViscElPhys()", "Law2_ScGeom_ViscElPhys_Basic()"),
    "mindlin": (FRICT[0], "Ip2_FrictMat_FrictMat_MindlinPhys()", "Law2_ScGeom_MindlinPhys_Mindlin()"),
}


def scene_for(law, tmpdir):
    """dense.py, or a copy of it with the material, Ip2 and Law2 of `law`."""
    if law == "frict":
        return SCENE
    text = open(SCENE).read()
    for old, new in zip(FRICT, LAWS[law]):
        if old not in text:
            raise SystemExit("dense.py no longer contains %r: update LAWS in %s" % (old, __file__))
        text = text.replace(old, new)
    path = os.path.join(tmpdir, "dense_%s.py" % law)
    with open(path, "w") as f:
        f.write(text)
    return path


def lattice(n_spheres):
    n = max(2, int(round(n_spheres ** (1. / 3.))))
    return n, max(2, n_spheres // (n * n))


def timed(cmd, threads, cwd=None, timeout=1800):
    cpus = "0" if threads == 1 else "0-%d" % (threads - 1)
    full = ["/usr/bin/time", "-v", "taskset", "-c", cpus] + cmd
    p = subprocess.run(full, capture_output=True, text=True, cwd=cwd, timeout=timeout)
    rss = RSS_RE.search(p.stderr)
    return p.stdout + p.stderr, (int(rss.group(1)) / 1024 if rss else None)


def run_yade(binary, scene, n, steps, threads):
    out, rss = timed([binary, "-n", "-x", "-j%d" % threads, scene, str(n), str(steps)], threads, cwd=tempfile.gettempdir())
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


def shares(scene, n, steps, threads):
    """Each engine's share of the timed steps (the 20 untimed steps that make the contacts excluded)."""
    text = open(scene).read()
    untimed = "O.run(20, True)"
    if untimed not in text:
        return []
    text = text.replace(untimed, untimed + "; O.timingEnabled = True; timing.reset()", 1)
    with tempfile.NamedTemporaryFile("w", suffix=".py", delete=False) as f:
        f.write("import sys\nsys.argv = [%r, %r, %r]\nfrom yade import O, timing\n" % (scene, str(n), str(steps)))
        f.write(text + "\ntiming.stats()\n")
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
    ap.add_argument("--law", default="frict", help="contact laws, comma-separated: " + ", ".join(LAWS))
    ap.add_argument("--periodic", action="store_true", help="the lattice in a periodic cell (periodic_dense.py)")
    ap.add_argument("--no-reference", action="store_true")
    ap.add_argument("--no-lammps", action="store_true")
    ap.add_argument("--no-shares", action="store_true")
    a = ap.parse_args(argv)
    sizes = [int(x) for x in a.sizes.split(",")]
    steps = [int(x) for x in a.steps.split(",")] if a.steps else [300 if n < 20000 else 100 for n in sizes]
    if len(steps) != len(sizes):
        ap.error("--steps needs one value per size")
    threads = [int(x) for x in a.threads.split(",")]
    laws = a.law.split(",")
    for law in laws:
        if law not in LAWS:
            ap.error("unknown --law %r (known: %s)" % (law, ", ".join(LAWS)))
    ref = None if a.no_reference else (shutil.which("yade-double") or shutil.which("yade"))
    lmp = None if a.no_lammps or a.periodic else shutil.which("lmp")
    tmpdir = tempfile.mkdtemp(prefix="dense_bench_")
    if a.periodic and laws != ["frict"]:
        ap.error("--periodic runs the frict law only")
    scenes = {"frict": PERIODIC_SCENE} if a.periodic else {law: scene_for(law, tmpdir) for law in laws}
    engines = [("here", lambda law, n, s, t: run_yade(LAUNCHER, scenes[law], n, s, t))]
    if ref:
        engines.append(("reference", lambda law, n, s, t: run_yade(ref, scenes[law], n, s, t)))
    if lmp:
        engines.append(("lammps", lambda law, n, s, t: run_lammps(n, s, t) if law == "frict" else "skip"))
    results, failed = {}, 0
    for r in range(a.repeats):
        for n, s in zip(sizes, steps):
            for t in threads:
                for law in laws:
                    for name, run in engines:
                        res = run(law, n, s, t)
                        if res == "skip":
                            continue
                        print("repeat %d  %-9s %-7s N=%-6d steps=%-4d -j%d  %s" % (r + 1, name, law, n, s, t,
                              "failed" if res is None else "%.1f iter/s, %.0f MB" % (res["iter_per_s"], res["rss"] or 0)), flush=True)
                        failed += res is None
                        results.setdefault((name, law, n, t), []).append(res)
    print("\n%-9s %-7s %7s %3s %10s %14s %9s %8s" % ("engine", "law", "N", "-j", "iter/s", "particle-st/s", "contacts", "peak MB"))
    for (name, law, n, t), rs in sorted(results.items(), key=lambda kv: (kv[0][2], kv[0][3], kv[0][1], kv[0][0])):
        ok = [x for x in rs if x]
        print("%-9s %-7s %7d %3d %10s %14s %9s %8s" % (name, law, n, t, fmt(median([x["iter_per_s"] for x in ok]), ".1f"),
              fmt(median([x["psps"] for x in ok]), ".3g"), fmt(median([x["contacts"] for x in ok]), ".0f"),
              fmt(median([x["rss"] for x in ok]), ".0f")))

    def ratio(a_key, b_key):  # median of the per-repeat ratios
        pairs = [x["iter_per_s"] / y["iter_per_s"] for x, y in zip(results.get(a_key, []), results.get(b_key, [])) if x and y]
        return (median(pairs), min(pairs), max(pairs)) if pairs else None

    def show(what, q):
        if q:
            print("%-44s %.2fx  (pairs %.2f-%.2f)" % (what, q[0], q[1], q[2]))

    print()
    for n in sizes:
        for t in threads:
            for law in laws:
                for other in ("reference", "lammps") if t == 1 else ("reference",):  # (LAMMPS runs one process)
                    show("N=%d -j%d %s  here / %s" % (n, t, law, other), ratio(("here", law, n, t), (other, law, n, t)))
                if law != "frict":
                    show("N=%d -j%d  here %s / here frict" % (n, t, law), ratio(("here", law, n, t), ("here", "frict", n, t)))
        if len(threads) > 1:
            for law in laws:
                show("N=%d %s  here -j%d / -j%d" % (n, law, threads[-1], threads[0]), ratio(("here", law, n, threads[-1]), ("here", law, n, threads[0])))
    if not a.no_shares:
        for law in laws:
            for n, s in zip(sizes, steps):
                rows = shares(scenes[law], n, s, threads[0])
                print("\nN=%d -j%d %s: shares of this engine's timed steps: %s" % (n, threads[0], law, ", ".join("%s %s%%" % r for r in rows) or "(not measured)"))
    shutil.rmtree(tmpdir, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
