#!/usr/bin/python3
"""Checkpoint benchmark: O.save / O.load (and O.saveTmp / O.loadTmp) of the dense lattice, this
engine against the reference Yade, interleaved.

    /usr/bin/python3 scripts/bench/checkpoint_bench.py [--n 50000] [--reps 3]
        [--formats yade,yade.gz,xml,yade.zst,tmp] [--no-reference] [--reference PATH]
        [--big N] [--timeout S] [--tmpdir DIR] [--json FILE]

Every run is a fresh process of scripts/bench/checkpoint_scene.py pinned to CPU 0
(`taskset -c 0 ENGINE -n -x -j1 checkpoint_scene.py MODE N FILE`): for a file format, a `save`
process builds the lattice (dense.py's scene, 20 steps) and times O.save(FILE), then a `load`
process of the same engine times O.load(FILE) of that file and runs one step; for `tmp` one
process times O.saveTmp() then O.loadTmp(). Each rep runs, format by format, this engine then
the reference. Files go to a temporary folder, each removed once loaded, the folder at the end.

Printed: per format and engine the median save and load times (min-max over the reps), the file
size, the peak RSS of the save and of the load process (ru_maxrss), the RSS of the built scene
before saving and of the process after loading; then reference / here for save and load, the
median of the per-rep ratios (above 1: this engine is faster). `.yade.zst` runs here only (the
reference does not know zstd: it writes plain binary under that name). A format whose save fails
with an error naming the codec/compression is reported "unsupported", not as a failure.
--big N runs this engine alone at N spheres (one rep; the reference would take too long there)
and prints its peak memory against the scene's RSS.
Exit status 0 when every run gave its figures (unsupported formats included), 1 otherwise,
2 on bad usage or a missing engine.
"""

import argparse
import datetime
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
SCENE = os.path.join(HERE_DIR, "checkpoint_scene.py")
DEFAULT_FORMATS = "yade,yade.gz,xml,yade.zst,tmp"
HERE_ONLY = {"yade.zst"}            # the reference (2023.02a) has no zstd
CODEC_RE = re.compile(r"codec|zstd|\bzst\b|compress|unsupported|not supported|unknown (?:format|extension|suffix)", re.I)
MAGIC = {".gz": b"\x1f\x8b", ".bz2": b"BZh", ".zst": b"\x28\xb5\x2f\xfd"}


