"""Convex polyhedra (pkg/dem/polyhedra, doc/polyhedra.md): shapes against analytic volumes, centroids and inertia, overlap
volumes of two cubes against the analytic ones, the volumetric law's static overlap on a wall and on facets, conservation
of momentum, bad input. The reference's own numbers are compared in tests/test_polyhedra_reference.py."""
import math

import pytest

from yade import (O, Vector3, Quaternion, Polyhedra, PolyhedraMat, PolyhedraGeom, PolyhedraPhys, Bo1_Polyhedra_Aabb, Bo1_Wall_Aabb,
                  Bo1_Facet_Aabb, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator,
                  Ig2_Polyhedra_Polyhedra_PolyhedraGeom, Ig2_Wall_Polyhedra_PolyhedraGeom, Ig2_Facet_Polyhedra_PolyhedraGeom,
                  Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys, Law2_PolyhedraGeom_PolyhedraPhys_Volumetric)
from yade import polyhedra_utils as pu
from yade import utils

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

CUBE = [Vector3(x, y, z) for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)]
TETRA = [Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)]


def approx(v, rel=1e-12, abs=1e-12):
    return pytest.approx(list(v), rel=rel, abs=abs)


# ---------------------------------------------------------------- the shape


def test_attributes_and_defaults_as_in_reference():
    p = Polyhedra()
    assert list(p.v) == [] and p.size == Vector3(1, 1, 1) and isinstance(p.seed, int)
    m = PolyhedraMat()
    assert (m.IsSplitable, m.strength, m.strengthTau, m.sigmaCZ, m.sigmaCD, m.Wei_m, m.Wei_S0, m.Wei_V0, m.Wei_P) == \
        (False, 100, -1, -1, -1, -1, -1, 1e-9, -1)
    assert (m.young, m.poisson, m.frictionAngle, m.density) == (1e9, 0.25, 0.5, 1000)
    g = PolyhedraGeom()
    assert math.isnan(g.penetrationVolume) and math.isnan(g.equivalentCrossSection) and g.normal == Vector3.Zero
    assert PolyhedraPhys().kn == 0 and math.isnan(PolyhedraPhys().tangensOfFrictionAngle)
    law = Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()
    assert (law.volumePower, law.traceEnergy, law.shearForce) == (1, False, Vector3.Zero)
    assert Bo1_Polyhedra_Aabb().aabbEnlargeFactor == -1 and Ig2_Polyhedra_Polyhedra_PolyhedraGeom().interactionDetectionFactor == 1


def test_cube_volume_centroid_inertia_and_faces():
    p = Polyhedra(v=[x * 2 + Vector3(1, 2, 3) for x in CUBE])
    assert p.GetVolume() == pytest.approx(8, rel=1e-14)
    assert p.GetCentroid() == approx((1, 2, 3))
    assert p.GetInertia() == approx([8 * (4 + 4) / 12] * 3)  # V (a² + b²)/12 per unit density
    assert p.GetOri() == Quaternion.Identity
    assert max(abs(c) for x in p.v for c in x) == pytest.approx(1)  # centered
    faces = p.GetSurfaces()
    assert len(faces) == 6 and all(len(f) == 4 for f in faces)
    assert len(p.GetSurfaceTriangulation()) == 6 * 2 * 3


def test_box_keeps_its_axes():
    """a box already along x, y, z keeps its axes in that order (as the reference: inertia 5, 6.5, 2.5 for 2×1×3)"""
    p = Polyhedra(v=[Vector3(2 * x[0], x[1], 3 * x[2]) for x in CUBE])
    assert p.GetVolume() == pytest.approx(6)
    assert p.GetInertia() == approx((5, 6.5, 2.5))


