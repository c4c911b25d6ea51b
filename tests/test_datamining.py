"""Data mining: unbalancedForce, kineticEnergy, avgNumInteractions, porosity, aabbExtrema,
getSpheresVolume, O.forces, Body.intrs(), O.energy, checked

1. on small scenes placed by hand, against hand computations (the expected semantics are those
   of the reference Yade 2023.02a, which printed the same numbers for the same scenes);
2. against the reference Yade on a deterministic 64-sphere scene settling in a box
   (GRID_TEMPLATE below; the reference numbers were printed by `yade -n -x -j1` running exactly
   that text, and are stored in GRID_REFERENCE).

Semantics of the reference (where this engine differs, the test is an xfail naming the bug):
  aabbExtrema(cutoff, centers): box of all spheres (or of their centers), shrunk by cutoff/2 of
      its size on every side;
  avgNumInteractions(): 2·(real interactions)/len(O.bodies); with cutoff or skipFree: over the
      bodies (of any shape) whose position is in aabbExtrema(cutoff), Z = Σcounts/N, with skipFree
      (Σcounts - N1)/(N - N0 - N1);
  unbalancedForce(useMaxForce): mean (max) over dynamic bodies of |F + m·g| (g of the
      NewtonIntegrator in O.engines) divided by the mean |Fn + Fs| of the real interactions;
  kineticEnergy(): Σ ½mv² + ½ω·Iω over dynamic bodies;
  porosity(V): (V - Vspheres)/V, V the aabbExtrema() box when not given."""
import contextlib
import io
import math

import numpy as np
import pytest

import yade
from yade import (O, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, FrictMat, Ig2_Facet_Sphere_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                  Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator, Sphere,
                  Vector3, geom, utils)
from yade.utils import (PWaveTimeStep, aabbExtrema, avgNumInteractions, facet, getSpheresVolume, kineticEnergy, porosity,
                        sphere, unbalancedForce)

E, RHO = 1e7, 1e3  # the default material
V1 = 4. / 3. * math.pi  # volume of a unit sphere


pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def arr(v):
    return np.array([float(x) for x in v])


# ====================================================================== 1. a static scene by hand

def static_scene():
    """Spheres of radius 1 (Kn = E·r = 1e7 between two of them) overlapping by .1 (Fn = 1e6) or
    .05 (5e5), a facet under sphere 0 (overlap .05, Kn = 4/3·E·r: Fn = 6.667e5), a free sphere and a
    facet far away. No NewtonIntegrator, so nothing moves; the collider has verletDist=0.

        id  body                      contacts
        0   sphere (0,0,0)            1, 4, 5, 6
        1   sphere (1.9,0,0)          0, 2
        2   sphere (3.8,0,0)          1
        3   sphere (10,0,0) r=.5      -
        4   sphere (0,1.95,0) fixed   0 (overlap .05), 7
        5   sphere (0,0,1.9)          0
        6   facet at z=-.95           0
        7   sphere (0,3.85,0)         4
        8   facet far away            -
    """
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()], verletDist=0),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
    ]
    O.bodies.append([
        sphere((0, 0, 0), 1), sphere((1.9, 0, 0), 1), sphere((3.8, 0, 0), 1), sphere((10, 0, 0), .5),
        sphere((0, 1.95, 0), 1, fixed=True), sphere((0, 0, 1.9), 1),
        facet([(-.5, -1, -.95), (.5, -1, -.95), (0, 1, -.95)]), sphere((0, 3.85, 0), 1),
        facet([(20, 20, 20), (21, 20, 20), (20, 21, 20)]),
    ])
    O.dt = 1e-6
    O.step()


FN_FACET = 4. / 3. * E * .05
EXPECTED_FORCES = {
    0: (-1e6, -5e5, -1e6 + FN_FACET), 1: (0, 0, 0), 2: (1e6, 0, 0), 3: (0, 0, 0), 4: (0, 5e5 - 1e6, 0), 5: (0, 0, 1e6),
    6: (0, 0, -FN_FACET), 7: (0, 1e6, 0), 8: (0, 0, 0),
}
EXPECTED_PARTNERS = {0: [1, 4, 5, 6], 1: [0, 2], 2: [1], 3: [], 4: [0, 7], 5: [0], 6: [0], 7: [4], 8: []}


def test_static_scene_forces_and_interactions():
    static_scene()
    assert O.interactions.countReal() == 6
    fn = {tuple(sorted((i.id1, i.id2))): i.phys.normalForce.norm() for i in O.interactions if i.isReal}
    assert fn == pytest.approx({(0, 1): 1e6, (1, 2): 1e6, (0, 4): 5e5, (0, 5): 1e6, (0, 6): FN_FACET, (4, 7): 1e6},
                               rel=1e-9)
    for k, f in EXPECTED_FORCES.items():
        np.testing.assert_allclose(arr(O.forces.f(k)), f, rtol=1e-9, atol=1e-6)
        assert O.forces.t(k).norm() < 1e-6
    # action and reaction: the forces sum to zero
    total = sum((O.forces.f(b.id) for b in O.bodies), Vector3(0, 0, 0))
    assert total.norm() < 1e-6


