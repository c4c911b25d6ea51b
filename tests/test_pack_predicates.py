"""Volume predicates of yade.pack (the manual 4.1: inSphere, inAlignedBox, inCylinder, inEllipsoid,
inHyperboloid, inParallelepiped, notInNotch, inSpace, and &, |, -, ^ on them) and the packings that
fill them (regularOrtho, regularHexa, filterSpherePack). The numbers are the reference Yade's
(2023.02a) printed for the same calls."""
import warnings

import pytest

from yade import O, pack, Vector3, Sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def near(a, b, tol=1e-12):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def box(p):
    lo, hi = p.aabb()
    return tuple(lo), tuple(hi)


def test_bounding_boxes_as_the_reference():
    sphere, aligned = pack.inSphere((1, 2, 3), 2), pack.inAlignedBox((-1, -2, -3), (1, 2, 3))
    cases = [
        (sphere, (-1, 0, 1), (3, 4, 5)),
        (aligned, (-1, -2, -3), (1, 2, 3)),
        (pack.inCylinder((0, 0, 0), (1, 1, 2), .5), (-0.4564354645876385, -0.4564354645876385, -0.2886751345948129),
         (1.4564354645876385, 1.4564354645876385, 2.288675134594813)),
        (pack.inEllipsoid((1, 1, 1), (3, 2, 1)), (-2, -1, 0), (4, 3, 2)),
        (pack.inHyperboloid((0, 0, -.1), (0, 0, .1), .05, .03), (-.05, -.05, -.1), (.05, .05, .1)),
        (pack.inParallelepiped((1, 1, 1), (2, 1, 1), (1.2, 2, 1), (1, 1.3, 2)), (1, 1, 1), (2.2, 2.3, 2)),
        (sphere | aligned, (-1, -2, -3), (3, 4, 5)),
        (sphere & aligned, (-1, 0, 1), (1, 2, 3)),
        (sphere ^ aligned, (-1, -2, -3), (3, 4, 5)),
        (aligned - pack.inCylinder((0, -2, 0), (0, 2, 0), 1), (-1, -2, -3), (1, 2, 3)),
    ]
    for p, lo, hi in cases:
        assert near(box(p)[0], lo) and near(box(p)[1], hi), (type(p).__name__, box(p))
    assert tuple(pack.inCylinder((0, 0, 0), (1, 1, 2), .5).dim()) == pytest.approx((1.912870929175277, 1.912870929175277, 2.577350269189626))
    assert tuple((sphere & aligned).center()) == (0, 1, 2)
    assert box(pack.notInNotch((0, 0, 0), (1, 0, 0), (0, 0, 1), .1)) == ((-float('inf'),) * 3, (float('inf'),) * 3)
    assert pack.inSpace()((1e9, 0, 0), 0)
    assert type(sphere - aligned).__name__ == 'PredicateDifference' and isinstance(sphere | aligned, pack.PredicateBoolean)


def test_inside_with_a_pad_as_the_reference():
    notch = pack.notInNotch((0, 0, 0), (1, 0, 0), (0, 0, 1), .1)
    # (point, pad, the reference's answer)
    for pt, pad, ref in [((0, -.3, .07), .05, False), ((0, -.3, .07), 0, True), ((0, .03, 0), .05, False), ((0, .03, 0), 0, True),
                         ((0, -.03, 0), .05, False), ((0, -.3, .04), .05, False), ((0, -.3, .04), -.02, True), ((0, -.3, .06), -.02, True),
                         ((0, .01, 0), -.02, True), ((0, -.01, 0), -.02, True), ((0, -.3, .11), .05, True), ((0, -.3, .099), .05, False)]:
        assert notch(pt, pad) is ref, (pt, pad)
    par = pack.inParallelepiped((1, 1, 1), (2, 1, 1), (1.2, 2, 1), (1, 1.3, 2))
    assert [par(p, 0) for p in [(1.5, 1.5, 1.5), (1.05, 1.5, 1.5), (1.15, 1.5, 1.2)]] == [True, False, True]
    cyl = pack.inCylinder((0, 0, 0), (0, 0, 1), 1)
    assert [cyl((0, 0, .05), .1), cyl((0, 0, -.05), -.1), cyl((1.05, 0, .5), -.1)] == [False, True, True]
    ell = pack.inEllipsoid((0, 0, 0), (3, 1, 1))
    assert [ell((2.5, 0, 0), .4), ell((0, .7, 0), .4)] == [True, False]
    hyp = pack.inHyperboloid((0, 0, -.1), (0, 0, .1), .05, .03)
    assert [hyp((.029, 0, 0), 0), hyp((.031, 0, 0), 0), hyp((.049, 0, .099), 0), hyp((.02, 0, 0), .01), hyp((.021, 0, 0), .01),
            hyp((0, 0, .095), .01)] == [True, False, True, False, False, False]
    sphere, aligned = pack.inSphere((0, 0, 0), 1), pack.inAlignedBox((0, 0, 0), (2, 2, 2))
    # the difference keeps pad away from B too; the symmetric difference is in exactly one
    assert (sphere - aligned)((-.5, 0, 0), .1) and not (sphere - aligned)((-.05, .5, .5), .1)
    assert (sphere ^ aligned)((1.5, 1.5, 1.5), 0) and (sphere ^ aligned)((-.5, 0, 0), 0) and not (sphere ^ aligned)((.3, .3, .3), 0)
    assert (sphere | aligned)((1.5, 1.5, 1.5), 0) and not (sphere & aligned)((1.5, 1.5, 1.5), 0)


