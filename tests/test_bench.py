"""The benchmark harness (scripts/bench/) and the correctness of InteractionLoop's fast path.

Timing is never tested here: only that the fast path (InteractionLoop.fastPath, on by default:
potential sphere-sphere pairs still apart are rejected from a contiguous array of positions,
before any functor is called) gives the same trajectories as the general path, and that the
harness runs and prints its table.

Each simulation runs in its own ./yade process (one thread), so that the two runs compared start
from identical, freshly built scenes; the state is written with exact float round-trips (JSON).
"""
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
BENCH = REPO / "scripts" / "bench"
RUN_BENCH = BENCH / "run_bench.py"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")

# A deposition like scripts/bench/deposition.py, smaller; argv: FAST(0/1) OUT STEPS FACTOR
# (FACTOR: interactionDetectionFactor = aabbEnlargeFactor, 1 = touching spheres only).
SCENE = r'''
import json, sys
from yade import pack, geom
from yade.utils import *

fast, out, steps, factor = sys.argv[1] == "1", sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
O.reset()
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label="mat"))
N, r = 1000, 0.01
side = (N * (4. / 3.) * 3.14159 * r ** 3 / 0.30) ** (1. / 3.)
O.bodies.append(geom.facetBox((side / 2, side / 2, side), (side / 2, side / 2, side), wallMask=31))
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (side, side, 1.5 * side), rMean=r, rRelFuzz=.2, num=N, seed=1)
sp.toSimulation()
loop = InteractionLoop(
    [Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=factor), Ig2_Facet_Sphere_ScGeom()],
    [Ip2_FrictMat_FrictMat_FrictPhys()],
    [Law2_ScGeom_FrictPhys_CundallStrack()],
)
assert loop.fastPath is True, "fastPath must be on by default"
loop.fastPath = fast
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=factor), Bo1_Facet_Aabb()]),
    loop,
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),
]
O.dt = .5 * PWaveTimeStep()
pos0 = [tuple(b.state.pos) for b in O.bodies]

def snapshot():
    real = sorted((min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions if i.isReal)
    potential = len(O.interactions) - len(real)     # iterating O.interactions gives the real ones only
    return {
        "iter": O.iter,
        "pos": [list(b.state.pos) for b in O.bodies],
        "vel": [list(b.state.vel) for b in O.bodies],
        "angVel": [list(b.state.angVel) for b in O.bodies],
        "real": real,
        "potential": potential,
    }

snaps = []
for chunk in (steps // 2, steps - steps // 2):
    O.run(chunk, True)
    snaps.append(snapshot())
moved = max(abs(a - b) for p, q in zip(pos0, snaps[-1]["pos"]) for a, b in zip(p, q))
with open(out, "w") as f:
    json.dump({"fastPath": O.engines[2].fastPath, "moved": moved, "snaps": snaps}, f)
'''


def run_scene(tmp_path, fast, steps, factor, threads=1):
    script = tmp_path / "fastpath_scene.py"
    script.write_text(SCENE)
    out = tmp_path / ("state_%d_%g.json" % (fast, factor))
    env = dict(os.environ)
    env.pop("OMP_NUM_THREADS", None)
    r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", "-j", str(threads), str(script),
                        "1" if fast else "0", str(out), str(steps), repr(factor)],
                       capture_output=True, text=True, timeout=600, env=env, cwd=str(tmp_path))
    assert r.returncode == 0 and out.exists(), "scene failed:\n%s\n%s" % (r.stdout[-3000:], r.stderr[-3000:])
    data = json.loads(out.read_text())
    assert data["fastPath"] is bool(fast)
    return data


def max_abs_diff(a, b):
    assert len(a) == len(b)
    return max((abs(x - y) for u, v in zip(a, b) for x, y in zip(u, v)), default=0.0)