def test_static_scene_intrs_partners():
    static_scene()
    for k, partners in EXPECTED_PARTNERS.items():
        got = [i.id2 if i.id1 == k else i.id1 for i in O.bodies[k].intrs()]
        assert sorted(got) == partners
        assert all(i.isReal for i in O.bodies[k].intrs())


def test_static_scene_intrs_in_partner_id_order():
    static_scene()
    for k, partners in EXPECTED_PARTNERS.items():
        assert [i.id2 if i.id1 == k else i.id1 for i in O.bodies[k].intrs()] == partners


def test_static_scene_unbalanced_force():
    static_scene()
    # dynamic bodies 0, 1, 2, 3, 5, 7: |F| = 7/6·1e6, 0, 1e6, 0, 1e6, 1e6
    body = [7. / 6. * 1e6, 0, 1e6, 0, 1e6, 1e6]
    assert O.forces.f(0).norm() == pytest.approx(7. / 6. * 1e6, rel=1e-12)
    contact = [1e6, 1e6, 5e5, 1e6, FN_FACET, 1e6]
    assert unbalancedForce() == pytest.approx(np.mean(body) / np.mean(contact), rel=1e-12)
    assert unbalancedForce() == pytest.approx(0.806451612903226, rel=1e-12)  # the reference's number
    assert unbalancedForce(True) == pytest.approx(max(body) / np.mean(contact), rel=1e-12)
    assert unbalancedForce(useMaxForce=True) == pytest.approx(1.35483870967742, rel=1e-12)


def test_static_scene_unbalanced_force_adds_the_weight():
    static_scene()
    g = Vector3(0, 0, -10)
    O.engines = O.engines + [NewtonIntegrator(gravity=g)]  # not run: only read by unbalancedForce
    body = [(O.forces.f(k) + O.bodies[k].state.mass * g).norm() for k in (0, 1, 2, 3, 5, 7)]
    assert body[1] == pytest.approx(V1 * RHO * 10) and body[3] == pytest.approx(V1 / 8 * RHO * 10)
    contact = [1e6, 1e6, 5e5, 1e6, FN_FACET, 1e6]
    assert unbalancedForce() == pytest.approx(np.mean(body) / np.mean(contact), rel=1e-12)
    assert unbalancedForce() == pytest.approx(0.810253127997469, rel=1e-12)
    assert unbalancedForce(True) == pytest.approx(max(body) / np.mean(contact), rel=1e-12)
    assert unbalancedForce(True) == pytest.approx(1.36953059559163, rel=1e-12)


def test_static_scene_kinetic_energy():
    static_scene()
    assert kineticEnergy() == 0
    b1 = O.bodies[1].state
    b1.vel, b1.angVel = (1, 2, 3), (.5, 0, -1)
    O.bodies[4].state.vel = (10, 0, 0)  # fixed: not counted
    O.bodies[6].state.vel = (0, 0, 1)  # facet, fixed and massless
    m = V1 * RHO
    expected = .5 * m * 14 + .5 * (.4 * m) * (.25 + 1)
    assert kineticEnergy() == pytest.approx(expected, rel=1e-13)
    assert kineticEnergy() == pytest.approx(30368.7289847013, rel=1e-12)  # the reference's number
    O.bodies[3].state.vel = (0, -2, 0)
    assert kineticEnergy() == pytest.approx(expected + .5 * m / 8 * 4, rel=1e-13)


def test_static_scene_aabbExtrema():
    static_scene()
    lo, hi = aabbExtrema()
    np.testing.assert_allclose(arr(lo), [-1, -1, -1])
    np.testing.assert_allclose(arr(hi), [10.5, 4.85, 2.9])
    lo, hi = aabbExtrema(centers=True)
    np.testing.assert_allclose(arr(lo), [0, 0, 0])
    np.testing.assert_allclose(arr(hi), [10, 3.85, 1.9])


def test_static_scene_aabbExtrema_cutoff():
    static_scene()
    lo, hi = aabbExtrema(cutoff=.2)
    size = np.array([11.5, 5.85, 3.9])
    np.testing.assert_allclose(arr(lo), np.array([-1, -1, -1]) + .1 * size, rtol=1e-14)
    np.testing.assert_allclose(arr(lo), [0.15, -0.415, -0.61], rtol=1e-14)
    np.testing.assert_allclose(arr(hi), [9.35, 4.265, 2.51], rtol=1e-14)
    lo, hi = aabbExtrema(.1, True)
    np.testing.assert_allclose(arr(lo), [0.5, 0.1925, 0.095], rtol=1e-14)
    np.testing.assert_allclose(arr(hi), [9.5, 3.6575, 1.805], rtol=1e-14)


