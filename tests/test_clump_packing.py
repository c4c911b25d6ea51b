"""Clumps on the packing side: SpherePack.makeClumpCloud, the clump id of each sphere (toList, getClumps,
save/load), SpherePack.toSimulation with clumps, utils.clumpTemplate, ymport/export.textClumps.

Reference values: tests/reference/clump_packing.py is a plain Yade script; tests/reference/data/clump_packing.json
is what the reference (Yade 2023.02a) printed running it (tests/reference/regenerate.sh). For a given seed
makeClumpCloud gives the reference's clumps (same mt19937 draws, same 200 tries), compared to 1e-12.

The tests that make clumps in the scene need O.bodies.appendClumped / O.bodies.clump (the clump core); until
that is in the build they are skipped, and the same Python paths are checked against a stand-in container."""
import importlib.util
import itertools
import json
import math
import os

import numpy as np
import pytest

from yade import O, Quaternion, Vector3, export, pack, utils, ymport
from yade.pack import SpherePack

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('clump_packing_scenes', os.path.join(HERE, 'reference', 'clump_packing.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'clump_packing.json')) as _f:
    REFERENCE = json.load(_f)

HAS_CLUMPS = hasattr(O.bodies, 'appendClumped') and hasattr(O.bodies, 'clump')
needs_clump_core = pytest.mark.skipif(not HAS_CLUMPS, reason='O.bodies.appendClumped / O.bodies.clump (the clump core) not in this build yet')

DUMBBELL = [SpherePack(scenes.DUMBBELL)]


def plain(x):
    """tuples as lists, as the reference's JSON has them"""
    return json.loads(json.dumps(x))


def members(sp):
    """{clumpId: [(center, radius), ...]} of a packing"""
    out = {}
    for t in sp.toList():
        if len(t) == 3:
            out.setdefault(t[2], []).append((np.array(tuple(t[0])), t[1]))
    return out


def min_gap_between_clumps(sp, cell=None):
    """smallest |c1 - c2| - r1 - r2 over the pairs of spheres not in the same clump (nearest image if cell)"""
    items = sp.toList()
    c = np.array([tuple(t[0]) for t in items])
    r = np.array([t[1] for t in items])
    ids = np.array([t[2] if len(t) == 3 else -1 - i for i, t in enumerate(items)])
    d = c[:, None, :] - c[None, :, :]
    if cell is not None:
        d -= np.array(cell) * np.round(d / np.array(cell))
    gap = np.linalg.norm(d, axis=2) - r[:, None] - r[None, :]
    gap[ids[:, None] == ids[None, :]] = np.inf
    return gap.min()


# ------------------------------------------------------------------ makeClumpCloud

@pytest.mark.parametrize('name', [c[0] for c in scenes.CLOUDS])
def test_cloud_is_the_references(name, recwarn):
    sp, n = scenes.cloud(name)
    ref = REFERENCE['clouds'][name]
    assert n == ref['returned']
    got = scenes.items(sp)
    assert len(got) == len(ref['spheres'])
    assert [s[3:] for s in got] == [s[3:] for s in ref['spheres']]  # radii and clump ids, exactly
    assert np.abs(np.array([s[:3] for s in got]) - np.array([s[:3] for s in ref['spheres']])).max() < 1e-12
    assert plain(sp.getClumps()) == ref['clumps']
    assert list(sp.cellSize) == ref['cellSize']


def test_cloud_figures():
    """29 dumbbells (58 spheres) in the unit box with seed 1; 40 clumps of 3 kinds (85 spheres) in (-1,0,2)-(1,1,3)."""
    counts = {name: (REFERENCE['clouds'][name]['returned'], len(REFERENCE['clouds'][name]['spheres'])) for name in REFERENCE['clouds']}
    assert counts == {'dumbbell': (29, 58), 'mixed': (40, 85), 'periodic': (71, 142), 'periodicMixed': (30, 56), 'tooMany': (24, 48)}


@pytest.mark.parametrize('name', ['dumbbell', 'mixed', 'periodic', 'periodicMixed'])
def test_no_overlap_between_clumps_and_members_inside(name):
    _, lo, hi, templates, periodic, num, seed = [c for c in scenes.CLOUDS if c[0] == name][0]
    sp, n = scenes.cloud(name)
    assert len(members(sp)) == n and not sp.getClumps()[0]
    assert min_gap_between_clumps(sp, cell=tuple(sp.cellSize) if periodic else None) >= -1e-12
    c = np.array([tuple(t[0]) for t in sp])
    r = np.array([t[1] for t in sp])
    if periodic:  # members may cross the faces (not wrapped, as in the reference); centres stay near the box
        assert sp.isPeriodic and tuple(sp.cellSize) == tuple(np.subtract(hi, lo))
        assert ((c < lo) | (c > hi)).any()
    else:
        assert (c - r[:, None] >= np.array(lo) - 1e-12).all() and (c + r[:, None] <= np.array(hi) + 1e-12).all()
        assert not sp.isPeriodic


def test_members_keep_the_templates_distances():
    """Each clump is its template turned and moved: the same radii and the same distances between members."""
    sp, _ = scenes.cloud('mixed')
    templates = [[(np.array(c, float), r) for c, r in t] for t in (scenes.DUMBBELL, scenes.TRIANGLE, scenes.SINGLE)]

    def distances(ms):
        return [np.linalg.norm(a[0] - b[0]) for a, b in itertools.combinations(ms, 2)]

    kinds = set()
    for ms in members(sp).values():
        t = [t for t in templates if [r for _, r in t] == [r for _, r in ms]]
        assert len(t) == 1
        kinds.add(len(ms))
        assert distances(ms) == pytest.approx(distances(t[0]), abs=1e-14)
    assert kinds == {1, 2, 3}


def test_orientations_are_turns_not_reflections():
    """The triangle with a fourth point above it (as a template) keeps the sign of its triple product."""
    tetra = scenes.TRIANGLE + [((.35, .13, .2), .01)]
    sp = SpherePack()
    sp.makeClumpCloud((0, 0, 0), (2, 2, 2), [SpherePack(tetra)], num=20, seed=4)

    def triple(ps):
        return np.dot(np.cross(ps[1] - ps[0], ps[2] - ps[0]), ps[3] - ps[0])

    want = triple([np.array(c, float) for c, _ in tetra])
    for ms in members(sp).values():
        assert triple([c for c, _ in ms]) == pytest.approx(want, rel=1e-10)


def test_seed_reproducible():
    def cloud(seed):
        sp = SpherePack()
        sp.makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=10, seed=seed)
        return sp.toList()

    assert cloud(5) == cloud(5)
    assert cloud(5) != cloud(6)
    assert cloud(-1) != cloud(-1)  # a random seed


def test_num_and_return_value():
    sp = SpherePack()
    assert sp.makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=5, seed=1) == 5
    assert len(sp) == 10 and len(sp.getClumps()[1]) == 5
    assert sp.makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=0, seed=1) == 0 and len(sp) == 10
    with pytest.warns(RuntimeWarning, match='only 24 of the 60 clumps'):  # the reference: "Only 24 clumps were added"
        assert SpherePack().makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=60, seed=2) == 24