def test_a_python_predicate_takes_part_in_the_operations():
    class above(pack.Predicate):
        def __call__(self, pt, pad):
            return pt[2] >= pad

        def aabb(self):
            return (Vector3(-1, -1, 0), Vector3(1, 1, 1))

    half = pack.inSphere((0, 0, 0), 1) & above()
    assert half((0, 0, .5), 0) and not half((0, 0, -.5), 0)
    assert box(half) == ((-1, -1, 0), (1, 1, 1))
    assert len(pack.regularOrtho(half, .1, 0)) > 0


def test_regular_packings_as_the_reference():
    cyl, sph = pack.inCylinder((0, 0, 0), (1, 1, 2), .5), pack.inSphere((1, 2, 3), 2)
    holed = pack.inAlignedBox((-1, -2, -3), (1, 2, 3)) - pack.inCylinder((0, -2, 0), (0, 2, 0), 1)
    # (generator, predicate, radius, gap, the reference's count, its first and last centres)
    for gen, pred, r, gap, count, first, last in [
            (pack.regularOrtho, cyl, .1, .01, 112, (-0.1464354645876385, 0.06356453541236151, 0.23132486540518712),
             (1.1135645354123618, 1.1135645354123618, 1.7013248654051871)),
            (pack.regularOrtho, sph, .3, .05, 72, (-0.04999999999999993, 0.95, 2.6000000000000005), (2.55, 2.2499999999999996, 3.2500000000000004)),
            (pack.regularHexa, cyl, .1, .01, 166, (-0.14143546458763845, -0.032083016733263525, 0.22571771138965452),
             (1.2235645354123617, 0.877243657240397, 1.5974319673482342)),
            (pack.regularHexa, sph, .3, .05, 102, (-0.02499999999999991, 1.3134718624063988, 2.5921683328090657),
             (2.25, 3.002221399786054, 2.5921683328090657)),
            (pack.regularHexa, holed, .2, 0, 480, (-0.8, -1.6535898384862247, -2.3468027352578194), (0.8, 1.5795716689756798, 2.5521767503085364))]:
        bodies = gen(pred, radius=r, gap=gap, color=(0, 0, 1))
        assert len(bodies) == count
        assert near(bodies[0].state.pos, first) and near(bodies[-1].state.pos, last)
        assert all(isinstance(b.shape, Sphere) and b.shape.radius == r and tuple(b.shape.color) == (0, 0, 1) for b in bodies)
        assert all(pred(b.state.pos, r) for b in bodies)
    # hexagonal close packing: every sphere of the inside touches 12 neighbours at 2r + gap
    bodies = pack.regularHexa(pack.inSphere((0, 0, 0), 1), .1, 0)
    inner = [b for b in bodies if b.state.pos.norm() < .6]
    pos = [b.state.pos for b in bodies]
    for b in inner:
        d = sorted((p - b.state.pos).norm() for p in pos)
        assert d[1:13] == pytest.approx([.2] * 12) and d[13] > .28
    O.bodies.append(bodies)
    assert len(O.bodies) == len(bodies)


