#!/usr/bin/python3
"""Benchmark harness: the deposition scene here and in the reference Yade, interleaved.

    /usr/bin/python3 scripts/bench/run_bench.py [--sizes 5000[,50000]] [--steps 600] [--settle 2000]
        [--repeats 3] [--threads 1[,2]] [--no-reference] [--features] [--memory] [--json FILE]

Every run is a fresh process (``<repo>/yade -n -x -j T SCENE N STEPS SETTLE`` here, ``yade -n -x
-j T ...`` for the reference when it is on PATH) and prints one line

    N=<spheres> steps=<n> contacts=<c> iter_per_s=<x> particle_steps_per_s=<y>

which is parsed. Runs are interleaved: each repeat runs every (size, threads, variant)
combination once, here then reference, so that slow drifts of the machine hit both alike.
Printed: a table of medians (iter/s, particle-steps/s, contacts, peak RSS and RSS per sphere with
--memory), the ratios here/reference and 2 threads / 1 thread, and with --features the cost of
each optional feature measured against the plain run of the same repeat. With several thread
counts each repeat also runs build/parallel_ceiling (scripts/bench/parallel_ceiling.cpp): what the
machine's threads give at that moment to a perfectly parallel loop of the same size, the ceiling
of any scaling measured next to it.

Timing is noisy (±25% between identical runs on shared machines): compare ratios measured in one
invocation, never absolute figures across invocations. Exit status: 0 when every run produced its
line, 1 when some failed (the table then shows what did run), 2 on bad usage.
"""

import argparse
import datetime
import hashlib
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE_DIR = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE_DIR))
LAUNCHER = os.path.join(REPO, "yade")
SCENE = os.path.join(HERE_DIR, "deposition.py")            # verbatim copy of the shared scene
VARIANT_SCRIPT = os.path.join(HERE_DIR, "deposition_variant.py")
TIME_BIN = "/usr/bin/time"

# optional features whose cost --features measures (names understood by deposition_variant.py)
FEATURES = [
    ("energy", "O.trackEnergy=True"),
    ("pyrunner", "PyRunner(command='pass', iterPeriod=100)"),
    ("wall", "unused Bo1_Wall_Aabb + Ig2_Wall_Sphere_ScGeom"),
]
FEATURE_DESC = dict(FEATURES)

LINE_RE = re.compile(r"N=(\d+)\s+steps=(\d+)\s+contacts=(\d+)\s+iter_per_s=([0-9.eE+-]+)\s+"
                     r"particle_steps_per_s=([0-9.eE+-]+)")
RSS_RE = re.compile(r"Maximum resident set size \(kbytes\):\s*(\d+)")


# ----------------------------------------------------------------------------- helpers

def int_list(text):
    try:
        vals = [int(x) for x in str(text).replace(" ", "").split(",") if x]
    except ValueError:
        raise argparse.ArgumentTypeError("expected a comma-separated list of integers, got %r" % text)
    if not vals or any(v < 1 for v in vals):
        raise argparse.ArgumentTypeError("expected positive integers, got %r" % text)
    return vals


def median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def fmt(x, spec, missing="-"):
    return missing if x is None else format(x, spec)


def load1():
    try:
        return os.getloadavg()[0]
    except OSError:
        return None


def build_stamp():
    """Identify the build the local runs use (a hash of the extension module), to notice a rebuild
    in the middle of a benchmark."""
    bdir = os.path.abspath(os.environ.get("YADE_BUILD_DIR") or os.path.join(REPO, "build"))
    try:
        mods = sorted(f for f in os.listdir(os.path.join(bdir, "yade")) if f.startswith("_yade") and f.endswith(".so"))
        with open(os.path.join(bdir, "yade", mods[0]), "rb") as f:
            return hashlib.sha1(f.read()).hexdigest()[:12]
    except (OSError, IndexError):
        return None


def ceiling_binary():
    """The build's parallel_ceiling program, or None."""
    bdir = os.path.abspath(os.environ.get("YADE_BUILD_DIR") or os.path.join(REPO, "build"))
    path = os.path.join(bdir, "parallel_ceiling")
    return path if os.access(path, os.X_OK) else None


CEILING_RE = re.compile(r"ceiling threads=(\d+) one_thread_steps_per_s=([0-9.]+) threads_steps_per_s=([0-9.]+) ratio=([0-9.]+)")


