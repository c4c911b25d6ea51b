"""yade.pack.SpherePack: makeCloud (rMean, porosity and psd modes, periodic), container protocol,
aabb/psd, save/load, toSimulation and argument errors.

Reference values marked "reference" were produced by the reference Yade (2023.02a) with the same
arguments: for a given seed makeCloud gives the same spheres (same mt19937 draws, same quantiles)."""
import math
import time

import numpy as np
import pytest

import yade
from yade import O, FrictMat, Matrix3, Vector3, pack, utils
from yade.pack import SpherePack


@pytest.fixture(autouse=True)
def fresh_scene():
    O.reset()
    yield


def arrays(sp):
    """(centers N×3, radii N) of a packing."""
    c = np.array([tuple(s[0]) for s in sp], dtype=float).reshape(-1, 3)
    r = np.array([s[1] for s in sp], dtype=float)
    return c, r


def min_gap(c, r, cell=None):
    """Smallest distance - r_i - r_j over all pairs (negative: overlap), through the nearest periodic
    image when cell is given; blocks of rows keep the memory small."""
    worst = np.inf
    for i0 in range(0, len(r), 256):
        d = c[i0:i0 + 256, None, :] - c[None, :, :]
        if cell is not None:
            d -= cell * np.round(d / cell)
        gap = np.sqrt((d ** 2).sum(-1)) - r[i0:i0 + 256, None] - r[None, :]
        rows = np.arange(i0, min(i0 + 256, len(r)))
        gap[rows - i0, rows] = np.inf
        worst = min(worst, gap.min())
    return worst


def min_gap_sweep(c, r):
    """min_gap for many spheres (not periodic): pairs i, i+k of the x-sorted list while their x distance
    can still be below 2·rmax."""
    order = np.argsort(c[:, 0])
    c, r = c[order], r[order]
    worst = np.inf
    for k in range(1, len(r)):
        if (c[k:, 0] - c[:-k, 0]).min() > 2 * r.max():
            break
        worst = min(worst, (np.linalg.norm(c[k:] - c[:-k], axis=1) - r[k:] - r[:-k]).min())
    return worst


def assert_inside(c, r, lo, hi):
    assert (c - r[:, None] >= np.array(lo) - 1e-12).all()
    assert (c + r[:, None] <= np.array(hi) + 1e-12).all()


def porosity(r, volume):
    return 1 - (4 / 3 * math.pi * r ** 3).sum() / volume


# ------------------------------------------------------------------ rMean (and num)

def test_rmean_num_places_num_spheres_without_overlap_inside_the_box():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 2, 1.5), rMean=.05, rRelFuzz=.3, num=500, seed=1) == 500
    c, r = arrays(sp)
    assert len(sp) == 500
    assert min_gap(c, r) >= 0
    assert_inside(c, r, (0, 0, 0), (1, 2, 1.5))


def test_rmean_num_radii_are_deterministic_quantiles_of_the_uniform_distribution():
    rMean, fuzz, num = .01, .4, 2000
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=rMean, rRelFuzz=fuzz, num=num, seed=2)
    _, r = arrays(sp)
    assert r.min() >= rMean * (1 - fuzz) and r.max() <= rMean * (1 + fuzz)
    expected = rMean * (1 - fuzz + 2 * fuzz * (1 - (np.arange(num) + .5) / (num + 1)))  # largest first
    assert np.allclose(r, expected, rtol=0, atol=1e-15)
    assert r.mean() == pytest.approx(rMean, rel=5e-3)


def test_rmean_without_num_fills_until_a_sphere_does_not_fit():
    rMean, fuzz = .04, .5
    sp = SpherePack()
    n = sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=rMean, rRelFuzz=fuzz, seed=3)
    c, r = arrays(sp)
    assert n == len(sp) > 500
    assert r.min() >= rMean * (1 - fuzz) and r.max() <= rMean * (1 + fuzz)
    assert r.std() > 0.2 * rMean * fuzz  # random radii, not one size
    assert min_gap(c, r) >= 0
    assert_inside(c, r, (0, 0, 0), (1, 1, 1))
    assert porosity(r, 1) < 0.9  # filled up, not stopped early


def test_mean_radius_of_a_large_random_cloud_is_close_to_rmean():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.02, rRelFuzz=.5, seed=4)
    _, r = arrays(sp)
    assert len(r) > 4000
    assert r.mean() == pytest.approx(.02, rel=.03)  # small spheres fill the last gaps: slightly below