def test_regular_packings_with_a_negative_gap_overlap_as_in_the_reference():
    """A negative gap (down to above -2*radius) packs overlapping spheres, as the reference allows (its
    ThermalEngine example uses gap=-1e-8); the counts and first two centres are the reference's."""
    box = pack.inAlignedBox((0, 0, 0), (10, 10, 10))
    for gen, gap, count, c0, c1 in [(pack.regularOrtho, -1e-8, 125, (1, 1, 1), (1, 1, 2.99999999)),
                                    (pack.regularOrtho, -0.5, 216, (1, 1, 1), (1, 1, 2.5)),
                                    (pack.regularHexa, -1e-8, 88, (1.99999999, 2.3094010652114974, 1.6329931536904863),
                                     (2.999999985, 1.7320507989086231, 3.2659863073809725)),
                                    (pack.regularHexa, -0.5, 231, (1.5, 1.7320508075688772, 1.224744871391589),
                                     (2.25, 1.299038105676658, 2.449489742783178))]:
        bodies = gen(box, radius=1, gap=gap)
        assert len(bodies) == count
        assert near(bodies[0].state.pos, c0) and near(bodies[1].state.pos, c1)
    for gen in (pack.regularOrtho, pack.regularHexa):  # (the reference: ZeroDivisionError, IndexError)
        for gap in (-2.0, -2.5, float('nan')):
            with pytest.raises(ValueError, match='gap'):
                gen(box, radius=1, gap=gap)


def test_filter_sphere_pack_centres_the_packing_on_the_predicate():
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (3, 3, 3), rMean=.2, rRelFuzz=.3, seed=5)
    n = len(sp)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        f = pack.filterSpherePack(pack.inSphere((1, 2, 3), 2), sp, returnSpherePack=True)
        bodies = pack.filterSpherePack(pack.inSphere((1, 2, 3), 2), sp, color=(1, 0, 0))
    assert [x.category for x in w] == [UserWarning, FutureWarning, UserWarning]  # (the packing smaller than the predicate)
    # the reference: 139 of the 152 spheres, the first at (1.8907..., 1.6365..., 4.2978...)
    assert (n, len(f), len(bodies)) == (152, 139, 139)
    c, r = list(f)[0]
    assert near(c, (1.890748228222589, 1.6365658578859932, 4.2978994526554075)) and r == pytest.approx(0.14662161449590677, rel=1e-15)
    assert near(f.center(), (0.9951511832241977, 2.0, 3.011711483751565))
    assert len(sp) == 152 and tuple(bodies[0].shape.color) == (1, 0, 0)


def test_bad_input_is_refused_clearly():
    with pytest.raises(ValueError, match="radius must be positive"):
        pack.inSphere((0, 0, 0), -1)
    with pytest.raises(ValueError, match="below maxAABB"):
        pack.inAlignedBox((1, 0, 0), (0, 1, 1))
    with pytest.raises(ValueError, match="same point"):
        pack.inCylinder((0, 0, 0), (0, 0, 0), 1)
    with pytest.raises(ValueError, match="skirt"):
        pack.inHyperboloid((0, 0, 0), (0, 0, 1), .1, .2)
    with pytest.raises(ValueError, match="coplanar"):
        pack.inParallelepiped((0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0))
    with pytest.raises(ValueError, match="finite"):
        pack.inSphere((0, float('nan'), 0), 1)
    with pytest.raises(TypeError, match="3 numbers"):
        pack.inSphere((0, 0), 1)
    with pytest.raises(TypeError, match="predicates"):
        pack.inSphere((0, 0, 0), 1) & 3
    with pytest.raises(ValueError, match="unbounded"):
        pack.regularHexa(pack.notInNotch((0, 0, 0), (1, 0, 0), (0, 0, 1), .1), .1, 0)
    with pytest.raises(ValueError, match="gap"):
        pack.regularOrtho(pack.inSphere((0, 0, 0), 1), .1, -1)
    with pytest.raises(TypeError, match="predicate"):
        pack.regularOrtho((0, 0, 0), .1, 0)
    with pytest.raises(NotImplementedError, match="aabb"):
        pack.Predicate().aabb()
    assert len(O.bodies) == 0