def test_spheres_already_there_are_avoided_and_ids_go_on():
    """(differs from the reference, which overlaps them and numbers each call's clumps from 0 again)"""
    sp = SpherePack([((.5, .5, .5), .3)])
    assert sp.makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=3, seed=1) == 3
    assert sp.makeClumpCloud((0, 0, 0), (1, 1, 1), DUMBBELL, num=3, seed=2) == 3
    assert plain(sp.getClumps()) == [[0], [[1, 2], [3, 4], [5, 6], [7, 8], [9, 10], [11, 12]]]
    assert min_gap_between_clumps(sp) >= -1e-12
    # a cloud of spheres after the clumps avoids them too (as in the reference)
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, num=10, seed=3) == 23
    assert min_gap_between_clumps(sp) >= -1e-12


def test_errors():
    sp = SpherePack()
    box = ((0, 0, 0), (1, 1, 1))
    with pytest.raises(ValueError, match='at least one template'):  # (the reference crashes)
        sp.makeClumpCloud(*box, [])
    with pytest.raises(ValueError, match='template 1 has no spheres'):  # (the reference makes clumps of nothing)
        sp.makeClumpCloud(*box, DUMBBELL + [SpherePack()])
    with pytest.raises(TypeError, match=r'clumps\[0\] must be a SpherePack.*clumpTemplate'):
        sp.makeClumpCloud(*box, [utils.clumpTemplate([1, 1], [(0, 0, 0), (1, 0, 0)])])
    with pytest.raises(TypeError, match='list of SpherePack'):
        sp.makeClumpCloud(*box, DUMBBELL[0])
    # box too small: the reference warns and places none
    with pytest.raises(ValueError, match='template 0 cannot fit in the box .its sphere 0 of diameter 0.2'):
        sp.makeClumpCloud((0, 0, 0), (.1, 1, 1), DUMBBELL)
    with pytest.raises(ValueError, match='cannot fit in the box in any orientation .its spheres 0 and 1'):
        sp.makeClumpCloud((0, 0, 0), (.22, .22, .22), DUMBBELL)
    with pytest.raises(ValueError, match='cannot fit in the periodic cell'):
        sp.makeClumpCloud((0, 0, 0), (.2, 1, 1), DUMBBELL, periodic=True)
    with pytest.raises(ValueError, match='above minCorner on every axis, clumps are 3D'):
        sp.makeClumpCloud((1, 1, 1), (0, 0, 0), DUMBBELL)
    with pytest.raises(ValueError, match='clumps are 3D .axis 2'):
        sp.makeClumpCloud((0, 0, 0), (1, 1, 0), DUMBBELL)
    assert len(sp) == 0
    # a box where the dumbbell fits only along one axis: tried, not refused (the reference's warning and 0)
    with pytest.warns(RuntimeWarning, match='only 0 of the 1'):
        assert sp.makeClumpCloud((0, 0, 0), (.3, .2, .2), DUMBBELL, num=1, seed=1) == 0