# (the fast path includes the skin: pairs certainly still apart are not even tested; with two
# threads each thread has its own lists and skin)
@pytest.mark.parametrize("factor,threads", [(1.0, 1), (1.5, 1), (1.0, 2)], ids=["touching", "detectionFactor1.5", "touching-2threads"])
def test_fast_path_gives_the_same_trajectories_as_the_general_path(tmp_path, factor, threads):
    steps = 1500
    fast = run_scene(tmp_path, True, steps, factor, threads)
    general = run_scene(tmp_path, False, steps, factor, threads)
    # the scene is not trivial: spheres fell, contacts formed, and there were potential pairs
    # still apart for the fast path to reject
    assert fast["moved"] > 0.01
    last = fast["snaps"][-1]
    assert last["iter"] == steps
    assert len(last["real"]) > 20, "too few contacts for a meaningful comparison: %d" % len(last["real"])
    assert last["potential"] > 100, "too few potential pairs for the fast path to act on: %d" % last["potential"]
    for sf, sg in zip(fast["snaps"], general["snaps"]):
        assert sf["iter"] == sg["iter"]
        for field in ("pos", "vel", "angVel"):
            d = max_abs_diff(sf[field], sg[field])
            assert d <= 1e-12, "%s differs by %g after %d steps (fastPath on vs off)" % (field, d, sf["iter"])
        assert len(sf["real"]) == len(sg["real"])
        assert sf["real"] == sg["real"], "different real interactions after %d steps" % sf["iter"]
        assert sf["potential"] == sg["potential"]
    # in fact identical to the last bit (same operations in the same order)
    assert fast["snaps"] == general["snaps"]


# ----------------------------------------------------------------------------- the harness

ROW_RE = re.compile(r"^(here|ref)\s+(\d+)\s+(\d+)\s+(\d+)!?\s+([0-9.]+)\s+\[([0-9.]+) - ([0-9.]+)\]\s+"
                    r"([0-9.eE+-]+)\s+(\d+)\s+(\S+)\s+(\S+)\s*$", re.M)


def run_harness(*args, timeout=600):
    env = dict(os.environ)
    env.pop("OMP_NUM_THREADS", None)
    return subprocess.run(["/usr/bin/python3", str(RUN_BENCH)] + list(args), capture_output=True, text=True,
                          timeout=timeout, env=env, cwd=str(REPO))


def test_run_bench_smoke_prints_the_table(tmp_path):
    js = tmp_path / "bench.json"
    r = run_harness("--no-reference", "--sizes", "300", "--steps", "50", "--settle", "50", "--repeats", "1",
                    "--json", str(js))
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    out = r.stdout
    assert "== deposition benchmark" in out
    header = [l for l in out.splitlines() if l.startswith("engine ")]
    assert header and "iter/s" in header[0] and "particle-st/s" in header[0] and "KB/sphere" in header[0]
    rows = ROW_RE.findall(out)
    assert len(rows) == 1, out
    engine, threads, n, runs, ips, lo, hi, pss, contacts, rss, kbs = rows[0]
    assert (engine, threads, n, runs) == ("here", "1", "300", "1")
    assert float(ips) > 0 and float(lo) <= float(ips) <= float(hi)
    # particle-steps/s = N * iter/s (both rounded as printed)
    assert float(pss) == pytest.approx(300 * float(ips), rel=1e-3)
    assert rss == "-" and kbs == "-"          # no --memory
    assert "ref " not in out.split("== deposition benchmark")[1]
    data = json.loads(js.read_text())
    assert [r["ok"] for r in data["runs"]] == [True]
    assert data["summary"]["rows"][0]["iter_per_s"] == pytest.approx(float(ips), rel=1e-3)