def test_half_space_and_convex_polyhedron_as_the_reference():
    h = pack.inHalfSpace((1, 2, 3), (0, 0, 1))
    assert box(h) == ((-float('inf'), -float('inf'), 3.0), (float('inf'),) * 3)
    assert [h((0, 0, 3.5), 0), h((0, 0, 2.5), 0), h((0, 0, 3.5), .6), h((0, 0, 3.5), .4), h((0, 0, 2.9), -.2)] == [True, False, False, True, True]
    h = pack.inHalfSpace((0, 0, 0), (1, 1, 0))  # (a slanted one: an infinite box)
    assert box(h) == ((-float('inf'),) * 3, (float('inf'),) * 3)
    assert [h((1, 0, 0), 0), h((-1, 0, 0), 0), h((1, 0, 0), .8), h((1, 0, 0), .7)] == [True, False, False, True]
    c = pack.inConvexPolyhedron([((0, 0, 0), (1, 0, 0)), ((1, 0, 0), (-1, 0, 0)), ((0, 0, 0), (0, 1, 0)), ((0, 1, 0), (0, -1, 0)),
                                 ((0, 0, 0), (0, 0, 1)), ((0, 0, 2), (0, 0, -1))])
    assert box(c) == ((0, 0, 0), (1, 1, 2))
    assert [c((.5, .5, 1), 0), c((.5, .5, 1), .4), c((.5, .5, 1), .6), c((1.5, .5, 1), 0)] == [True, True, False, False]
    # a tetrahedron: its box is that of its vertices; a regular packing fills it
    tet = pack.inConvexPolyhedron([((0, 0, 0), (1, 0, 0)), ((0, 0, 0), (0, 1, 0)), ((0, 0, 0), (0, 0, 1)), ((1, 0, 0), (-1, -1, -1))])
    assert near(box(tet)[0], (0, 0, 0)) and near(box(tet)[1], (1, 1, 1))
    assert all(sum(b.state.pos) <= 1 - .05 * 3 ** .5 + 1e-12 for b in pack.regularOrtho(tet, .05, 0))
    with pytest.raises(ValueError, match="unbounded"):
        pack.inConvexPolyhedron([((0, 0, 0), (1, 0, 0)), ((1, 0, 0), (-1, 0, 0)), ((0, 0, 0), (0, 1, 0)), ((0, 1, 0), (0, -1, 0))])
    with pytest.raises(ValueError, match="dir must not be zero"):
        pack.inHalfSpace((0, 0, 0), (0, 0, 0))


def test_best_fit_oriented_box_and_sphere_pack_helpers():
    from yade import Quaternion
    q = Quaternion((1, 2, 3), .5)
    corners = [q * Vector3(3 * x, 2 * y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    center, half, ori = pack.cloudBestFitOBB(tuple(corners))
    # the box of those corners exactly (6 x 4 x 2 = 48; the reference's search stops at 57.4 here)
    assert 8 * half[0] * half[1] * half[2] == pytest.approx(48, rel=1e-9) and sorted(half) == pytest.approx([1, 2, 3], rel=1e-9)
    assert near(center, (0, 0, 0), 1e-9)
    assert all(abs(x) <= h + 1e-9 for p in corners for x, h in zip(ori.conjugate() * (p - center), half))
    sp = pack.SpherePack()
    sp.fromList([((1, 0, 0), .1), ((0, 2, 0), .2)])
    assert type(iter(sp)) is pack.SpherePackIterator and [r for _, r in iter(sp)] == [.1, .2]
    from math import pi
    ids = sp.toSimulation(rot=Quaternion((0, 0, 1), pi / 2), color=(0, 0, 1))
    # the reference: (2.2e-16, 1, 0) and (-2, 4.4e-16, 0), orientations unchanged
    assert near(O.bodies[ids[0]].state.pos, (0, 1, 0), 1e-15) and near(O.bodies[ids[1]].state.pos, (-2, 0, 0), 1e-15)
    assert tuple(O.bodies[ids[0]].state.ori) == (0, 0, 0, 1) and pack.SpherePack_toSimulation is pack.SpherePack.toSimulation
    with pytest.raises(TypeError, match="rot must be"):
        sp.toSimulation(rot=(0, 0, 1))
    assert len(O.bodies) == 2