def run_ceiling(binary, threads):
    """T threads / 1 thread for a perfectly parallel loop (threads bound to CPUs, as the engine's), or None."""
    env = dict(os.environ)
    if not any(k in env for k in ("OMP_PROC_BIND", "OMP_PLACES", "GOMP_CPU_AFFINITY", "YADE_NO_PINNING")):
        env["OMP_PROC_BIND"] = "true"
    try:
        out = subprocess.run([binary, str(threads)], capture_output=True, text=True, timeout=120, env=env).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    m = CEILING_RE.search(out)
    return float(m.group(4)) if m else None


def reference_binary():
    """The first 'yade' on PATH that is not this repository's launcher."""
    for d in os.environ.get("PATH", "").split(os.pathsep):
        cand = shutil.which("yade", path=d or ".")
        if cand and os.path.realpath(cand) != os.path.realpath(LAUNCHER):
            return cand
    return None


def here_version():
    try:
        r = subprocess.run(["git", "-C", REPO, "describe", "--always", "--dirty"], capture_output=True,
                           text=True, timeout=10)
        return r.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def command_for(engine, threads, variant, n, steps, settle, scene, ref_bin):
    """The command line of one run (without the /usr/bin/time wrapper)."""
    if variant == "plain":
        script_args = [scene]
    else:
        script_args = [VARIANT_SCRIPT, variant]
    script_args += [str(n), str(steps), str(settle)]
    if engine == "here":
        return ["/usr/bin/python3", LAUNCHER, "-n", "-x", "-j", str(threads)] + script_args
    return [ref_bin, "-n", "-x", "-j", str(threads)] + script_args


def run_one(cmd, memory, timeout, scene):
    """Run one benchmark process. Returns a dict with the parsed figures (None where missing)."""
    env = dict(os.environ)
    env.pop("OMP_NUM_THREADS", None)          # the launchers set it from -j
    env["BENCH_SCENE"] = scene                # for deposition_variant.py
    tfile = None
    full = list(cmd)
    if memory:
        fd, tfile = tempfile.mkstemp(prefix="bench-time-", suffix=".txt")
        os.close(fd)
        full = [TIME_BIN, "-v", "-o", tfile] + full
    res = {"cmd": cmd, "ok": False, "rc": None, "wall_s": None, "n": None, "steps": None, "contacts": None,
           "iter_per_s": None, "particle_steps_per_s": None, "rss_kb": None, "error": None}
    t0 = time.time()
    try:
        p = subprocess.run(full, capture_output=True, text=True, timeout=timeout, env=env, cwd=REPO,
                           stdin=subprocess.DEVNULL)
        res["rc"] = p.returncode
        out = p.stdout + "\n" + p.stderr
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        res["error"] = "timed out after %d s" % timeout
    except OSError as e:
        out = ""
        res["error"] = "cannot run: %s" % e
    res["wall_s"] = time.time() - t0
    res["load1"] = load1()
    m = None
    for m in LINE_RE.finditer(out):
        pass                                  # the last such line
    if m:
        res.update(n=int(m.group(1)), steps=int(m.group(2)), contacts=int(m.group(3)),
                   iter_per_s=float(m.group(4)), particle_steps_per_s=float(m.group(5)))
    if tfile:
        try:
            with open(tfile) as f:
                mm = RSS_RE.search(f.read())
            if mm:
                res["rss_kb"] = int(mm.group(1))
        finally:
            os.unlink(tfile)
    if m and res["rc"] == 0:
        res["ok"] = True
    elif res["error"] is None:
        tail = "\n".join(out.strip().splitlines()[-8:])
        res["error"] = "exit status %s%s\n%s" % (res["rc"], "" if m else ", no result line", tail)
    return res


# ----------------------------------------------------------------------------- the runs

def plan(args, engines):
    """The interleaved order of runs: a list of rounds (one per repeat), each a list of keys
    (engine, threads, size, variant). Within a round, engines alternate for each configuration;
    the variant order is rotated from one repeat to the next so that no variant always runs
    right after the plain one."""
    variants = ["plain"] + ([f for f, _ in FEATURES] if args.features else [])
    rounds = []
    for rep in range(args.repeats):
        rot = rep % len(variants)
        order = variants[rot:] + variants[:rot]
        keys = []
        for n in args.sizes:
            for t in args.threads:
                for v in order:
                    for e in engines:
                        keys.append((e, t, n, v))
        rounds.append(keys)
    return rounds


