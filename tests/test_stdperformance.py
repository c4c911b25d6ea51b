"""The standard performance test: `./yade --stdperformance N` (scripts/bench/stdperformance.py) builds the
scene of the reference's `yade --stdperformance` (read off a run of the reference: 10 009 spheres of
radius 0.01625, a regular hexagonal packing filling a ball of radius 0.5, 12 facets, ViscElMat with
tc = 1 ms, en = et = 0.003, gravity 9.81 along -y, dt = 1e-4), and the reference's own script runs
here unchanged (when the reference is installed)."""
import os
import re
import subprocess
import sys

import pytest

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LAUNCHER = os.path.join(REPO, "yade")
REFERENCE_SCRIPT = "/usr/lib/x86_64-linux-gnu/yade-double/py/yade/tests/checks/performance/checkPerf.py"


def run(*args, timeout=600, cwd=None):
    return subprocess.run([sys.executable, LAUNCHER] + list(args), capture_output=True, text=True, timeout=timeout, cwd=cwd)


def test_the_scene_is_the_references():
    """The counts, the material and the engines the reference's run shows (its bodies: 10 009 spheres and
    12 facets; 10 009 is also what regularHexa in a ball of radius 0.5 gives here)."""
    sys.path.insert(0, os.path.join(REPO, "scripts", "bench"))
    try:
        import stdperformance
    finally:
        sys.path.pop(0)
    from yade import O
    from yade.wrapper import Sphere, Facet
    n = stdperformance.build()
    assert n == 10021
    kinds = [type(b.shape) for b in O.bodies]
    assert kinds.count(Sphere) == 10009 and kinds.count(Facet) == 12
    mat = O.materials[0]
    assert (mat.tc, mat.en, mat.et, mat.density, mat.young, mat.poisson) == (0.001, 0.003, 0.003, 2300, 1e9, 0.25)
    assert O.dt == 1e-4
    assert [type(e).__name__ for e in O.engines] == ['ForceResetter', 'InsertionSortCollider', 'InteractionLoop', 'NewtonIntegrator']
    assert tuple(O.engines[-1].gravity) == (0, -9.81, 0) and O.engines[-1].damping == 0
    radii = {b.shape.radius for b in O.bodies if isinstance(b.shape, Sphere)}
    assert radii == {0.01625}
    lo = min(b.state.pos[1] for b in O.bodies if isinstance(b.shape, Sphere))
    O.run(300, True)
    # 300 steps of free fall (0.03 s): every sphere 0.5·g·t² = 4.4 mm lower, none in contact yet
    assert O.interactions.countReal() == 0
    assert min(b.state.pos[1] for b in O.bodies if isinstance(b.shape, Sphere)) == pytest.approx(lo - 0.5 * 9.81 * 0.03 ** 2, rel=1e-3)
    O.reset()


def test_launcher_runs_it_and_prints_the_speed():
    r = run("-n", "-x", os.path.join(REPO, "scripts", "bench", "stdperformance.py"), "2", "20")
    assert r.returncode == 0, r.stderr
    assert len(re.findall(r"^run [12]: 10021 bodies, 20 steps, [0-9.]+ iter/s", r.stdout, re.M)) == 2
    assert re.search(r"^stdperformance: 10009 spheres, 2 runs of 20 steps: [0-9.]+ iter/s \+/- [0-9.]+ %", r.stdout, re.M), r.stdout


def test_bad_count_is_refused():
    r = run("-n", "--stdperformance", "0")
    assert r.returncode == 2
    assert "at least 1" in r.stdout


@pytest.mark.skipif(not os.path.exists(REFERENCE_SCRIPT), reason="the reference Yade is not installed")
def test_the_references_own_script_runs_here_unchanged(tmp_path):
    """`./yade --stdperformance 1 checkPerf.py`: the reference's script reads opts.stdperformance, builds its
    10 021 bodies, runs its 7 000 steps and prints its summary."""
    r = run("-n", "-x", "-j1", "--stdperformance", "1", REFERENCE_SCRIPT, cwd=str(tmp_path), timeout=900)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    assert "number of bodies 10021" in r.stdout
    speed = float(re.search(r"^Performance\s+([0-9.]+)\s+iter/sec", r.stdout, re.M).group(1))
    assert speed > 0
    assert re.search(r"10021\s+spheres,.*calculation velocity", r.stdout)
