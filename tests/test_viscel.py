"""The linear visco-elastic contact law (ViscElMat, Ip2_ViscElMat_ViscElMat_ViscElPhys, Law2_ScGeom_ViscElPhys_Basic):
the contact constants and the trajectories below are what the reference printed for the same scenes
(38 of its example scripts use this law). Where this engine differs on purpose (the damping computed from
young and en: here it gives the asked restitution coefficient) the test says so (doc/compatibility.md)."""
import math

import pytest

from yade import (O, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, InteractionLoop,
                  Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_ViscElMat_ViscElMat_ViscElPhys,
                  Law2_ScGeom_ViscElPhys_Basic, MatchMaker, NewtonIntegrator, ViscElMat, ViscElPhys)
from yade.utils import facet, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

# the reference's bodies (pos, vel, angVel) at the end of each scene of trajectories() below
REFERENCE = {"oblique": [[9.457630533871012e-05, -1.5146641739173678e-05, 0.00015647127978944897, -0.12641291358820017, -0.07842182215748175, -1.2130472353288075, -16.030267368758377, -17.604874551272395, 34.9319310203491], [0.004895819202715003, 0.002062804933655423, 0.02473213494818699, -0.12103464563181482, 0.11452255965879293, -0.09017643790207251, -3.2161587121169615, 0.2959275146911062, 0.6093626291699628]], "facet": [0.003942781073323924, 0.0, 0.010507848246062077, 0.38640713122551873, 0.0, 0.014303281428202358, 0.0, 28.369026185599377, 0.0], "roll1": [0.001000095131669977, 3.816787107035957e-09, 0.019902015307129275, 0.0038122116683495656, 0.00018224034766363398, 0.078569037626098, 0.0011168396430215268, 0.00022151031685040793, 4.999943877701634], "roll2": [0.001000042973946139, -4.745266900273335e-09, 0.019902017928095633, 0.002101193736587327, -0.00010119411710307876, 0.07865501681931499, 0.2516391470815936, -1.4967549029724962, 4.574243504257964], "direct": [[0.0003505299761800404, 0.00024802692019211975, 0.0005161533765446866, 0.07650512513372518, 0.07423143054345292, 0.013167416350190453, 6.848669916372478, -6.814254489657038, -1.3766170686175832], [0.004249470023820015, 5.197307980787847e-05, 0.020883846623455368, 0.12349487486627486, 0.025768569456547097, 0.48683258364980964, 6.848669916372478, -6.814254489657038, -1.3766170686175832]]}


def mat(**kw):
    kw.setdefault('density', 2500)
    kw.setdefault('frictionAngle', 0.4)
    return O.materials.append(ViscElMat(**kw))


def engines(gravity=(0, 0, 0), ip2=None):
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                                 [ip2 or Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
                 NewtonIntegrator(damping=0, gravity=gravity)]


def state(ids):
    return [list(O.bodies[i].state.pos) + list(O.bodies[i].state.vel) + list(O.bodies[i].state.angVel) for i in ids]


def pair(m1kw, m2kw, r1=0.01, r2=0.02, ip2=None, dens=(2000, 3000)):
    """Two spheres touching (overlap 1e-5): the ViscElPhys of their contact after one step."""
    O.reset()
    m1 = O.materials.append(ViscElMat(density=dens[0], frictionAngle=0.3, **m1kw))
    m2 = O.materials.append(ViscElMat(density=dens[1], frictionAngle=0.5, **m2kw))
    O.bodies.append(sphere((0, 0, 0), r1, material=m1))
    O.bodies.append(sphere((0, 0, r1 + r2 - 1e-5), r2, material=m2))
    engines(ip2=ip2)
    O.dt = 1e-7
    O.step()
    return O.interactions[0, 1].phys


def constants(p):
    return [p.kn, p.ks, p.cn, p.cs]


def test_attributes_and_defaults_as_in_reference():
    assert ViscElMat().dict() == pytest.approx(dict(cn=math.nan, cs=math.nan, density=1000.0, en=math.nan, et=math.nan,
        frictionAngle=0.5, id=-1, kn=math.nan, ks=math.nan, label='', lubrication=False, mR=0.0, mRtype=1, poisson=0.25,
        roughnessScale=0.001, tc=math.nan, viscoDyn=0.001, young=1e9), nan_ok=True)
    assert set(ViscElPhys().dict()) == {'Fn', 'Fv', 'cn', 'cs', 'kn', 'ks', 'mR', 'mRtype', 'normalForce', 'shearForce',
                                        'tangensOfFrictionAngle'}
    assert set(Ip2_ViscElMat_ViscElMat_ViscElPhys().dict()) == {'en', 'et', 'frictAngle', 'label', 'tc'}