def run_all(args, engines, ref_bin, log=print, ceilings=None):
    """ceilings: a dict filled with {threads: [parallel_ceiling ratio per repeat]} (several thread counts only)."""
    rounds = plan(args, engines)
    total = sum(len(r) for r in rounds)
    results = {}          # key -> list over repeats of run_one()'s dicts (failed ones have ok False)
    ceiling_bin = ceiling_binary() if ceilings is not None and len(args.threads) > 1 else None
    k = 0
    for rep, keys in enumerate(rounds):
        for t in args.threads if ceiling_bin else []:
            if t > 1:
                c = run_ceiling(ceiling_bin, t)
                if c is not None:
                    ceilings.setdefault(t, []).append(c)
                    log("  (machine ceiling, a perfectly parallel loop: %d/1 threads %.2f)" % (t, c))
        for key in keys:
            k += 1
            e, t, n, v = key
            cmd = command_for(e, t, v, n, args.steps, args.settle, args.scene, ref_bin)
            r = run_one(cmd, args.memory, args.timeout, args.scene)
            for _ in range(args.retries):
                if r["ok"]:
                    break
                log("  (run failed: %s; retrying in 5 s)" % (r["error"] or "").splitlines()[0])
                time.sleep(5)
                r = run_one(cmd, args.memory, args.timeout, args.scene)
            r["repeat"] = rep
            if e == "here":
                r["build"] = build_stamp()
            results.setdefault(key, []).append(r)
            if r["ok"]:
                log("  [%*d/%d] %-4s j%d N=%-6d %-8s %9.1f iter/s  %9.3g particle-steps/s%s  (%.1f s, load %s)"
                    % (len(str(total)), k, total, e, t, n, v, r["iter_per_s"], r["particle_steps_per_s"],
                       "  %7.1f MB" % (r["rss_kb"] / 1024.) if r["rss_kb"] else "", r["wall_s"],
                       fmt(r["load1"], ".1f")))
            else:
                log("  [%*d/%d] %-4s j%d N=%-6d %-8s FAILED: %s"
                    % (len(str(total)), k, total, e, t, n, v, r["error"]))
    return results


