"""Boundaries: a sphere against a Facet, a Wall and a Box, checked against analytic solutions
(resting overlap m·g/Kn, closest-point geometry of faces, edges and vertices), and the helpers
that build them (utils.facet, utils.wall, utils.box, utils.aabbWalls, geom.facetBox,
geom.facetCylinder).

Stiffnesses (manual 3.2): Kn = 2·E1·R1·E2·R2/(E1·R1 + E2·R2) with the reference radii the Ig2
functor stores: facet+sphere R1 = 2r, R2 = r (Kn = 4/3·E·r for equal E); wall+sphere and
box+sphere R1 = R2 = r (Kn = E·r). Ks is the same mean of E·ν.

Where the behaviour is not analytic (one-sided walls, aabbWalls sizes, the facets of a
facetCylinder) the expected numbers were printed by the reference Yade 2023.02a
(`yade -n -x -j1`, scripts quoted next to the numbers)."""
import math

import numpy as np
import pytest

from yade import (O, Bo1_Box_Aabb, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, Box, Facet, ForceResetter, FrictMat,
                  Ig2_Box_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                  InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys,
                  Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator, Quaternion, Vector3, Wall, geom, utils)
from yade.utils import PWaveTimeStep, aabbWalls, box, facet, kineticEnergy, sphere, wall

G = 9.81
E, NU, RHO = 1e7, 0.3, 1e3  # utils.defaultMaterial(): the material used when none is given


pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def engines(gravity=(0, 0, 0), damping=0.0):
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb(), Bo1_Box_Aabb()]),
        InteractionLoop(
            [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
            [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(gravity=gravity, damping=damping),
    ]


def arr(v):
    return np.array([float(x) for x in v])


def sphere_mass(r, rho=RHO):
    return 4. / 3. * math.pi * r ** 3 * rho


def real_interactions():
    return [i for i in O.interactions if i.isReal]


def one_step(bodies, dt=1e-6):
    """The bodies in a scene without gravity, one step: the geometry of the (single) contact
    is that of the initial placement (the motion of the step comes after the forces)."""
    O.engines = engines()
    ids = O.bodies.append(bodies)
    O.dt = dt
    O.step()
    return ids


def settle(obstacle, r, center, gravity, steps=5000):
    """A sphere put at `center` (just touching) falls on the obstacle with damping 0.3 and comes
    to rest; returns (obstacle id, sphere id)."""
    O.engines = engines(gravity=gravity, damping=0.3)
    ids = O.bodies.append([obstacle, sphere(center, r)])
    O.dt = .5 * PWaveTimeStep()
    O.run(steps, True)
    return ids


def closest_on_segment(p, a, b):
    t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0, 1)
    return a + t * (b - a)


def closest_on_triangle(p, verts):
    """Closest point of the (filled) triangle to p, by hand: the projection on the plane if it
    falls inside, otherwise the closest of the three edges' closest points."""
    a, b, c = verts
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n)
    q = p - np.dot(p - a, n) * n
    inside = all(np.dot(np.cross(v1 - v0, q - v0), n) >= 0 for v0, v1 in ((a, b), (b, c), (c, a)))
    if inside:
        return q, 'face'
    cands = [closest_on_segment(p, v0, v1) for v0, v1 in ((a, b), (b, c), (c, a))]
    best = min(cands, key=lambda x: np.linalg.norm(p - x))
    return best, ('vertex' if min(np.linalg.norm(best - v) for v in verts) < 1e-12 else 'edge')


def check_contact_geometry(i, center, r, closest, refR1):
    """ScGeom of a sphere (center, r) touching an obstacle at `closest`: the normal points from the
    closest point to the center, penetration r - distance, contact point in the middle of the
    overlap: center - n·(r - pen/2)."""
    d = center - closest
    dist = np.linalg.norm(d)
    n = d / dist
    pen = r - dist
    assert pen > 0
    np.testing.assert_allclose(arr(i.geom.normal), n, rtol=0, atol=1e-12)
    assert i.geom.penetrationDepth == pytest.approx(pen, rel=1e-12, abs=1e-15)
    np.testing.assert_allclose(arr(i.geom.contactPoint), center - n * (r - pen / 2), rtol=0, atol=1e-12)
    assert i.geom.refR1 == pytest.approx(refR1, rel=1e-15)
    assert i.geom.refR2 == pytest.approx(r, rel=1e-15)
    return n, pen


# ====================================================================== facets

TRI = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]


@pytest.mark.parametrize('xy', [(0.05, 0.02), (-0.3, -0.5), (0.4, -0.8)])
def test_sphere_rests_on_facet_face_with_overlap_mg_over_kn(xy):
    r = 0.1
    fid, sid = settle(facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]), r, (xy[0], xy[1], r), (0, 0, -G))
    s = O.bodies[sid].state
    m = sphere_mass(r)
    kn = 4. / 3. * E * r
    i = O.interactions[fid, sid]
    assert i.phys.kn == pytest.approx(kn, rel=1e-12)
    assert i.geom.refR1 == pytest.approx(2 * r) and i.geom.refR2 == pytest.approx(r)
    assert i.geom.penetrationDepth == pytest.approx(m * G / kn, rel=1e-6)
    np.testing.assert_allclose(arr(i.geom.normal), [0, 0, 1], atol=1e-14)
    assert s.pos[2] == pytest.approx(r - m * G / kn, rel=1e-9)
    assert s.pos[0] == pytest.approx(xy[0], abs=1e-12) and s.pos[1] == pytest.approx(xy[1], abs=1e-12)
    assert s.vel.norm() < 1e-9
    # the facet carries the weight: reaction -m·g on it, +m·g (contact) on the sphere
    np.testing.assert_allclose(arr(O.forces.f(fid)), [0, 0, -m * G], rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(arr(O.forces.f(sid)), [0, 0, m * G], rtol=1e-6, atol=1e-9)
    assert arr(i.phys.shearForce) == pytest.approx([0, 0, 0], abs=1e-9)


def test_sphere_pressed_against_facet_from_below_gets_the_reversed_normal():
    r = 0.1
    f = facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)])
    assert arr(f.shape.normal) == pytest.approx([0, 0, 1])
    fid, sid = settle(f, r, (0.05, 0.02, -r), (0, 0, +G))  # "gravity" pushes it up against the facet
    m, kn = sphere_mass(r), 4. / 3. * E * r
    i = O.interactions[fid, sid]
    np.testing.assert_allclose(arr(i.geom.normal), [0, 0, -1], atol=1e-14)
    assert i.geom.penetrationDepth == pytest.approx(m * G / kn, rel=1e-6)
    assert O.bodies[sid].state.pos[2] == pytest.approx(-(r - m * G / kn), rel=1e-9)
    np.testing.assert_allclose(arr(O.forces.f(sid)), [0, 0, -m * G], rtol=1e-6, atol=1e-9)