def test_run_bench_reports_the_machine_ceiling_next_to_the_scaling(tmp_path):
    """With two thread counts, each repeat also times a perfectly parallel loop (build/parallel_ceiling):
    the ceiling of the scaling on this machine at that moment."""
    js = tmp_path / "bench.json"
    r = run_harness("--no-reference", "--sizes", "200", "--steps", "20", "--settle", "20", "--repeats", "2",
                    "--threads", "1,2", "--json", str(js))
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    m = re.search(r"^machine ceiling \(.*\): 2/1 threads ([0-9.]+)  runs \[([0-9. ]+)\]$", r.stdout, re.M)
    assert m, r.stdout[-2000:]
    runs = [float(x) for x in m.group(2).split()]
    assert len(runs) == 2 and all(0.2 < x < 4 for x in runs)
    ceiling = json.loads(js.read_text())["summary"]["ceiling"]
    assert [c["threads"] for c in ceiling] == [2] and ceiling[0]["runs"] == pytest.approx(runs, abs=0.006)


def test_parallel_ceiling_program():
    binary = REPO / "build" / "parallel_ceiling"
    if not binary.exists():
        pytest.skip("build/parallel_ceiling not built")
    out = subprocess.run([str(binary), "1", "50", "2"], capture_output=True, text=True, timeout=60).stdout
    m = re.match(r"ceiling threads=1 one_thread_steps_per_s=([0-9.]+) threads_steps_per_s=([0-9.]+) ratio=([0-9.]+)$", out.strip())
    assert m and float(m.group(1)) > 0 and float(m.group(2)) > 0
    assert float(m.group(3)) == pytest.approx(float(m.group(2)) / float(m.group(1)), rel=1e-2)  # (1 thread both: about 1)
    assert subprocess.run([str(binary), "0"], capture_output=True, timeout=60).returncode == 2


def test_run_bench_features_and_memory(tmp_path):
    if not os.access("/usr/bin/time", os.X_OK):
        pytest.skip("/usr/bin/time is not installed (Debian package 'time')")
    js = tmp_path / "bench.json"
    r = run_harness("--no-reference", "--sizes", "200", "--steps", "20", "--settle", "20", "--repeats", "2",
                    "--features", "--memory", "--json", str(js))
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    rows = ROW_RE.findall(r.stdout)
    assert len(rows) == 1
    rss, kbs = float(rows[0][9]), float(rows[0][10])
    assert 5 < rss < 5000 and kbs == pytest.approx(rss * 1024 / 200, rel=1e-2)
    assert "== feature costs" in r.stdout
    data = json.loads(js.read_text())
    variants = sorted({x["variant"] for x in data["runs"]})
    assert variants == ["energy", "plain", "pyrunner", "wall"]
    assert all(x["ok"] for x in data["runs"]) and len(data["runs"]) == 8
    feats = {f["feature"]: f for f in data["summary"]["features"]}
    assert set(feats) == {"energy", "pyrunner", "wall"}
    for f in feats.values():
        assert len(f["paired"]) == 2 and f["cost_percent"] is not None
        assert re.search(r"^here\s+1\s+200\s+%s\s" % f["feature"], r.stdout, re.M)