def test_too_many_spheres_gives_fewer_and_warns():
    sp = SpherePack()
    with pytest.warns(RuntimeWarning, match='only 58 of the 1000'):
        n = sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, num=1000, seed=11)
    assert n == len(sp) == 58  # reference: 58 (1000 tries per sphere, then gives up)


def test_num_zero_with_rmean_creates_nothing():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, num=0) == 0
    assert len(sp) == 0


# ------------------------------------------------------------------ seeds

def test_same_seed_same_packing_different_seed_different_packing():
    def cloud(seed, **kw):
        sp = SpherePack()
        sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, rRelFuzz=.3, seed=seed, **kw)
        return sp.toList()

    for kw in ({}, {'num': 100}, {'periodic': True}):
        assert cloud(7, **kw) == cloud(7, **kw)
        assert cloud(7, **kw) != cloud(8, **kw)
    assert cloud(-1) != cloud(-1)  # random seed


# ------------------------------------------------------------------ porosity mode (rMean < 0)

def test_porosity_mode_gives_num_spheres_at_the_requested_porosity():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), rRelFuzz=.2, num=1000, porosity=.8, seed=5) == 1000
    c, r = arrays(sp)
    assert min_gap(c, r) >= 0
    assert_inside(c, r, (0, 0, 0), (1, 1, 1))
    assert porosity(r, 1) == pytest.approx(.8, abs=.01)
    rm = (1 * (1 - .8) / (4 / 3 * math.pi * (1 + .2 ** 2) * 1000)) ** (1 / 3)  # manual's formula
    assert r.max() <= rm * 1.2 and r.min() >= rm * .8


def test_porosity_mode_raises_the_porosity_until_num_spheres_fit():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), num=1000, porosity=.3, seed=1) == 1000
    c, r = arrays(sp)
    assert min_gap(c, r) >= 0
    p = porosity(r, 1)
    assert p > .3
    # the porosities tried are 1-(1-0.3)·0.9^k (reference); the reference ends at k=9: r=0.038768426539817685
    k = math.log((1 - p) / .7) / math.log(.9)
    assert k == pytest.approx(round(k), abs=1e-6)
    assert r[0] == pytest.approx(0.038768426539817685, rel=1e-12)


def test_porosity_mode_reference_spheres():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), num=200, rRelFuzz=.3, seed=5) == 200
    assert tuple(sp[0][0]) == pytest.approx((0.13909383556015, 0.7688240017285058, 0.38944245361844776), abs=1e-12)
    assert sp[0][1] == pytest.approx(0.09432325159533948, rel=1e-12)
    assert sp[-1][1] == pytest.approx(0.05117307442873591, rel=1e-12)


# ------------------------------------------------------------------ psd

SIZES, CUMM = [.02, .04, .08], [0, .3, 1]


def test_psd_sizes_are_diameters_following_the_cumulative_distribution():
    sp = SpherePack()
    n = sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=SIZES, psdCumm=CUMM, seed=7)
    c, r = arrays(sp)
    assert n == len(sp) > 1000
    assert min_gap_sweep(c, r) >= 0
    assert_inside(c, r, (0, 0, 0), (1, 1, 1))
    d = 2 * r
    assert d.min() >= .02 and d.max() <= .08
    q = np.array([.1, .3, .5, .7, .9])
    # random sizes, then the largest stop fitting first: compare loosely
    assert np.quantile(d, q) == pytest.approx(np.interp(q, CUMM, SIZES), rel=.1)
    assert (d < .04).mean() == pytest.approx(.3, abs=.05)


def test_psd_distribute_mass_follows_the_mass_distribution():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=SIZES, psdCumm=CUMM, distributeMass=True, seed=8)
    _, r = arrays(sp)
    d, m = 2 * r, r ** 3
    assert d.min() >= .02 and d.max() <= .08
    assert m[d < .04].sum() / m.sum() == pytest.approx(.3, abs=.05)
    assert (d < .04).mean() > .6  # many more small spheres by number
    edges, cumm = sp.psd(bins=30, mass=True)
    assert np.interp(.04, edges, cumm) == pytest.approx(.3, abs=.06)


def test_psd_with_num_gives_the_deterministic_quantiles():
    num, cumm = 300, [0, .5, 1]
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=SIZES, psdCumm=cumm, num=num, seed=9) == num
    c, r = arrays(sp)
    assert min_gap(c, r) >= 0
    assert sp.appliedPsdScaling == 1
    expected = np.interp(1 - (np.arange(num) + .5) / (num + 1), cumm, SIZES) / 2
    assert np.allclose(r, expected, rtol=0, atol=1e-15)
    assert sp[0][1] == pytest.approx(0.03993355481727575, rel=1e-12)  # reference