def summarize(args, engines, results, ceilings=None):
    """Medians and ratios; returns a JSON-serialisable dict."""
    rows = []
    for n in args.sizes:
        for t in args.threads:
            for e in engines:
                rs = [r for r in results.get((e, t, n, "plain"), []) if r["ok"]]
                ips = [r["iter_per_s"] for r in rs]
                pss = [r["particle_steps_per_s"] for r in rs]
                rss = [r["rss_kb"] for r in rs if r["rss_kb"]]
                nsph = rs[0]["n"] if rs else None
                peak = max(rss) if rss else None
                rows.append({
                    "engine": e, "threads": t, "size": n, "spheres": nsph, "runs": len(rs),
                    "runs_failed": len(results.get((e, t, n, "plain"), [])) - len(rs),
                    "iter_per_s": median(ips), "iter_per_s_min": min(ips) if ips else None,
                    "iter_per_s_max": max(ips) if ips else None,
                    "particle_steps_per_s": median(pss),
                    "contacts": median([r["contacts"] for r in rs]),
                    "timed_s": median([r["steps"] / r["iter_per_s"] for r in rs if r["iter_per_s"]]),
                    "rss_mb": peak / 1024. if peak else None,
                    "rss_kb_per_sphere": peak / nsph if peak and nsph else None,
                })
    by = {(r["engine"], r["threads"], r["size"]): r for r in rows}

    def paired(key_a, key_b, field="iter_per_s"):
        """Per-repeat ratios a/b of runs from the same repeat."""
        a = {r["repeat"]: r for r in results.get(key_a, []) if r["ok"]}
        b = {r["repeat"]: r for r in results.get(key_b, []) if r["ok"]}
        return [a[k][field] / b[k][field] for k in sorted(a) if k in b and b[k][field]]

    ratios = []
    if "ref" in engines:
        for n in args.sizes:
            for t in args.threads:
                h, f = by[("here", t, n)], by[("ref", t, n)]
                pr = paired(("here", t, n, "plain"), ("ref", t, n, "plain"))
                ratios.append({
                    "kind": "here/ref", "threads": t, "size": n,
                    "iter_per_s": h["iter_per_s"] / f["iter_per_s"] if h["iter_per_s"] and f["iter_per_s"] else None,
                    "paired": pr,
                    "rss": h["rss_mb"] / f["rss_mb"] if h["rss_mb"] and f["rss_mb"] else None,
                    "rss_per_sphere_here_kb": h["rss_kb_per_sphere"], "rss_per_sphere_ref_kb": f["rss_kb_per_sphere"],
                })
    scaling = []
    if len(args.threads) > 1:
        t1 = min(args.threads)
        for n in args.sizes:
            for e in engines:
                for t in args.threads:
                    if t == t1:
                        continue
                    a, b = by[(e, t, n)], by[(e, t1, n)]
                    scaling.append({
                        "engine": e, "size": n, "threads": t, "base_threads": t1,
                        "speedup": a["iter_per_s"] / b["iter_per_s"] if a["iter_per_s"] and b["iter_per_s"] else None,
                        "paired": paired((e, t, n, "plain"), (e, t1, n, "plain")),
                    })
    marginal = []
    if args.memory and len(args.sizes) > 1:
        n0 = min(args.sizes)
        for e in engines:
            for t in args.threads:
                base = by[(e, t, n0)]
                for n in args.sizes:
                    if n == n0:
                        continue
                    r = by[(e, t, n)]
                    if r["rss_mb"] and base["rss_mb"] and r["spheres"] and base["spheres"]:
                        marginal.append({"engine": e, "threads": t, "size": n, "base_size": n0,
                                         "kb_per_sphere": (r["rss_mb"] - base["rss_mb"]) * 1024.
                                         / (r["spheres"] - base["spheres"])})
    features = []
    if args.features:
        for n in args.sizes:
            for t in args.threads:
                for e in engines:
                    for f, desc in FEATURES:
                        rs = [r for r in results.get((e, t, n, f), []) if r["ok"]]
                        # ratio of the medians (robust to one outlier in either set) and the
                        # per-repeat ratios (show the spread); cost = extra wall time per step
                        pr = paired((e, t, n, f), (e, t, n, "plain"))
                        vi, pi = median([r["iter_per_s"] for r in rs]), by[(e, t, n)]["iter_per_s"]
                        rr = vi / pi if vi and pi else None
                        features.append({
                            "engine": e, "threads": t, "size": n, "feature": f, "description": desc,
                            "runs": len(rs), "iter_per_s": vi, "plain_iter_per_s": pi,
                            "ratio_variant_plain": rr, "paired": pr, "paired_median": median(pr),
                            "cost_percent": 100. * (1. / rr - 1.) if rr else None,
                        })
    builds = sorted({r.get("build") for (e, _, _, _), rs in results.items() if e == "here" for r in rs
                     if r.get("build")})
    loads = [r["load1"] for rs in results.values() for r in rs if r.get("load1") is not None]
    return {"load1_min": min(loads) if loads else None, "load1_max": max(loads) if loads else None,
            "builds": builds, "rows": rows, "ratios": ratios, "scaling": scaling, "marginal_memory": marginal,
            "features": features,
            "ceiling": [{"threads": t, "ratio": median(v), "runs": v} for t, v in sorted((ceilings or {}).items())]}