# The reference's constants: kn = m*(pi^2 + ln^2 en)/tc^2 with m* the reduced mass and tc, en, et the materials'
# means; otherwise the materials' values in series, a1*a2/(a1+a2) (the reference's documentation says 2*a1*a2/(a1+a2),
# its runs give a1*a2/(a1+a2)); young gives kn = young*2r, ks = poisson*kn.
@pytest.mark.parametrize("m1, m2, ip2, expected", [
    (dict(tc=1e-4, en=0.5, et=0.6), dict(tc=1e-4, en=0.5, et=0.6), None,
     [8003855.83734654, 2238315.795692915, 107.20423829186964, 22.573095762829507]),
    (dict(tc=1e-4, en=0.5, et=0.6), dict(tc=2e-4, en=0.7, et=0.8), None,
     [3481824.571077867, 981675.3143881225, 52.67055677993551, 10.507509531170445]),
    (dict(kn=1e5, ks=2e4, cn=3, cs=1), dict(kn=3e5, ks=5e4, cn=7, cs=2), None, [75000.0, 14285.714285714284, 2.1, 2 / 3]),
    (dict(), dict(), dict(tc=1e-4, en=0.5, et=0.6), [8003855.83734654, 2238315.795692915, 107.20423829186964, 22.573095762829507]),
    (dict(tc=1e-4, en=.5, et=.5), dict(tc=1e-4, en=.5, et=.5),
     dict(tc=MatchMaker(matches=((0, 1, 3e-4),)), en=MatchMaker(matches=((0, 1, 0.3),)), et=MatchMaker(matches=((0, 1, 0.4),))),
     [972585.9534959618, 262907.33002366056, 62.07002448725765, 13.496789951335435]),
    (dict(tc=1e-4, en=1.0, et=1.0), dict(tc=1e-4, en=1.0, et=1.0), None, [7632314.25976611, 2180661.217076031, 0.0, 0.0]),
    (dict(kn=1e5, ks=2e4, cn=3, cs=1, tc=1e-4, en=.5, et=.5), dict(kn=1e5, ks=2e4, cn=3, cs=1, tc=1e-4, en=.5, et=.5), None,
     [8003855.83734654, 2286815.9535275823, 107.20423829186964, 30.62978236910561]),
    (dict(young=1e7, poisson=0.3, cn=3, cs=1), dict(young=2e7, poisson=0.2, cn=3, cs=1), None, [160000.0, 43636.36363636363, 1.5, 0.5]),
], ids=['tc', 'tc-two-materials', 'kn', 'ip2-numbers', 'ip2-matchmakers', 'en=1', 'tc-first', 'young-cn'])
def test_contact_constants_as_in_reference(m1, m2, ip2, expected):
    p = pair(m1, m2, ip2=Ip2_ViscElMat_ViscElMat_ViscElPhys(**ip2) if ip2 else None)
    assert constants(p) == pytest.approx(expected, rel=1e-13)
    assert p.tangensOfFrictionAngle == pytest.approx(math.tan(0.3), rel=1e-15)


def test_rolling_resistance_coefficient_is_the_harmonic_mean():
    p = pair(dict(tc=1e-4, en=0.5, et=0.6, mR=0.1, mRtype=2), dict(tc=1e-4, en=0.5, et=0.6, mR=0.3, mRtype=2))
    assert p.mR == pytest.approx(0.15, rel=1e-15) and p.mRtype == 2


@pytest.mark.parametrize("other, mass, kn, cn", [
    ('sphere', None, 7707416.732259628, 103.23371094772631),
    ('facet', None, 4335421.9118960425, 58.068962408096056),   # mass 0: the sphere's mass counts twice
    ('sphere-fixed', None, 7707416.732259628, 103.23371094772631),  # fixed or not: the bodies' masses
    ('facet', 1.0, 8598806.629824365, 115.17305330114577),
])
def test_reduced_mass_as_in_reference(other, mass, kn, cn):
    m = mat(density=2000, frictionAngle=0.3, tc=1e-4, en=0.5, et=0.6)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m))
    if other == 'facet':
        z = 0.01 - 1e-5
        O.bodies.append(facet([(-1, -1, z), (1, -1, z), (0, 1, z)], material=m))
    else:
        O.bodies.append(sphere((0, 0, 0.03 - 1e-5), 0.02, material=m, fixed=other == 'sphere-fixed'))
    if mass:
        O.bodies[1].state.mass = mass
    engines()
    O.dt = 1e-7
    O.step()
    p = O.interactions[0, 1].phys
    assert (p.kn, p.cn) == pytest.approx((kn, cn), rel=1e-13)