def test_tetrahedron_volume_centroid_and_principal_inertia():
    p = Polyhedra(v=TETRA)
    assert p.GetVolume() == pytest.approx(1 / 6, rel=1e-14)
    assert p.GetCentroid() == approx((0.25, 0.25, 0.25))
    # about the centroid the tensor has a = 1/80 on the diagonal and b = 1/480 off it: eigenvalues a - b (twice), a + 2b
    a, b = 1 / 80, 1 / 480
    assert sorted(p.GetInertia()) == approx(sorted([a - b, a - b, a + 2 * b]))
    # the vertices turned back by GetOri and moved back by GetCentroid are the ones given
    back = sorted(tuple(round(c, 12) + 0 for c in p.GetOri() * x + p.GetCentroid()) for x in p.v)
    assert back == sorted(tuple(float(c) for c in x) for x in TETRA)


def test_inner_points_are_dropped():
    p = Polyhedra(v=CUBE + [Vector3(0.1, 0.2, 0.3), Vector3(0, 0, 0)])
    assert len(p.v) == 8 and p.GetVolume() == pytest.approx(1)


@pytest.mark.parametrize("v", [[Vector3(0, 0, 0)] * 3, TETRA[:3], TETRA[:3] + [Vector3(1, 1, 0)], [Vector3(0, 0, 0)] * 5])
def test_fewer_than_four_non_coplanar_vertices_are_refused(v):
    with pytest.raises(ValueError, match="at least 4 non-coplanar"):
        Polyhedra(v=v)
    with pytest.raises(ValueError, match="at least 4 non-coplanar"):
        pu.polyhedra(PolyhedraMat(), v=v)


def test_non_finite_vertices_are_refused():
    with pytest.raises(ValueError):
        Polyhedra(v=TETRA[:3] + [Vector3(0, 0, float('nan'))])


def test_random_shape_is_defined_by_seed_and_size():
    m = PolyhedraMat(density=2000)
    a, b, c = (pu.polyhedra(m, size=(0.1, 0.2, 0.3), seed=s) for s in (11, 11, 12))
    assert [tuple(x) for x in a.shape.v] == [tuple(x) for x in b.shape.v]
    assert a.shape.GetVolume() != c.shape.GetVolume()
    assert 0 < a.shape.GetVolume() < 0.1 * 0.2 * 0.3
    assert max(x.norm() for x in a.shape.v) <= math.sqrt(0.1 ** 2 + 0.2 ** 2 + 0.3 ** 2) / 2 + 1e-12
    assert a.state.mass == pytest.approx(2000 * a.shape.GetVolume())
    assert a.state.inertia == approx(2000 * a.shape.GetInertia())
    assert sorted(pu.SizeOfPolyhedra(a.shape), reverse=True) == list(pu.SizeOfPolyhedra(a.shape))


def test_polyhedra_body_from_vertices():
    m = PolyhedraMat(density=2000)
    b = pu.polyhedra(m, v=[x + Vector3(1, 2, 3) for x in CUBE], mask=3, fixed=True)
    assert b.state.pos == approx((1, 2, 3)) and b.state.mass == pytest.approx(2000)
    assert b.state.inertia == approx([2000 / 6] * 3)
    assert (b.dynamic, b.mask) == (False, 3)
    ball = pu.polyhedralBall(0.5, 30, m, (1, 2, 3))
    assert len(ball.shape.v) == 30 and ball.state.pos == Vector3(1, 2, 3)
    assert 0.8 * 4 / 3 * math.pi * 0.125 < ball.shape.GetVolume() < 4 / 3 * math.pi * 0.125
    with pytest.raises(ValueError):
        pu.polyhedralBall(0.5, 3, m, (0, 0, 0))
    assert len(pu.polyhedraSnubCube(1, m, (0, 0, 0)).shape.v) == 24
    assert len(pu.polyhedraTruncIcosaHed(1, m, (0, 0, 0)).shape.v) == 60


