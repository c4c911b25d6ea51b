# Checkpoint benchmark scene: times O.save / O.load / O.saveTmp+O.loadTmp of the dense lattice.
# Runs unchanged in this engine and in the reference Yade:
#     yade -n -x -j1 checkpoint_scene.py MODE N FILE
#   MODE save  builds the lattice of N spheres (dense.py beside this script), runs its 20 steps so that
#              contacts exist, then times O.save(FILE) (the format follows FILE's suffix).
#   MODE load  a fresh process: does NOT build anything; times O.load(FILE), then runs one step
#              (untimed) to check that the loaded scene runs.
#   MODE tmp   builds the lattice, then times O.saveTmp() and O.loadTmp() (FILE is ignored: pass "-").
# Prints one JSON line per timed operation, starting with '{':
#   {"engine", "version", "op", "n" (spheres), "bodies", "contacts" (real interactions), "seconds",
#    "rss_before_mb" (save/saveTmp: VmRSS before the operation), "rss_after_mb" (load/loadTmp: after it),
#    "peak_mb" (ru_maxrss of the process so far), "size_mb" (save: the file's size; load: the file read)}
# Engine: "reference" when the yade package comes from the system (its real path under /usr/, as
# the Debian yade-double: /usr/lib/x86_64-linux-gnu/yade-double/py/yade), else "here" (this
# repository's build/yade); $CHECKPOINT_ENGINE overrides the name.
import json, os, resource, sys, time
import yade
from yade import geom  # noqa: F401  (dense.py uses them)
from yade.utils import *

args = [a for a in sys.argv[1:] if not a.startswith('-') or a == '-']
# (this script's folder: sys.argv[0] in both launchers; the reference's __file__ is its launcher)
HERE = os.path.dirname(os.path.abspath(sys.argv[0]))
if len(args) < 2 or args[0] not in ('save', 'load', 'tmp'):
    sys.stderr.write("usage: checkpoint_scene.py save|load|tmp N FILE\n")
    sys.exit(2)
MODE, N = args[0], int(args[1])
FILE = args[2] if len(args) > 2 else '-'

_pkg = os.path.realpath(yade.__file__)
ENGINE = os.environ.get('CHECKPOINT_ENGINE') or ('reference' if _pkg.startswith('/usr/') else 'here')
try:
    from yade import config as _config
    VERSION = str(getattr(_config, 'version', '?'))
except Exception:
    VERSION = '?'


def rss_mb():
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                return int(line.split()[1]) / 1024.
    return None


def peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.


def contacts():
    return O.interactions.countReal()


def spheres():
    return sum(1 for b in O.bodies if b is not None and isinstance(b.shape, Sphere))


def report(op, seconds, **kw):
    d = {"engine": ENGINE, "version": VERSION, "op": op, "n": spheres(), "bodies": len(O.bodies),
         "contacts": contacts(), "seconds": seconds}
    d.update(kw)
    print(json.dumps(d), flush=True)


def build():
    """The scene of dense.py beside this script (the repository's copy of shared/bench/dense.py), up to
    and with its untimed 20 steps (the contacts are made), run here as its own text."""
    src = open(os.path.join(HERE, 'dense.py')).read()
    upTo = 'O.run(20, True)'
    sys.argv = ['dense.py', str(N)]
    exec(src[:src.index(upTo) + len(upTo)] + '\n', globals())


if MODE == 'save':
    build()
    nc, ns = contacts(), spheres()         # counted before the timed part
    rss0 = rss_mb()
    t0 = time.perf_counter()
    O.save(FILE)
    dt = time.perf_counter() - t0
    print(json.dumps({"engine": ENGINE, "version": VERSION, "op": "save", "n": ns, "bodies": len(O.bodies),
                      "contacts": nc, "seconds": dt, "rss_before_mb": rss0, "peak_mb": peak_mb(),
                      "size_mb": os.path.getsize(FILE) / 1e6}), flush=True)
elif MODE == 'load':
    rss0 = rss_mb()
    t0 = time.perf_counter()
    O.load(FILE)
    dt = time.perf_counter() - t0
    rss1, peak1 = rss_mb(), peak_mb()
    nb = len(O.bodies)
    report("load", dt, rss_before_mb=rss0, rss_after_mb=rss1, peak_mb=peak1, size_mb=os.path.getsize(FILE) / 1e6)
    it0 = O.iter
    O.run(1, True)                         # untimed: the loaded scene runs
    print("loaded bodies=%d iter %d -> %d" % (nb, it0, O.iter), flush=True)
    if O.iter != it0 + 1:
        sys.stderr.write("the loaded scene did not run one step\n")
        sys.exit(1)
else:  # tmp
    build()
    nc, ns, nb = contacts(), spheres(), len(O.bodies)
    rss0 = rss_mb()
    t0 = time.perf_counter()
    O.saveTmp()
    dt_save = time.perf_counter() - t0
    rss_saved = rss_mb()
    t0 = time.perf_counter()
    O.loadTmp()
    dt_load = time.perf_counter() - t0
    rss1, peak1 = rss_mb(), peak_mb()
    print(json.dumps({"engine": ENGINE, "version": VERSION, "op": "saveTmp", "n": ns, "bodies": nb, "contacts": nc,
                      "seconds": dt_save, "rss_before_mb": rss0, "rss_after_mb": rss_saved, "peak_mb": peak1,
                      "size_mb": None}), flush=True)
    report("loadTmp", dt_load, rss_before_mb=rss_saved, rss_after_mb=rss1, peak_mb=peak1, size_mb=None)
    it0 = O.iter
    O.run(1, True)
    print("loaded bodies=%d iter %d -> %d" % (len(O.bodies), it0, O.iter), flush=True)