def test_static_scene_avgNumInteractions_without_cutoff():
    static_scene()
    assert avgNumInteractions() == pytest.approx(2 * 6 / 9., rel=1e-15)
    # bodies in the box: the 7 spheres and facet 6 (at (0,-.61,-.95)); counts 4,2,1,0,2,1,1 and 1
    assert avgNumInteractions(skipFree=True) == pytest.approx((12 - 4) / (8 - 1 - 4.), rel=1e-15)


def test_static_scene_avgNumInteractions_with_cutoff():
    static_scene()
    assert avgNumInteractions(cutoff=.2) == pytest.approx(1.5)
    assert avgNumInteractions(cutoff=.2, skipFree=True) == pytest.approx(2.0)


def test_static_scene_porosity_and_volume():
    static_scene()
    vs = V1 * (6 + .125)  # six spheres of radius 1, one of .5
    assert getSpheresVolume() == pytest.approx(vs, rel=1e-14)
    box = 11.5 * 5.85 * 3.9
    assert porosity() == pytest.approx((box - vs) / box, rel=1e-13)
    assert porosity() == pytest.approx(0.902214065863165, rel=1e-13)  # the reference's number
    assert porosity(1000) == pytest.approx((1000 - vs) / 1000, rel=1e-13)
    assert porosity(volume=1000) == pytest.approx(0.974343659995683, rel=1e-13)
    O.bodies[2].mask = 2
    O.bodies[3].mask = 6
    assert getSpheresVolume(mask=1) == pytest.approx(V1 * 5, rel=1e-14)
    assert getSpheresVolume(mask=2) == pytest.approx(V1 * (1 + .125), rel=1e-14)
    assert getSpheresVolume(mask=4) == pytest.approx(V1 * .125, rel=1e-14)
    assert getSpheresVolume(mask=-1) == pytest.approx(vs, rel=1e-14)


def test_getSpheresVolume_mask_zero_means_all():
    static_scene()
    assert getSpheresVolume(mask=0) == pytest.approx(V1 * 6.125, rel=1e-14)


# ====================================================================== a resting column

def test_resting_column_forces_and_overlaps():
    """Three spheres (r = .1) stacked on a facet settle under gravity (damping .3): the contact
    under sphere k carries the weight of the spheres above it and k, overlaps (3-k)·m·g/Kn with
    Kn = 4/3·E·r on the facet and E·r between spheres; the contact forces on each sphere sum to
    +m·g (O.forces holds no gravity), the facet gets -3·m·g; at rest the unbalanced force and the
    kinetic energy vanish."""
    g, r = 9.81, .1
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(gravity=(0, 0, -g), damping=.3),
    ]
    fid = O.bodies.append(facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]))
    ids = O.bodies.append([sphere((0, 0, r + 2 * r * k), r) for k in range(3)])
    O.dt = .5 * PWaveTimeStep()
    O.run(20000, True)
    m = O.bodies[ids[0]].state.mass
    assert m == pytest.approx(V1 * r ** 3 * RHO)
    W = m * g
    below = [fid] + ids[:2]
    z = 0
    for k, (a, b) in enumerate(zip(below, ids)):
        i = O.interactions[a, b]
        kn = (4. / 3. if k == 0 else 1.) * E * r
        assert i.phys.kn == pytest.approx(kn, rel=1e-12)
        assert i.phys.normalForce.norm() == pytest.approx((3 - k) * W, rel=1e-6)
        assert i.geom.penetrationDepth == pytest.approx((3 - k) * W / kn, rel=1e-6)
        z += (r if k == 0 else 2 * r) - i.geom.penetrationDepth
        assert O.bodies[b].state.pos[2] == pytest.approx(z, rel=1e-9)
        np.testing.assert_allclose(arr(O.forces.f(b)), [0, 0, W], rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(arr(O.forces.f(fid)), [0, 0, -3 * W], rtol=1e-6, atol=1e-9)
    assert O.interactions.countReal() == 3
    assert unbalancedForce() < 1e-6
    assert kineticEnergy() < 1e-12 * W * r
    assert [len(O.bodies[k].intrs()) for k in [fid] + ids] == [1, 2, 2, 1]


# ====================================================================== NewtonIntegrator details behind the drift

def two_spheres_shearing(damping):
    """Sphere 1 (r = .1) overlapping the fixed sphere 0 by .01 along z, sliding at 1 m/s along x:
    after one step, the shear force gives it a torque (no gravity)."""
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(damping=damping),
    ]
    O.bodies.append([sphere((0, 0, 0), .1, fixed=True), sphere((0, 0, .19), .1)])
    O.bodies[1].state.vel = (1, 0, 0)
    O.dt = 1e-5
    O.step()  # creates the contact; the shear force is computed in this step already
    return O.bodies[1].state