@pytest.mark.parametrize('center, kind', [
    ((.2, .2, .45), 'face'),
    ((.2, .2, -.45), 'face'),  # from below: reversed normal
    ((.5, -.3, .2), 'edge'),  # beyond the edge y=0
    ((.7, .7, .1), 'edge'),  # beyond the hypotenuse x+y=1
    ((-.2, .4, -.1), 'edge'),  # beyond x=0, below the plane
    ((-.2, -.3, .1), 'vertex'),  # beyond (0,0,0)
    ((1.3, -.1, .2), 'vertex'),  # beyond (1,0,0)
    ((-.1, 1.2, -.3), 'vertex'),  # beyond (0,1,0)
])
def test_facet_contact_geometry_face_edge_vertex(center, kind):
    r = 0.5
    fid, sid = one_step([facet(TRI), sphere(center, r)])
    c = arr(center)
    closest, k = closest_on_triangle(c, [arr(v) for v in TRI])
    assert k == kind
    (i,) = real_interactions()
    assert (i.id1, i.id2) == (fid, sid)
    n, pen = check_contact_geometry(i, c, r, closest, refR1=2 * r)
    if kind == 'face':
        assert abs(n[2]) == pytest.approx(1) and n[2] * c[2] > 0
    # the force on the sphere is Kn·pen along the normal
    kn = 4. / 3. * E * r
    np.testing.assert_allclose(arr(O.forces.f(sid)), kn * pen * n, rtol=1e-12, atol=1e-6)


def test_facet_contact_values_printed_by_the_reference():
    """Penetrations printed by the reference for two of the placements above (same script)."""
    for center, pen in [((.5, -.3, .2), 0.139444872453601), ((-.2, -.3, .1), 0.125834261322606), ((.7, .7, .1), 0.2)]:
        O.reset()
        one_step([facet(TRI), sphere(center, .5)])
        (i,) = real_interactions()
        assert i.geom.penetrationDepth == pytest.approx(pen, rel=1e-12)


def test_tilted_facet_face_contact_along_its_normal():
    verts = [arr(v) for v in [(0, 0, 0), (2, 0, 1), (0, 2, 1)]]
    n = np.cross(verts[1] - verts[0], verts[2] - verts[0])
    n /= np.linalg.norm(n)
    foot = (verts[0] + verts[1] + verts[2]) / 3
    r, gap = 0.3, 0.25
    c = foot + gap * n
    fid, sid = one_step([facet([tuple(v) for v in verts]), sphere(tuple(c), r)])
    np.testing.assert_allclose(arr(O.bodies[fid].shape.normal), n, atol=1e-14)
    (i,) = real_interactions()
    got_n, pen = check_contact_geometry(i, c, r, foot, refR1=2 * r)
    assert pen == pytest.approx(r - gap)
    np.testing.assert_allclose(got_n, n, atol=1e-12)


def test_sphere_beyond_reach_of_a_vertex_has_no_contact():
    one_step([facet(TRI), sphere((1.4, -.4, .2), .5)])  # 0.6 from the vertex (1,0,0)
    assert real_interactions() == []


def test_facet_stiffness_with_two_materials():
    """Facet of E1 = 2e7, ν1 = .2 and sphere of E2 = 5e6, ν2 = .4, r = .3 (R1 = .6, R2 = .3);
    Kn = 2·E1R1·E2R2/(E1R1+E2R2) = 2.6667e6, Ks = 9.6e5, tan φ = tan(min(.3, .4)) (reference:
    kn 2666666.66667, ks 960000, 0.30933624961)."""
    O.materials.append(FrictMat(young=2e7, poisson=.2, density=2000, frictionAngle=.3, label='stiff'))
    O.materials.append(FrictMat(young=5e6, poisson=.4, density=3000, frictionAngle=.4, label='soft'))
    one_step([facet(TRI, material='stiff'), sphere((.2, .2, .25), .3, material='soft')])
    (i,) = real_interactions()
    E1R1, E2R2 = 2e7 * .6, 5e6 * .3
    assert i.phys.kn == pytest.approx(2 * E1R1 * E2R2 / (E1R1 + E2R2), rel=1e-12)
    assert i.phys.kn == pytest.approx(2666666.66667, rel=1e-11)
    assert i.phys.ks == pytest.approx(2 * (.2 * E1R1) * (.4 * E2R2) / (.2 * E1R1 + .4 * E2R2), rel=1e-12)
    assert i.phys.tangensOfFrictionAngle == pytest.approx(math.tan(.3), rel=1e-12)


def shear_after_steps(obstacle, nsteps):
    """A sphere r = .1 overlapping the obstacle (plane z = 0) by .01, held in place (DOFs xyzXY
    blocked; Z is free but gets no torque; blocking all six would make it non-dynamic, and two
    non-dynamic bodies are never paired) with velocity (1,0,0) and angular velocity (0,3,1): the
    shear force after n steps of dt = 1e-4 (friction angle 1.5: no sliding)."""
    O.materials.append(FrictMat(young=E, poisson=NU, density=RHO, frictionAngle=1.5))
    O.engines = engines()
    ids = O.bodies.append([obstacle(), sphere((0, 0, .09), .1)])
    s = O.bodies[ids[1]].state
    s.vel, s.angVel = (1, 0, 0), (0, 3, 1)
    s.blockedDOFs = 'xyzXY'
    O.dt = 1e-4
    O.run(nsteps, True)
    return O.interactions[ids[0], ids[1]], ids


def test_wall_shear_increment_uses_reference_radius_lever_and_overlap_scaling():
    """Wall+sphere (as sphere+sphere): the incident velocity is taken with lever arms refR and the
    translational part scaled by α = (R1+R2)/(R1+R2-pen): u̇ = α·1 - 3·r = 1.05263 - .3; Ks = ν·E·r
    = 3e5 → Fs = -Ks·dt·u̇ = -22.5789 per step (the reference prints -22.5789473684, -45.157...)."""
    i, ids = shear_after_steps(lambda: wall(0, axis=2), 1)
    alpha = .2 / (.2 - .01)
    ud = alpha * 1 - 3 * .1
    assert i.phys.ks == pytest.approx(NU * E * .1)
    assert i.phys.shearForce[0] == pytest.approx(-NU * E * .1 * 1e-4 * ud, rel=1e-9)
    assert i.phys.shearForce[0] == pytest.approx(-22.5789473684, rel=1e-10)
    # the torque on the sphere: contact point .095 below the center
    assert O.forces.t(ids[1])[1] == pytest.approx(.095 * 22.5789473684, rel=1e-9)