def test_psd_with_num_and_distribute_mass_reference_radii():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=SIZES, psdCumm=[0, .5, 1], num=10, distributeMass=True, seed=1)
    _, r = arrays(sp)
    reference = [0.02680238, 0.0191986, 0.01695131, 0.01534443, 0.01412209, 0.01315192, 0.01235765, 0.01169184,
                 0.01112321, 0.01063022]  # number density ∝ d⁻³ inside each mass segment
    assert r == pytest.approx(reference, abs=1e-8)


def test_psd_with_num_is_scaled_down_when_too_large():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=[.2, .4, .8], psdCumm=[0, .5, 1], num=20, seed=1) == 20
    assert sp.appliedPsdScaling == pytest.approx(0.3536369106274249, rel=1e-12)  # reference
    c, r = arrays(sp)
    assert min_gap(c, r) >= 0
    assert r.max() == pytest.approx(0.1380867936735659, rel=1e-12)  # reference


def test_psd_function_returns_diameters_and_cumulative_fractions():
    sp = SpherePack([((0, 0, 0), r) for r in (.5, 1, 1.5, 2)])
    edges, cumm = sp.psd(bins=3, mass=False)
    assert edges == pytest.approx([1, 2, 3, 4])
    assert cumm == pytest.approx([0, .25, .5, 1])
    edges, cumm = sp.psd(bins=4)  # mass (volume) fractions: 1:8:27:64
    assert edges == pytest.approx([1, 1.75, 2.5, 3.25, 4])
    assert cumm == pytest.approx([0, .01, .09, .36, 1])
    assert len(sp.psd()[0]) == len(sp.psd()[1]) == 51
    assert SpherePack().psd() == ([], [])
    assert SpherePack([((0, 0, 0), 3)]).psd(bins=2) == ([5.5, 6, 6.5], [0, 0, 1])  # reference


# ------------------------------------------------------------------ 2D, appending

def test_flat_box_gives_a_2d_packing():
    sp = SpherePack()
    assert sp.makeCloud((0, 0, 0), (2, 1, 0), rMean=.05, seed=10) == 121  # reference: 121
    c, r = arrays(sp)
    assert (c[:, 2] == 0).all()
    assert min_gap(c, r) >= 0


def test_makecloud_appends_and_avoids_existing_spheres():
    sp = SpherePack()
    sp.add((.5, .5, .5), .3)
    n = sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, num=50, seed=1)
    assert n == len(sp) == 51  # the count includes the previous spheres, as in the reference
    c, r = arrays(sp)
    assert min_gap(c, r) >= 0
    assert sp[0] == (Vector3(.5, .5, .5), .3)


# ------------------------------------------------------------------ timing

@pytest.mark.parametrize('kw', [dict(rMean=.01, num=10000), dict(num=10000)], ids=['rMean', 'porosity'])
def test_ten_thousand_spheres_in_well_under_a_second(kw):
    sp = SpherePack()
    t0 = time.perf_counter()
    n = sp.makeCloud((0, 0, 0), (1, 1, 1), seed=1, **kw)
    elapsed = time.perf_counter() - t0
    print('makeCloud(%s): %d spheres in %.3f s' % (kw, n, elapsed))
    assert n == 10000
    assert elapsed < 2
    c, r = arrays(sp)
    assert min_gap_sweep(c, r) >= 0


# ------------------------------------------------------------------ periodic

def test_periodic_cloud_has_no_overlap_across_the_boundary():
    lo, hi = np.array([1., 0, 0]), np.array([2., 1, 1.5])
    sp = SpherePack()
    n = sp.makeCloud(tuple(lo), tuple(hi), rMean=.08, rRelFuzz=.2, periodic=True, seed=12)
    c, r = arrays(sp)
    assert n > 100
    assert sp.isPeriodic and tuple(sp.cellSize) == pytest.approx(tuple(hi - lo))
    assert ((c >= lo) & (c < hi)).all()
    assert ((c - r[:, None] < lo) | (c + r[:, None] > hi)).any()  # some spheres cross a face
    assert min_gap(c, r, cell=hi - lo) >= 0  # through the periodic images
    # reference: first center of a small periodic cloud with seed 1
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, num=3, seed=1, periodic=True)
    assert tuple(sp[0][0]) == pytest.approx((0.9971848082302656, 0.9325573613681655, 0.128124447772306), abs=1e-12)