def print_report(args, engines, summary, out=print):
    out("")
    out("== deposition benchmark: median over %d repeat%s, %d timed steps after %d untimed =="
        % (args.repeats, "" if args.repeats == 1 else "s", args.steps, args.settle))
    out("%-6s %7s %7s %5s %11s %19s %14s %9s %11s %10s"
        % ("engine", "threads", "N", "runs", "iter/s", "[min - max]", "particle-st/s", "contacts",
           "peakRSS MB", "KB/sphere"))
    for r in summary["rows"]:
        spread = ("[%s - %s]" % (fmt(r["iter_per_s_min"], ".1f"), fmt(r["iter_per_s_max"], ".1f"))
                  if r["runs"] else "")
        out("%-6s %7d %7s %5s %11s %19s %14s %9s %11s %10s"
            % (r["engine"], r["threads"], r["spheres"] or r["size"],
               "%d%s" % (r["runs"], "!" if r["runs_failed"] else ""),
               fmt(r["iter_per_s"], ".1f"), spread, fmt(r["particle_steps_per_s"], ".4g"),
               fmt(r["contacts"], ".0f"), fmt(r["rss_mb"], ".1f"), fmt(r["rss_kb_per_sphere"], ".2f")))
    if any(r["runs_failed"] for r in summary["rows"]):
        out("('!': some runs of that line failed, see the log above)")
    short = [r for r in summary["rows"] if r["engine"] == "ref" and r["timed_s"] is not None and r["timed_s"] < 2.]
    if short:
        out("note: the reference's O.run(n, True) waits in 40 ms polls, so its timed phase is rounded up to a")
        out("      multiple of ~40 ms; with timed phases of %s s its iter/s is underestimated by up to %s"
            % ("/".join("%.2f" % r["timed_s"] for r in short),
               "/".join("%.0f%%" % (100. * .04 / r["timed_s"]) for r in short)))
        out("      (use more --steps for a timed phase of several seconds)")
    if len(summary.get("builds", [])) > 1:
        out("WARNING: the local build changed during the runs (%d different builds: %s): the local"
            % (len(summary["builds"]), ", ".join(summary["builds"])))
        out("         figures mix them; rerun when the build is stable")
    cpus = os.cpu_count() or 1
    if summary.get("load1_max") is not None:
        out("load average (1 min) during the runs: %.1f - %.1f on %d CPUs%s"
            % (summary["load1_min"], summary["load1_max"], cpus,
               ": the machine was busy, figures are noisier than usual" if summary["load1_max"] > cpus + .5 else ""))
    if summary["ratios"]:
        out("")
        out("== here / reference (ratio of medians; paired = per-repeat ratios) ==")
        for q in summary["ratios"]:
            line = "threads %d, N=%d: iter/s ratio %s  paired [%s]" % (
                q["threads"], q["size"], fmt(q["iter_per_s"], ".2f"), " ".join("%.2f" % x for x in q["paired"]))
            if q["rss"] is not None:
                line += "  | peak RSS ratio %.2f, per sphere %.2f vs %.2f KB" % (
                    q["rss"], q["rss_per_sphere_here_kb"], q["rss_per_sphere_ref_kb"])
            out(line)
    if summary["scaling"]:
        out("")
        out("== thread scaling (iter/s at T threads / at %d thread, ratio of medians) ==" % min(args.threads))
        for s in summary["scaling"]:
            out("%-4s N=%d: %d/%d threads %s  paired [%s]" % (
                s["engine"], s["size"], s["threads"], s["base_threads"], fmt(s["speedup"], ".2f"),
                " ".join("%.2f" % x for x in s["paired"])))
        for c in summary.get("ceiling", []):
            out("machine ceiling (a perfectly parallel loop, once per repeat): %d/1 threads %s  runs [%s]" % (
                c["threads"], fmt(c["ratio"], ".2f"), " ".join("%.2f" % x for x in c["runs"])))
    if summary["marginal_memory"]:
        out("")
        out("== memory per added sphere ((RSS(N) - RSS(N0)) / (N - N0)) ==")
        for m in summary["marginal_memory"]:
            out("%-4s threads %d, N=%d vs N0=%d: %.2f KB/sphere" % (
                m["engine"], m["threads"], m["size"], m["base_size"], m["kb_per_sphere"]))
    if summary["features"]:
        out("")
        out("== feature costs: each variant interleaved with the plain run in the same repeats; variant/plain =")
        out("== ratio of median iter/s, cost = plain/variant - 1 (extra time per step); paired = per-repeat ratios ==")
        out("%-6s %7s %7s %-9s %-46s %9s %9s %13s %8s  %s"
            % ("engine", "threads", "N", "feature", "what", "iter/s", "plain", "variant/plain", "cost %",
               "paired variant/plain"))
        for f in summary["features"]:
            out("%-6s %7d %7d %-9s %-46s %9s %9s %13s %8s  [%s]"
                % (f["engine"], f["threads"], f["size"], f["feature"], f["description"],
                   fmt(f["iter_per_s"], ".1f"), fmt(f["plain_iter_per_s"], ".1f"),
                   fmt(f["ratio_variant_plain"], ".3f"), fmt(f["cost_percent"], "+.1f"),
                   " ".join("%.2f" % x for x in f["paired"])))
    out("")
    out("(timings vary by about ±25% between identical runs: compare ratios from one invocation)")