@pytest.mark.parametrize('name, obstacle, ks', [
    ('facet', lambda: facet([(-5, -5, 0), (5, -5, 0), (0, 5, 0)]), NU * 4. / 3. * E * .1),
    ('box', lambda: box((0, 0, -1), (5, 5, 1), fixed=True), NU * E * .1),
])
def test_facet_and_box_shear_increment_uses_contact_point_kinematics(name, obstacle, ks):
    """Facet+sphere and box+sphere in the reference: the relative velocity at the contact point
    v + ω×(cp - center), cp - center = (0,0,-(r - pen/2)) = (0,0,-.095): u̇ = 1 - 3·.095 = .715;
    Fs = -Ks·dt·u̇ after one step, twice that after two. Reference: facet -28.6, -57.2;
    box -21.45, -42.9. This engine gives facet -29.379, box -22.579 (α = 1.0345 / 1.0526 and
    lever r instead of r - pen/2)."""
    i, ids = shear_after_steps(obstacle, 1)
    ud = 1 - 3 * .095
    assert i.phys.shearForce[0] == pytest.approx(-ks * 1e-4 * ud, rel=1e-9)
    assert i.phys.shearForce[0] == pytest.approx({'facet': -28.6, 'box': -21.45}[name], rel=1e-9)
    O.step()
    assert i.phys.shearForce[0] == pytest.approx(2 * -ks * 1e-4 * ud, rel=1e-9)


# ====================================================================== walls

@pytest.mark.parametrize('side', [+1, -1])
def test_sphere_rests_on_two_sided_wall_from_either_side(side):
    r = 0.1
    wid, sid = settle(wall(0, axis=2), r, (0.05, 0.02, side * r), (0, 0, -side * G))
    m, kn = sphere_mass(r), E * r
    i = O.interactions[wid, sid]
    assert i.phys.kn == pytest.approx(kn, rel=1e-12)
    assert i.geom.refR1 == pytest.approx(r) and i.geom.refR2 == pytest.approx(r)
    assert i.geom.penetrationDepth == pytest.approx(m * G / kn, rel=1e-6)
    np.testing.assert_allclose(arr(i.geom.normal), [0, 0, side], atol=1e-14)
    # contact point: the center projected on the wall
    np.testing.assert_allclose(arr(i.geom.contactPoint), [0.05, 0.02, 0], atol=1e-12)
    assert O.bodies[sid].state.pos[2] == pytest.approx(side * (r - m * G / kn), rel=1e-9)
    np.testing.assert_allclose(arr(O.forces.f(wid)), [0, 0, -side * m * G], rtol=1e-6, atol=1e-9)


# (sense, z of the center of a sphere r = .5 at x=.3, y=.1, wall z = 0) -> (normal z, penetration)
# or None; printed by the reference for
#   O.bodies.append([wall(0, axis=2, sense=sense), sphere((.3, .1, z), .5)]); O.step()
# A one-sided wall pushes along +sense whichever side the center is on; the penetration is
# r - |distance| in both cases.
WALL_SENSE_REFERENCE = {
    (1, .45): (1, .05), (1, .2): (1, .3), (1, -.2): (1, .3), (1, -.45): (1, .05), (1, .55): None, (1, -.55): None,
    (-1, .45): (-1, .05), (-1, .2): (-1, .3), (-1, -.2): (-1, .3), (-1, -.45): (-1, .05), (-1, .55): None,
    (-1, -.55): None,
    (0, .45): (1, .05), (0, .2): (1, .3), (0, -.2): (-1, .3), (0, -.45): (-1, .05), (0, .55): None, (0, -.55): None,
}


@pytest.mark.parametrize('sense, z', sorted(WALL_SENSE_REFERENCE))
def test_wall_sense_normal_and_penetration_as_in_reference(sense, z):
    r = .5
    wid, sid = one_step([wall(0, axis=2, sense=sense), sphere((.3, .1, z), r)])
    expected = WALL_SENSE_REFERENCE[(sense, z)]
    if expected is None:
        assert real_interactions() == []
        return
    nz, pen = expected
    (i,) = real_interactions()
    np.testing.assert_allclose(arr(i.geom.normal), [0, 0, nz], atol=0)
    assert i.geom.penetrationDepth == pytest.approx(pen, rel=1e-12)
    np.testing.assert_allclose(arr(i.geom.contactPoint), [.3, .1, 0], atol=1e-15)
    assert i.phys.kn == pytest.approx(E * r)
    np.testing.assert_allclose(arr(O.forces.f(sid)), [0, 0, nz * E * r * pen], rtol=1e-12)


@pytest.mark.parametrize('axis', [0, 1, 2])
def test_wall_on_each_axis(axis):
    r, d = .2, .15
    c = [1., 2., 3.]
    c[axis] = -4 + d  # the wall through -4 along `axis`
    wid, sid = one_step([wall(-4, axis=axis), sphere(tuple(c), r)])
    (i,) = real_interactions()
    n = [0, 0, 0]
    n[axis] = 1
    np.testing.assert_allclose(arr(i.geom.normal), n, atol=0)
    assert i.geom.penetrationDepth == pytest.approx(r - d, rel=1e-12)
    cp = list(c)
    cp[axis] = -4
    np.testing.assert_allclose(arr(i.geom.contactPoint), cp, atol=1e-14)


# ====================================================================== boxes

def test_sphere_rests_on_box_top_face_with_overlap_mg_over_kn():
    r = 0.1
    bid, sid = settle(box((0, 0, -.5), (1, 1, .5), fixed=True), r, (0.05, 0.02, r), (0, 0, -G))
    m, kn = sphere_mass(r), E * r
    i = O.interactions[bid, sid]
    assert i.phys.kn == pytest.approx(kn, rel=1e-12)
    assert i.geom.refR1 == pytest.approx(r) and i.geom.refR2 == pytest.approx(r)
    assert i.geom.penetrationDepth == pytest.approx(m * G / kn, rel=1e-6)
    np.testing.assert_allclose(arr(i.geom.normal), [0, 0, 1], atol=1e-14)
    assert O.bodies[sid].state.pos[2] == pytest.approx(r - m * G / kn, rel=1e-9)
    np.testing.assert_allclose(arr(O.forces.f(bid)), [0, 0, -m * G], rtol=1e-6, atol=1e-9)


def closest_on_box(p, center, ext, q):
    """Closest point of a (solid) box to an outside point: clamp in the box's own frame."""
    qc = q.conjugate()
    local = arr(qc * Vector3(*(p - center)))
    clamped = np.clip(local, -ext, ext)
    return center + arr(q * Vector3(*clamped))


