"""The periodic cell controllers (PeriTriaxController, PeriIsoCompressor, their base BoundaryController).

Agreement with the reference: the scenes are tests/reference/peri_controllers.py, a plain Yade script;
tests/reference/data/peri_controllers.json is what the reference (Yade 2023.02a) printed running it
(tests/reference/regenerate.sh). The laws the reference follows, found by running it, are in
doc/periodic.md. The other tests check the behaviour the manual describes (goal reached, doneHook,
strain rates capped) and the refusal of bad input."""
import importlib.util
import json
import math
import os

import __main__
import pytest

from yade import O, Matrix3, Vector3, BoundaryController, GlobalEngine, PeriIsoCompressor, PeriTriaxController, NewtonIntegrator, PyRunner
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('peri_controllers_scenes', os.path.join(HERE, 'reference', 'peri_controllers.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'peri_controllers.json')) as _f:
    REFERENCE = json.load(_f)


@pytest.fixture(autouse=True)
def hooks_in_main():
    """doneHook runs in the script's namespace (__main__), as the reference's does: the scenes' hooks go there."""
    names = {n: getattr(scenes, n) for n in ('O', 'HOOKS', 'compactionFinished', 'triaxFinished')}
    saved = {n: getattr(__main__, n) for n in names if hasattr(__main__, n)}
    for n, v in names.items():
        setattr(__main__, n, v)
    yield
    for n in names:
        if n in saved:
            setattr(__main__, n, saved[n])
        else:
            delattr(__main__, n)


def flat(x):
    if isinstance(x, dict):
        return [v for k in sorted(x) for v in flat(x[k])]
    if isinstance(x, list):
        return [v for y in x for v in flat(y)]
    return [x]


def assert_close(here, ref, rel, abs_=1e-300):
    """every number of `here` within rel of the reference's (NaN or None where it has them); same keys and lengths"""
    if isinstance(ref, dict):
        assert sorted(here) == sorted(ref)
    a, b = flat(here), flat(ref)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        if y is None or (isinstance(y, float) and math.isnan(y)):
            assert x is None or (isinstance(x, float) and math.isnan(x)), (x, y)
        elif isinstance(y, bool) or isinstance(y, int):
            assert x == y
        else:
            assert x == pytest.approx(y, rel=rel, abs=abs_)


# ---------------------------------------------------------------- the classes

def test_classes_and_defaults_as_in_reference():
    assert issubclass(BoundaryController, GlobalEngine)
    assert issubclass(PeriTriaxController, BoundaryController) and issubclass(PeriIsoCompressor, BoundaryController)
    ours = scenes.defaults()
    for cls, ref in REFERENCE['defaults'].items():
        here = {k: v for k, v in ours[cls].items() if k in ref}
        assert set(ref) <= set(ours[cls]), cls
        assert here == ref, cls
    # (as the reference, PeriIsoCompressor's sigma and currUnbalanced are read-only properties outside dict())
    c = PeriIsoCompressor()
    assert tuple(c.sigma) == (0, 0, 0) and c.currUnbalanced == -1
    with pytest.raises(AttributeError):
        c.sigma = Vector3(1, 2, 3)


# ---------------------------------------------------------------- the laws, against the reference

@pytest.mark.parametrize('name,kw,n,every', scenes.TRIAX_CASES, ids=[c[0] for c in scenes.TRIAX_CASES])
def test_triax_law_as_reference(name, kw, n, every):
    """Fixed spheres, so that the controller's law is seen alone: stress, stiffness, strain rate, strain,
    work, doneHook calls and the cell at each step, as the reference's (to rounding)."""
    assert_close(scenes.triax_steps(kw, n, every), REFERENCE['triax'][name], rel=1e-9)


@pytest.mark.parametrize('case', scenes.ISO_CASES, ids=[c[0] for c in scenes.ISO_CASES])
def test_iso_law_as_reference(case):
    name, kw, n, spheres, size = case
    assert_close(scenes.iso_steps(kw, n, spheres, size), REFERENCE['iso'][name], rel=1e-9)


@pytest.mark.parametrize('dynCell', [True, False])
def test_packing_compressed_as_reference(dynCell):
    """A loose cloud of 73 spheres compressed by PeriTriaxController: the first 300 steps (contacts
    appear, the stress grows to about the goal) as the reference's; the two differ by rounding only
    (about 1e-10 relative here; it grows later, as in any dense packing)."""
    here = scenes.packing_triax(dynCell, 300, 10)
    ref = REFERENCE['packingTriax' if dynCell else 'packingTriaxStiff']
    assert [r['contacts'] for r in here] == [r['contacts'] for r in ref]
    assert_close(here, ref, rel=1e-6, abs_=1e-6)


@pytest.mark.parametrize('keepProportions', [True, False])
def test_packing_iso_compressed_as_reference(keepProportions):
    assert_close(scenes.packing_iso(keepProportions, 400, 20), REFERENCE['packingIso' if keepProportions else 'packingIsoAxes'], rel=1e-6, abs_=1e-6)


def test_tutorial_periodic_triaxial_test():
    """The manual's periodic triaxial test (2.6.6) on a 215-sphere cloud: both phases end with their
    doneHook, at the goal, close to the reference (the runs differ by rounding, which a packing
    amplifies over thousands of steps: the phases end some hundred steps apart, at the same state)."""
    here, ref = scenes.tutorial(), REFERENCE['tutorial']
    assert here['bodies'] == ref['bodies'] == 215
    for phase in ('compacted', 'finished'):
        assert phase in here, phase
        assert here[phase]['iter'] == pytest.approx(ref[phase]['iter'], rel=0.25)
    c, f = here['compacted'], here['finished']
    assert all(abs(s + 1e5) <= 1e-3 * 1e5 for s in c['stress'])  # relStressTol=1e-3 (and absStressTol)
    assert f['strain'][2] == pytest.approx(-0.1, abs=1e-6) and all(abs(s + 1e5) <= 1e3 for s in f['stress'][:2])
    assert c['strain'] == pytest.approx(ref['compacted']['strain'], rel=0.02)
    assert f['strain'][:2] == pytest.approx(ref['finished']['strain'][:2], rel=0.15)
    assert f['stress'][2] == pytest.approx(ref['finished']['stress'][2], rel=0.05)
    assert f['externalWork'] == pytest.approx(ref['finished']['externalWork'], rel=0.05)


# ---------------------------------------------------------------- behaviour the manual describes

def loose_cloud(**kw):
    scenes.cloud(**kw)


def test_goal_stress_reached_and_done_hook_called():
    loose_cloud()
    del scenes.HOOKS[:]
    c = PeriTriaxController(goal=(-1e4, -1e4, -1e4), stressMask=7, dynCell=True, maxStrainRate=(10, 10, 10), maxUnbalanced=.1, relStressTol=1e-3,
                            doneHook='HOOKS.append((O.iter, tuple(O.engines[3].stress), O.engines[3].currUnbalanced)); O.pause()')
    O.engines = scenes.laws() + [c, NewtonIntegrator(damping=.2)]
    O.dt = .5 * scenes.PWaveTimeStep()
    O.run(20000, True)
    assert len(scenes.HOOKS) == 1
    it, stress, unb = scenes.HOOKS[0]
    assert it < 20000
    for s in stress:
        assert abs(s + 1e4) <= c.absStressTol and abs(s + 1e4) <= c.relStressTol * 1e4
    assert unb < c.maxUnbalanced


def test_stress_is_love_weber_sum():
    """stressTensor = -1/V Σ f ⊗ l over the contacts, l from body 1 to body 2's image (pos2 + hSize·cellDist - pos1),
    computed here in Python right after the controller (before the integrator moves the bodies)."""
    loose_cloud()
    seen = []

    def check():
        c = O.engines[3]
        sigma = [[0.0] * 3 for _ in range(3)]
        H = O.cell.hSize
        for i in O.interactions:
            if not i.isReal:
                continue
            f = i.phys.normalForce + i.phys.shearForce
            d = i.cellDist
            l = O.bodies[i.id2].state.pos + H * Vector3(d[0], d[1], d[2]) - O.bodies[i.id1].state.pos
            for a in range(3):
                for b in range(3):
                    sigma[a][b] -= f[a] * l[b] / O.cell.volume
        seen.append((O.iter, [[c.stressTensor[a, b] for b in range(3)] for a in range(3)], sigma))

    __main__.loveCheck = check
    try:
        c = PeriTriaxController(goal=(-1e4, -1e4, -1e4), stressMask=7, maxStrainRate=(10, 10, 10), globUpdate=1)
        O.engines = scenes.laws() + [c, PyRunner(command='loveCheck()', iterPeriod=1), NewtonIntegrator(damping=.2)]
        O.dt = .5 * scenes.PWaveTimeStep()
        O.run(150, True)
    finally:
        del __main__.loveCheck
    assert len(seen) >= 149 and max(abs(x) for s in seen for row in s[2] for x in row) > 1e3
    for it, here, expected in seen:
        for a in range(3):
            assert here[a] == pytest.approx(expected[a], rel=1e-9, abs=1e-6), it


def test_love_weber_stress_over_cell_images():
    """Two spheres in contact across the cell's boundary only: the branch vector goes to body 2's image."""
    O.periodic = True
    O.cell.hSize = Matrix3(1, 0, 0, 0, 1, 0, 0, 0, 1)
    O.bodies.append([sphere((0.05, 0.5, 0.5), 0.1), sphere((0.9, 0.5, 0.5), 0.1)])
    c = PeriTriaxController(goal=(0, 0, 0), stressMask=0, globUpdate=1)
    O.engines = scenes.laws(verletDist=0) + [c]
    O.dt = 1e-6
    O.step()
    i = O.interactions[0, 1]
    assert i.isReal and tuple(i.cellDist) in ((-1, 0, 0), (1, 0, 0))
    # overlap 0.05, kn = E r = 1e6, branch length 0.15, V = 1: σxx = -(5e4)(0.15) = -7500 (compression negative)
    assert c.stressTensor[0, 0] == pytest.approx(-7500, rel=1e-9)
    assert c.stress[0] == pytest.approx(-7500, rel=1e-9)
    assert c.stiff[0] == pytest.approx(1e6, rel=1e-9)  # |n_x| kn + (1 - |n_x|) ks, n along x


def test_strain_axis_follows_max_strain_rate():
    """Stress on x and y, strain on z: far from its goal the z axis shortens at maxStrainRate, and the strain
    is log(trsf[2,2])."""
    loose_cloud()
    c = PeriTriaxController(goal=(-1e3, -1e3, -0.02), stressMask=3, maxStrainRate=(1, 1, 0.5))
    O.engines = scenes.laws() + [c, NewtonIntegrator(damping=.2)]
    O.dt = .5 * scenes.PWaveTimeStep()
    for k in range(5):
        O.step()
        assert O.cell.velGrad[2, 2] == -0.5 == c.strainRate[2]
        assert c.strain[2] == pytest.approx(math.log(O.cell.trsf[2, 2]) - 0.5 * O.dt, rel=1e-6)  # (predicted between updates)
        assert abs(O.cell.velGrad[0, 0]) <= 1 and abs(O.cell.velGrad[1, 1]) <= 1
    steps = int(0.019 / (0.5 * O.dt))
    O.run(steps, True)
    assert c.strain[2] == pytest.approx(-0.02, abs=1e-3)
    O.run(400, True)
    assert c.strain[2] == pytest.approx(-0.02, abs=1e-6)


def test_work_and_energy():
    """externalWork and O.energy['velGradWork'] (its opposite) follow the stress times the strain rate."""
    loose_cloud()
    O.trackEnergy = True
    c = PeriTriaxController(goal=(-1e4, -1e4, -1e4), stressMask=7, maxStrainRate=(10, 10, 10))
    O.engines = scenes.laws() + [c, NewtonIntegrator(damping=.2)]
    O.dt = .5 * scenes.PWaveTimeStep()
    O.run(300, True)
    assert c.externalWork > 0  # the packing is compressed
    assert O.energy['velGradWork'] == pytest.approx(-c.externalWork, rel=1e-12)


def test_iso_compressor_goes_through_its_stresses():
    loose_cloud()
    del scenes.HOOKS[:]
    c = PeriIsoCompressor(stresses=[-2e3, -5e3], globalUpdateInt=5, maxUnbalanced=1e-2, doneHook='HOOKS.append(O.iter)')
    O.engines = scenes.laws() + [c, NewtonIntegrator(damping=.4)]
    O.dt = .5 * scenes.PWaveTimeStep()
    states = []
    for k in range(40):
        O.run(200, True)
        states.append(c.state)
        if c.state == 2:
            break
    assert c.state == 2 and states == sorted(states)
    assert len(scenes.HOOKS) == 1
    assert sum(c.sigma) / 3 == pytest.approx(-5e3, rel=5e-3)
    assert 2 * O.bodies[0].shape.radius < c.charLen < 4 * O.bodies[0].shape.radius  # (the first body's bound, Verlet distance included)
    # done: the controller does nothing more
    vg = Matrix3(O.cell.velGrad)
    O.run(10, True)
    assert O.cell.velGrad == vg and len(scenes.HOOKS) == 1


# ---------------------------------------------------------------- bad input

def test_bad_input_raises():
    O.bodies.append(sphere((0.5, 0.5, 0.5), 0.1))
    c = PeriTriaxController(goal=(-100, -0.001, -30), stressMask=5)
    O.engines = scenes.laws(verletDist=0) + [c, NewtonIntegrator()]
    with pytest.raises(RuntimeError, match='aperiodic'):
        O.step()
    O.periodic = True
    O.cell.hSize = Matrix3(0.41, 0, 0, 0, 3, 0, 0, 0, 4)
    with pytest.raises(RuntimeError, match='2.1'):
        O.step()
    O.cell.hSize = Matrix3(0.43, 0, 0, 0, 3, 0, 0, 0, 4)
    O.step()
    nan, inf = float('nan'), float('inf')
    with pytest.raises(ValueError, match='goal'):
        c.goal = (nan, 0, 0)
    with pytest.raises(ValueError, match='goal'):
        PeriTriaxController(goal=(inf, 0, 0))
    with pytest.raises(ValueError, match='maxStrainRate'):
        c.maxStrainRate = (-1, 1, 1)
    with pytest.raises(ValueError, match='globUpdate'):
        c.globUpdate = 0
    c.dynCell, c.mass = True, -1
    with pytest.raises(ValueError, match='mass'):
        O.step()
    c.mass = nan  # (the bodies' total mass)
    O.step()
    assert c.mass == pytest.approx(O.bodies[0].state.mass)
    iso = PeriIsoCompressor(stresses=[1e3])
    O.engines = scenes.laws(verletDist=0) + [iso, NewtonIntegrator()]
    with pytest.raises(ValueError, match='negative'):
        O.step()
    iso.stresses = [nan]
    with pytest.raises(ValueError, match='negative'):
        O.step()
    with pytest.raises(ValueError, match='globalUpdateInt'):
        iso.globalUpdateInt = 0
    iso.stresses = [-1e3]
    O.step()
    O.periodic = False
    with pytest.raises(RuntimeError, match='non-periodic'):
        O.step()
    # nothing was broken: the scene still runs
    O.engines = O.engines[:3] + [NewtonIntegrator()]
    O.step()