def test_translational_damping_of_the_first_step():
    """Non-viscous damping (manual 3.5.12) with the on-step velocity estimate v + a·dt/2: from
    rest along z the acceleration is reduced by the factor (1 - d), in both engines."""
    d = .2
    s = two_spheres_shearing(d)
    f = O.forces.f(1)
    assert f[2] > 0
    assert s.vel[2] == pytest.approx((1 - d) * O.dt * f[2] / s.mass, rel=1e-12)


def test_rotational_damping_of_the_first_step():
    d = .2
    s = two_spheres_shearing(d)
    t = O.forces.t(1)
    assert abs(t[1]) > 0
    assert s.angVel[1] == pytest.approx((1 - d) * O.dt * t[1] / s.inertia[1], rel=1e-12)


@pytest.mark.xfail(strict=True, reason="DELIBERATE DEVIATION (kept as a record): NewtonIntegrator::action adds to "
                   "O.energy['kinetic'] (and 'nonviscDamp') with the on-step estimate v + a·dt/2; the reference uses "
                   "the velocity before the step's update (v of the previous step): after n steps of free fall "
                   "kinetic = ½·m·(g·(n-1)·dt)², and nonviscDamp = d·|gravWork| (reference at step 100: kinetic "
                   "1011.289164, nonviscDamp 249.4260654). The on-step estimate is consistent with the positions at which 'elastPotential is measured and halves the energy drift (0.12 % vs the reference's 0.38 % on an elastic gas)")
def test_tracked_kinetic_energy_in_free_fall_as_reference():
    """Tutorial 1's free sphere (r = .5, ρ = 1000), thrown at .3 m/s along x, falling with damping .2 for 100 steps of
    dt = .5·PWaveTimeStep; the reference printed kinetic 1011.289164, gravWork -1247.130327,
    nonviscDamp 249.4260654 (this engine: kinetic 1021.291401, nonviscDamp 251.9455206)."""
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=.2)]
    O.bodies.append([sphere((0, 0, 0), .5, fixed=True), sphere((.1, 0, 2), .5)])
    O.bodies[1].state.vel = (.3, 0, 0)
    O.dt = .5 * PWaveTimeStep()
    O.trackEnergy = True
    O.run(100, True)
    m, g, dt = O.bodies[1].state.mass, 9.81 * .8, O.dt  # gravity is damped too (dampGravity)
    assert O.energy['gravWork'] == pytest.approx(-1247.130327, rel=1e-9)
    assert O.energy['kinetic'] == pytest.approx(.5 * m * (.3 ** 2 + (g * 99 * dt) ** 2), rel=1e-9)
    assert O.energy['kinetic'] == pytest.approx(1011.289164, rel=1e-9)
    assert O.energy['nonviscDamp'] == pytest.approx(.2 * -O.energy['gravWork'], rel=1e-9)


@pytest.mark.xfail(strict=True, reason="DELIBERATE DEVIATION (kept as a record; issue 3 requires it): Body::mayCollide requires one of the two bodies to be "
                   "dynamic; the reference collider also makes interactions between two non-dynamic bodies (two fixed "
                   "overlapping spheres get Fn = 1e6 each there). Note tests/test_dem_physics.py::"
                   "test_two_non_dynamic_spheres_never_interact asserts the opposite")
def test_two_fixed_overlapping_spheres_interact_as_in_reference():
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(),
    ]
    O.bodies.append([sphere((0, 0, 0), 1, fixed=True), sphere((1.9, 0, 0), 1, fixed=True)])
    O.dt = 1e-5
    O.step()
    assert O.interactions.countReal() == 1
    np.testing.assert_allclose(arr(O.forces.f(0)), [-1e6, 0, 0], rtol=1e-9)


def test_all_dofs_blocked_is_not_dynamic_for_kinetic_energy():
    b = sphere((0, 0, 0), 1)
    O.bodies.append(b)
    b.state.vel = (1, 0, 0)
    b.state.blockedDOFs = 'xyzXYZ'
    assert kineticEnergy() == 0
    assert not b.dynamic


# ====================================================================== 2. the reference Yade, 64 spheres in a box