BOX_CASES = {
    # name: (box center, extents, orientation, sphere center)
    'top': ((0, 0, 0), (1, 1, 1), Quaternion.Identity, (.2, .3, 1.4)),
    'side': ((0, 0, 0), (1, 1, 1), Quaternion.Identity, (-1.45, .3, .2)),
    'edge': ((0, 0, 0), (1, 1, 1), Quaternion.Identity, (1.2, .3, 1.3)),
    'corner': ((0, 0, 0), (1, 1, 1), Quaternion.Identity, (1.2, 1.2, 1.2)),
    'rotated-z': ((0, 0, 0), (1, 1, 1), Quaternion((0, 0, 1), math.pi / 4), (1.6, 0, .3)),  # its vertical edge
    'rotated': ((0, 0, 0), (1, .5, .7), Quaternion(Vector3(1, 1, 0).normalized(), .5), (.3, .2, 1.1)),
    'offset-rotated': ((1, -2, .5), (.3, .6, .9), Quaternion(Vector3(1, 2, 3).normalized(), 1.2), (1.5, -1.6, 1.1)),
}
# penetrations printed by the reference for the same placements (sphere r = .5)
BOX_REFERENCE_PEN = {'top': .1, 'side': .05, 'edge': 0.139444872453601, 'corner': 0.153589838486225,
                     'rotated-z': 0.314213562373095, 'rotated': 0.190499522694297}


@pytest.mark.parametrize('name', sorted(BOX_CASES))
def test_box_contact_normal_from_closest_box_point(name):
    bc, ext, q, c = BOX_CASES[name]
    r = .5
    bid, sid = one_step([box(bc, ext, orientation=q, fixed=True), sphere(c, r)])
    closest = closest_on_box(arr(c), arr(bc), arr(ext), q)
    (i,) = real_interactions()
    n, pen = check_contact_geometry(i, arr(c), r, closest, refR1=r)
    if name in BOX_REFERENCE_PEN:
        assert pen == pytest.approx(BOX_REFERENCE_PEN[name], rel=1e-12)
    np.testing.assert_allclose(arr(O.forces.f(sid)), E * r * pen * n, rtol=1e-9, atol=1e-6)


def test_box_corner_normal_is_the_diagonal():
    one_step([box((0, 0, 0), (1, 1, 1), fixed=True), sphere((1.2, 1.2, 1.2), .5)])
    (i,) = real_interactions()
    np.testing.assert_allclose(arr(i.geom.normal), [3 ** -.5] * 3, atol=1e-14)
    assert i.geom.penetrationDepth == pytest.approx(.5 - .2 * 3 ** .5, rel=1e-12)


def test_box_rotated_45_degrees_is_touched_by_its_edge():
    """Box of half-size 1 turned by 45° about z: its vertical edge is at x = √2; a sphere r = .5
    at x = 1.6 overlaps it by √2 + .5 - 1.6, normal +x."""
    one_step([box((0, 0, 0), (1, 1, 1), orientation=Quaternion((0, 0, 1), math.pi / 4), fixed=True),
              sphere((1.6, 0, .3), .5)])
    (i,) = real_interactions()
    assert i.geom.penetrationDepth == pytest.approx(2 ** .5 + .5 - 1.6, rel=1e-12)
    np.testing.assert_allclose(arr(i.geom.normal), [1, 0, 0], atol=1e-14)


def test_sphere_inside_reach_of_box_only_within_radius():
    one_step([box((0, 0, 0), (1, 1, 1), fixed=True), sphere((1.3, 1.3, 1.3), .5)])  # .52 from the corner
    assert real_interactions() == []


# ====================================================================== construction helpers

def test_utils_facet_position_vertices_and_defaults():
    vs = [(1, 0, 0), (4, 0, 0), (1, 4, 0)]  # 3-4-5 right triangle, inradius 1
    f = facet(vs)
    assert isinstance(f.shape, Facet)
    # inscribed-circle center: at distance 1 from both legs
    np.testing.assert_allclose(arr(f.state.pos), [2, 1, 0], atol=1e-15)
    absolute = [arr(v) + arr(f.state.pos) for v in f.shape.vertices]
    np.testing.assert_allclose(absolute, np.array(vs, dtype=float), atol=1e-15)
    np.testing.assert_allclose(arr(f.shape.normal), [0, 0, 1], atol=1e-15)
    assert f.shape.area == pytest.approx(6)
    assert not f.dynamic and f.shape.wire
    assert f.state.mass == 0
    assert f.material.young == E and f.material.density == RHO  # the default material
    # the unit right triangle of the reference: position (1-1/√2)(1,1,0)
    g = facet(TRI)
    np.testing.assert_allclose(arr(g.state.pos), [1 - 2 ** -.5, 1 - 2 ** -.5, 0], atol=1e-15)
    assert g.shape.area == pytest.approx(.5)


def test_utils_facet_keywords():
    O.materials.append(FrictMat(young=2e7, label='stiff'))
    O.materials.append(FrictMat(young=5e6, label='soft'))
    f = facet(TRI, color=(0, 0, 1), material=O.materials[1], mask=3, fixed=False, wire=False)
    assert arr(f.shape.color) == pytest.approx([0, 0, 1])
    assert f.material.label == 'soft' and f.mask == 3 and f.dynamic and not f.shape.wire
    assert facet(TRI, material='stiff').material.label == 'stiff'
    assert facet(TRI, material=1).material.label == 'soft'
    assert facet(TRI).material.label == 'soft'  # the last defined one


@pytest.mark.parametrize('axis', [0, 1, 2, 'x', 'y', 'z'])
def test_utils_wall_scalar_position_and_axis(axis):
    """A scalar position is the coordinate along the axis (the others 0). The axis may be given as
    'x', 'y', 'z' in this engine (the reference 2023.02a accepts only 0, 1, 2)."""
    w = wall(2.5, axis=axis, sense=-1, color=(.5, .5, .5), mask=4)
    a = axis if isinstance(axis, int) else 'xyz'.index(axis)
    p = [0, 0, 0]
    p[a] = 2.5
    assert isinstance(w.shape, Wall)
    np.testing.assert_allclose(arr(w.state.pos), p)
    assert w.shape.axis == a and w.shape.sense == -1
    assert not w.dynamic and w.state.mass == 0 and w.mask == 4
    assert arr(w.shape.color) == pytest.approx([.5, .5, .5])


def test_utils_wall_vector_position_and_material():
    O.materials.append(FrictMat(young=2e7, label='stiff'))
    w = wall((1, 2, 3), axis=1, material='stiff')
    np.testing.assert_allclose(arr(w.state.pos), [1, 2, 3])
    assert w.shape.axis == 1 and w.shape.sense == 0 and w.material.label == 'stiff'


def test_utils_box_mass_and_inertia():
    O.materials.append(FrictMat(density=3000, label='soft'))
    ex, ey, ez = .5, .25, .125
    b = box((1, 2, 3), (ex, ey, ez), material='soft', color=(.1, .2, .3), mask=2, wire=True)
    m = 8 * ex * ey * ez * 3000
    assert b.state.mass == pytest.approx(m, rel=1e-14)
    assert b.state.mass == pytest.approx(375)  # the reference's number
    a, bb, c = 2 * ex, 2 * ey, 2 * ez
    np.testing.assert_allclose(arr(b.state.inertia), [m / 12 * (bb ** 2 + c ** 2), m / 12 * (a ** 2 + c ** 2),
                                                      m / 12 * (a ** 2 + bb ** 2)], rtol=1e-14)
    np.testing.assert_allclose(arr(b.state.inertia), [9.765625, 33.203125, 39.0625], rtol=1e-14)
    assert isinstance(b.shape, Box) and arr(b.shape.extents) == pytest.approx([ex, ey, ez])
    assert b.dynamic and b.shape.wire and b.mask == 2 and b.material.label == 'soft'
    np.testing.assert_allclose(arr(b.state.pos), [1, 2, 3])


