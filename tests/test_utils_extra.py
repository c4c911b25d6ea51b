"""More functions of the reference's yade.utils: critical time steps (SpherePWaveTimeStep,
RayleighWaveTimeStep), growing particles (growParticle, growParticles), setContactFriction,
sumFacetNormalForces, negPosExtremeIds, cart2spher/spher2cart, fractionalBox, scalarOnColorScale,
randomOrientation, saveVars/loadVars, perpendicularArea, getSpheresVolume2D, getTotalDynamicStress.

Constants named REF_* were printed by the reference Yade 2023.02a (`yade -n -x probe.py`) for the
same scene and calls as the test that uses them (repr of each number)."""
import math
import sys
import warnings

import pytest

from yade import (O, utils, Vector3, FrictMat, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator,
                  Bo1_Sphere_Aabb, Bo1_Facet_Aabb, Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                  Law2_ScGeom_FrictPhys_CundallStrack)

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def engines(facets=False):
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81) if facets else (0, 0, 0), damping=0.3)]


# --- critical time steps -----------------------------------------------------------------------------

def test_sphere_p_wave_time_step():
    assert utils.SpherePWaveTimeStep(0.05, 2600, 1e7) == 0.05 / math.sqrt(1e7 / 2600)
    assert utils.SpherePWaveTimeStep(0.05, 2600, 1e7) == 0.000806225774829855  # REF


def test_rayleigh_wave_time_step_as_the_reference():
    m1 = O.materials.append(FrictMat(young=1e7, poisson=0.3, density=2600))
    m2 = O.materials.append(FrictMat(young=3e7, poisson=0.2, density=1000))

    def dt(spheres):
        O.bodies.clear()
        for r, m, fixed in spheres:
            O.bodies.append(utils.sphere((0, 0, 0), r, material=m, fixed=fixed))
        return utils.RayleighWaveTimeStep()
    assert dt([(0.05, m1, False)]) == 0.004412659110316445  # REF
    assert dt([(0.05, m2, False)]) == 0.0015452313192093766  # REF
    assert dt([(0.05, m1, True)]) == 0.004412659110316445  # REF (fixed spheres count)
    assert dt([(0.05, m1, False), (0.04, m2, False)]) == 0.0012361850553675013  # REF (the smallest)
    assert dt([]) == math.inf  # REF
    O.bodies.append(utils.facet([(0, 0, 0), (1, 0, 0), (0, 1, 0)]))
    assert utils.RayleighWaveTimeStep() == math.inf  # REF (facets do not count)
    # the formula: pi r sqrt(rho/G) / (0.1631 nu + 0.876605), G = E / (2 (1 + nu))
    G = 1e7 / 2.6
    assert dt([(0.05, m1, False)]) == pytest.approx(math.pi * 0.05 * math.sqrt(2600 / G) / (0.1631 * 0.3 + 0.876605), rel=1e-15)


# --- growing particles ---------------------------------------------------------------------------------

def test_grown_spheres_touch_at_the_next_step_as_in_the_reference():
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((2.05, 0, 0), 1)])
    engines()
    O.dt = 1e-6
    O.run(10, True)
    assert O.interactions.countReal() == 0
    utils.growParticles(1.1)
    O.run(1, True)
    i = O.interactions[0, 1]
    assert i.isReal and repr(i.geom.penetrationDepth) == '0.15000000000000036' and i.geom.refR1 == 1.1  # REF


def test_grow_particle_scales_radius_mass_inertia_and_contact_radii():
    m2 = O.materials.append(FrictMat(young=3e7, poisson=0.2, density=1000))
    O.bodies.append([utils.sphere((0, 0, 0), 0.05, material=m2), utils.sphere((0, 0, 0.099), 0.05, material=m2),
                     utils.sphere((1, 0, 0), 0.04, fixed=True)])
    engines()
    O.dt = 1e-6
    O.step()
    assert O.bodies[0].state.mass == 0.5235987755982989  # REF
    utils.growParticle(0, 1.1)
    b = O.bodies[0]
    assert b.shape.radius == 0.05500000000000001 and b.state.mass == 0.6969099703213361  # REF
    assert b.state.inertia == Vector3(1, 1, 1) * 0.0008432610640888168  # REF
    assert O.interactions[0, 1].geom.refR1 == 0.05 * 1.1 and O.interactions[0, 1].geom.refR2 == 0.05
    utils.growParticle(1, 1.2, False)  # (mass kept)
    assert O.bodies[1].shape.radius == 0.05 * 1.2 and O.bodies[1].state.mass == 0.5235987755982989
    mass2 = O.bodies[2].state.mass
    utils.growParticles(0.9)  # dynamic spheres only
    assert O.bodies[2].shape.radius == 0.04 and O.bodies[0].shape.radius == 0.05500000000000001 * 0.9
    assert O.bodies[0].state.mass == 0.6969099703213361 * 0.9 ** 3
    utils.growParticles(1.05, updateMass=False, dynamicOnly=False)
    assert O.bodies[2].shape.radius == 0.04 * 1.05 and O.bodies[2].state.mass == mass2
    assert O.interactions[0, 1].geom.refR2 == 0.05 * 1.2 * 0.9 * 1.05
    O.bodies.append(utils.facet([(0, 0, 0), (1, 0, 0), (0, 1, 0)]))
    with pytest.raises(TypeError, match="#3 is not a sphere"):
        utils.growParticle(3, 2)