# ------------------------------------------------------------------ clump ids in a SpherePack

def test_items_with_clump_ids():
    sp = SpherePack([((0, 0, 0), 1, 3), ((1, 1, 1), 1), ((2, 2, 2), 1, 0), ((3, 3, 3), 1, -4)])
    assert sp.toList() == [(Vector3(0, 0, 0), 1, 3), (Vector3(1, 1, 1), 1), (Vector3(2, 2, 2), 1, 0), (Vector3(3, 3, 3), 1)]
    assert sp[0] == (Vector3(0, 0, 0), 1, 3) and sp[1] == (Vector3(1, 1, 1), 1)
    assert [len(t) for t in sp] == [2, 2, 2, 2]  # iteration gives (center, radius), as the reference
    assert plain(sp.getClumps()) == [[1, 3], [[2], [0]]]  # by increasing clump id
    assert sp.hasClumps() and not SpherePack([((0, 0, 0), 1)]).hasClumps()
    assert plain(SpherePack([((0, 0, 0), 1)]).getClumps()) == [[0], []]
    sp.fromList(sp.toList())
    assert sp.toList()[0] == (Vector3(0, 0, 0), 1, 3)
    with pytest.raises(ValueError, match='clumpId'):
        sp.fromList([((0, 0, 0), 1, 2, 3)])