# The script run in both engines. BOUNDARY ('facets': geom.facetBox open at the top; 'walls':
# five one-sided Walls), FRICTION and DAMPING are defined before it. To regenerate the numbers:
#   printf "from yade import *\nfrom yade.utils import *\nfrom yade import geom\n
#           BOUNDARY, FRICTION, DAMPING = 'facets', 0, .2\n" > s.py
#   (the text of GRID_TEMPLATE) >> s.py;  yade -n -x -j1 s.py | grep -E '^(ROW|CUT)'
# Each ROW: iter, unbalancedForce(), unbalancedForce(True), kineticEnergy(), countReal,
# porosity(), getSpheresVolume(), aabbExtrema() lo (3) hi (3), aabbExtrema(0, True) lo (3) hi (3),
# Σ O.forces.f of the boundaries (3), Σ positions (3), Σ|v|, Σ|ω| of the spheres.
# CUT: avgNumInteractions(), avgNumInteractions(skipFree=True), avgNumInteractions(.2),
# aabbExtrema(.2) lo (3) hi (3).
GRID_TEMPLATE = """\
O.materials.append(FrictMat(young=1e7, poisson=.3, density=2600, frictionAngle=FRICTION))
if BOUNDARY == 'facets':
    O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))
else:
    O.bodies.append([wall(0, axis=2, sense=1), wall(0, axis=0, sense=1), wall(1, axis=0, sense=-1),
                     wall(0, axis=1, sense=1), wall(1, axis=1, sense=-1)])
for k in range(4):
    for j in range(4):
        for i in range(4):
            off = .05 * (k % 2)
            O.bodies.append(sphere((.12 + .22 * i + off, .12 + .22 * j + off, .098 + .185 * k), .1))
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=DAMPING)
]
O.dt = .5 * PWaveTimeStep()
spheres = [b for b in O.bodies if isinstance(b.shape, Sphere)]
others = [b for b in O.bodies if not isinstance(b.shape, Sphere)]
for n in range(5):
    O.run(100, True)
    lo, hi = aabbExtrema()
    clo, chi = aabbExtrema(0, True)
    fb = Vector3(0, 0, 0)
    for b in others:
        fb += O.forces.f(b.id)
    vals = ([O.iter, unbalancedForce(), unbalancedForce(True), kineticEnergy(), O.interactions.countReal(), porosity(),
             getSpheresVolume()] + list(lo) + list(hi) + list(clo) + list(chi) + list(fb) +
            [sum(b.state.pos[a] for b in spheres) for a in range(3)] +
            [sum(b.state.vel.norm() for b in spheres), sum(b.state.angVel.norm() for b in spheres)])
    print('ROW ' + ' '.join('%.17g' % v for v in vals))
lo, hi = aabbExtrema(.2)
print('CUT ' + ' '.join('%.17g' % v for v in [avgNumInteractions(), avgNumInteractions(skipFree=True),
                                              avgNumInteractions(.2)] + list(lo) + list(hi)))
"""