def test_periodic_porosity_mode():
    sp = SpherePack()
    assert sp.makeCloud((1, 0, 0), (2, 1, 3), num=300, periodic=True, seed=6) == 300
    c, r = arrays(sp)
    assert min_gap(c, r, cell=np.array([1, 1, 3.])) >= 0
    assert r[0] == pytest.approx(0.08779871329807519, rel=1e-12)  # reference (after 2 porosity raises)
    assert tuple(sp[0][0]) == pytest.approx((1.9474760764029018, 0.2094063657177565, 0.1927638224940019), abs=1e-12)


def test_non_periodic_cell_size_is_zero():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, seed=1)
    assert tuple(sp.cellSize) == (0, 0, 0) and not sp.isPeriodic


# ------------------------------------------------------------------ container protocol and geometry

def test_iteration_len_getitem_lists_and_add():
    sp = SpherePack([((1, 2, 3), .5), ((0, 0, 0), .25)])
    assert len(sp) == 2
    items = list(sp)
    assert items == [(Vector3(1, 2, 3), .5), (Vector3(0, 0, 0), .25)]
    c, r = items[0]
    assert isinstance(c, Vector3) and isinstance(r, float)
    assert sp[-1] == sp[1] == (Vector3(0, 0, 0), .25)
    with pytest.raises(IndexError):
        sp[2]
    sp.add((4, 4, 4), 1)
    assert len(sp) == 3 and sp[2] == (Vector3(4, 4, 4), 1)
    assert sp.toList() == list(sp)
    sp.fromList([((9, 9, 9), 2)])
    assert sp.toList() == [(Vector3(9, 9, 9), 2)]
    for center, radius in SpherePack():
        pytest.fail('empty packing iterated')


def test_aabb_dim_center_translate_scale_reldensity():
    sp = SpherePack([((0, 0, 0), 1), ((4, 1, 0), .5)])
    lo, hi = sp.aabb()
    assert tuple(lo) == (-1, -1, -1) and tuple(hi) == (4.5, 1.5, 1)
    assert tuple(sp.dim()) == (5.5, 2.5, 2)
    assert tuple(sp.center()) == (1.75, .25, 0)
    assert sp.relDensity() == pytest.approx(4 / 3 * math.pi * (1 + .125) / (5.5 * 2.5 * 2))
    sp.translate((1, 1, 1))
    assert sp[0] == (Vector3(1, 1, 1), 1)
    sp.scale(2)  # about center()
    assert tuple(sp[0][0]) == pytest.approx((1 + (1 - 2.75), 1 + (1 - 1.25), 1 + (1 - 1))) and sp[0][1] == 2
    lo, hi = SpherePack().aabb()
    assert tuple(lo) == (math.inf,) * 3 and tuple(hi) == (-math.inf,) * 3  # as the reference


# ------------------------------------------------------------------ save / load

def test_save_load_round_trip(tmp_path):
    for periodic in (False, True):
        sp = SpherePack()
        sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, rRelFuzz=.5, periodic=periodic, seed=13)
        f = str(tmp_path / ('p%d.txt' % periodic))
        sp.save(f)
        loaded = SpherePack()
        loaded.add((7, 7, 7), 7)  # discarded by load
        loaded.load(f)
        a, b = np.array([list(c) + [r] for c, r in sp]), np.array([list(c) + [r] for c, r in loaded])
        assert a.shape == b.shape and np.abs(a - b).max() <= 1e-12
        assert tuple(loaded.cellSize) == tuple(sp.cellSize)
    first = open(str(tmp_path / 'p1.txt')).readline()
    assert first.split()[0] == '##PERIODIC::'


def test_load_reads_the_reference_format(tmp_path):
    f = tmp_path / 'yade.txt'
    f.write_text('##PERIODIC:: 1 1 1\n0.997185 0.932557 0.128124 0.1 -1\n\n0.999041 0.236089 0.396581 0.1 -1\n')
    sp = SpherePack()
    sp.load(str(f))
    assert sp.toList() == [(Vector3(0.997185, 0.932557, 0.128124), .1), (Vector3(0.999041, 0.236089, 0.396581), .1)]
    assert tuple(sp.cellSize) == (1, 1, 1)


def test_load_errors(tmp_path):
    sp = SpherePack([((0, 0, 0), 1)])
    with pytest.raises(FileNotFoundError):
        sp.load(str(tmp_path / 'missing.txt'))
    bad = tmp_path / 'bad.txt'
    bad.write_text('0 0 0 1\n1 2 x 3\n')
    with pytest.raises(ValueError, match='line 2'):
        sp.load(str(bad))
    bad.write_text('0 0 0 1\n1 2 3\n')
    with pytest.raises(ValueError, match='line 2'):
        sp.load(str(bad))
    bad.write_text('0 0 0 -1\n')
    with pytest.raises(ValueError, match='line 1'):
        sp.load(str(bad))
    assert sp.toList() == [(Vector3(0, 0, 0), 1)]  # unchanged by a failed load
    with pytest.raises(OSError):
        sp.save(str(tmp_path / 'no' / 'such' / 'dir.txt'))