# --- friction -------------------------------------------------------------------------------------------

def test_set_contact_friction_as_the_reference():
    mA = O.materials.append(FrictMat(frictionAngle=0.5, label='A'))
    mB = O.materials.append(FrictMat(frictionAngle=0.4, label='B'))
    mC = O.materials.append(FrictMat(frictionAngle=0.1, label='C'))
    O.bodies.append([utils.sphere((0, 0, 0), 1, fixed=True, material=mB), utils.sphere((0, 0, 1.95), 1, material=mA),
                     utils.sphere((0, 0, 3.9), 1, material=mA), utils.sphere((5, 0, 0), 0.5, fixed=True, material=mC)])
    engines()
    O.dt = 1e-6
    O.run(2, True)
    assert [(i.id1, i.id2, i.phys.tangensOfFrictionAngle) for i in O.interactions if i.isReal] == \
        [(0, 1, 0.4227932187381618), (1, 2, 0.5463024898437905)]  # REF
    utils.setContactFriction(0.3)
    # only the materials of dynamic bodies change; contacts take tan of the smaller angle of their two bodies
    assert [(m.label, m.frictionAngle) for m in O.materials] == [('A', 0.3), ('B', 0.4), ('C', 0.1)]  # REF
    assert [i.phys.tangensOfFrictionAngle for i in O.interactions if i.isReal] == [0.30933624960962325] * 2  # REF
    assert math.tan(0.3) == 0.30933624960962325
    # negPosExtremeIds on the same column of spheres
    assert utils.negPosExtremeIds(2, 0) == ([], []) and utils.negPosExtremeIds(2, 1) == ([0], [2])  # REF
    assert utils.negPosExtremeIds(0, 1) == ([0, 1, 2], [3]) and utils.negPosExtremeIds(0, 0.5) == ([], [])  # REF


def test_sum_facet_normal_forces_of_a_resting_sphere():
    O.bodies.append([utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]), utils.sphere((0, 0, 0.0999), 0.1)])
    engines(facets=True)
    O.dt = 1e-5
    O.run(20000, True)
    weight = O.bodies[1].state.mass * 9.81
    # the facet carries the sphere: its force points down, its normal up
    assert utils.sumFacetNormalForces([0]) == pytest.approx(-weight, rel=1e-4)
    assert utils.sumFacetNormalForces([0], 2) == 0.0 and utils.sumFacetNormalForces([0], 0) == utils.sumFacetNormalForces([0])
    with pytest.raises(TypeError, match="#1 is not a facet"):
        utils.sumFacetNormalForces([0, 1])


# --- coordinates, boxes, colors, orientations --------------------------------------------------------

def test_spherical_coordinates_as_the_reference():
    assert utils.cart2spher(Vector3(1, 2, 3)) == Vector3(3.741657386773941329, 0.6405223126794244992, 1.107148717794090409)  # REF
    assert utils.cart2spher(Vector3(-1, 0.5, -2)) == Vector3(2.291287847477919914, 2.63185297475828639, 2.677945044588986967)  # REF
    assert utils.spher2cart(Vector3(2, 0.3, 1.1)) == Vector3(0.2680936390889373522, 0.5267395664469244343, 1.910672978251211962)  # REF
    for v in (Vector3(1, 2, 3), Vector3(-1, 0.5, -2), Vector3(0, 0, -4)):
        assert (utils.spher2cart(utils.cart2spher(v)) - v).norm() < 1e-15 * 8
    with pytest.warns(RuntimeWarning, match="between 0 and pi"):  # (the reference logs an error and computes it all the same)
        assert utils.spher2cart(Vector3(1, -2, 4)) == Vector3(0.5943564625123037848, 0.6881585615987542148, -0.4161468365471424069)  # REF
    with pytest.raises(ValueError, match="zero vector"):
        utils.cart2spher(Vector3(0, 0, 0))