def test_utils_box_orientation_and_fixed():
    q = Quaternion(Vector3(0, 1, 0), .3)
    b = box((0, 0, 0), (.1, .2, .3), orientation=q, fixed=True)
    assert not b.dynamic
    np.testing.assert_allclose(arr(b.state.ori * Vector3(1, 0, 0)), [math.cos(.3), 0, -math.sin(.3)], atol=1e-15)
    assert b.state.mass == pytest.approx(48)  # 8·.1·.2·.3·1000: fixed bodies keep their mass


def test_utils_box_of_zero_extent_is_a_plate():
    """A zero half-size is accepted, as in the reference (its 2D examples make plates so:
    box(extents=(30, 0, 30))); a negative one is refused (the reference gives a negative mass)."""
    b = box((0, 0, 0), (30, 0, 30), fixed=True)
    assert b.state.mass == 0 and arr(b.shape.extents) == pytest.approx([30, 0, 30])
    assert arr(box((0, 0, 0), (0, 0, 0)).shape.extents) == pytest.approx([0, 0, 0])
    with pytest.raises(ValueError, match='non-negative'):
        box((0, 0, 0), (1, -1, 1))
    with pytest.raises(ValueError, match='extents'):
        Box(extents=(1, -1, 1))


# The sphere's center inside the box, exactly on a mid-plane (a tie between two opposite faces): the
# reference's output for each of these (box half-sizes, center): normal, depth, contact point
BOX_TIES_REFERENCE = [
    ((1, 1, 1), (0, 0, 0), (-1, 0, 0), 1.3, (-0.35, 0, 0)),
    ((1, 0.5, 1), (0, 0, 0), (0, -1, 0), 0.8, (0, -0.1, 0)),
    ((1, 1, 0.5), (0, 0, 0), (0, 0, -1), 0.8, (0, 0, -0.1)),
    ((1, 0, 1), (0, 0, 0), (0, -1, 0), 0.3, (0, 0.15, 0)),
    ((0, 1, 1), (0, 0, 0), (-1, 0, 0), 0.3, (0.15, 0, 0)),
    ((1, 0, 1), (0.2, 0, 0.3), (0, -1, 0), 0.3, (0.2, 0.15, 0.3)),
]


@pytest.mark.parametrize('ext,center,normal,depth,point', BOX_TIES_REFERENCE)
def test_box_sphere_tie_on_a_mid_plane_as_in_reference(ext, center, normal, depth, point):
    one_step([box((0, 0, 0), ext, fixed=True), sphere(center, 0.3)], dt=1e-9)
    g = O.interactions[0, 1].geom
    np.testing.assert_allclose(arr(g.normal), normal, atol=1e-15)
    assert g.penetrationDepth == pytest.approx(depth, rel=1e-12)
    np.testing.assert_allclose(arr(g.contactPoint), point, atol=1e-12)


# aabbWalls([(0,0,0),(1,1,1)], thickness=.1), printed by the reference: (pos, extents), all
# non-dynamic, mass 225 (default density 1000)
AABB_WALLS_REFERENCE = [
    ((-0.05, 0.5, 0.5), (0.05, 0.75, 0.75)), ((1.05, 0.5, 0.5), (0.05, 0.75, 0.75)),
    ((0.5, -0.05, 0.5), (0.75, 0.05, 0.75)), ((0.5, 1.05, 0.5), (0.75, 0.05, 0.75)),
    ((0.5, 0.5, -0.05), (0.75, 0.75, 0.05)), ((0.5, 0.5, 1.05), (0.75, 0.75, 0.05)),
]


def test_aabbWalls_positions_and_extents_as_in_reference():
    ws = aabbWalls([(0, 0, 0), (1, 1, 1)], thickness=.1)
    assert len(ws) == 6
    for w, (pos, ext) in zip(ws, AABB_WALLS_REFERENCE):
        assert isinstance(w.shape, Box)
        np.testing.assert_allclose(arr(w.state.pos), pos, atol=1e-15)
        np.testing.assert_allclose(arr(w.shape.extents), ext, atol=1e-15)
        assert not w.dynamic
        assert w.state.mass == pytest.approx(225, rel=1e-14)
    assert utils.aabbWall is aabbWalls or utils.aabbWall([(0, 0, 0), (1, 1, 1)], thickness=.1)


def test_aabbWalls_oversize_and_keywords_as_in_reference():
    """aabbWalls(thickness=.2, oversizeFactor=2, material='stiff', color=(1,1,0)) around three
    spheres (extrema (-.5,-.5,-.5), (2.25,4,5)), printed by the reference."""
    O.materials.append(FrictMat(young=2e7, poisson=.2, density=2000, frictionAngle=.3, label='stiff'))
    O.bodies.append([sphere((0, 0, 0), .5), sphere((2, 1, 0), .25), sphere((1, 3, 4), 1)])
    ref = [((-0.6, 1.75, 2.25), (0.1, 4.5, 5.5), 39600), ((2.35, 1.75, 2.25), (0.1, 4.5, 5.5), 39600),
           ((0.875, -0.6, 2.25), (2.75, 0.1, 5.5), 24200), ((0.875, 4.1, 2.25), (2.75, 0.1, 5.5), 24200),
           ((0.875, 1.75, -0.6), (2.75, 4.5, 0.1), 19800), ((0.875, 1.75, 5.1), (2.75, 4.5, 0.1), 19800)]
    ws = aabbWalls(thickness=.2, oversizeFactor=2, material='stiff', color=(1, 1, 0))
    for w, (pos, ext, mass) in zip(ws, ref):
        np.testing.assert_allclose(arr(w.state.pos), pos, atol=1e-14)
        np.testing.assert_allclose(arr(w.shape.extents), ext, atol=1e-14)
        assert w.state.mass == pytest.approx(mass, rel=1e-12)
        assert w.material.label == 'stiff' and arr(w.shape.color) == pytest.approx([1, 1, 0]) and not w.dynamic