def test_variant_wrapper_turns_on_exactly_its_feature(tmp_path):
    """deposition_variant.py inserts its lines before the scene's 'O.dt =' line; check with a tiny
    scene (given through $BENCH_SCENE) that reports what is on."""
    scene = tmp_path / "tiny.py"
    scene.write_text(
        "import sys\n"
        "from yade.utils import *\n"
        "O.reset()\n"
        "O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),\n"
        "    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],\n"
        "                    [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator()]\n"
        "O.dt = 1e-5\n"
        "bc = [e for e in O.engines if isinstance(e, InsertionSortCollider)][0]\n"
        "il = [e for e in O.engines if isinstance(e, InteractionLoop)][0]\n"
        "print('REPORT args=%s energy=%s pyrunners=%d bo1=%s ig2=%s' % (','.join(sys.argv[1:]), O.trackEnergy,\n"
        "    sum(1 for e in O.engines if isinstance(e, PyRunner)),\n"
        "    '+'.join(type(f).__name__ for f in bc.boundDispatcher.functors),\n"
        "    '+'.join(type(f).__name__ for f in il.geomDispatcher.functors)))\n")
    env = dict(os.environ, BENCH_SCENE=str(scene))
    env.pop("OMP_NUM_THREADS", None)
    seen = {}
    for v in ("plain", "energy", "pyrunner", "wall"):
        r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", str(BENCH / "deposition_variant.py"), v,
                            "7", "8", "9"], capture_output=True, text=True, timeout=120, env=env, cwd=str(tmp_path))
        m = re.search(r"^REPORT (.*)$", r.stdout, re.M)
        assert r.returncode == 0 and m, r.stdout + r.stderr
        seen[v] = m.group(1)
    assert seen["plain"] == "args=7,8,9 energy=False pyrunners=0 bo1=Bo1_Sphere_Aabb ig2=Ig2_Sphere_Sphere_ScGeom"
    assert seen["energy"] == seen["plain"].replace("energy=False", "energy=True")
    assert seen["pyrunner"] == seen["plain"].replace("pyrunners=0", "pyrunners=1")
    assert seen["wall"] == ("args=7,8,9 energy=False pyrunners=0 bo1=Bo1_Sphere_Aabb+Bo1_Wall_Aabb "
                            "ig2=Ig2_Sphere_Sphere_ScGeom+Ig2_Wall_Sphere_ScGeom")


def test_bundled_scene_is_the_shared_one():
    shared = pathlib.Path("/work/shared/bench/deposition.py")
    if not shared.exists():
        pytest.skip("no shared copy of the scene on this machine")
    assert (BENCH / "deposition.py").read_bytes() == shared.read_bytes()


def test_dense_harness_runs_and_prints_its_table():
    """scripts/bench/dense_bench.py on a small lattice, this engine only: the table, the engine
    shares and exit status 0 (the reference and LAMMPS are left out to keep it short)."""
    p = subprocess.run([sys.executable, str(BENCH / "dense_bench.py"), "--sizes", "300", "--steps", "20",
                        "--repeats", "1", "--no-reference", "--no-lammps"], capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr
    row = re.search(r"^here\s+frict\s+(\d+)\s+1\s+([0-9.]+)\s+([0-9.e+]+)\s+(\d+)\s+(\d+)", p.stdout, re.M)
    assert row, p.stdout
    assert int(row.group(1)) == 300 and float(row.group(2)) > 0 and int(row.group(4)) > 2 * 294 and int(row.group(5)) > 10
    shares = dict(re.findall(r"(\w+) ([0-9.]+)%", p.stdout.split("shares of this engine's timed steps:")[1]))
    assert {"InteractionLoop", "NewtonIntegrator"} <= set(shares)
    assert sum(map(float, shares.values())) == pytest.approx(100, abs=1)


def test_dense_harness_other_laws():
    """--law viscel,mindlin: the same lattice with ViscEl and Hertz-Mindlin (the same contacts, all
    live), each law's speed over Cundall-Strack's printed; an unknown law is refused by name."""
    p = subprocess.run([sys.executable, str(BENCH / "dense_bench.py"), "--sizes", "300", "--steps", "20", "--repeats", "1",
                        "--no-reference", "--no-lammps", "--no-shares", "--law", "frict,viscel,mindlin"],
                       capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stdout + p.stderr
    contacts = {law: int(c) for law, c in re.findall(r"^here\s+(\w+)\s+300\s+1\s+[0-9.]+\s+[0-9.e+]+\s+(\d+)", p.stdout, re.M)}
    assert set(contacts) == {"frict", "viscel", "mindlin"}, p.stdout
    assert all(c > 2 * 294 for c in contacts.values())
    assert re.search(r"here viscel / here frict\s+[0-9.]+x", p.stdout) and re.search(r"here mindlin / here frict\s+[0-9.]+x", p.stdout)
    bad = subprocess.run([sys.executable, str(BENCH / "dense_bench.py"), "--law", "hooke"], capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and "unknown --law 'hooke'" in bad.stderr