def test_normal_force_parts_and_no_attraction():
    """Head-on: Fn = kn*u, Fv = cn*(approach speed), normalForce their sum; once the sum is negative the contact
    carries no force but stays until the spheres part."""
    m = mat(tc=1e-4, en=0.6, et=0.7)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m))
    O.bodies.append(sphere((0, 0, 0.0201), 0.01, material=m))
    O.bodies[0].state.vel = (0, 0, 1)
    O.bodies[1].state.vel = (0, 0, -0.5)
    engines()
    O.dt = 2e-6
    pulled = 0
    while O.iter < 200:
        v = O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2]
        O.step()
        if not O.interactions.has(0, 1) or not O.interactions[0, 1].isReal:
            continue
        i = O.interactions[0, 1]
        p, u = i.phys, i.geom.penetrationDepth
        assert p.Fn == pytest.approx(p.kn * u, rel=1e-12)
        assert p.Fv == pytest.approx(-p.cn * v, rel=1e-9, abs=1e-12)
        if p.Fn + p.Fv > 0:
            assert p.normalForce[2] == pytest.approx(p.Fn + p.Fv, rel=1e-12)
        else:
            pulled += 1
            assert p.normalForce.norm() == 0 and p.shearForce.norm() == 0
    assert pulled > 0
    # the reference after 200 steps: body 0 at -0.22471193040579113 m/s (momentum: body 1 at 0.5 m/s more)
    assert O.bodies[0].state.vel[2] == pytest.approx(-0.22471193040579113, rel=1e-12)
    assert O.bodies[1].state.vel[2] == pytest.approx(0.7247119304057907, rel=1e-12)


def trajectories():
    out = {}
    # oblique collision of two materials with spin
    O.reset()
    m1 = mat(tc=1e-4, en=0.6, et=0.7, frictionAngle=0.2)
    m2 = mat(tc=2e-4, en=0.8, et=0.5, density=4000, frictionAngle=0.6)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m1))
    O.bodies.append(sphere((0.005, 0.002, 0.02495), 0.015, material=m2))
    O.bodies[0].state.vel = (0.3, 0, 1)
    O.bodies[0].state.angVel = (10, -20, 30)
    O.bodies[1].state.vel = (-0.2, 0.1, -0.5)
    engines()
    O.dt = 2e-6
    O.run(300, True)
    out['oblique'] = state([0, 1])
    # sliding, then rolling, on a facet under gravity
    O.reset()
    m = mat(tc=5e-4, en=0.3, et=0.3, frictionAngle=0.3)
    O.bodies.append(sphere((0, 0, 0.0101), 0.01, material=m))
    O.bodies.append(facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m))
    O.bodies[0].state.vel = (0.5, 0, -0.2)
    engines((0, 0, -9.81))
    O.dt = 5e-6
    O.run(2000, True)
    out['facet'] = state([0])[0]
    # rolling resistance of both types: a spinning sphere on a fixed spinning one
    for t in (1, 2):
        O.reset()
        m1 = mat(tc=5e-4, en=0.3, et=0.3, frictionAngle=0.5, mR=0.05, mRtype=t)
        m2 = mat(tc=5e-4, en=0.3, et=0.3, frictionAngle=0.5, mR=0.02, mRtype=t)
        O.bodies.append(sphere((0, 0, 0), 0.01, material=m1, fixed=True))
        O.bodies.append(sphere((0.001, 0, 0.0199), 0.01, material=m2))
        O.bodies[0].state.angVel = (0, 0, 5)
        O.bodies[1].state.angVel = (3, -20, 0)
        engines((0, 0, -9.81))
        O.dt = 5e-8
        O.run(1000, True)
        out['roll%d' % t] = state([1])[0]
    # the materials' stiffnesses and viscous constants given directly
    O.reset()
    m1 = mat(kn=1e5, ks=3e4, cn=2, cs=0.5)
    m2 = mat(kn=2e5, ks=5e4, cn=4, cs=1, frictionAngle=0.1)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m1))
    O.bodies.append(sphere((0.004, 0, 0.0199), 0.01, material=m2))
    O.bodies[0].state.vel = (0.2, 0.1, 0.5)
    engines()
    O.dt = 1e-5
    O.run(300, True)
    out['direct'] = state([0, 1])
    return out


def flat(x):
    return [v for row in x for v in (row if isinstance(row, list) else [row])]