def test_aabbWalls_default_thickness_around_spheres():
    """Thickness 0 (the default): the reference makes boxes with a zero extent; this engine gives
    them a thickness of 1e-9 of their size (a zero-size Box is degenerate). Positions and the
    other extents as the reference printed."""
    O.bodies.append([sphere((0, 0, 0), .5), sphere((2, 1, 0), .25), sphere((1, 3, 4), 1)])
    ref = [((-0.5, 1.75, 2.25), (0.0, 3.375, 4.125)), ((2.25, 1.75, 2.25), (0.0, 3.375, 4.125)),
           ((0.875, -0.5, 2.25), (2.0625, 0.0, 4.125)), ((0.875, 4.0, 2.25), (2.0625, 0.0, 4.125)),
           ((0.875, 1.75, -0.5), (2.0625, 3.375, 0.0)), ((0.875, 1.75, 5.0), (2.0625, 3.375, 0.0))]
    ws = aabbWalls()
    for k, (w, (pos, ext)) in enumerate(zip(ws, ref)):
        np.testing.assert_allclose(arr(w.state.pos), pos, atol=1e-14)
        np.testing.assert_allclose(arr(w.shape.extents), ext, atol=1e-8)
        assert not w.dynamic


def popcount(m):
    return bin(m).count('1')


@pytest.mark.parametrize('mask', [63, 31, 1, 2, 4, 8, 16, 32, 5, 48, 0])
def test_facetBox_count(mask):
    fs = geom.facetBox((0, 0, 0), (1, 1, 1), wallMask=mask)
    assert len(fs) == 2 * popcount(mask)
    if mask == 63:
        assert len(fs) == 12
    if mask == 31:
        assert len(fs) == 10


# facetBox((.5,.5,.5), (.5,.5,.5)) in the reference: (position, normal) of the 12 facets in order
FACETBOX_REFERENCE = [
    ((0.0, 0.7071067811865475, 0.2928932188134525), (1, 0, 0)), ((0.0, 0.2928932188134525, 0.7071067811865475), (1, 0, 0)),
    ((1.0, 0.2928932188134525, 0.7071067811865475), (-1, 0, 0)), ((1.0, 0.7071067811865475, 0.2928932188134525), (-1, 0, 0)),
    ((0.2928932188134525, 0.0, 0.7071067811865475), (0, 1, 0)), ((0.7071067811865475, 0.0, 0.2928932188134525), (0, 1, 0)),
    ((0.7071067811865475, 1.0, 0.2928932188134525), (0, -1, 0)), ((0.2928932188134525, 1.0, 0.7071067811865475), (0, -1, 0)),
    ((0.7071067811865475, 0.2928932188134525, 0.0), (0, 0, 1)), ((0.2928932188134525, 0.7071067811865475, 0.0), (0, 0, 1)),
    ((0.2928932188134525, 0.7071067811865475, 1.0), (0, 0, -1)), ((0.7071067811865475, 0.2928932188134525, 1.0), (0, 0, -1)),
]


def test_facetBox_facets_as_in_reference():
    fs = geom.facetBox((.5, .5, .5), (.5, .5, .5))
    for f, (pos, n) in zip(fs, FACETBOX_REFERENCE):
        np.testing.assert_allclose(arr(f.state.pos), pos, atol=1e-15)
        np.testing.assert_allclose(arr(f.shape.normal), n, atol=1e-15)
        assert not f.dynamic and f.shape.wire


@pytest.mark.parametrize('orientation', [Quaternion.Identity, Quaternion(Vector3(1, 2, 3).normalized(), .7)])
def test_facetBox_vertices_on_the_box_surface_and_normals_inward(orientation):
    c, ext = arr((1, -2, 3)), arr((.4, .7, 1.1))
    fs = geom.facetBox(tuple(c), tuple(ext), orientation=orientation)
    qc = orientation.conjugate()
    area = 0
    for f in fs:
        local = [arr(qc * Vector3(*(arr(v) + arr(f.state.pos) - c))) for v in f.shape.vertices]
        for p in local:
            # a corner of the box: |each local coordinate| = the extent
            np.testing.assert_allclose(np.abs(p), ext, rtol=1e-12)
        # all three on one face: one coordinate the same for all
        face_axes = [a for a in range(3) if abs(local[0][a] - local[1][a]) < 1e-12 and abs(local[0][a] - local[2][a]) < 1e-12]
        assert len(face_axes) == 1
        a = face_axes[0]
        nl = arr(qc * f.shape.normal)
        expected = np.zeros(3)
        expected[a] = -np.sign(local[0][a])  # toward the center
        np.testing.assert_allclose(nl, expected, atol=1e-12)
        area += f.shape.area
    assert area == pytest.approx(8 * (ext[0] * ext[1] + ext[1] * ext[2] + ext[0] * ext[2]), rel=1e-12)


def test_facetBox_keywords_passed_through():
    O.materials.append(FrictMat(young=5e6, label='soft'))
    fs = geom.facetBox((0, 0, 0), (1, 2, 3), color=(1, 0, 0), material='soft', mask=6, wire=False, fixed=False)
    assert len(fs) == 12
    for f in fs:
        assert arr(f.shape.color) == pytest.approx([1, 0, 0])
        assert f.material.label == 'soft' and f.mask == 6 and not f.shape.wire and f.dynamic and f.state.mass == 0


@pytest.mark.parametrize('mask, count', [(7, 40), (4, 20), (1, 10), (2, 10), (3, 20), (6, 30), (5, 30)])
def test_facetCylinder_count(mask, count):
    assert len(geom.facetCylinder((0, 0, 0), 1, 2, wallMask=mask, segmentsNumber=10)) == count


def cylinder_expected(center, R, height, n):
    """The facets of a closed cylinder around z, by hand (as the reference triangulates them):
    per segment [a, b], the top cap (Ctop, P(b), P(a)), the bottom cap (Cbot, P(a), P(b)) and the
    side (P(b,h), P(b,-h), P(a,-h)), (P(a,-h), P(a,h), P(b,h)). Returned as the triangles' vertex
    sets with the inward normal."""
    c = arr(center)
    h = height / 2

    def P(a, z):
        return c + np.array([R * math.cos(a), R * math.sin(a), z])

    out = []
    for i in range(n):
        a, b = 2 * math.pi * i / n, 2 * math.pi * (i + 1) / n
        mid = (a + b) / 2
        inward = -np.array([math.cos(mid), math.sin(mid), 0])
        out.append(([c + [0, 0, h], P(b, h), P(a, h)], np.array([0, 0, -1.])))
        out.append(([c - [0, 0, h], P(a, -h), P(b, -h)], np.array([0, 0, 1.])))
        out.append(([P(b, h), P(b, -h), P(a, -h)], inward))
        out.append(([P(a, -h), P(a, h), P(b, h)], inward))
    return out


def incenter(vs):
    a, b, c = vs
    la, lb, lc = np.linalg.norm(b - c), np.linalg.norm(c - a), np.linalg.norm(a - b)
    return (la * a + lb * b + lc * c) / (la + lb + lc)


