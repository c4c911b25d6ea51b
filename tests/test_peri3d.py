"""Peri3dController: the six components of the periodic cell's strain and stress, each driven to a
strain or a stress goal along a load path.

Agreement with the reference: the scenes are tests/reference/peri3d.py, a plain Yade script;
tests/reference/data/peri3d.json is what the reference (Yade 2023.02a) printed running it
(tests/reference/regenerate.sh). The law the reference follows, found by running it, is in
doc/periodic.md. The other tests check the new attribute kinds (Vector6i, a list of Vector2), a save
and load in the middle of a run, and the refusal of bad input."""
import importlib.util
import json
import math
import os

import __main__
import pytest

from yade import O, Vector2, Vector3i, Vector6, Vector6i, BoundaryController, Peri3dController
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('peri3d_scenes', os.path.join(HERE, 'reference', 'peri3d.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'peri3d.json')) as _f:
    REFERENCE = json.load(_f)


@pytest.fixture(autouse=True)
def hooks_in_main():
    """doneHook runs in the script's namespace (__main__), as the reference's does: the scenes' hooks go there."""
    names = {n: getattr(scenes, n) for n in ('O', 'HOOKS')}
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


def assert_close(here, ref, rel, abs_=1e-300, where=''):
    """every number of `here` within rel of the reference's; same keys and lengths"""
    if isinstance(ref, dict):
        assert sorted(here) == sorted(ref), where
        for k in ref:
            assert_close(here[k], ref[k], rel, abs_, where + '.' + k)
        return
    a, b = flat(here), flat(ref)
    assert len(a) == len(b), where
    for x, y in zip(a, b):
        if isinstance(y, bool) or isinstance(y, int):
            assert x == y, (where, x, y)
        else:
            assert x == pytest.approx(y, rel=rel, abs=abs_), (where, a, b)


# ---------------------------------------------------------------- the class and its attributes

def test_class_and_defaults_as_in_reference():
    assert issubclass(Peri3dController, BoundaryController)
    ours, ref = scenes.defaults(), REFERENCE['defaults']
    assert set(ref) <= set(ours)  # (and this engine's execCount, execTime of every engine)
    assert {k: v for k, v in ours.items() if k in ref} == ref


def test_internal_state_read_only_as_in_reference():
    c = Peri3dController()
    for name in ('pe', 'ps', 'pathSizes', 'pathsCounter', 'lenPe', 'lenPs', 'stressGoal', 'strainGoal'):
        with pytest.raises(AttributeError):
            setattr(c, name, getattr(c, name))
    assert isinstance(c.pe, Vector6i) and isinstance(c.goal, Vector6)


def test_vector6i_math_type():
    v = Vector6i(1, 2, 3, 4, 5, 6)
    assert repr(v) == 'Vector6i(1,2,3, 4,5,6)' and len(v) == 6 and v[5] == 6
    assert v.head() == Vector3i(1, 2, 3) and v.tail() == Vector3i(4, 5, 6)
    assert Vector6i(Vector3i(1, 2, 3), Vector3i(4, 5, 6)) == v and Vector6i([1, 2, 3, 4, 5, 6]) == v
    assert v + Vector6i.Ones == Vector6i(2, 3, 4, 5, 6, 7) and 2 * v == Vector6i(2, 4, 6, 8, 10, 12)
    with pytest.raises(TypeError):
        Vector6i(1.5, 2, 3, 4, 5, 6)


def test_paths_are_lists_of_vector2():
    c = Peri3dController(xxPath=[(2, 3), (4, 1), (5, 2)])
    assert c.xxPath == [Vector2(2, 3), Vector2(4, 1), Vector2(5, 2)] and c.yyPath == [Vector2(1, 1)]
    c.yzPath = [Vector2(1, -2)]
    assert c.yzPath == [Vector2(1, -2)]
    with pytest.raises(TypeError):
        c.xxPath = [(1, 2, 3)]
    with pytest.raises(ValueError):
        c.xxPath = [(1, float('nan'))]


# ---------------------------------------------------------------- agreement with the reference

# (rel, abs) per recorded quantity: the fixed scenes agree to rounding
TOLERANCE = dict(stress=(1e-9, 1e-9), strain=(1e-9, 1e-19), strainRate=(1e-9, 1e-25), velGrad=(1e-9, 1e-8), trsf=(1e-12, 1e-14))


@pytest.mark.parametrize('name,kw,n', scenes.FIXED_CASES, ids=[c[0] for c in scenes.FIXED_CASES])
def test_fixed_scene_step_by_step_as_reference(name, kw, n):
    here, ref = scenes.fixed_steps(kw, n), REFERENCE['fixed'][name]
    assert len(here) == len(ref)
    for h, r in zip(here, ref):
        for key in r:
            rel, abs_ = TOLERANCE.get(key, (1e-12, 1e-12))
            assert_close(h[key], r[key], rel, abs_, '%s step %d %s' % (name, r['iter'], key))


@pytest.mark.parametrize('name,kw,n,trsf', scenes.ROTATED_CASES, ids=[c[0] for c in scenes.ROTATED_CASES])
def test_rotated_cell_as_reference(name, kw, n, trsf):
    here, ref = scenes.fixed_steps(kw, n, trsf), REFERENCE['rotated'][name]
    assert len(here) == len(ref)
    for h, r in zip(here, ref):
        for key in r:
            rel, abs_ = TOLERANCE.get(key, (1e-12, 1e-12))
            assert_close(h[key], r[key], rel, abs_, '%s step %d %s' % (name, r['iter'], key))


@pytest.mark.parametrize('name,kw,upTo', [
    ('packingStrain', dict(goal=(-.2, -.2, -.25, .05, 0, 0), nSteps=400), 400),
    ('packingMixed', dict(goal=(-1e4, -1e4, -.3, 0, 0, 0), stressMask=3, nSteps=600, maxStrainRate=2), 400),
])
def test_packing_as_reference(name, kw, upTo):
    here, ref = scenes.packing(kw, upTo, 20), REFERENCE[name]
    assert len(here) == len(ref)
    for h, r in zip(here, ref):
        assert h['contacts'] == r['contacts'], r['iter']
        for key in ('progress', 'strain', 'strainRate', 'stressIdeal', 'hSize'):
            assert_close(h[key], r[key], 1e-6, 1e-9, '%s step %d %s' % (name, r['iter'], key))
        assert_close(h['stress'], r['stress'], 1e-4, 1e-2, '%s step %d stress' % (name, r['iter']))


# ---------------------------------------------------------------- behaviour

@pytest.mark.parametrize('fileName', ['peri3d.xml', 'peri3d.yade'])
def test_save_and_load_in_the_middle_of_a_run(tmp_path, fileName):
    """the predictor's memory (the last stress error) and the new kinds (pathsCounter, the paths) are saved"""
    kw = dict(goal=(1e-3, -300, -50, 0, 0, 0), stressMask=0b000110, nSteps=12, yyPath=[(1, 2), (2, 1)], zzPath=[(3, -1), (4, 1)])
    straight = scenes.fixed_steps(kw, 10)
    scenes.fixed_steps(kw, 5)
    f = str(tmp_path / fileName)
    O.save(f)
    O.load(f)
    c = O.engines[3]
    rest = []
    for k in range(5):
        O.step()
        rest.append(scenes.record(c))
    assert_close(rest, straight[5:], 1e-12, 1e-25)
    assert c.yyPath == [Vector2(1, 2), Vector2(2, 1)] and c.pathsCounter == Vector6i(0, 1, 1, 0, 0, 0)


def test_done_hook_runs_every_step_after_nsteps_and_dead_without_it():
    out = scenes.fixed_steps(dict(goal=(1e-3, 0, 0, 0, 0, 0), nSteps=3, doneHook='HOOKS.append(O.iter)'), 5)
    assert [r['hooks'] for r in out] == [0, 0, 1, 2, 3] and not out[-1]['dead']
    out = scenes.fixed_steps(dict(goal=(1e-3, 0, 0, 0, 0, 0), nSteps=3), 5)
    assert [r['dead'] for r in out] == [False, False, True, True, True]
    assert out[-1]['strain'][0] == pytest.approx(1e-3, rel=1e-12)


def test_bad_input_raises():
    c = Peri3dController(goal=(1e-3, 0, 0, 0, 0, 0))
    scenes.fixed_scene(c)
    O.periodic = False
    with pytest.raises(RuntimeError, match='aperiodic'):
        O.step()
    with pytest.raises(ValueError):
        Peri3dController(goal=(float('nan'), 0, 0, 0, 0, 0))
    with pytest.raises(ValueError):
        Peri3dController(nSteps=0)
    for bad in (dict(xxPath=[(2, 1), (1, 2)]), dict(xxPath=[(0, 1)]), dict(goal=(1, 0, 0, 0, 0, 0), xxPath=[(1, 1), (2, 0)]), dict(xxPath=[])):
        c = Peri3dController(**bad)
        scenes.fixed_scene(c)
        with pytest.raises(ValueError, match='Path'):
            O.step()
    c = Peri3dController(goal=(1e-3, 0, 0, 0, 0, 0))
    scenes.fixed_scene(c)
    c.dict()  # (no exception)
    c.youngEstimation = 0
    with pytest.raises(ValueError, match='youngEstimation'):
        O.step()
    c = Peri3dController(goal=(1e-3, 0, 0, 0, 0, 0))
    scenes.fixed_scene(c)
    O.cell.trsf = ((1, 0, 0), (0, 0, 0), (0, 0, 1))
    with pytest.raises(RuntimeError, match='invertible'):
        O.step()
    c = Peri3dController(goal=(1e308, 0, 0, 0, 0, 0), maxStrainRate=1e308, nSteps=1)
    scenes.fixed_scene(c)
    with pytest.raises(RuntimeError, match='not finite'):
        O.step()
    for kw in (dict(stressMask=-1, goal=(1, 2, 3, 4, 5, 6)), dict(maxStrainRate=0, goal=(1e-3, 0, 0, 0, 0, 0))):
        c = Peri3dController(**kw)  # (odd but harmless: every component a stress; nothing moves)
        scenes.fixed_scene(c)
        O.run(3, True)
        assert c.strainRate.maxAbsCoeff() < 1e-10
