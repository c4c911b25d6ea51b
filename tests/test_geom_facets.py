"""geom's facet builders (facetCylinder, facetCone, facetBunker, facetPolygon, facetHelix, facetSphere,
facetParallelepiped, facetBox) and utils.aabbExtrema2d.

1. Against the reference Yade 2023.02a: tests/data/geom_facets/reference.json holds, for 30 calls, each facet's
   position and world-space vertices as the reference returns them (made by make_reference.py beside it, run with
   `yade -n -x`); here the same calls give the same facets, in the same order, with the same vertex order (so the
   same normals), to 1e-12.
2. Analytic checks: areas and enclosed volumes of the polygonal surfaces (exact for the polygon, not only in the
   limit), a facetSphere that is closed and whose volume approaches 4/3·π·r³, a facetHelix on its helix.
3. Bad arguments: a clear geom.GeomArgumentError (a ValueError, also a RuntimeError as the reference raises),
   including where the reference makes degenerate facets or crashes (doc/compatibility.md lists these)."""
import json
import math
import pathlib

import numpy as np
import pytest

from yade import O, FrictMat, Quaternion, Vector2, Vector3, geom, utils

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

REFERENCE = json.loads((pathlib.Path(__file__).parent / 'data' / 'geom_facets' / 'reference.json').read_text())


def run(call):
    return eval(call, {'geom': geom, 'Quaternion': Quaternion, 'Vector3': Vector3, 'math': math})


def world(b):
    return [list(b.state.pos)] + [list(b.state.pos + b.state.ori * v) for v in b.shape.vertices]


def triangles(facets):
    """The facets' world-space vertices, an (n, 3, 3) array."""
    return np.array([world(b)[1:] for b in facets], dtype=float).reshape(-1, 3, 3)


def areas(tris):
    return 0.5 * np.linalg.norm(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]), axis=1)