def make_parser():
    p = argparse.ArgumentParser(
        prog="run_bench.py",
        description="Run the deposition benchmark here and in the reference Yade (if installed), "
                    "interleaved, and print medians, ratios and optional feature costs.",
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    p.add_argument("--sizes", type=int_list, default=[5000], help="sphere counts, comma-separated")
    p.add_argument("--steps", type=int, default=600, help="timed steps")
    p.add_argument("--settle", type=int, default=2000, help="untimed steps before the timed ones")
    p.add_argument("--repeats", type=int, default=3, help="runs of each configuration")
    p.add_argument("--threads", type=int_list, default=[1], help="thread counts, comma-separated (e.g. 1,2)")
    p.add_argument("--no-reference", action="store_true", help="do not run the reference Yade")
    p.add_argument("--reference", default=None, metavar="PATH",
                   help="reference launcher (default: 'yade' on PATH)")
    p.add_argument("--features", action="store_true",
                   help="also run the feature-cost variants (%s)" % ", ".join(f for f, _ in FEATURES))
    p.add_argument("--memory", action="store_true",
                   help="wrap each run in %s -v and report the peak resident set size" % TIME_BIN)
    p.add_argument("--scene", default=SCENE, help="the benchmark scene script")
    p.add_argument("--timeout", type=int, default=3600, help="seconds allowed to one run")
    p.add_argument("--retries", type=int, default=1,
                   help="re-run a failed run this many times (e.g. while the build is being replaced)")
    p.add_argument("--json", metavar="FILE", default=None, help="also write all runs and the summary as JSON")
    p.add_argument("--quiet", action="store_true", help="do not log each run")
    return p


def main(argv=None):
    args = make_parser().parse_args(argv)
    if args.repeats < 1 or args.steps < 1 or args.settle < 0:
        print("run_bench.py: --repeats and --steps must be at least 1, --settle at least 0", file=sys.stderr)
        return 2
    args.scene = os.path.abspath(args.scene)
    if not os.path.isfile(args.scene):
        print("run_bench.py: no scene %s" % args.scene, file=sys.stderr)
        return 2
    if args.memory and not os.access(TIME_BIN, os.X_OK):
        print("run_bench.py: --memory needs %s (Debian package 'time': apt-get install -y time)" % TIME_BIN,
              file=sys.stderr)
        return 2
    ref_bin = None
    if not args.no_reference:
        ref_bin = args.reference or reference_binary()
        if args.reference and not (shutil.which(args.reference) or os.access(args.reference, os.X_OK)):
            print("run_bench.py: reference %s not found" % args.reference, file=sys.stderr)
            return 2
    engines = ["here"] + (["ref"] if ref_bin else [])
    args.sizes = list(dict.fromkeys(args.sizes))
    args.threads = list(dict.fromkeys(args.threads))

    log = (lambda *a, **k: None) if args.quiet else (lambda s: print(s, flush=True))
    print("deposition benchmark, %s" % datetime.datetime.now().strftime("%Y-%m-%d %H:%M:%S"))
    print("machine: %s, %d CPUs (%s); python %s" % (platform.node(), os.cpu_count() or 0, cpu_model(),
                                                   platform.python_version()))
    print("here:      %s (git %s; build %s)" % (LAUNCHER, here_version(), build_stamp()))
    print("reference: %s" % (ref_bin or ("not run (--no-reference)" if args.no_reference else "not installed ('yade' not on PATH)")))
    print("scene: %s  sizes %s, threads %s, steps %d, settle %d, repeats %d%s%s"
          % (args.scene, ",".join(map(str, args.sizes)), ",".join(map(str, args.threads)), args.steps,
             args.settle, args.repeats, ", features" if args.features else "", ", memory" if args.memory else ""))
    print("command (here): %s" % " ".join(command_for("here", args.threads[0], "plain", args.sizes[0], args.steps,
                                                    args.settle, args.scene, ref_bin)))
    sys.stdout.flush()

    t0 = time.time()
    ceilings = {}
    results = run_all(args, engines, ref_bin, log=log, ceilings=ceilings)
    summary = summarize(args, engines, results, ceilings)
    print_report(args, engines, summary)
    nfail = sum(1 for rs in results.values() for r in rs if not r["ok"])
    print("%d runs in %.0f s%s" % (sum(len(rs) for rs in results.values()), time.time() - t0,
                                  ", %d FAILED" % nfail if nfail else ""))
    if args.json:
        raw = [dict(r, engine=k[0], threads=k[1], size=k[2], variant=k[3])
               for k, rs in results.items() for r in rs]
        with open(args.json, "w") as f:
            json.dump({"args": {k: v for k, v in vars(args).items()}, "reference": ref_bin,
                       "summary": summary, "runs": raw}, f, indent=1)
    return 1 if nfail else 0


if __name__ == "__main__":
    sys.exit(main())