def test_facetCylinder_vertices_radius_height_and_inward_normals():
    center, R, H, n = (1, 2, 3), 2, 4, 10
    fs = geom.facetCylinder(center, R, H, segmentsNumber=n)
    expected = cylinder_expected(center, R, H, n)
    assert len(fs) == len(expected) == 40
    used = set()
    for f in fs:
        verts = [arr(v) + arr(f.state.pos) for v in f.shape.vertices]
        for v in verts:
            rho = math.hypot(v[0] - 1, v[1] - 2)
            assert rho == pytest.approx(R, rel=1e-12) or rho < 1e-12  # rim or cap center
            assert abs(v[2] - 3) == pytest.approx(H / 2, rel=1e-12)
        # the same triangle as one expected (in any order of its vertices), at its incenter
        k = [j for j, (ev, en) in enumerate(expected)
             if all(min(np.linalg.norm(v - e) for e in ev) < 1e-12 for v in verts)]
        assert len(k) == 1 and k[0] not in used
        used.add(k[0])
        np.testing.assert_allclose(arr(f.state.pos), incenter(expected[k[0]][0]), atol=1e-12)
        # caps: -z on top, +z at the bottom; sides: horizontal, toward the axis (the bisector)
        np.testing.assert_allclose(arr(f.shape.normal), expected[k[0]][1], atol=1e-12)
    assert len(used) == 40


def test_facetCylinder_facet_order_as_in_reference():
    fs = geom.facetCylinder((1, 2, 3), 2, 4, segmentsNumber=10)
    expected = cylinder_expected((1, 2, 3), 2, 4, 10)
    for f, (ev, en) in zip(fs, expected):
        np.testing.assert_allclose(arr(f.state.pos), incenter(ev), atol=1e-12)


# (position, normal) of the facets of facetCylinder((1,2,3), 2, 4, **kw) printed by the reference
# (10 decimals), compared as sets (the order is tested above)
CYL_REFERENCE = {
    'sector': (dict(angleRange=(0, math.pi), segmentsNumber=4, wallMask=7), [
        (2.2346331353, 2.5114017892, 5.0, 0, 0, -1), (2.2346331353, 2.5114017892, 1.0, 0, 0, 1),
        (2.6529781455, 2.8377848676, 1.6239219232, -0.9238795325, -0.3826834324, 0),
        (2.7612354169, 2.5764286947, 4.3760780768, -0.9238795325, -0.3826834324, 0),
        (1.5114017892, 3.2346331353, 5.0, 0, 0, -1), (1.5114017892, 3.2346331353, 1.0, 0, 0, 1),
        (1.5764286947, 3.7612354169, 1.6239219232, -0.3826834324, -0.9238795325, 0),
        (1.8377848676, 3.6529781455, 4.3760780768, -0.3826834324, -0.9238795325, 0),
        (0.4885982108, 3.2346331353, 5.0, 0, 0, -1), (0.4885982108, 3.2346331353, 1.0, 0, 0, 1),
        (0.1622151324, 3.6529781455, 1.6239219232, 0.3826834324, -0.9238795325, 0),
        (0.4235713053, 3.7612354169, 4.3760780768, 0.3826834324, -0.9238795325, 0),
        (-0.2346331353, 2.5114017892, 5.0, 0, 0, -1), (-0.2346331353, 2.5114017892, 1.0, 0, 0, 1),
        (-0.7612354169, 2.5764286947, 1.6239219232, 0.9238795325, -0.3826834324, 0),
        (-0.6529781455, 2.8377848676, 4.3760780768, 0.9238795325, -0.3826834324, 0)]),
    'closeGap': (dict(angleRange=(0, math.pi / 2), segmentsNumber=3, wallMask=4, closeGap=True), [
        (2.8489688289, 2.5636560040, 1.4517365455, -0.9659258263, -0.2588190451, 0),
        (2.8830819787, 2.4363439960, 4.5482634545, -0.9659258263, -0.2588190451, 0),
        (2.3194259746, 3.4126248329, 1.4517365455, -0.7071067812, -0.7071067812, 0),
        (2.4126248329, 3.3194259746, 4.5482634545, -0.7071067812, -0.7071067812, 0),
        (1.4363439960, 3.8830819787, 1.4517365455, -0.2588190451, -0.9659258263, 0),
        (1.5636560040, 3.8489688289, 4.5482634545, -0.2588190451, -0.9659258263, 0),
        (2.2360679775, 2.0, 1.7639320225, 0, 1, 0), (1.7639320225, 2.0, 4.2360679775, 0, 1, 0),
        (1.0, 2.7639320225, 1.7639320225, 1, 0, 0), (1.0, 3.2360679775, 4.2360679775, 1, 0, 0)]),
    'rings': (dict(radiusTopInner=.5, radiusBottomInner=.3, segmentsNumber=5, wallMask=3), [
        (1.5910067448, 2.1786107935, 5.0, 0, 0, 1), (1.7888087189, 2.8238838217, 5.0, 0, 0, 1),
        (1.3620768440, 2.1218326661, 1.0, 0, 0, 1), (1.8043690322, 2.7256398696, 1.0, 0, 0, 1),
        (1.0127621689, 2.6172745864, 5.0, 0, 0, 1), (0.4601952221, 3.0047957745, 5.0, 0, 0, 1),
        (0.9960181470, 2.3820039062, 1.0, 0, 0, 1), (0.5584391743, 2.9892354611, 1.0, 0, 0, 1),
        (0.4168807093, 2.2028858813, 5.0, 0, 0, 1), (-0.1224264189, 1.7971141187, 5.0, 0, 0, 1),
        (0.6354622356, 2.1142587317, 1.0, 0, 0, 1), (-0.0772686306, 1.8857412683, 1.0, 0, 0, 1),
        (0.6268502899, 1.5081157841, 5.0, 0, 0, 1), (0.8461071011, 0.8698138550, 5.0, 0, 0, 1),
        (0.7786851244, 1.6886118735, 1.0, 0, 0, 1), (0.7757721970, 0.9401487592, 1.0, 0, 0, 1),
        (1.3525000870, 1.4931129547, 5.0, 0, 0, 1), (2.0273153767, 1.5043924301, 5.0, 0, 0, 1),
        (1.2277576491, 1.6932928224, 1.0, 0, 0, 1), (1.9386882271, 1.4592346419, 1.0, 0, 0, 1)]),
    'oriented': (dict(orientation=Quaternion((1, 0, 0), math.pi / 2), segmentsNumber=4), [
        (1.5857864376, 0.0, 3.5857864376, 0, 1, 0), (1.5857864376, 4.0, 3.5857864376, 0, -1, 0),
        (1.6821627548, 3.0352761804, 4.3178372452, -0.7071067812, 0, -0.7071067812),
        (2.3178372452, 0.9647238196, 3.6821627548, -0.7071067812, 0, -0.7071067812),
        (0.4142135624, 0.0, 3.5857864376, 0, 1, 0), (0.4142135624, 4.0, 3.5857864376, 0, -1, 0),
        (-0.3178372452, 3.0352761804, 3.6821627548, 0.7071067812, 0, -0.7071067812),
        (0.3178372452, 0.9647238196, 4.3178372452, 0.7071067812, 0, -0.7071067812),
        (0.4142135624, 0.0, 2.4142135624, 0, 1, 0), (0.4142135624, 4.0, 2.4142135624, 0, -1, 0),
        (0.3178372452, 3.0352761804, 1.6821627548, 0.7071067812, 0, 0.7071067812),
        (-0.3178372452, 0.9647238196, 2.3178372452, 0.7071067812, 0, 0.7071067812),
        (1.5857864376, 0.0, 2.4142135624, 0, 1, 0), (1.5857864376, 4.0, 2.4142135624, 0, -1, 0),
        (2.3178372452, 3.0352761804, 2.3178372452, -0.7071067812, 0, 0.7071067812),
        (1.6821627548, 0.9647238196, 1.6821627548, -0.7071067812, 0, 0.7071067812)]),
}