def test_fill_box_makes_separate_polyhedra_inside_the_box():
    m = O.materials.append(PolyhedraMat())
    pu.fillBox((0, 0, 0), (0.3, 0.3, 0.3), m, sizemin=[0.05] * 3, sizemax=[0.1] * 3, seed=3)
    assert len(O.bodies) >= 5
    engines([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], gravity=(0, 0, 0))
    O.dt = 1e-6
    O.step()
    assert not any(i.isReal for i in O.interactions)
    for b in O.bodies:
        for x in b.shape.v:
            p = b.state.pos + b.state.ori * x
            assert all(-1e-12 <= p[k] <= 0.3 + 1e-12 for k in range(3))


# ---------------------------------------------------------------- the contact


def engines(ig2s, gravity=(0, 0, -9.81), damping=0.3, law=None):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()], verletDist=0.001),
        InteractionLoop(ig2s, [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()], [law or Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
        NewtonIntegrator(damping=damping, gravity=gravity)
    ]


def cube_pair(offset, q=Quaternion.Identity, young=1e8):
    m = O.materials.append(PolyhedraMat(young=young, poisson=0.3, density=2000, frictionAngle=0.4))
    O.bodies.append([pu.polyhedra(m, v=CUBE), pu.polyhedra(m, v=CUBE)])
    O.bodies[1].state.pos = offset
    O.bodies[1].state.ori = q
    engines([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], gravity=(0, 0, 0), damping=0)
    O.dt = 1e-6
    O.step()
    return O.interactions[0, 1] if O.interactions.has(0, 1) else None


H45 = 0.5 - (1.1 - math.sqrt(0.5))  # depth of the rotated cube's edge in the other cube


@pytest.mark.parametrize("offset, q, volume, point", [
    ((0.9, 0, 0), Quaternion.Identity, 0.1, (0.45, 0, 0)),
    ((0.9, 0.8, 0), Quaternion.Identity, 0.1 * 0.2, (0.45, 0.4, 0)),
    ((0.9, 0.8, 0.7), Quaternion.Identity, 0.1 * 0.2 * 0.3, (0.45, 0.4, 0.35)),
    ((1.1, 0, 0), Quaternion((0, 0, 1), math.pi / 4), H45 ** 2, (0.5 - H45 / 3, 0, 0)),  # a triangular prism
])
def test_overlap_volume_of_two_unit_cubes_is_the_analytic_one(offset, q, volume, point):
    i = cube_pair(Vector3(offset), q)
    g = i.geom
    assert g.penetrationVolume == pytest.approx(volume, rel=1e-12)
    assert g.contactPoint == approx(point, abs=1e-12)
    assert g.equivalentCrossSection == pytest.approx(volume ** (2 / 3))
    assert g.equivalentPenetrationDepth == pytest.approx(volume ** (1 / 3))


def test_cubes_that_do_not_overlap_have_no_contact():
    cube_pair(Vector3(1.01, 0, 0))
    assert not O.interactions.has(0, 1) or not O.interactions[0, 1].isReal


def unit(*v):
    return tuple(x / math.sqrt(sum(y * y for y in v)) for x in v)


@pytest.mark.parametrize("offset, q, normal", [
    ((0.9, 0, 0), Quaternion.Identity, (1, 0, 0)),
    ((0.9, 0.1, 0), Quaternion.Identity, unit(0.9, 0.1, 0)),  # body 1's faces x = 0.5 (area 0.9) and y = 0.5 (0.1) in body 2
    ((0.9, 0.8, 0), Quaternion.Identity, unit(0.2, 0.1, 0)),
    ((1.1, 0, 0), Quaternion((0, 0, 1), math.pi / 4), (1, 0, 0)),
    # its face x = 0.5: a band 2h wide, 0.9 high; its face z = 0.5: a triangle of area h²
    ((1.1, 0.2, 0.1), Quaternion((0, 0, 1), math.pi / 4), unit(1.8 * H45, 0, H45 ** 2)),
])
def test_normal_is_the_area_vector_of_body_1s_faces_in_the_overlap(offset, q, normal):
    i = cube_pair(Vector3(offset), q)
    assert i.geom.normal == approx(normal, abs=1e-12)


def test_normal_force_is_kn_times_volume_and_forces_balance():
    i = cube_pair(Vector3(0.9, 0.8, 0.7))
    kn = 1e8 * 1e8 / 2e8
    assert (i.phys.kn, i.phys.ks) == (pytest.approx(kn), pytest.approx(0.3e8 / 2))
    assert i.phys.tangensOfFrictionAngle == pytest.approx(math.tan(0.4))
    f = kn * 0.006 * i.geom.normal
    assert i.phys.normalForce == approx(f, rel=1e-12, abs=1e-6)
    assert O.forces.f(1) == approx(f, rel=1e-12, abs=1e-6)
    assert O.forces.f(0) == approx(-f, rel=1e-12, abs=1e-6)
    # torques about each center from the contact point
    c = i.geom.contactPoint
    assert O.forces.t(1) == approx((c - O.bodies[1].state.pos).cross(f), abs=1e-6)
    assert O.forces.t(0) == approx((c - O.bodies[0].state.pos).cross(-f), abs=1e-6)


def test_volume_power():
    m = O.materials.append(PolyhedraMat(young=1e8, poisson=0.3, density=2000))
    O.bodies.append([pu.polyhedra(m, v=CUBE), pu.polyhedra(m, v=CUBE)])
    O.bodies[1].state.pos = (0.9, 0, 0)
    engines([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], gravity=(0, 0, 0), law=Law2_PolyhedraGeom_PolyhedraPhys_Volumetric(volumePower=1 / 3))
    O.dt = 1e-6
    O.step()
    assert O.interactions[0, 1].phys.normalForce[0] == pytest.approx(5e7 * 0.1 ** (1 / 3), rel=1e-12)


def cube_on(support, a=0.1, steps=6000):
    m = O.materials.append(PolyhedraMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.5))
    if support == 'wall':
        O.bodies.append(utils.wall(0, axis=2, material=m))
        engines([Ig2_Wall_Polyhedra_PolyhedraGeom()])
    else:
        O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (1, 1, 0)], material=m))
        O.bodies.append(utils.facet([(-1, -1, 0), (1, 1, 0), (-1, 1, 0)], material=m))
        engines([Ig2_Facet_Polyhedra_PolyhedraGeom()])
    cid = O.bodies.append(pu.polyhedra(m, v=[x * a + Vector3(0, 0, a / 2 + 0.001) for x in CUBE]))
    O.dt = 1e-4
    O.run(steps, True)
    return O.bodies[cid]


