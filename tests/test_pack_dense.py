"""Dense random packings: pack.randomPeriPack and pack.randomDensePack (yade/_densePack.py) and the SpherePack
methods they use (cellRepeat, cellFill, fromSimulation).

The scenes are tests/reference/pack_dense.py, a plain Yade script; tests/reference/data/pack_dense.json is what the
reference (Yade 2023.02a) printed running it. Packings are random and the generators differ, so what is compared
is their statistics: sphere counts, radii, solid fraction (doc/pack-dense.md)."""
import importlib.util
import json
import math
import os
import subprocess
import sys

import numpy
import pytest

from yade import O, SpherePack, Vector3, ForceResetter, PyRunner
from yade import pack, utils

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('pack_dense_scenes', os.path.join(HERE, 'reference', 'pack_dense.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'pack_dense.json')) as _f:
    REFERENCE = json.load(_f)


@pytest.fixture(scope='module')
def here():
    """the reference script's scenes run here (once for the module)"""
    O.reset()
    out = scenes.scenes()
    O.reset()
    return out


def max_overlap(sp):
    """largest overlap of two spheres of sp, relative to the smaller radius (through the periodic images if periodic)"""
    c = numpy.array([tuple(x) for x, r in sp])
    r = numpy.array([r for x, r in sp])
    d = c[:, None, :] - c[None, :, :]
    if sp.isPeriodic:
        L = numpy.array(tuple(sp.cellSize))
        d -= L * numpy.round(d / L)
    dist = numpy.sqrt((d ** 2).sum(-1))
    over = (r[:, None] + r[None, :] - dist) / numpy.minimum(r[:, None], r[None, :])
    numpy.fill_diagonal(over, -1)
    return over.max()


@pytest.mark.parametrize('key', ['peri1', 'peri2', 'periFuzz'])
def test_randomPeriPack_as_the_references(here, key):
    """same count (the same makeCloud draws), radii, and solid fraction within 0.03 of the reference's"""
    h, r = here[key], REFERENCE[key]
    assert h['n'] == r['n'] and h['periodic'] and r['periodic']
    for k in ('rMean', 'rStd', 'rMin', 'rMax'):
        assert h[k] == pytest.approx(r[k], rel=1e-9, abs=1e-12)
    assert h['fill'] == pytest.approx(r['fill'], abs=.03)
    assert h['cell'][0] == pytest.approx(r['cell'][0], rel=.02)


@pytest.mark.parametrize('key', ['denseBoxPeri', 'denseSpherePeri'])
def test_randomDensePack_periodic_as_the_references(here, key):
    """spheresInCell: number of spheres within 5 % of the reference's, mean radius and spread within 3 %"""
    h, r = here[key], REFERENCE[key]
    assert not h['periodic']
    assert h['n'] == pytest.approx(r['n'], rel=.05)
    assert h['fill'] == pytest.approx(r['fill'], rel=.05)
    assert h['rMean'] == pytest.approx(r['rMean'], rel=.03)
    assert h['rStd'] == pytest.approx(r['rStd'], rel=.05, abs=1e-12)


def test_the_users_scene_is_left_as_it_was(here):
    """the compression runs in the secondary scene: the user's bodies, engines, dt and periodicity are kept"""
    assert here['userScene'] == REFERENCE['userScene'] == [1, 1, 1.234e-3, False]


def test_periodic_packing_has_no_overlaps_and_radii_in_range():
    sp = pack.randomPeriPack(radius=.1, initSize=(1, 1, 1), rRelFuzz=.2, seed=5, noPrint=True)
    assert sp.isPeriodic and len(sp) > 50
    assert max_overlap(sp) < 1e-3
    rs = [r for c, r in sp]
    assert min(rs) >= .08 - 1e-12 and max(rs) <= .12 + 1e-12
    assert all(0 <= c[a] < sp.cellSize[a] for c, r in sp for a in range(3))  # (wrapped into the cell)


def test_randomDensePack_respects_the_predicate_and_returns_bodies():
    pred = pack.inCylinder((0, 0, 0), (0, 0, .6), .3)
    bodies = pack.randomDensePack(pred, radius=.04, spheresInCell=200, seed=2, returnSpherePack=False, color=(1, 0, 0))
    assert len(bodies) > 100
    for b in bodies:
        assert pred(b.state.pos, b.shape.radius) and tuple(b.shape.color) == (1, 0, 0)
    assert len(O.bodies) == 0  # (returned, not added)
    sp = SpherePack([(b.state.pos, b.shape.radius) for b in bodies])
    assert max_overlap(sp) < 1e-3


def test_randomDensePack_without_spheresInCell_fills_the_box():
    """one compressed cell the size of the predicate: the spheres inside the box fill it as the periodic packing (solid
    fraction about 0.56) less the layer along the faces where the spheres crossing them were cut off"""
    sp = pack.randomDensePack(pack.inAlignedBox((0, 0, 0), (.6, .6, .6)), radius=.05, returnSpherePack=True, seed=1)
    assert not sp.isPeriodic
    lo, hi = sp.aabb()
    assert all(l >= -1e-9 and h <= .6 + 1e-9 for l, h in zip(lo, hi))
    fill = sum(4 / 3. * math.pi * r ** 3 for c, r in sp) / .6 ** 3
    assert .3 < fill < .4  # (0.56·(1 - 2r/0.6)³ = 0.33)


def test_cellRepeat_and_cellFill():
    sp = SpherePack([((.1, .2, .3), .05), ((.5, .5, .5), .1)])
    with pytest.raises(RuntimeError, match='non-periodic'):
        sp.cellFill((1, 1, 1))
    with pytest.raises(RuntimeError, match='non-periodic'):
        sp.cellRepeat((2, 1, 1))
    sp.cellSize = (1, 1, 1)
    sp.cellRepeat((2, 3, 1))
    assert len(sp) == 12 and tuple(sp.cellSize) == (2, 3, 1)
    assert sorted(tuple(c) for c, r in sp if r == .05)[-1] == pytest.approx((1.1, 2.2, .3))
    sp.cellFill((4.5, 3, 1))  # 3 more along x (2·3 >= 4.5)
    assert len(sp) == 36 and tuple(sp.cellSize) == (6, 3, 1)
    with pytest.raises(ValueError):
        sp.cellRepeat((0, 1, 1))


def test_fromSimulation_wraps_into_the_cell():
    O.periodic = True
    O.cell.setBox(1, 1, 1)
    O.bodies.append([utils.sphere((1.25, .5, -.25), .1), utils.sphere((.5, .5, .5), .2)])
    sp = SpherePack()
    sp.fromSimulation()
    assert tuple(sp.cellSize) == (1, 1, 1) and len(sp) == 2
    assert tuple(sp[0][0]) == pytest.approx((.25, .5, .75)) and sp[1][1] == .2


def test_memoizeDb_stores_then_finds(tmp_path, capsys):
    db = str(tmp_path / 'packs.sqlite')
    pred = pack.inAlignedBox((0, 0, 0), (.5, .5, .5))
    a = pack.randomDensePack(pred, radius=.05, spheresInCell=100, memoizeDb=db, returnSpherePack=True, seed=3)
    assert 'Packing saved to the database' in capsys.readouterr().out
    b = pack.randomDensePack(pred, radius=.1, spheresInCell=100, memoizeDb=db, returnSpherePack=True)  # (scaled by 2)
    out = capsys.readouterr().out
    assert 'Found suitable packing in %s (radius=0.1±0,N=100' % db in out and 'scale=2' in out
    assert 'running PERIODIC compression' not in out
    assert all(r == pytest.approx(.1) for c, r in b)
    assert len(a) > 0 and len(b) > 0


@pytest.mark.parametrize('kw, error', [(dict(radius=-.1), ValueError), (dict(radius='a'), TypeError), (dict(radius=.1, rRelFuzz=1.5), ValueError),
                                       (dict(radius=.1, spheresInCell=-3), ValueError)])
def test_bad_input_is_an_error(kw, error):
    with pytest.raises(error):
        pack.randomDensePack(pack.inSphere((0, 0, 0), 1), **kw)


def test_bad_predicate_and_initSize():
    with pytest.raises(TypeError, match='predicate'):
        pack.randomDensePack((0, 0, 0), radius=.1)
    with pytest.raises(ValueError, match='initSize'):
        pack.randomPeriPack(.1, (1, -1, 1))


def test_called_while_running_is_the_references_error():
    """from a PyRunner (the simulation runs): the reference's words, and the scene unchanged"""
    O.engines = [ForceResetter(), PyRunner(iterPeriod=1, command='from yade import pack; pack.randomDensePack(pack.inSphere((0,0,0),1), spheresInCell=100, radius=.1)')]
    O.dt = 1e-3
    with pytest.raises(RuntimeError, match=r'Please stop the simulation first, e.g. O.pause\(\).'):
        O.run(3, True)
    assert len(O.engines) == 2


REFERENCE_CORE = '/usr/lib/x86_64-linux-gnu/yade-double/py/yade/tests/core.py'


@pytest.mark.skipif(not os.path.exists(REFERENCE_CORE), reason='the reference Yade is not installed')
def test_the_references_own_randomDensePack_case():
    """the reference's regression case testPythonToCppToPythonThrow (yade.tests.core), run here as it is"""
    script = ('import importlib.util, unittest\n'
              'spec = importlib.util.spec_from_file_location("core", %r)\n'
              'm = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n'
              'cases = [t for s in unittest.defaultTestLoader.loadTestsFromModule(m) for t in s if t.id().endswith(".testPythonToCppToPythonThrow")]\n'
              'r = unittest.TextTestRunner(verbosity=2).run(unittest.TestSuite(cases))\n'
              'print("RESULT", r.testsRun, len(r.failures), len(r.errors))\n') % REFERENCE_CORE
    out = subprocess.run([sys.executable, '-c', script], env=dict(os.environ), capture_output=True, text=True, timeout=120)
    assert 'RESULT 1 0 0' in out.stdout, out.stdout + out.stderr