GRID_REFERENCE = {  # printed by the reference Yade 2023.02a (yade -n -x -j1), see GRID_TEMPLATE
    ('facets', 0.0, 0.2): ([
        [100, 0.37362796479166616, 1.6154731690079402, 110.25284821631304, 14, 0.62455247548069992,
         0.26808257310632883, -0.00054334286206723925, -0.00054334286206723925, -0.00020408410565130042,
         0.97169994109009017, 0.97169994109009017, 0.75518279065062821, 0.099456657137932766,
         0.099456657137932766, 0.099795915894348705, 0.87169994109009019, 0.87169994109009019,
         0.65518279065062823, -2611.4412167833798, -2611.4412167834162, -2377.4751510921378,
         30.43583682678204, 30.435836826782037, 23.875533104459489, 34.204439152586907,
         1.2546956587023793e-14],
        [200, 0.64763096490509942, 3.1181470898257406, 238.25834543241268, 26, 0.6192325360330172,
         0.26808257310632883, 0.00045066941134763727, 0.00045066941134760952, -0.00016607918165480184,
         1.0003872450634133, 1.0003872450634133, 0.70398174761333765, 0.10045066941134764,
         0.10045066941134762, 0.099833920818345204, 0.90038724506341328, 0.90038724506341328,
         0.60398174761333767, 1828.612210711289, 1828.612210711289, -1271.9857160342813, 30.787306582181074,
         30.787306582181085, 21.700486521270626, 49.03834206658685, 1.573088756058986e-14],
        [300, 0.86529795570359702, 3.8231699462547408, 220.84632453353024, 34, 0.58472362555417734,
         0.26808257310632883, 0.0014598646702102397, 0.0014598646702147083, -0.0017469991028376541,
         0.99982838608681446, 0.99982838608681446, 0.64591676642863383, 0.10145986467021025,
         0.10145986467021471, 0.098253000897162351, 0.89982838608681448, 0.89982838608681448,
         0.54591676642863385, 329.42670149752962, 329.42670149752985, -5736.9909987368501,
         31.108732645561151, 31.108732645561059, 19.23535317074057, 45.163277035148433,
         3.0902555253855787e-14],
        [400, 0.6659182058240779, 2.3352732796757683, 110.00801253013596, 39, 0.56146967001708148,
         0.26808257310632883, -0.00037104688407692266, -0.00037104688379407946, -0.0010715261422493266,
         1.0009130373952113, 1.0009130373948802, 0.60868200154796515, 0.099628953115923083,
         0.099628953116205926, 0.098928473857750679, 0.90091303739521122, 0.90091303739488016,
         0.50868200154796517, 1457.6582454585525, 1457.6582453585024, -6702.5863016555631,
         31.616314421713994, 31.616314421709234, 17.927473491314643, 27.701154860279964,
         3.4668239449470061e-14],
        [500, 1.0828490862099156, 5.3907516273509071, 50.423419072681781, 61, 0.55248633741563358,
         0.26808257310632883, 3.3151102066364402e-05, 3.3151103464482135e-05, -0.00094892281957267843,
         1.0002341854607042, 1.0002341854570607, 0.59785920392824188, 0.10003315110206637,
         0.10003315110346449, 0.099051077180427327, 0.90023418546070411, 0.90023418545706069,
         0.4978592039282419, 389.74022956361893, 389.74020095775774, -6415.2858306674534, 31.599680188852332,
         31.599680188773558, 17.151863989412469, 19.501117131823545, 3.0813044944502876e-14],
    ], [1.6486486486486487, 3.25, 1.6557377049180328, 0.10005325453793015, 0.10005325453882409,
        0.05893188985520878, 0.90021408202484043, 0.90021408202170106, 0.53797839125346036]),
    ('walls', 0.5, 0.0): ([
        [100, float('nan'), float('nan'), 74.228995398675437, 0, 0.60623175320206812, 0.26808257310632883,
         0.002598012967102728, 0.002598012967102728, 0.0011011951614440796, 0.94808623017578131,
         0.9480862301757812, 0.76268140363210213, 0.10259801296710273, 0.10259801296710273,
         0.10110119516144409, 0.84808623017578133, 0.84808623017578122, 0.66268140363210215, 0, 0, 0,
         30.703341193995261, 30.703341193995264, 24.202884993295712, 26.611769204210624, 146.97695982379147],
        [200, 0.34817792430113254, 1.3908366032950357, 222.37103928617333, 17, 0.59815498246674703,
         0.26808257310632883, 0.010375989917851811, 0.010375989917851811, -0.0034188421692462195,
         0.97783402605678238, 0.97783402605678238, 0.70934510229939307, 0.11037598991785182,
         0.11037598991785182, 0.096581157830753786, 0.8778340260567824, 0.8778340260567824,
         0.60934510229939309, -4098.0029947354833, -4098.0029947355142, -32874.12462555313,
         31.150318426195224, 31.15031842619522, 21.996713537923103, 43.163752513069134, 232.53724482097982],
        [300, 0.85107307209453587, 3.2192362441965483, 310.20240660501042, 56, 0.59229438742640306,
         0.26808257310632883, -0.00020366437452387642, -0.00020366437452377928, -0.0046148064680712197,
         1.0019611915393101, 1.0019611915393094, 0.65008702476694036, 0.099796335625476129,
         0.099796335625476226, 0.095385193531928786, 0.90196119153930998, 0.90196119153930943,
         0.55008702476694038, -192.70657702738617, -192.70657703375537, -21944.067012010211,
         31.888014402439889, 31.888014402439861, 19.251310470902158, 45.523514867699674, 462.58353287253283],
        [400, 0.57831165567486964, 3.1554399595875751, 203.58771106961655, 28, 0.57822391232181214,
         0.26808257310632883, -0.00062118980996117568, -0.00062118981014136487, -0.0016422557314504371,
         1.0005166471667672, 1.0005166471667517, 0.63251779281481202, 0.09937881019003883,
         0.099378810189858641, 0.098357744268549568, 0.90051664716676716, 0.90051664716675173,
         0.53251779281481204, 269.52922524986843, 269.52922507151561, -6381.5894854328562,
         32.229249947574004, 32.229249947573727, 19.085653115259127, 33.988199344295886, 405.44530194763689],
        [500, 0.51418514640750046, 3.1234267972052421, 134.77163237177723, 22, 0.59742209076650077,
         0.26808257310632883, -6.3333592002279282e-05, -6.3333591953013135e-05, -0.0016070184130784898,
         1.0001691140402718, 1.0001691140391726, 0.66399827209987616, 0.099936666407997726,
         0.099936666408046992, 0.098392981586921516, 0.90016911404027167, 0.90016911403917255,
         0.56399827209987619, 135.55381672773186, 135.55381331401668, -4307.930240181262, 32.053669936108548,
         32.053669936104598, 18.95800539518795, 28.039923567559441, 310.73648355242568],
    ], [0.6376811594202898, 2.75, 0.4838709677419355, 0.099959911171225116, 0.099959911171159571,
        0.064953510638216985, 0.90014586927704432, 0.90014586927606, 0.59743774304858066]),
    ('facets', 0.5, 0.2): ([
        [100, float('nan'), float('nan'), 54.027587770633261, 0, 0.60158472324217882, 0.26808257310632883,
         0.0055726021081580757, 0.0055726021081580757, 0.00092554548690125527, 0.9492098356470664,
         0.9492098356470664, 0.75657863668655545, 0.10557260210815808, 0.10557260210815808,
         0.10092554548690126, 0.84920983564706642, 0.84920983564706642, 0.65657863668655547, 0, 0, 0,
         30.68080164068699, 30.68080164068698, 24.143018537978072, 19.665959187511714, 173.39518955708056],
        [200, 1.4077891566779019, 1.4418059408214661, 194.59582796982397, 8, 0.59434158868608744,
         0.26808257310632883, 0.0035612114017249674, 0.0035612114017249119, -1.4620956938563023e-05,
         0.9706454651959977, 0.9706454651959977, 0.70659488163137929, 0.10356121140172497,
         0.10356121140172492, 0.099985379043061443, 0.87064546519599773, 0.87064546519599773,
         0.60659488163137931, 169.74075023736492, 169.74075023736492, -542.03101207576458,
         30.974389569423238, 30.974389569423199, 22.208346900745685, 41.071480706417105, 154.5737042821774],
        [300, 0.6972149689901862, 4.2510035496417604, 191.21435913929369, 33, 0.58253536313976251,
         0.26808257310632883, 0.0038730136027269185, 0.0038730136027268491, -0.001476321927824667,
         0.99908228694482382, 0.99908228694482382, 0.64688942410405481, 0.10387301360272692,
         0.10387301360272685, 0.098523678072175339, 0.89908228694482384, 0.89908228694482384,
         0.54688942410405483, -1807.3552214776646, -1807.3552214679225, -6972.8963145157904,
         31.513606962208648, 31.513606962208755, 19.739462021997554, 38.996029167568466, 250.7575970965666],
        [400, 0.79780782958870078, 3.3626440531749058, 118.59563680303887, 35, 0.56340860652650315,
         0.26808257310632883, -0.00093726385931904022, -0.00093726385939567336, -0.0004268047544830067,
         1.0006526291054494, 1.0006526291053697, 0.61166074564418194, 0.099062736140680965,
         0.099062736140604332, 0.099573195245516999, 0.90065262910544941, 0.9006526291053697,
         0.51166074564418196, 605.06277647437832, 605.06277601943418, -4500.1644387386687,
         32.218047568658569, 32.218047568668808, 18.461131244553112, 23.855699165404651, 223.40780864658811],
        [500, 0.77819645275300842, 3.0188215880476865, 20.934589166136522, 55, 0.55447874440724931,
         0.26808257310632883, -0.00038956775898939255, -0.00038956774316567522, -0.00028164628761734312,
         1.0000572029928663, 1.0000572029834591, 0.60090895299547908, 0.099610432241010613,
         0.09961043225683433, 0.099718353712382662, 0.90005720299286618, 0.90005720298345915,
         0.50090895299547911, -871.84079786763004, -871.84080992735198, -4933.0138070978965,
         32.187622626252107, 32.187622626016662, 18.099309833899479, 10.112642309245633, 86.226317914104726],
    ], [1.4864864864864864, 2.7941176470588234, 1.3333333333333333, 0.099655109316196172,
        0.099655109329496824, 0.059837413640692297, 0.90001252591768066, 0.90001252591079661,
        0.5407898930671694]),
}