@pytest.mark.parametrize("support", ['wall', 'facets'])
def test_cube_at_rest_on_a_plane_where_kn_times_volume_is_the_weight(support):
    a = 0.1
    b = cube_on(support, a)
    weight = b.state.mass * 9.81
    V = weight / 5e7
    assert b.state.pos[2] == pytest.approx(a / 2 - V / a ** 2, rel=1e-9)
    volume = sum(i.geom.penetrationVolume for i in O.interactions if i.isReal)
    assert volume == pytest.approx(V, rel=1e-7)
    assert abs(b.state.vel.norm()) < 1e-9
    assert sum(i.phys.normalForce[2] for i in O.interactions if i.isReal) == pytest.approx(weight, rel=1e-7)


def test_a_wall_with_a_sense_acts_on_that_side_only():
    m = O.materials.append(PolyhedraMat(young=1e8, density=2000))
    O.bodies.append(utils.wall(0, axis=2, sense=-1, material=m))
    O.bodies.append(pu.polyhedra(m, v=[x * 0.1 + Vector3(0, 0, 0.04) for x in CUBE]))  # 1 cm into the wall from above
    engines([Ig2_Wall_Polyhedra_PolyhedraGeom()], gravity=(0, 0, 0))
    O.dt = 1e-6
    O.step()
    i = O.interactions[0, 1]
    # the solid side of sense=-1 is above: the part of the cube above z = 0, pushed down
    assert i.geom.normal == Vector3(0, 0, -1)
    assert i.geom.penetrationVolume == pytest.approx(0.01 * 0.09, rel=1e-12)