@pytest.mark.parametrize("name", sorted(REFERENCE))
def test_trajectories_as_in_reference(name):
    here = trajectories()[name]
    # positions, velocities and spins to 1e-9 of each value's size (seen: 6e-14 at most)
    for a, b in zip(flat(here), flat(REFERENCE[name])):
        assert a == pytest.approx(b, rel=1e-9, abs=1e-12)


def test_young_and_en_give_the_asked_restitution():
    """With young and en (no cn), the viscous constant is solved so that a head-on impact rebounds with en (the normal
    force cut at zero, Schwager & Poeschel 2007). The reference's numerical solution is approximate: it rebounds with
    0.2009, 0.5004 and 0.9288 for en = 0.2, 0.5, 0.925 (doc/compatibility.md)."""
    for en in (0.2, 0.5, 0.925):
        O.reset()
        m = mat(young=1e7, poisson=0.3, en=en)
        O.bodies.append(sphere((0, 0, 0), 0.01, material=m))
        O.bodies.append(sphere((0, 0, 0.0201), 0.01, material=m))
        O.bodies[0].state.vel = (0, 0, 0.5)
        O.bodies[1].state.vel = (0, 0, -0.5)
        engines()
        O.dt = 1e-7
        O.run(30000, True)
        assert O.interactions.countReal() == 0
        assert O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2] == pytest.approx(en, abs=2e-4)


@pytest.mark.parametrize("m1, m2, message", [
    (dict(), dict(), "do not give the contact's constants"),
    (dict(tc=1e-4, en=0.5, et=0.5), dict(kn=1e5, ks=1e4, cn=1, cs=1), "do not give the contact's constants"),
    (dict(kn=1e5, ks=2e4), dict(kn=1e5, ks=2e4), "do not give the contact's constants"),
    (dict(tc=1e-4, en=0.5, et=0.5, lubrication=True), dict(tc=1e-4, en=0.5, et=0.5), "lubrication is not available"),
    (dict(tc=1e-4, en=1.5, et=0.5), dict(tc=1e-4, en=0.5, et=0.5), "en must be in"),
    (dict(tc=-1e-4, en=0.5, et=0.5), dict(tc=1e-4, en=0.5, et=0.5), "tc must be positive"),
    (dict(tc=1e-4, en=0.5, et=0.5, mR=0.1, mRtype=3), dict(tc=1e-4, en=0.5, et=0.5, mR=0.1), "mRtype must be 1 or 2"),
])
def test_bad_materials_are_refused_and_the_scene_is_left_as_it_was(m1, m2, message):
    """The reference aborts the process (terminate called after a std::runtime_error) on the first three and on mRtype 3."""
    with pytest.raises(RuntimeError, match=message):
        pair(m1, m2)
    assert O.iter == 0 and tuple(O.bodies[1].state.pos) == (0, 0, 0.03 - 1e-5)


def test_saved_and_loaded_scene_goes_on_the_same(tmp_path):
    m = mat(tc=1e-4, en=0.6, et=0.7, mR=0.01)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m))
    O.bodies.append(sphere((0.003, 0, 0.0195), 0.01, material=m))
    O.bodies[0].state.vel = (0.1, 0, 0.5)
    engines()
    O.dt = 1e-6
    O.run(20, True)
    f = str(tmp_path / 's.yade.gz')
    O.save(f)
    O.run(50, True)
    after = state([0, 1])
    O.load(f)
    assert isinstance(O.interactions[0, 1].phys, ViscElPhys) and O.materials[0].mR == 0.01
    O.run(50, True)
    assert state([0, 1]) == after


def test_a_spin_made_unstable_by_rolling_resistance_is_diagnosed():
    """O.dt below the stiffnesses' critical step, but a rolling resistance far too large for it: the run stops with a
    StabilityError naming mR (ViscElPhys.diagnoseSpin, what the integrator asks each contact's physics)."""
    from yade import StabilityError
    m = mat(tc=5e-4, en=0.3, et=0.3, frictionAngle=0.5, mR=1e4, mRtype=1)
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m, fixed=True))
    O.bodies.append(sphere((0.001, 0, 0.0199), 0.01, material=m))
    O.bodies[0].state.angVel = (0, 0, 5)
    O.bodies[1].state.angVel = (3, -20, 0)
    engines((0, 0, -9.81))
    O.dt = 5e-5
    with pytest.raises(StabilityError, match=r'body #1: .*Likely cause: the rolling resistance of its contacts '
                       r'\(ViscElPhys\.mR=1e\+04, mRtype=1\): .*use a smaller O\.dt or mR$'):
        O.run(20000, True)