# ------------------------------------------------------------------ toSimulation

def test_tosimulation_appends_spheres_with_keywords():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, num=20, seed=1)
    O.bodies.append(utils.sphere((5, 5, 5), 1))
    mat = FrictMat(density=2000, label='packMat')
    O.materials.append(mat)
    ids = sp.toSimulation(color=(1, 0, 0), material='packMat', fixed=True)
    assert ids == list(range(1, 21))
    assert len(O.bodies) == 21
    for i, (c, r) in zip(ids, sp):
        b = O.bodies[i]
        assert b.shape.radius == r and tuple(b.state.pos) == tuple(c)
        assert tuple(b.shape.color) == (1, 0, 0)
        assert b.material.label == 'packMat' and not b.dynamic
        assert b.state.mass == pytest.approx(2000 * 4 / 3 * math.pi * r ** 3)
    assert SpherePack().toSimulation() == []


def test_tosimulation_of_a_periodic_packing_sets_the_periodic_cell():
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 2, 3), rMean=.1, num=5, periodic=True, seed=1)
    assert len(sp.toSimulation()) == 5
    assert O.periodic and O.cell.hSize == Matrix3(1, 0, 0, 0, 2, 0, 0, 0, 3) and O.cell.trsf == Matrix3.Identity
    O.reset()
    sp.cellSize = (0, 0, 0)  # insert without the cell
    assert len(sp.toSimulation()) == 5 and not O.periodic


def test_pack_module_is_imported_with_yade():
    assert yade.pack is pack and pack.SpherePack is SpherePack
    assert 'SpherePack' in pack.__doc__


# ------------------------------------------------------------------ arguments

def test_keyword_arguments_as_documented():
    sp = SpherePack()
    n = sp.makeCloud(minCorner=(0, 0, 0), maxCorner=(1, 1, 1), rMean=-1, rRelFuzz=0, num=10, periodic=False,
                     porosity=0.65, psdSizes=[], psdCumm=[], distributeMass=False, seed=1)
    assert n == 10
    sp = SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), psdSizes=np.array([.1, .2]), psdCumm=(0, 1), num=5, seed=1)
    assert len(sp) == 5


@pytest.mark.parametrize('kw, match', [
    (dict(minCorner=(1, 0, 0), maxCorner=(0, 1, 1), rMean=.1), 'maxCorner'),
    (dict(minCorner=(0, 0, 0), maxCorner=(1, 0, 0), rMean=.1), 'maxCorner'),
    (dict(rMean=0), 'rMean'),
    (dict(rMean=.1, rRelFuzz=-.1), 'rRelFuzz'),
    (dict(rMean=.1, rRelFuzz=1), 'rRelFuzz'),
    (dict(num=0), 'num'),
    (dict(), 'num'),
    (dict(psdSizes=[.1, .2], psdCumm=[0, .5, 1]), 'same length'),
    (dict(psdSizes=[.1], psdCumm=[1]), 'at least 2'),
    (dict(psdSizes=[.1, .2], psdCumm=[0, .5]), 'from 0 to 1'),
    (dict(psdSizes=[.2, .1], psdCumm=[0, 1]), 'non-decreasing'),
    (dict(psdSizes=[.1, .2], psdCumm=[0, 1], rMean=.1), "can't be combined"),
    (dict(num=10, porosity=1), 'porosity'),
])
def test_bad_arguments_raise_value_error(kw, match):
    kw.setdefault('minCorner', (0, 0, 0))
    kw.setdefault('maxCorner', (1, 1, 1))
    sp = SpherePack()
    with pytest.raises(ValueError, match=match):
        sp.makeCloud(**kw)
    assert len(sp) == 0


def test_bad_spheres_raise():
    sp = SpherePack()
    with pytest.raises(ValueError):
        sp.add((0, 0, 0), -1)
    with pytest.raises(ValueError):
        sp.add((0, math.nan, 0), 1)
    with pytest.raises(ValueError):
        SpherePack([((0, 0, 0),)])
    with pytest.raises(ValueError):
        sp.psd(bins=0)
    with pytest.raises(ValueError):
        sp.scale(0)