def test_collision_conserves_momentum_and_sliding_dissipates():
    m = O.materials.append(PolyhedraMat(young=1e7, poisson=0.3, density=2000, frictionAngle=0.3))
    O.bodies.append([pu.polyhedra(m, v=CUBE), pu.polyhedra(m, v=CUBE)])
    O.bodies[1].state.pos = (1.001, 0.3, 0.2)
    O.bodies[1].state.ori = Quaternion((1, 1, 0), 0.2)
    O.bodies[1].state.vel = (-1, 0.5, 0)
    O.bodies[1].state.angVel = (0, 0, 2)
    law = Law2_PolyhedraGeom_PolyhedraPhys_Volumetric(traceEnergy=True)
    engines([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], gravity=(0, 0, 0), damping=0, law=law)
    O.dt = 1e-5
    p0 = sum((b.state.mass * b.state.vel for b in O.bodies), Vector3.Zero)
    touched = False
    for _ in range(40):
        O.run(100, True)
        touched = touched or any(i.isReal for i in O.interactions)
    assert touched
    p1 = sum((b.state.mass * b.state.vel for b in O.bodies), Vector3.Zero)
    assert p1 == approx(p0, rel=1e-9, abs=1e-9)
    assert law.plasticDissipation() >= 0 and law.elasticEnergy() >= 0


def test_saved_and_loaded_scene_goes_on_the_same(tmp_path):
    b = cube_on('wall', steps=200)
    path = str(tmp_path / 's.yade.gz')
    O.save(path)
    O.run(100, True)
    ref = tuple(b.state.pos) + tuple(b.state.vel)
    O.load(path)
    O.run(100, True)
    b = O.bodies[1]
    assert len(b.shape.v) == 8
    assert tuple(b.state.pos) + tuple(b.state.vel) == pytest.approx(ref, rel=1e-12, abs=1e-15)


def sphere_and_cube(center, r=0.3):
    from yade import FrictMat, Ig2_Sphere_Polyhedra_ScGeom, Ip2_FrictMat_PolyhedraMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, Bo1_Sphere_Aabb
    pm = O.materials.append(PolyhedraMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.4))
    fm = O.materials.append(FrictMat(young=3e7, poisson=0.2, density=1000, frictionAngle=0.3))
    O.bodies.append(pu.polyhedra(pm, v=CUBE))
    O.bodies.append(utils.sphere(center, r, material=fm))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Polyhedra_ScGeom()], [Ip2_FrictMat_PolyhedraMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.step()
    return O.interactions[0, 1]


@pytest.mark.parametrize("center, depth, normal", [
    ((0.7, 0, 0), 0.1, (-1, 0, 0)),  # a face
    ((0.6, 0.55, 0), 0.3 - math.sqrt(0.1 ** 2 + 0.05 ** 2), unit(-0.1, -0.05, 0)),  # an edge
    ((0.62, 0.6, 0.58), 0.3 - math.sqrt(0.12 ** 2 + 0.1 ** 2 + 0.08 ** 2), unit(-0.12, -0.1, -0.08)),  # a vertex
    ((0.4, 0, 0), 0.3 + 0.1, (-1, 0, 0)),  # the center inside, 0.1 from the face x = 0.5 (the reference says 0.3: r)
])
def test_sphere_touches_the_closest_point_of_the_cube(center, depth, normal):
    i = sphere_and_cube(Vector3(center))
    assert (i.id1, i.id2) == (1, 0)  # the sphere is body 1
    assert i.geom.penetrationDepth == pytest.approx(depth, rel=1e-12)
    assert i.geom.normal == approx(normal, abs=1e-12)
    assert i.geom.contactPoint == approx(Vector3(center) + (0.3 - depth / 2) * Vector3(normal), abs=1e-12)
    assert i.phys.kn == pytest.approx(2 * 0.3 * 3e7 * 1e9 / (3e7 + 1e9))