def check_cylinder_as_set(name):
    kw, ref = CYL_REFERENCE[name]
    fs = geom.facetCylinder((1, 2, 3), 2, 4, **kw)
    assert len(fs) == len(ref)
    got = sorted(tuple(round(x, 8) + 0.0 for x in list(f.state.pos) + list(f.shape.normal)) for f in fs)
    want = sorted(tuple(round(x, 8) + 0.0 for x in r) for r in ref)
    np.testing.assert_allclose(np.array(got), np.array(want), atol=2e-8)


@pytest.mark.parametrize('name', ['sector', 'oriented'])
def test_facetCylinder_sector_and_orientation_as_in_reference(name):
    check_cylinder_as_set(name)


def test_facetCylinder_closeGap_as_in_reference():
    check_cylinder_as_set('closeGap')


def test_facetCylinder_rings_as_in_reference():
    check_cylinder_as_set('rings')


def test_facetCylinder_keywords_passed_through():
    O.materials.append(FrictMat(young=2e7, label='stiff'))
    O.materials.append(FrictMat(young=5e6, label='soft'))
    fs = geom.facetCylinder((0, 0, 0), 1, 2, color=(0, 1, 0), material=0, mask=5, segmentsNumber=6)
    assert len(fs) == 24
    for f in fs:
        assert arr(f.shape.color) == pytest.approx([0, 1, 0])
        assert f.material.label == 'stiff' and f.mask == 5 and f.shape.wire and not f.dynamic
    m = O.materials['soft']
    fs = geom.facetCylinder((0, 0, 0), 1, 2, material=m, fixed=False, wire=False, segmentsNumber=3, wallMask=4)
    assert len(fs) == 6 and all(f.material is m or f.material.label == 'soft' for f in fs)
    assert all(f.dynamic and not f.shape.wire for f in fs)


# ====================================================================== a sphere in a facetBox

def test_sphere_dropped_into_facetBox_stays_inside_with_bounded_energy():
    """A sphere (r = .1) thrown sideways (2, -1.5, 0) m/s into an open-top unit facetBox bounces on
    the faces, edges and the floor for 4 s (no damping, friction .5). It never leaves the box
    (the center keeps at r - .01 from every face), and its mechanical energy (kinetic + m·g·z +
    the elastic energy of the contacts) never exceeds the initial one by more than 2 % (the
    leapfrog error of the short contacts at dt = PWaveTimeStep/10)."""
    O.engines = engines(gravity=(0, 0, -G))
    O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))
    r = .1
    sid = O.bodies.append(sphere((.3, .6, .8), r))
    b = O.bodies[sid]
    b.state.vel = (2, -1.5, 0)
    O.dt = .1 * PWaveTimeStep()
    m = b.state.mass

    def energy():
        el = sum(.5 * i.phys.normalForce.squaredNorm() / i.phys.kn + .5 * i.phys.shearForce.squaredNorm() / i.phys.ks
                 for i in O.interactions if i.isReal)
        return kineticEnergy() + m * G * b.state.pos[2] + el

    e0 = energy()
    assert e0 == pytest.approx(.5 * m * 6.25 + m * G * .8, rel=1e-12)
    emax, lo, hi, touched = e0, np.full(3, 9.), np.full(3, -9.), set()
    for k in range(40000):
        O.step()
        p = arr(b.state.pos)
        lo, hi = np.minimum(lo, p), np.maximum(hi, p)
        if k % 10 == 0:
            emax = max(emax, energy())
            touched |= {i.id1 for i in O.interactions if i.isReal}
    assert (lo[:2] > r - .01).all() and (hi[:2] < 1 - r + .01).all() and lo[2] > r - .01
    assert emax <= 1.02 * e0
    assert energy() < e0  # friction has dissipated some
    # it has hit the floor and several side faces
    faces = {O.bodies[i].shape.normal.dot(Vector3(0, 0, 1)) > .5 for i in touched}
    assert True in faces and False in faces and len(touched) >= 4


# facetBox with one zero extent in the reference (Yade 2023.02a): one rectangle, two facets with the
# normal along + the flat axis, whatever wallMask; two zero extents are refused. Printed by
#   for ext, mask in [((1,1,0),63), ((1,0,1),63), ((0,1,1),63), ((1,1,0),16), ((1,1,0),15)]:
#       f = geom.facetBox((0,0,0), ext, wallMask=mask)
#       print(len(f), [(v[1]-v[0]).cross(v[2]-v[0]) for v in (facet's global vertices)])
# the z-flat box's facets having the vertices (-1,-1,0) (1,-1,0) (1,1,0) and (-1,-1,0) (1,1,0) (-1,1,0).
@pytest.mark.parametrize("ext,mask,normal", [((1, 1, 0), 63, (0, 0, 4)), ((1, 0, 1), 63, (0, 4, 0)),
                                             ((0, 1, 1), 63, (4, 0, 0)), ((1, 1, 0), 16, (0, 0, 4)),
                                             ((1, 1, 0), 15, (0, 0, 4))])
def test_flat_facetBox_is_one_rectangle_as_in_the_reference(ext, mask, normal):
    fs = geom.facetBox((0, 0, 0), ext, wallMask=mask)
    assert len(fs) == 2
    for b in fs:
        v = [b.state.pos + b.state.ori * w for w in b.shape.vertices]
        n = (v[1] - v[0]).cross(v[2] - v[0])
        assert (n - Vector3(*normal)).norm() < 1e-12
        assert all(abs(p[i]) < 1e-12 for p in v for i in range(3) if ext[i] == 0)
    if ext == (1, 1, 0):
        got = [[tuple(round(c, 12) + 0.0 for c in b.state.pos + b.state.ori * w) for w in b.shape.vertices] for b in fs]
        assert got == [[(-1, -1, 0), (1, -1, 0), (1, 1, 0)], [(-1, -1, 0), (1, 1, 0), (-1, 1, 0)]]


def test_facetBox_refuses_two_zero_or_negative_extents():
    with pytest.raises(ValueError, match="at least 2 non-zero"):
        geom.facetBox((0, 0, 0), (1, 0, 0))
    with pytest.raises(ValueError, match="non-negative"):
        geom.facetBox((0, 0, 0), (1, -1, 1))