COLUMNS = ['iter', 'unbalanced', 'unbalancedMax', 'kinetic', 'countReal', 'porosity', 'spheresVolume', 'lo.x', 'lo.y',
           'lo.z', 'hi.x', 'hi.y', 'hi.z', 'clo.x', 'clo.y', 'clo.z', 'chi.x', 'chi.y', 'chi.z', 'fb.x', 'fb.y', 'fb.z',
           'sumPos.x', 'sumPos.y', 'sumPos.z', 'sumVel', 'sumAngVel']


def run_grid(boundary, friction, damping):
    """Runs GRID_TEMPLATE here, in this process, as the reference ran it; returns (rows, cut)."""
    ns = {}
    exec('from yade import *\nfrom yade.utils import *\nfrom yade import geom\n', ns)
    ns.update(BOUNDARY=boundary, FRICTION=friction, DAMPING=damping)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(GRID_TEMPLATE, 'GRID_TEMPLATE', 'exec'), ns)
    lines = out.getvalue().splitlines()
    rows = np.array([[float(x) for x in l.split()[1:]] for l in lines if l.startswith('ROW ')])
    cut = np.array([float(x) for x in [l for l in lines if l.startswith('CUT ')][0].split()[1:]])
    return rows, cut


def reference(key):
    rows, cut = GRID_REFERENCE[key]
    return np.array(rows), np.array(cut)