def git_rev():
    try:
        return subprocess.run(["git", "-C", REPO, "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, timeout=10).stdout.strip() or "?"
    except Exception:
        return "?"


def run_scene(cmd, mode, n, path, timeout, cwd):
    """One pinned process; returns (dict op -> JSON record, rc, output text)."""
    full = ["taskset", "-c", "0"] + cmd + ["-n", "-x", "-j1", SCENE, mode, str(n), path]
    t0 = time.time()
    try:
        p = subprocess.run(full, capture_output=True, text=True, timeout=timeout, cwd=cwd)
        out, rc = p.stdout + p.stderr, p.returncode
    except subprocess.TimeoutExpired as e:
        def s(x):
            return x.decode(errors="replace") if isinstance(x, bytes) else (x or "")
        out, rc = s(e.stdout) + s(e.stderr) + "\n[timed out after %d s]" % timeout, "timeout"
    recs = {}
    for line in out.splitlines():
        line = line.strip()
        if line.startswith("{"):
            try:
                d = json.loads(line)
            except ValueError:
                continue
            if isinstance(d, dict) and "op" in d:
                d["wall_s"] = time.time() - t0
                recs[d["op"]] = d
    return recs, rc, out


def tail(out, k=6):
    lines = [l for l in out.strip().splitlines() if l.strip()]
    return "\n        ".join(lines[-k:])


def magic_note(path, fmt):
    ext = os.path.splitext(path)[1]
    if ext not in MAGIC:
        return None
    with open(path, "rb") as f:
        head = f.read(4)
    if not head.startswith(MAGIC[ext]):
        return ".%s: the file written is not %s-compressed (its first bytes: %s)" % (fmt, {"gz": "gzip", "zst": "zstd"}.get(ext[1:], ext[1:]), head.hex())
    return None


def one(engine, cmd, fmt, n, timeout, tmpdir, tag, notes):
    """Save then load (or tmp) of one format by one engine: a dict of op -> record, or a status string."""
    if fmt == "tmp":
        recs, rc, out = run_scene(cmd, "tmp", n, "-", timeout, tmpdir)
        if "saveTmp" in recs and "loadTmp" in recs and rc == 0:
            return {"save": recs["saveTmp"], "load": recs["loadTmp"]}
        print("    %s tmp failed (rc %s):\n        %s" % (engine, rc, tail(out)), flush=True)
        return "failed"
    path = os.path.join(tmpdir, "%s_%s.%s" % (engine, tag, fmt))
    try:
        recs, rc, out = run_scene(cmd, "save", n, path, timeout, tmpdir)
        if "save" not in recs or rc != 0:
            if CODEC_RE.search(out.replace(path, "FILE")) and rc != "timeout":
                print("    %s .%s: save failed on the codec -> unsupported:\n        %s" % (engine, fmt, tail(out, 3)), flush=True)
                return "unsupported"
            print("    %s .%s save failed (rc %s):\n        %s" % (engine, fmt, rc, tail(out)), flush=True)
            return "failed"
        note = magic_note(path, fmt)
        if note and note not in notes:
            notes.append("%s: %s" % (engine, note))
        lrecs, lrc, lout = run_scene(cmd, "load", n, path, timeout, tmpdir)
        if "load" not in lrecs or lrc != 0:
            print("    %s .%s load failed (rc %s):\n        %s" % (engine, fmt, lrc, tail(lout)), flush=True)
            return "failed"
        s, l = recs["save"], lrecs["load"]
        if (s["bodies"], s["contacts"]) != (l["bodies"], l["contacts"]):
            notes.append("%s .%s: saved %d bodies / %d contacts, loaded %d / %d" % (
                engine, fmt, s["bodies"], s["contacts"], l["bodies"], l["contacts"]))
        return {"save": s, "load": l}
    finally:
        if os.path.exists(path):
            os.unlink(path)


def median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def fmt_time(xs):
    xs = [x for x in xs if x is not None]
    if not xs:
        return "-"
    m = statistics.median(xs)
    return "%.3f" % m if len(xs) == 1 else "%.3f (%.3f-%.3f)" % (m, min(xs), max(xs))


def fmt_num(x, spec=".1f"):
    return "-" if x is None else format(x, spec)


def table(results, formats, engines):
    """results[(fmt, engine)] = list of {"save": rec, "load": rec} or status strings."""
    hdr = ("format", "engine", "runs", "save s med (min-max)", "load s med (min-max)", "file MB",
           "peak save MB", "peak load MB", "scene rss MB", "rss loaded MB", "contacts")
    rows = []
    for f in formats:
        for e in engines:
            rs = results.get((f, e))
            if rs is None:
                continue
            ok = [r for r in rs if isinstance(r, dict)]
            bad = sorted(set(r for r in rs if not isinstance(r, dict)))
            if not ok:
                rows.append(("." + f if f != "tmp" else f, e, "0", ", ".join(bad) or "-") + ("",) * 7)
                continue
            sv = [r["save"] for r in ok]
            ld = [r["load"] for r in ok]
            rows.append(("." + f if f != "tmp" else f, e, "%d%s" % (len(ok), " +%s" % ",".join(bad) if bad else ""),
                         fmt_time([x["seconds"] for x in sv]), fmt_time([x["seconds"] for x in ld]),
                         fmt_num(median([x.get("size_mb") for x in sv]), ".2f"),
                         fmt_num(max(x["peak_mb"] for x in sv), ".0f"),
                         fmt_num(max(x["peak_mb"] for x in ld), ".0f") if f != "tmp" else "(same)",
                         fmt_num(median([x.get("rss_before_mb") for x in sv]), ".0f"),
                         fmt_num(median([x.get("rss_after_mb") for x in ld]), ".0f"),
                         "%d" % median([x["contacts"] for x in sv])))
    widths = [max(len(str(r[i])) for r in rows + [hdr]) for i in range(len(hdr))]
    line = lambda r: "  ".join(str(c).ljust(w) for c, w in zip(r, widths)).rstrip()
    print(line(hdr))
    print("  ".join("-" * w for w in widths))
    for r in rows:
        print(line(r))


def ratios(results, formats):
    print("\nreference / here (median of the per-rep ratios, their range; > 1: this engine is faster)")
    any_ = False
    for f in formats:
        h, r = results.get((f, "here"), []), results.get((f, "reference"), [])
        out = []
        for op in ("save", "load"):
            pairs = [b[op]["seconds"] / a[op]["seconds"] for a, b in zip(h, r)
                     if isinstance(a, dict) and isinstance(b, dict) and a[op]["seconds"] > 0]
            if pairs:
                out.append("%s %.2fx (%.2f-%.2f)" % (op, statistics.median(pairs), min(pairs), max(pairs)))
        if out:
            any_ = True
            print("  %-9s %s" % ("." + f if f != "tmp" else "tmp", "   ".join(out)))
    if not any_:
        print("  (no pair)")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--n", type=int, default=50000, help="spheres of the lattice (default 50000)")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--formats", default=DEFAULT_FORMATS,
                    help="file suffixes (yade, yade.gz, yade.bz2, xml, xml.gz, yade.zst, ...) and 'tmp' (default %s)" % DEFAULT_FORMATS)
    ap.add_argument("--no-reference", action="store_true")
    ap.add_argument("--reference", default=None, help="the reference's launcher (default: yade-double on PATH)")
    ap.add_argument("--big", type=int, default=0, metavar="N",
                    help="then this engine alone at N spheres, one rep (intended: 1000000)")
    ap.add_argument("--timeout", type=int, default=3600, help="seconds per process (default 3600)")
    ap.add_argument("--tmpdir", default=None, help="where the checkpoint files go (default: the system's temp folder)")
    ap.add_argument("--json", default=None, help="write every record to this file")
    a = ap.parse_args(argv)
    formats = [f.strip().lstrip(".") for f in a.formats.split(",") if f.strip()]
    if a.reps < 1 or a.n < 8:
        ap.error("--reps must be >= 1 and --n >= 8")

    if not (os.path.isfile(LAUNCHER) and os.access(LAUNCHER, os.X_OK)):
        print("error: this engine's launcher %s is missing or not executable" % LAUNCHER, file=sys.stderr)
        return 2
    if not os.path.isdir(os.path.join(REPO, "build", "yade")) and not os.environ.get("YADE_BUILD_DIR"):
        print("error: %s/build/yade is missing: this engine is not built (bash scripts/setup.sh)" % REPO, file=sys.stderr)
        return 2
    if shutil.which("taskset") is None:
        print("error: taskset not found (Debian package util-linux)", file=sys.stderr)
        return 2
    engines = [("here", [LAUNCHER])]
    if not a.no_reference:
        ref = a.reference or shutil.which("yade-double")
        if not ref or not (os.path.isfile(ref) and os.access(ref, os.X_OK)):
            print("error: the reference Yade (%s) is not found; install it (Debian package yade) or pass --no-reference"
                  % (a.reference or "yade-double on PATH"), file=sys.stderr)
            return 2
        engines.append(("reference", [ref]))
    names = [e for e, _ in engines]

    print("checkpoint_bench  %s  %s (%d CPUs)  git %s" % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
          platform.node(), os.cpu_count() or 0, git_rev()))
    print("run: taskset -c 0 ENGINE -n -x -j1 %s save|load|tmp %d FILE   engines: %s" % (
          os.path.relpath(SCENE, REPO), a.n, ", ".join("%s=%s" % (e, c[0]) for e, c in engines)))
    if not a.no_reference and any(f in HERE_ONLY for f in formats):
        print("note: %s run here only: the reference Yade has no zstd (skipped there)." % ", ".join("." + f for f in formats if f in HERE_ONLY))
    print("note: the load process reads the file its engine's save process has just written (page cache: no disk read timed).")

    tmpdir = tempfile.mkdtemp(prefix="checkpoint_bench_", dir=a.tmpdir)
    results, notes, unsupported, failed, records = {}, [], set(), 0, []
    try:
        for rep in range(a.reps):
            for f in formats:
                for name, cmd in engines:
                    if name == "reference" and f in HERE_ONLY:
                        results[(f, name)] = ["skipped (no zstd)"]
                        continue
                    if (f, name) in unsupported:
                        continue
                    res = one(name, cmd, f, a.n, a.timeout, tmpdir, "r%d" % rep, notes)
                    results.setdefault((f, name), []).append(res)
                    if res == "unsupported":
                        unsupported.add((f, name))
                    elif res == "failed":
                        failed += 1
                    else:
                        records.append({"rep": rep, "format": f, "engine": name, **res})
                        if name == "here" and res["save"].get("engine") != "here":
                            notes.append("this engine's runs report engine=%r: check build/yade" % res["save"].get("engine"))
                    desc = res if isinstance(res, str) else "save %.3f s  load %.3f s  %s  peak %.0f/%.0f MB  rss %.0f MB" % (
                        res["save"]["seconds"], res["load"]["seconds"],
                        "-" if res["save"].get("size_mb") is None else "%.2f MB" % res["save"]["size_mb"],
                        res["save"]["peak_mb"], res["load"]["peak_mb"], res["save"]["rss_before_mb"])
                    print("rep %d  %-9s %-9s %s" % (rep + 1, "." + f if f != "tmp" else f, name, desc), flush=True)

        n_sph = next((r["save"]["n"] for r in records), a.n)
        n_con = next((r["save"]["contacts"] for r in records), 0)
        print("\nN=%d spheres (lattice for --n %d), %d contacts, %d rep(s), 1 thread, pinned to CPU 0\n" % (n_sph, a.n, n_con, a.reps))
        table(results, formats, names)
        for f in formats:
            if f in HERE_ONLY and "reference" in names:
                print("  .%s: reference skipped (no zstd in the reference Yade)" % f)
            for e in names:
                if (f, e) in unsupported:
                    print("  .%s: unsupported by %s (its save failed on the codec)" % (f, e))
        if "reference" in names:
            ratios(results, formats)

        if a.big:
            print("\n--big %d: this engine only, 1 rep. The reference is skipped at this size, for time: each of its"
                  " processes would build the lattice in Python and run 20 steps before the save (two more processes"
                  " per format), and it needs several times this engine's memory." % a.big, flush=True)
            big = {}
            for f in formats:
                if (f, "here") in unsupported:
                    print("big  .%s  skipped (unsupported)" % f)
                    continue
                res = one("here", engines[0][1], f, a.big, a.timeout, tmpdir, "big", notes)
                big[(f, "here")] = [res]
                if res == "failed":
                    failed += 1
                elif isinstance(res, dict):
                    records.append({"rep": "big", "format": f, "engine": "here", **res})
                print("big  %-9s %s" % ("." + f if f != "tmp" else f, res if isinstance(res, str) else
                      "save %.2f s  load %.2f s" % (res["save"]["seconds"], res["load"]["seconds"])), flush=True)
            print()
            table(big, formats, ["here"])
            print("\npeak memory against the scene's RSS (N=%d):" % a.big)
            for f in formats:
                r = big.get((f, "here"), [None])[0]
                if not isinstance(r, dict):
                    continue
                s, l = r["save"], r["load"]
                rss = s["rss_before_mb"]
                print("  %-9s save: peak %.0f MB = scene rss %.0f MB x %.2f (+%.0f MB)   load: peak %.0f MB (x %.2f the scene rss), rss after %.0f MB" % (
                      "." + f if f != "tmp" else f, s["peak_mb"], rss, s["peak_mb"] / rss, s["peak_mb"] - rss,
                      l["peak_mb"], l["peak_mb"] / rss, l["rss_after_mb"]))
        for note in dict.fromkeys(notes):
            print("note: " + note)
    finally:
        shutil.rmtree(tmpdir, ignore_errors=True)
        if a.json:
            with open(a.json, "w") as fh:
                json.dump({"n": a.n, "reps": a.reps, "formats": formats, "engines": names, "records": records,
                           "unsupported": sorted("%s:%s" % x for x in unsupported), "notes": notes}, fh, indent=1)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