def signedVolume(tris, origin=(0, 0, 0)):
    """Σ det(v0, v1, v2) / 6 about origin: the enclosed volume of a closed surface whose facets all turn
    the same way (negative when their normals point inward)."""
    t = tris - np.asarray(origin, dtype=float)
    return float(np.einsum('ij,ij->i', t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6)


def local(points, center, q):
    """World points back into the builder's local frame."""
    qc = q.conjugate()
    return np.array([list(qc * (Vector3(*p) - Vector3(*center))) for p in points])


# ------------------------------------------------------------------------------- 1. the reference's facets

@pytest.mark.parametrize('ref', REFERENCE, ids=[r['call'].split('(')[0][5:] + '-%d' % i for i, r in enumerate(REFERENCE)])
def test_same_facets_as_the_reference(ref):
    got = run(ref['call'])
    if 'nodes' in ref:
        got, nodes, elements = got
        assert [list(e) for e in elements] == ref['elements']
        np.testing.assert_allclose(np.array([list(n) for n in nodes]), np.array(ref['nodes']), rtol=0, atol=1e-12)
        assert all(isinstance(n, Vector3) for n in nodes) and all(isinstance(e, tuple) for e in elements)
    assert len(got) == len(ref['facets']), ref['call']
    # body position and the three vertices, in the reference's order (so its normals)
    np.testing.assert_allclose(np.array([world(b) for b in got]), np.array(ref['facets']), rtol=0, atol=1e-12,
                               err_msg=ref['call'])


def test_reference_data_covers_every_builder():
    names = {r['call'].split('(')[0] for r in REFERENCE}
    assert names == {'geom.' + n for n in geom.__all__}


# ------------------------------------------------------------------------------- 2. analytic checks

def regularArea(r, n, dphi):
    """Area of a fan of n triangles of apex angle dphi and sides r."""
    return n * 0.5 * r * r * math.sin(dphi)


@pytest.mark.parametrize('rT, rB, H, n', [(1, 2, 3, 7), (0.5, 0.5, 2, 12), (0, 1.5, 1, 5), (2, 0, 0.7, 9), (1, 3, 0, 6)])
def test_facetCone_side_and_caps_areas_exact_and_limit(rT, rB, H, n):
    """The side of a regular n-gon frustum: n planar trapezoids, sides 2·r·sin(π/n), apart
    sqrt(((rB - rT)·cos(π/n))² + H²); each cap a fan of n triangles. Then the limit π(rT + rB)·slant."""
    q = Quaternion(Vector3(0.48, -0.6, 0.64), 0.7)
    side = areas(triangles(geom.facetCone((1, 2, 3), rT, rB, H, orientation=q, segmentsNumber=n, wallMask=4))).sum()
    s = math.sin(math.pi / n)
    assert side == pytest.approx(n * (rT + rB) * s * math.hypot((rB - rT) * math.cos(math.pi / n), H), rel=1e-12)
    for bit, r in ((1, rT), (2, rB)):
        caps = geom.facetCone((1, 2, 3), rT, rB, H, orientation=q, segmentsNumber=n, wallMask=bit)
        assert len(caps) == (n if r > 0 else 0)
        assert areas(triangles(caps)).sum() == pytest.approx(regularArea(r, n, 2 * math.pi / n), rel=1e-12, abs=1e-15)
    many = areas(triangles(geom.facetCone((0, 0, 0), rT, rB, H, segmentsNumber=400, wallMask=4))).sum()
    assert many == pytest.approx(math.pi * (rT + rB) * math.hypot(rB - rT, H), rel=1e-4)


@pytest.mark.parametrize('rT, rB, H', [(1, 2, 3), (1.5, 1.5, 2), (0, 1, 1), (1, 0, 2)])
def test_closed_cone_and_cylinder_enclose_the_frustum(rT, rB, H):
    """A closed frustum (wallMask 7): every facet's normal points inward, and the enclosed volume is that of the
    regular n-gon frustum, H/3·(A1 + A2 + sqrt(A1·A2))."""
    n, c = 8, (1, -2, 0.5)
    fs = geom.facetCone(c, rT, rB, H, orientation=Quaternion(Vector3(0, 0.6, 0.8), -2.1), segmentsNumber=n)
    A1, A2 = regularArea(rT, n, 2 * math.pi / n), regularArea(rB, n, 2 * math.pi / n)
    vol = H / 3 * (A1 + A2 + math.sqrt(A1 * A2))
    assert signedVolume(triangles(fs), c) == pytest.approx(-vol, rel=1e-12)
    assert signedVolume(triangles(fs), (4, 5, 6)) == pytest.approx(-vol, rel=1e-12)  # closed: any origin
    if rT == rB:
        cyl = geom.facetCylinder(c, rT, H, orientation=Quaternion(Vector3(0, 0.6, 0.8), -2.1), segmentsNumber=n)
        np.testing.assert_allclose(triangles(cyl), triangles(fs), atol=1e-14)


def test_facetCylinder_closed_sector_encloses_the_sector():
    """A sector of less than π closed by two radial planes, and of more than π closed by the chord plane and the
    caps' triangles: both closed surfaces (the same volume about any origin), of the polygonal sector's volume."""
    R, H, n = 1.3, 2.0, 6
    for a0, a1 in ((0.2, 2.0), (0.5, 0.5 + 1.4 * math.pi)):
        fs = geom.facetCylinder((0, 0, 0), R, H, segmentsNumber=n, angleRange=(a0, a1), closeGap=True)
        d = (a1 - a0) / n
        area = regularArea(R, n, d) + (0.5 * R * R * math.sin(2 * math.pi - (a1 - a0)) if a1 - a0 > math.pi else 0)
        v0, v1 = signedVolume(triangles(fs)), signedVolume(triangles(fs), (3, -1, 2))
        assert abs(v0) == pytest.approx(area * H, rel=1e-12) and v1 == pytest.approx(v0, rel=1e-12)


def test_facetBunker_closed_encloses_its_three_parts():
    """wallMask 7 with a pipe: pipe + cone + cylinder, all normals inward; each vertex on its part's circle."""
    dB, dO, hB, hO, hP, n = 2.2, 0.8, 1.5, 1.1, 0.4, 10
    q = Quaternion(Vector3(0.48, -0.6, 0.64), 0.7)
    fs = geom.facetBunker((1, 2, 3), dB, dO, hB, hO, hP, orientation=q, segmentsNumber=n, wallMask=7)
    assert len(fs) == n * (1 + 2 + 2 + 2 + 1)
    AB, AO = regularArea(dB / 2, n, 2 * math.pi / n), regularArea(dO / 2, n, 2 * math.pi / n)
    vol = AO * hP + hO / 3 * (AB + AO + math.sqrt(AB * AO)) + AB * hB
    assert signedVolume(triangles(fs), (1, 2, 3)) == pytest.approx(-vol, rel=1e-12)
    p = local(triangles(fs).reshape(-1, 3), (1, 2, 3), q)
    rho = np.hypot(p[:, 0], p[:, 1])
    for z, r in zip(p[:, 2], rho):
        expected = (dO / 2 if z < hP + 1e-12 else dB / 2 if z > hP + hO - 1e-12 else None)
        assert r < 1e-12 or expected is None or r == pytest.approx(expected, rel=1e-12)
    assert p[:, 2].min() == pytest.approx(0, abs=1e-12) and p[:, 2].max() == pytest.approx(hP + hO + hB, rel=1e-12)


@pytest.mark.parametrize('rO, rI, a0, a1, n', [(1.7, 0, 0, 2 * math.pi, 6), (2, 0.5, 0.3, 2.1, 5), (1, 0.2, 2.5, -1, 4),
                                            (1, 0, 0, math.pi / 2, 3)])
def test_facetPolygon_area_and_plane(rO, rI, a0, a1, n):
    q = Quaternion(Vector3(0, 0.6, 0.8), -2.1)
    fs = geom.facetPolygon((1, 2, 3), rO, orientation=q, segmentsNumber=n, angleRange=(a0, a1), radiusInner=rI)
    assert len(fs) == (2 * n if rI > 0 else n)
    tris = triangles(fs)
    assert areas(tris).sum() == pytest.approx(regularArea(rO, n, abs(a1 - a0) / n) - regularArea(rI, n, abs(a1 - a0) / n),
                                              rel=1e-12)
    p = local(tris.reshape(-1, 3), (1, 2, 3), q)
    assert np.abs(p[:, 2]).max() < 1e-12  # all in the local xy plane
    for b in fs:
        assert abs(abs((q.conjugate() * b.shape.normal)[2]) - 1) < 1e-12


@pytest.mark.parametrize('rO, rI, pitch, a0, a1, n', [(1.7, 0, 2.0, 0, 2 * math.pi, 6), (1.7, 0.5, 0.3, 0, 5 * math.pi, 25),
                                                   (1, 0.3, 1.0, 2, 1, 4)])
def test_facetHelix_points_on_the_helix(rO, rI, pitch, a0, a1, n):
    """Every rim vertex (radius rO or rI) at angle θ is at height pitch·|θ - a0|/2π, θ counted along the range;
    the axis vertices are on the axis, between 0 and the height reached."""
    q, c = Quaternion(Vector3(0.48, -0.6, 0.64), 0.7), (1, 2, 3)
    fs = geom.facetHelix(c, rO, pitch, orientation=q, segmentsNumber=n, angleRange=(a0, a1), radiusInner=rI)
    assert len(fs) == (2 * n if rI > 0 else n)
    p = local(triangles(fs).reshape(-1, 3), c, q)
    rho, z = np.hypot(p[:, 0], p[:, 1]), p[:, 2]
    top = pitch * abs(a1 - a0) / (2 * math.pi)
    assert z.min() == pytest.approx(0, abs=1e-12) and z.max() == pytest.approx(top, rel=1e-12)
    for (x, y, zz), r in zip(p, rho):
        if r < 1e-12:
            continue
        assert min(abs(r - rO), abs(r - rI)) < 1e-12
        theta = a0 + math.copysign(2 * math.pi * zz / pitch, a1 - a0)  # the angle that height belongs to
        assert math.hypot(x - r * math.cos(theta), y - r * math.sin(theta)) < 1e-11


def sphereVolumeAndEdges(nt, nph, r=1.5, c=(1, 2, 3)):
    fs, nodes, elements = geom.facetSphere(c, r, nt, nph, returnElementMap=True)
    tris = triangles(fs)
    t = tris - np.asarray(c, dtype=float)
    # (the reference's facets do not all turn the same way, so the volume is summed as |det| about the center,
    # inside the convex polyhedron)
    vol = float(np.abs(np.einsum('ij,ij->i', t[:, 0], np.cross(t[:, 1], t[:, 2]))).sum() / 6)
    edges = {}
    for e in elements:
        for i, j in ((e[0], e[1]), (e[1], e[2]), (e[2], e[0])):
            edges[frozenset((i, j))] = edges.get(frozenset((i, j)), 0) + 1
    return fs, nodes, elements, vol, edges


def test_facetSphere_closed_and_volume_approaches_the_ball():
    r = 1.5
    errors = []
    for nt, nph in ((6, 5), (12, 9), (24, 17), (48, 33)):
        fs, nodes, elements, vol, edges = sphereVolumeAndEdges(nt, nph, r)
        assert len(nodes) == 2 + nt * (nph - 2) and len(fs) == len(elements) == 2 * nt * (nph - 2)
        assert set(edges.values()) == {2}  # closed: every edge between exactly two facets
        assert all(abs((n - Vector3(1, 2, 3)).norm() - r) < 1e-12 for n in nodes)
        errors.append(4 / 3 * math.pi * r ** 3 - vol)
    assert all(e > 0 for e in errors)  # inscribed polyhedra, from below
    assert all(b < a / 3.5 for a, b in zip(errors, errors[1:]))  # about 4x smaller per doubling (second order)
    assert errors[-1] / (4 / 3 * math.pi * r ** 3) < 6e-3  # (5.3e-3 with 48 x 33)


def test_facetSphere_default_resolution():
    fs = geom.facetSphere((0, 0, 0), 2)
    assert len(fs) == 2 * 8 * 6
    assert len(geom.facetSphere((0, 0, 0), 2, returnElementMap=True)) == 3


@pytest.mark.parametrize('ext, h', [((1, 2, 3), 1), ((1.2, 0.7, 2), 1.5), ((1, 2, 3), 3), ((0.5, 0.5, 4), 0.1)])
def test_facetParallelepiped_volume(ext, h):
    """Closed (wallMask 63), all normals the same way: the volume is the base 2ex·2ey times the height 2h; the top
    face is the bottom one moved by (sqrt(ez² - h²), 0, 2h)."""
    q, c = Quaternion(Vector3(0, 0.6, 0.8), -2.1), (1, 2, 3)
    fs = geom.facetParallelepiped(c, ext, h, orientation=q)
    assert len(fs) == 12
    tris = triangles(fs)
    assert abs(signedVolume(tris, c)) == pytest.approx(8 * ext[0] * ext[1] * h, rel=1e-12)
    assert signedVolume(tris, (5, 5, 5)) == pytest.approx(signedVolume(tris, c), rel=1e-12)
    p = local(tris.reshape(-1, 3), c, q)
    s = math.sqrt(ext[2] ** 2 - h ** 2)
    top = p[p[:, 2] > 0]
    assert np.allclose(np.abs(p[:, 2]), h, atol=1e-12)
    assert top[:, 0].min() == pytest.approx(s - ext[0], abs=1e-12) and top[:, 0].max() == pytest.approx(s + ext[0], abs=1e-12)
    if h == ext[2]:  # a box of half-sizes (ex, ey, h), the same facets as facetBox's
        np.testing.assert_allclose(tris, triangles(geom.facetBox(c, ext, orientation=q)), atol=1e-12)


def test_facetParallelepiped_flat_is_one_rectangle():
    for ext, h in (((1, 2, 3), 0), ((0, 2, 3), 1)):
        fs = geom.facetParallelepiped((0, 0, 0), ext, h, wallMask=0)  # (whatever wallMask, as facetBox)
        assert len(fs) == 2 and areas(triangles(fs)).sum() == pytest.approx(
            4 * ext[1] * (ext[0] if h == 0 else math.hypot(math.sqrt(ext[2] ** 2 - h ** 2), 2 * h) / 2), rel=1e-12)


# -------------------------------------------------------------- where this engine differs from the reference

def test_closeGap_on_a_whole_turn_adds_nothing():
    """The reference closes a whole turn's 'gap' with facets of nearly coincident vertices."""
    for kw in ({}, {'angleRange': (0.5, 2 * math.pi + 0.5)}):
        for wm in (3, 4, 7):
            a = geom.facetCylinder((0, 0, 0), 1, 3, segmentsNumber=5, wallMask=wm, closeGap=True, **kw)
            b = geom.facetCylinder((0, 0, 0), 1, 3, segmentsNumber=5, wallMask=wm, **kw)
            np.testing.assert_allclose(triangles(a), triangles(b), atol=0)
    assert len(geom.facetBunker((0, 0, 0), 2, 1, 3, 1, 0.5, segmentsNumber=5, wallMask=7, closeGap=True)) == 5 * 8


def test_whole_turn_closes_exactly():
    """The last segment ends on the first point (the reference: one rounding away), so the mesh shares its seam."""
    fs = geom.facetCylinder((0, 0, 0), 1, 3, segmentsNumber=5, wallMask=4)
    assert world(fs[-1])[3] == world(fs[1])[2]  # P(a = 2π, top) of the last segment is P(0, top)


def test_facetPolygon_default_angleRange_is_a_whole_turn():
    """The reference's facetPolygon fails on its own default (TypeError: 'NoneType' object is not subscriptable)."""
    np.testing.assert_allclose(triangles(geom.facetPolygon((1, 2, 3), 1.7, segmentsNumber=6)),
                               triangles(geom.facetPolygon((1, 2, 3), 1.7, segmentsNumber=6, angleRange=(0, 2 * math.pi))),
                               atol=1e-15)
    np.testing.assert_allclose(triangles(geom.facetHelix((1, 2, 3), 1.7, 2, segmentsNumber=6)),
                               triangles(geom.facetHelix((1, 2, 3), 1.7, 2, segmentsNumber=6, angleRange=(0, 2 * math.pi))),
                               atol=1e-15)


def test_facetBunker_without_cylinder_gets_its_top_lid():
    """hBunker = 0 with wallMask bit 1: the cone's top is closed (the reference makes no lid)."""
    n = 6
    fs = geom.facetBunker((0, 0, 0), 2, 1, 0, 1, 0.5, segmentsNumber=n, wallMask=7)
    assert len(fs) == n * (3 + 2 + 1)
    lid = triangles(fs[-n:])
    assert np.allclose(lid[:, :, 2], 1.5) and areas(lid).sum() == pytest.approx(regularArea(1, n, 2 * math.pi / n))
    assert all(abs(b.shape.normal[2] + 1) < 1e-12 for b in fs[-n:])  # -z, as the cylinder's top cap
    assert len(geom.facetBunker((0, 0, 0), 2, 1, 0, 1, 0.5, segmentsNumber=n, wallMask=6)) == n * (3 + 2)


def test_facetBunker_inner_radii_make_rings_of_the_caps():
    n = 4
    fs = geom.facetBunker((0, 0, 0), 2, 1, 3, 1, 0, segmentsNumber=n, wallMask=3, radiusTopInner=0.4,
                          radiusBottomInner=0.2)
    assert len(fs) == 4 * n
    a = areas(triangles(fs))
    assert a[:2 * n].sum() == pytest.approx(regularArea(0.5, n, math.pi / 2) - regularArea(0.2, n, math.pi / 2))
    assert a[2 * n:].sum() == pytest.approx(regularArea(1, n, math.pi / 2) - regularArea(0.4, n, math.pi / 2))
    with pytest.raises(TypeError):
        geom.facetBunker((0, 0, 0), 2, 1, 3, 1, segmentsNumber=3, radiusInner=0.2)  # goes to utils.facet


# ------------------------------------------------------------------------------------ 3. bad arguments

BAD = [
    ('geom.facetCylinder((0,0,0), 1, 2, segmentsNumber=2)', 'segmentsNumber must be at least 3'),
    ('geom.facetCylinder((0,0,0), -1, 2)', 'radius must be positive'),
    ('geom.facetCylinder((0,0,0), 0, 2)', 'radius must be positive'),
    ('geom.facetCylinder((0,0,0), 1, 0)', 'height must be positive'),  # reference: degenerate facets
    ('geom.facetCylinder((0,0,0), 1, -2)', 'height must be positive'),
    ('geom.facetCylinder((0,0,0), 1, 2, radiusTopInner=1)', 'radiusTopInner'),  # reference: degenerate facets
    ('geom.facetCylinder((0,0,0), 1, 2, radiusBottomInner=2)', 'radiusBottomInner'),
    ('geom.facetCylinder((0,0,0), 1, 2, angleRange=(1, 0))', 'must not be smaller'),
    ('geom.facetCylinder((0,0,0), 1, 2, angleRange=(1, 1))', 'angleRange is empty'),  # reference: degenerate facets
    ('geom.facetCylinder((0,0,0), 1, 2, angleRange=(0, 3*math.pi))', 'larger than 2π'),
    ('geom.facetCylinder((0,0,0), 1, 2, angleRange=(0, float("nan")))', 'finite'),
    ('geom.facetCone((0,0,0), 0, 0, 2)', 'radiusTop or radiusBottom must be positive'),
    ('geom.facetCone((0,0,0), -1, 2, 2)', 'radii must be non-negative'),  # reference: mirrored points
    ('geom.facetCone((0,0,0), 1, 2, -2)', 'height must be non-negative'),
    ('geom.facetCone((0,0,0), 1, 1, 0)', 'side of zero height'),
    ('geom.facetCone((0,0,0), 0, 1, 2, radiusTopInner=0.5)', 'radiusTopInner'),
    ('geom.facetBunker((0,0,0), 0, 1, 3, 1)', 'dBunker must be positive'),
    ('geom.facetBunker((0,0,0), 2, 0, 3, 1)', 'dOutput must be positive'),
    ('geom.facetBunker((0,0,0), 2, 1, -3, 1)', 'hBunker must be non-negative'),
    ('geom.facetBunker((0,0,0), 2, 1, 3, 0)', 'hOutput must be positive'),
    ('geom.facetBunker((0,0,0), 2, 1, 3, 1, -0.5)', 'hPipe must be non-negative'),
    ('geom.facetBunker((0,0,0), 2, 1, 3, 1, segmentsNumber=1)', 'segmentsNumber'),
    ('geom.facetPolygon((0,0,0), 0, angleRange=(0, 1))', 'radiusOuter must be positive'),
    ('geom.facetPolygon((0,0,0), 1, radiusInner=-0.5)', 'radiusInner must be non-negative'),
    ('geom.facetPolygon((0,0,0), 1, radiusInner=2)', 'radiusInner'),  # reference: reversed normals
    ('geom.facetPolygon((0,0,0), 1, segmentsNumber=2)', 'segmentsNumber'),
    ('geom.facetPolygon((0,0,0), 1, angleRange=(0, 7))', 'larger than 2π'),
    ('geom.facetHelix((0,0,0), 1, 0)', 'pitch must be positive'),
    ('geom.facetHelix((0,0,0), 1, -2)', 'pitch must be positive'),
    ('geom.facetHelix((0,0,0), 1, 2, radiusInner=1)', 'radiusInner'),  # reference: degenerate facets
    ('geom.facetHelix((0,0,0), 1, 2, angleRange=(2, 2))', 'angleRange is empty'),  # reference: degenerate facets
    ('geom.facetSphere((0,0,0), 0)', 'radius must be positive'),
    ('geom.facetSphere((0,0,0), -1)', 'radius must be positive'),
    ('geom.facetSphere((0,0,0), 1, 2, 5)', 'thetaResolution must be at least 3'),
    ('geom.facetSphere((0,0,0), 1, 5, 2)', 'phiResolution must be at least 3'),
    ('geom.facetParallelepiped((0,0,0), (1,2,3), 4)', 'must not exceed extents'),
    ('geom.facetParallelepiped((0,0,0), (1,2,3), -1)', 'height must be non-negative'),
    ('geom.facetParallelepiped((0,0,0), (-1,2,3), 1)', 'non-negative'),  # reference: inward-turned faces
    ('geom.facetParallelepiped((0,0,0), (0,2,3), 0)', 'at least 2 non-zero'),  # reference: degenerate facets
    ('geom.facetBox((0,0,0), (1,0,0))', 'at least 2 non-zero'),
]


@pytest.mark.parametrize('call, match', BAD, ids=[c for c, _ in BAD])
def test_bad_arguments_raise_a_clear_error(call, match):
    with pytest.raises(ValueError, match=match) as e:
        run(call)
    assert isinstance(e.value, RuntimeError) and isinstance(e.value, geom.GeomArgumentError)


@pytest.mark.parametrize('call', ['geom.facetCylinder((0,0,0), 1, 2, segmentsNumber=3.5)',
                                  'geom.facetSphere((0,0,0), 1, 4.0, 4)', 'geom.facetCone((0,0,0), "a", 1, 2)',
                                  'geom.facetCylinder((0,0,0), 1, 2, angleRange=3)'])
def test_wrong_types_raise_TypeError(call):
    with pytest.raises(TypeError):
        run(call)


# ------------------------------------------------------------------------------------ keywords to utils.facet

BUILDERS = [
    lambda **kw: geom.facetCylinder((0, 0, 0), 1, 2, segmentsNumber=3, **kw),
    lambda **kw: geom.facetCone((0, 0, 0), 1, 2, 2, segmentsNumber=3, **kw),
    lambda **kw: geom.facetBunker((0, 0, 0), 2, 1, 3, 1, 0.5, segmentsNumber=3, wallMask=7, **kw),
    lambda **kw: geom.facetPolygon((0, 0, 0), 1, segmentsNumber=3, radiusInner=0.3, **kw),
    lambda **kw: geom.facetHelix((0, 0, 0), 1, 2, segmentsNumber=3, **kw),
    lambda **kw: geom.facetSphere((0, 0, 0), 1, 3, 3, **kw),
    lambda **kw: geom.facetParallelepiped((0, 0, 0), (1, 2, 3), 1, **kw),
]


@pytest.mark.parametrize('i', range(len(BUILDERS)))
def test_keywords_pass_through_to_facet(i):
    O.materials.append(FrictMat(young=2e7, label='stiff'))
    soft = FrictMat(young=5e6, label='soft')
    O.materials.append(soft)
    fs = BUILDERS[i](color=(0, 1, 0), material='stiff', mask=5)
    assert fs and all(f.material.label == 'stiff' and f.mask == 5 and f.shape.wire and not f.dynamic for f in fs)
    assert all(tuple(f.shape.color) == (0, 1, 0) for f in fs)
    fs = BUILDERS[i](material=soft, fixed=False, wire=False)
    assert all(f.material.label == 'soft' and f.dynamic and not f.shape.wire for f in fs)
    with pytest.raises(TypeError):
        BUILDERS[i](colour=(1, 0, 0))


# ------------------------------------------------------------------------------------ utils.aabbExtrema2d

def test_aabbExtrema2d():
    # the reference gives this one too (its loop only goes wrong when a point lowers a minimum and should raise a maximum)
    assert utils.aabbExtrema2d([(0, 1), (2, -1), (1, 5)]) == ((0, -1), (2, 5))
    # the reference: ((0.0, -1.0), (2.0, -inf)) and ((1, 2), (-inf, -inf))
    assert utils.aabbExtrema2d([Vector2(0, 1), Vector2(2, -1)]) == ((0, -1), (2, 1))
    assert utils.aabbExtrema2d([(1, 2)]) == ((1, 2), (1, 2))
    assert utils.aabbExtrema2d(iter([(3, 1, 9), (-1, 4, 9)])) == ((-1, 1), (3, 4))  # the first two coordinates
    assert utils.aabbExtrema2d(np.array([[0, 1], [2, 3.]])) == ((0, 1), (2, 3))
    pts = np.random.default_rng(3).normal(size=(50, 2))
    assert utils.aabbExtrema2d(pts.tolist()) == (tuple(pts.min(axis=0)), tuple(pts.max(axis=0)))
    assert 'aabbExtrema2d' in utils.__all__
    for bad, match in (([], 'no points'), ([(1,)], 'fewer than 2'), ([(float('nan'), 1)], 'NaN'), ([3], 'fewer than 2')):
        with pytest.raises(ValueError, match=match):
            utils.aabbExtrema2d(bad)
    with pytest.raises(TypeError):
        utils.aabbExtrema2d(5)