def test_save_load_keeps_clump_ids(tmp_path):
    for name in ('mixed', 'periodic'):
        sp, _ = scenes.cloud(name)
        f = str(tmp_path / (name + '.txt'))
        sp.save(f)
        lines = open(f).read().splitlines()
        assert len(lines[-1].split()) == 5 and lines[-1].split()[4] == str(sp.toList()[-1][2])
        loaded = SpherePack()
        loaded.load(f)
        assert loaded.toList() == sp.toList() and tuple(loaded.cellSize) == tuple(sp.cellSize)
    mixed = SpherePack([((0, 0, 0), 1), ((1, 1, 1), 1, 4)])
    mixed.save(str(tmp_path / 'm.txt'))
    assert open(str(tmp_path / 'm.txt')).read() == '0 0 0 1 -1\n1 1 1 1 4\n'
    SpherePack([((0, 0, 0), 1)]).save(str(tmp_path / 'p.txt'))
    assert open(str(tmp_path / 'p.txt')).read() == '0 0 0 1\n'  # (no clumps: 4 columns; the reference writes -1 too)


def test_load_reads_the_references_clump_ids(tmp_path):
    assert scenes.loaded(str(tmp_path)) == dict(REFERENCE['loaded'], clumps=tuple(REFERENCE['loaded']['clumps']))
    # a file the reference's save wrote (SpherePack.save after makeClumpCloud, 6 digits)
    (tmp_path / 'r.txt').write_text('##PERIODIC:: 1 1 1\n0.961427 0.970987 0.517398 0.1 0\n1.0212 1.0175 0.582695 0.1 0\n'
                                    '0.632397 0.86503 0.700615 0.1 1\n0.631715 0.958635 0.735793 0.1 1\n')
    sp = SpherePack()
    sp.load(str(tmp_path / 'r.txt'))
    assert plain(sp.getClumps()) == [[], [[0, 1], [2, 3]]] and sp.toList()[1] == (Vector3(1.0212, 1.0175, 0.582695), .1, 0)
    (tmp_path / 'bad.txt').write_text('0 0 0 1 2\n1 1 1 1 2.5\n')
    with pytest.raises(ValueError, match='line 2: the clump id .5th column. must be an integer'):  # (the reference: "bad lexical cast")
        sp.load(str(tmp_path / 'bad.txt'))
    assert len(sp) == 4


# ------------------------------------------------------------------ utils.clumpTemplate

def test_clump_template_as_the_reference():
    ref = REFERENCE['templates']
    got = scenes.templates()
    assert got == ref
    t = utils.clumpTemplate(relRadii=[1, .5], relPositions=[(0, 0, 0), Vector3(1, 0, 0)])
    assert vars(t) == {'numCM': 2, 'relRadii': [1, .5], 'relPositions': [(0, 0, 0), Vector3(1, 0, 0)]}
    assert t.relPositions[1] is not None and utils.clumpTemplate((1, 2, 3), ((0, 0, 0), (1, 0, 0), (2, 0, 0))).numCM == 3
    assert 'clumpTemplate' in utils.__all__
    with pytest.raises(TypeError):
        utils.clumpTemplate([1, 1], [(0, 0, 0), (1, 0, 0)], foo=1)


@pytest.mark.parametrize('radii, positions, match', [
    ([-1, 1], [(0, 0, 0), (1, 1, 1)], r'relRadii\[0\] must be a positive finite number, got -1'),
    ([1, 0], [(0, 0, 0), (1, 1, 1)], r'relRadii\[1\]'),
    ([float('nan'), 1], [(0, 0, 0), (1, 1, 1)], r'relRadii\[0\]'),
    ([1, 'a'], [(0, 0, 0), (1, 1, 1)], r'relRadii\[1\]'),
    ([1, 1], [(0, 0, 0), (1, 'a', 1)], r'relPositions\[1\] must be 3 finite numbers'),
    ([1, 1], [(0, 0, 0), (1, 1)], r'relPositions\[1\]'),
    ([1, 1], [(0, 0, math.inf), (1, 1, 1)], r'relPositions\[0\]'),
])
def test_clump_template_refuses_bad_members(radii, positions, match):
    """(the reference keeps any values)"""
    with pytest.raises(ValueError, match=match):
        utils.clumpTemplate(radii, positions)


