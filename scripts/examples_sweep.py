#!/usr/bin/python3
"""Run the reference Yade's example scripts here (and, with --reference, in the reference too) and report,
script by script, where each stops: the first error, or none within the time limit.

    /usr/bin/python3 scripts/examples_sweep.py [--timeout 10] [--reference] [--only SUBSTRING] [--grep REGEX] [--gui] [--cpu 1]

The examples come with the reference's documentation package (yade-doc, /usr/share/doc/yade/examples);
they are copied to a scratch folder first (many write files beside themselves) and each runs from its own
folder as `yade -n -x -j1 script.py`, stdin closed, pinned to one CPU. A script "ran" when it exited with
status 0 or was still running at the time limit with no error printed; otherwise the last exception line
of its output is its stopper. Printed: one line per script, then the counts and the most frequent
stoppers (a name missing here shows up as NameError / AttributeError / ImportError). Exit status 0 always
(a report, not a test)."""
import argparse
import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLES = "/usr/share/doc/yade/examples"
ERROR_RE = re.compile(r"^([A-Za-z_][A-Za-z_.]*(Error|Exception|Interrupt))(:.*)?$")


def stopper(binary, folder, script, timeout, cpu, gui=False):
    """'' when the script ran (or was still running at the limit without an error), else its last error line."""
    cmd = ["taskset", "-c", str(cpu), binary] + ([] if gui else ["-n"]) + ["-x", "-j1", script]
    try:
        p = subprocess.run(cmd, cwd=folder, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=timeout,
                           errors="replace")
        out, rc = p.stdout + p.stderr, p.returncode
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") + (e.stderr or b"").decode(errors="replace")
        rc = 0
    errors = [line.strip() for line in out.splitlines() if ERROR_RE.match(line.strip())]
    if errors:
        return errors[-1][:200]
    return "" if rc == 0 else "exit status %d" % rc


def kind(line):
    """What a stopper is about: the missing name or module, or the error's class."""
    for pattern in (r"name '([^']+)' is not defined", r"cannot import name '([^']+)'", r"No module named '([^']+)'",
                    r"has no attribute '([^']+)'"):
        m = re.search(pattern, line)
        if m:
            return m.group(1)
    return line.split(":")[0]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--timeout", type=float, default=10)
    ap.add_argument("--reference", action="store_true", help="run each script in the reference too (`yade` on PATH)")
    ap.add_argument("--only", default="", help="only the scripts whose path contains this")
    ap.add_argument("--grep", default="", help="only the scripts whose text matches this regular expression "
                    "(e.g. 'yade import .*qt' for those that open a view)")
    ap.add_argument("--gui", action="store_true", help="run without -n, so that scripts open their windows (under a "
                    "display: e.g. xvfb-run -a -s '-screen 0 1280x1024x24' python3 scripts/examples_sweep.py --gui)")
    ap.add_argument("--cpu", type=int, default=0)
    a = ap.parse_args(argv)
    if not os.path.isdir(EXAMPLES):
        print("no examples at %s (apt-get install yade-doc)" % EXAMPLES)
        return 0
    engines = [("here", os.path.join(ROOT, "yade"))]
    if a.reference:
        ref = shutil.which("yade")
        if ref:
            engines.append(("reference", ref))
        else:
            print("no reference on PATH: running here only")
    work = tempfile.mkdtemp(prefix="yade-examples-")
    results = {name: {} for name, _ in engines}
    try:
        for name, binary in engines:  # (a fresh copy each: scripts leave files behind)
            copy = os.path.join(work, name)
            shutil.copytree(EXAMPLES, copy)
            scripts = sorted(os.path.relpath(os.path.join(d, f), copy) for d, _, fs in os.walk(copy) for f in fs if f.endswith(".py"))
            scripts = [s for s in scripts if a.only in s]
            if a.grep:
                scripts = [s for s in scripts if re.search(a.grep, open(os.path.join(copy, s), errors="replace").read())]
            for s in scripts:
                results[name][s] = stopper(binary, os.path.join(copy, os.path.dirname(s)), os.path.basename(s), a.timeout, a.cpu,
                                           a.gui)
                print("%-9s %-70s %s" % (name, s, results[name][s] or "ran"), flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print()
    for name, _ in engines:
        r = results[name]
        print("%s: %d of %d ran (no error within %g s)" % (name, sum(1 for v in r.values() if not v), len(r), a.timeout))
    if len(engines) == 2:
        here, ref = results["here"], results["reference"]
        both = [s for s in here if not here[s] and not ref.get(s)]
        onlyRef = [s for s in here if here[s] and not ref.get(s)]
        onlyHere = [s for s in here if not here[s] and ref.get(s)]
        print("both ran: %d; only the reference: %d; only here: %d" % (len(both), len(onlyRef), len(onlyHere)))
        for s in onlyRef:
            print("  only the reference ran %-60s here: %s" % (s, here[s]))
    counts = collections.Counter(kind(v) for v in results["here"].values() if v)
    print("\nmost frequent stoppers here:")
    for what, n in counts.most_common(25):
        print("  %4d  %s" % (n, what))
    return 0


if __name__ == "__main__":
    sys.exit(main())