def test_fractional_box_and_color_scale_as_the_reference():
    assert utils.fractionalBox(0.2, ((0, 0, 0), (1, 2, 3))) == ((0.4, 0.8, 1.2000000000000002), (0.6, 1.2, 1.7999999999999998))  # REF
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((4, 2, 1), 0.5)])
    assert utils.fractionalBox() == ((-1, -1, -1), (4.5, 2.5, 1.5))
    assert utils.fractionalBox(0.5) == ((0.375, -0.125, -0.375), (3.125, 1.625, 0.875))
    REF = [Vector3(0, 0, 1), Vector3(0, 0, 1), Vector3(0, 0.4000000000000000222, 1), Vector3(0, 1, 0.8000000000000000444), Vector3(0, 1, 0),
           Vector3(0.7999999999999998224, 1, 0), Vector3(1, 0.3999999999999999112, 0), Vector3(1, 0, 0), Vector3(1, 0, 0)]
    assert [utils.scalarOnColorScale(x) for x in (-0.5, 0, 0.1, 0.3, 0.5, 0.7, 0.9, 1, 2)] == REF
    assert utils.scalarOnColorScale(5, 2, 10) == Vector3(0, 1, 0.5)  # REF


def test_random_orientation_is_uniform():
    qs = [utils.randomOrientation() for _ in range(4000)]
    assert all(abs(q.norm() - 1) < 1e-14 for q in qs)
    # a uniform rotation sends a vector anywhere on the sphere: the mean of the rotated vectors is about zero
    # (its components have a standard deviation of 1/sqrt(3·4000) = 0.009) and each direction gets a third of |v|²
    rotated = [q * Vector3(1, 0, 0) for q in qs]
    mean = sum(rotated, Vector3.Zero) / len(rotated)
    assert mean.norm() < 0.05
    for k in range(3):
        assert abs(sum(v[k] ** 2 for v in rotated) / len(rotated) - 1 / 3.) < 0.03


# --- saveVars, loadVars -----------------------------------------------------------------------------------

def test_save_vars_travel_with_the_simulation(tmp_path):
    utils.saveVars('abc', a=1, b=[2, 3])
    from yade.params.abc import a, b
    assert (a, b) == (1, [2, 3])
    assert 'pickledPythonVariablesDictionaryabc' in O.tags.keys()  # REF (the tag's name)
    utils.saveVars(loadNow=False, c=4.5)
    path = str(tmp_path / "vars.yade")
    O.save(path)
    O.reset()
    O.load(path)
    with pytest.warns(UserWarning, match="Overwriting yade.params.abc"):
        utils.loadVars()  # every mark; '' into yade.params itself
    import yade.params
    assert yade.params.c == 4.5 and sys.modules['yade.params.abc'].b == [2, 3]
    with pytest.raises(KeyError, match="Invalid key: pickledPythonVariablesDictionarynope."):  # REF
        utils.loadVars('nope')
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        utils.saveVars('fresh', d={'x': 'ü'})
    assert sys.modules['yade.params.fresh'].d == {'x': 'ü'}


# --- areas and the dynamic stress ---------------------------------------------------------------------------

def test_areas_and_dynamic_stress_as_the_reference():
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((3, 1, 0.5), 0.5, fixed=True), utils.sphere((-1, 2, 4), 0.7),
                     utils.facet([(-5, -5, 0), (5, -5, 0), (0, 5, 0)])])
    O.bodies[0].state.vel = (1, -2, 0.5)
    O.bodies[2].state.vel = (0.3, 0.1, -4)
    O.bodies[1].state.vel = (7, 0, 0)
    O.bodies[2].mask = 4
    # the spheres' box (facets left out), face by face
    assert [utils.perpendicularArea(a) for a in range(3)] == [21.090000000000003, 29.64, 19.240000000000002]  # REF
    assert [utils.getSpheresVolume2D(m) for m in (-1, 1, 4, 5, 2)] == \
        [5.466371217246239, 3.9269908169872414, 1.5393804002589984, 5.466371217246239, 0.0]  # REF
    REF = [14987.21908136239472, -4167.238879182765231, 185.144527051558839, -4167.238879182765231, 8384.764184773990564,
           -2381.746110441541532, 185.144527051558839, -2381.746110441541532, 12017.63909753215012]
    s = utils.getTotalDynamicStress(2.0)  # (fixed bodies moving count too)
    assert [s[i // 3, i % 3] for i in range(9)] == REF
    with pytest.raises(ValueError, match="Must provide volume"):  # (the reference logs this and returns zeros)
        utils.getTotalDynamicStress()