# ------------------------------------------------------------------ export / ymport textClumps

def test_export_without_clumps_and_bad_format(tmp_path):
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((3, 0, 0), 1)])
    f = str(tmp_path / 'c.txt')
    assert export.textClumps(f, comment='none') == (0, 0)
    assert open(f).read() == '#format x_y_z_r_clumpId\n# none\n'
    with pytest.raises(ValueError, match="unknown format 'x_y_z_r'"):  # (the reference writes its one format anyway)
        export.textClumps(f, format='x_y_z_r')


@needs_clump_core
def test_export_as_the_reference(tmp_path):
    got = scenes.exported(str(tmp_path))
    assert plain(got) == REFERENCE['exported']


@needs_clump_core
def test_ymport_as_the_reference(tmp_path):
    got = scenes.imported(str(tmp_path))
    for name in ('plain', 'moved'):
        ref = REFERENCE['imported'][name]
        assert plain(got[name]['returned']) == ref['returned']
        assert [b[:3] for b in got[name]['bodies']] == [b[:3] for b in ref['bodies']]
        for g, r in zip(got[name]['bodies'], ref['bodies']):
                assert len(g) == len(r) and g[3:] == pytest.approx(r[3:], abs=1e-12)


@needs_clump_core
def test_export_then_ymport_round_trip(tmp_path):
    sp, _ = scenes.cloud('mixed')
    sp.toSimulation()
    f = str(tmp_path / 'c.txt')
    assert export.textClumps(f) == (40, 85)
    before = sorted(tuple(b.state.pos) + (b.shape.radius,) for b in O.bodies if b.isClumpMember)
    O.reset()
    ret = ymport.textClumps(f)
    assert len(ret) == 40 and sum(len(m) for _, m in ret) == 85
    after = sorted(tuple(b.state.pos) + (b.shape.radius,) for b in O.bodies if b.isClumpMember)
    assert np.array(after) == pytest.approx(np.array(before), abs=1e-5)  # (%g: 6 digits)


@needs_clump_core
def test_to_simulation_as_the_reference():
    got = scenes.simulation()
    ref = REFERENCE['simulation']
    assert got['ids'] == ref['ids'] and [b[:3] for b in got['bodies']] == [b[:3] for b in ref['bodies']]
    for g, r in zip(got['bodies'], ref['bodies']):
        assert len(g) == len(r) and g[3:] == pytest.approx(r[3:], rel=1e-12, abs=1e-12)


@pytest.mark.skipif(HAS_CLUMPS, reason='the clump core is in the build')
def test_clumps_need_the_clump_core(tmp_path):
    sp, _ = scenes.cloud('dumbbell')
    with pytest.raises(NotImplementedError, match='O.bodies.clump'):
        sp.toSimulation()
    assert len(O.bodies) == 0  # refused before adding anything
    (tmp_path / 'c.txt').write_text('0 0 0 1 1\n')
    with pytest.raises(NotImplementedError, match='appendClumped'):
        ymport.textClumps(str(tmp_path / 'c.txt'))


# ------------------------------------------------------------------ the Python paths, with a stand-in container

class _StandInBodies:
    """O.bodies with clump() and appendClumped() recorded, not made (ids counted on from the real container)."""

    def __init__(self):
        self.clumps = []

    def __getattr__(self, name):
        return getattr(O.bodies, name)

    def __len__(self):
        return len(O.bodies) + len(self.clumps)

    def append(self, bodies):
        assert not self.clumps  # (clumps come after all spheres)
        return O.bodies.append(bodies)

    def clump(self, ids):
        self.clumps.append(list(ids))
        return len(self) - 1

    def appendClumped(self, bodies, discretization=0):
        ids = O.bodies.append(bodies)  # (the stand-in does not leave room for the clump's own id)
        self.clumps.append((ids, discretization))
        return (-len(self.clumps), ids)