@pytest.fixture(scope='module')
def grid_runs():
    cache = {}

    def get(key):
        if key not in cache:
            O.reset()
            cache[key] = run_grid(*key)
            O.reset()
        return cache[key]

    return get


def compare_rows(ours, ref, rtol, skip=()):
    """|ours - ref| <= rtol·(|ref| + the column's largest |ref|) for every row and column: relative
    to the value, and to the column's scale for values crossing zero (extrema near 0, force
    components that should vanish)."""
    assert ours.shape == ref.shape
    scale = np.nanmax(np.abs(ref), axis=0)
    bad = []
    for c, name in enumerate(COLUMNS):
        if name in skip:
            continue
        for r in range(ref.shape[0]):
            a, b = ours[r, c], ref[r, c]
            if math.isnan(b):
                if not math.isnan(a):
                    bad.append((name, r, a, b))
            elif not abs(a - b) <= rtol * (abs(b) + scale[c]):
                bad.append((name, r, a, b))
    assert not bad, bad[:10]


@pytest.mark.parametrize('key', [('facets', 0.0, 0.2), ('walls', 0.5, 0.0)])
def test_grid_agrees_with_reference(grid_runs, key):
    """Frictionless spheres in the facet box with damping .2, and frictional spheres between
    walls without damping: the trajectories are the reference's up to the rounding of the force
    sums (the packing is chaotic: the difference grows from 1e-15 at step 100 to about 1e-8 at
    step 500), so all aggregates agree to 1e-6. Σ|ω| is rounding noise (1e-14) in the
    frictionless case and is only checked to be tiny."""
    ours, cut = grid_runs(key)
    ref, refcut = reference(key)
    np.testing.assert_array_equal(ours[:, 0], [100, 200, 300, 400, 500])
    if key[1] == 0:
        assert np.abs(ours[:, -1]).max() < 1e-10 and np.abs(ref[:, -1]).max() < 1e-10
        compare_rows(ours, ref, 1e-6, skip=('sumAngVel',))
    else:
        compare_rows(ours, ref, 1e-6)
    np.testing.assert_array_equal(ours[:, 4], ref[:, 4])  # the same number of contacts
    # spheres' volume: 64·4/3·π·.1³
    assert ours[0, 6] == pytest.approx(64 * V1 * 1e-3, rel=1e-14)


def test_grid_settles_consistently(grid_runs):
    """Within the agreeing run: the packing gets denser, spheres stay in the box, and at step 500
    the boundaries carry about the weight (64·m·g, within the remaining dynamics)."""
    rows, cut = grid_runs(('facets', 0.0, 0.2))
    c = {n: k for k, n in enumerate(COLUMNS)}
    assert (np.diff(rows[:, c['porosity']]) < 0).all()
    assert (rows[:, c['lo.x']] > -.01).all() and (rows[:, c['hi.x']] < 1.01).all()
    assert (rows[:, c['lo.z']] > -.01).all()
    W = 64 * V1 * 1e-3 * 2600 * 9.81
    assert -rows[-1, c['fb.z']] == pytest.approx(W, rel=.5)


def test_grid_coordination_and_cutoff_as_reference(grid_runs):
    ours, cut = grid_runs(('facets', 0.0, 0.2))
    ref, refcut = reference(('facets', 0.0, 0.2))
    assert cut[0] == pytest.approx(2 * ours[-1, 4] / 74, rel=1e-12)
    np.testing.assert_allclose(cut, refcut, rtol=1e-6, atol=1e-6)


def test_grid_frictional_facets_with_damping_agrees_with_reference(grid_runs):
    ours, cut = grid_runs(('facets', 0.5, 0.2))
    ref, refcut = reference(('facets', 0.5, 0.2))
    compare_rows(ours, ref, 1e-6)


def test_grid_frictional_facets_with_damping_aggregates_close_to_reference(grid_runs):
    """The same scene with friction: the trajectories drift apart (see the xfail above; by step 500
    the kinetic energy differs by 25 %, the number of contacts by 50 %), but the packing as a
    whole stays close: porosity within 5 %, the height of the packing and the mean position of
    the spheres within 2 %; the volume of the spheres is exact."""
    ours, cut = grid_runs(('facets', 0.5, 0.2))
    ref, refcut = reference(('facets', 0.5, 0.2))
    c = {n: k for k, n in enumerate(COLUMNS)}
    np.testing.assert_allclose(ours[:, c['porosity']], ref[:, c['porosity']], rtol=.05)
    np.testing.assert_allclose(ours[:, c['hi.z']], ref[:, c['hi.z']], rtol=.02)
    for a in ('sumPos.x', 'sumPos.y', 'sumPos.z'):
        np.testing.assert_allclose(ours[:, c[a]], ref[:, c[a]], rtol=.02)
    np.testing.assert_array_equal(ours[:, c['spheresVolume']], ref[:, c['spheresVolume']])