class _StandInO:
    def __init__(self):
        self.bodies = _StandInBodies()

    def __getattr__(self, name):
        return getattr(O, name)

    def __setattr__(self, name, value):
        if name == 'bodies':
            object.__setattr__(self, name, value)
        else:
            setattr(O, name, value)


@pytest.fixture
def stand_in(monkeypatch):
    o = _StandInO()
    for module in (pack, ymport):
        monkeypatch.setattr(module, 'O', o)
    return o


def test_to_simulation_clumps_members_after_the_spheres(stand_in):
    sp = SpherePack([((0, 0, 0), .1), ((1, 0, 0), .1, 7), ((2, 0, 0), .1, 3), ((3, 0, 0), .1, 7), ((4, 0, 0), .2)])
    ids = sp.toSimulation(rot=Quaternion((0, 0, 1), math.pi / 2), color=(1, 0, 0))
    assert ids == [0, 1, 2, 3, 4, 5, 6]  # the spheres, then one clump per clump id (increasing)
    assert stand_in.bodies.clumps == [[2], [1, 3]]
    assert O.bodies[3].state.pos == pytest.approx(Vector3(0, 3, 0), abs=1e-15) and O.bodies[4].shape.radius == .2
    assert tuple(O.bodies[1].shape.color) == (1, 0, 0)


def test_to_simulation_periodic_cloud_sets_the_cell(stand_in):
    sp, n = scenes.cloud('periodic')
    ids = sp.toSimulation()
    assert len(ids) == len(sp) + n and O.periodic and tuple(O.cell.size) == pytest.approx((1, 1.5, 1.2))
    assert stand_in.bodies.clumps == [[2 * i, 2 * i + 1] for i in range(n)]


def test_ymport_groups_consecutive_lines(stand_in, tmp_path):
    f = tmp_path / 'c.txt'
    f.write_text('#format x_y_z_r_clumpId\n1\t0\t0\t1\t5\n0\t1\t0\t0.5\t2\n2\t0\t0\t1\t5\n# a comment\n\n3 3 3 .25 5\n4 4 4 .5 7\n5 4 4 .5 7\n')
    ret = ymport.textClumps(str(f), shift=(10, 0, 0), discretization=3, scale=2, orientation=Quaternion((0, 0, 1), math.pi / 2), color=(0, 1, 0))
    assert ret == [(-1, [0]), (-2, [1]), (-3, [2, 3]), (-4, [4, 5])]  # runs of one id (5 twice: two clumps, as the reference)
    assert [d for _, d in stand_in.bodies.clumps] == [3] * 4
    assert np.array([tuple(b.state.pos) for b in O.bodies]) == pytest.approx(np.array([(10, 2, 0), (8, 0, 0), (10, 4, 0), (4, 6, 6), (2, 8, 8), (2, 10, 8)]), abs=1e-14)
    assert [b.shape.radius for b in O.bodies] == [2, 1, 2, .5, 1, 1] and tuple(O.bodies[0].shape.color) == (0, 1, 0)
    (tmp_path / 'bad.txt').write_text('1 0 0 1 5\n1 0 0 1\n')
    with pytest.raises(ValueError, match='bad.txt:2: a clump member needs 5 columns'):  # (the reference: IndexError)
        ymport.textClumps(str(tmp_path / 'bad.txt'))
    with pytest.raises(TypeError, match='orientation must be a Quaternion'):
        ymport.textClumps(str(f), orientation=[])
    with pytest.raises(FileNotFoundError):
        ymport.textClumps(str(tmp_path / 'missing.txt'))
