"""Kinematic and force engines (issue 15): TranslationEngine, RotationEngine, HelixEngine,
HarmonicMotionEngine, HarmonicRotationEngine, CombinedKinematicEngine (built by +),
ServoPIDController, ForceEngine, TorqueEngine, AxialGravityEngine and
CentralConstantAccelerationEngine (CentralGravityEngine), with labels, dead and ids.

Constants named REF_* are what the reference Yade 2023.02a printed for the same scene, with
`yade-double -n -x script.py`, the script being the body of the test that uses them (each
printed '%.17g' of the quantities compared)."""
import math
import warnings

import pytest

import yade
from yade import (O, Vector3, Quaternion, ForceResetter, NewtonIntegrator, InsertionSortCollider, InteractionLoop,
                  Bo1_Sphere_Aabb, Bo1_Facet_Aabb, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom,
                  Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, PyRunner,
                  KinematicEngine, TranslationEngine, RotationEngine, HelixEngine, HarmonicMotionEngine,
                  HarmonicRotationEngine, CombinedKinematicEngine, ServoPIDController, ForceEngine, TorqueEngine,
                  AxialGravityEngine, CentralConstantAccelerationEngine, CentralGravityEngine)
from yade.utils import sphere, facet

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def close(a, b, tol=1e-12):
    return all(abs(x - y) <= tol * max(1.0, abs(y)) for x, y in zip(a, b))


def rotate(v, axis, angle):
    """Rodrigues' rotation of v about the unit axis."""
    a = Vector3(axis).normalized()
    v = Vector3(v)
    return v * math.cos(angle) + a.cross(v) * math.sin(angle) + a * a.dot(v) * (1 - math.cos(angle))


# --- defaults --------------------------------------------------------------------------------------

def test_defaults_match_the_reference():
    assert isinstance(TranslationEngine(), KinematicEngine)
    assert TranslationEngine().velocity == 0 and TranslationEngine().translationAxis == Vector3(0, 0, 0)
    r = RotationEngine()
    assert (r.angularVelocity, r.rotationAxis, r.rotateAroundZero, r.zeroPoint) == (0, Vector3(1, 0, 0), False, Vector3(0, 0, 0))
    h = HelixEngine()
    assert isinstance(h, RotationEngine) and h.linearVelocity == 0 and h.angleTurned == 0
    hm = HarmonicMotionEngine()
    assert hm.A == Vector3(0, 0, 0) and hm.f == Vector3(0, 0, 0) and hm.fi == Vector3(math.pi / 2, math.pi / 2, math.pi / 2)
    hr = HarmonicRotationEngine()
    assert isinstance(hr, RotationEngine) and (hr.A, hr.f, hr.fi) == (0, 0, math.pi / 2)
    s = ServoPIDController()
    assert isinstance(s, TranslationEngine)
    assert (s.iterPeriod, s.iterPrevStart, s.kP, s.kI, s.kD, s.maxVelocity, s.target) == (100, -1, 0, 0, 0, 0, 0)
    assert CombinedKinematicEngine().comb == [] and CombinedKinematicEngine().ids == []
    assert ForceEngine().force == Vector3(0, 0, 0) and TorqueEngine().moment == Vector3(0, 0, 0)
    a = AxialGravityEngine()
    assert (a.axisPoint, a.axisDirection, a.acceleration, a.mask) == (Vector3(0, 0, 0), Vector3(1, 0, 0), 0, 0)
    c = CentralConstantAccelerationEngine()
    assert (c.centralBody, c.accel, c.reciprocal, c.mask) == (-1, 0, False, 0)


def test_axes_are_normalized():
    assert TranslationEngine(translationAxis=(2, 0, 0)).translationAxis == Vector3(1, 0, 0)
    assert RotationEngine(rotationAxis=(0, 0, 3)).rotationAxis == Vector3(0, 0, 1)


# --- TranslationEngine -----------------------------------------------------------------------------

def test_translation_is_v_n_dt_for_fixed_and_free_bodies():
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    b = O.bodies.append(sphere((5, 2, 3), 1))
    O.engines = [ForceResetter(), TranslationEngine(velocity=2., translationAxis=(0, 3, 4), ids=[a, b]), NewtonIntegrator()]
    O.dt = 1e-3
    n = 250
    O.run(n, True)
    for i, p0 in ((a, (1, 2, 3)), (b, (5, 2, 3))):
        expected = Vector3(p0) + Vector3(0, 0.6, 0.8) * (2. * n * 1e-3)
        assert close(O.bodies[i].state.pos, expected, 1e-13)
        assert close(O.bodies[i].state.vel, (0, 1.2, 1.6))


def test_each_kinematic_engine_resets_the_velocities_first():
    # REF: two TranslationEngines on one body: the second one's velocity only; a RotationEngine
    # without rotateAroundZero zeroes the linear velocity set from Python
    a = O.bodies.append(sphere((0, 0, 0), 1, fixed=True))
    b = O.bodies.append(sphere((0, 5, 0), 1, fixed=True))
    O.bodies[b].state.vel = (3, 3, 3)
    O.engines = [TranslationEngine(velocity=1., translationAxis=(2, 0, 0), ids=[a]),
                 TranslationEngine(velocity=2., translationAxis=(0, 1, 0), ids=[a]),
                 RotationEngine(angularVelocity=0.5, rotationAxis=(0, 0, 3), ids=[b]), NewtonIntegrator()]
    O.dt = 0.1
    O.step()
    assert close(O.bodies[a].state.pos, (0, 0.2, 0)) and O.bodies[a].state.vel == Vector3(0, 2, 0)
    sb = O.bodies[b].state
    assert sb.pos == Vector3(0, 5, 0) and sb.vel == Vector3(0, 0, 0) and sb.angVel == Vector3(0, 0, 0.5)
    axis, angle = sb.ori.toAxisAngle()
    assert close(axis, (0, 0, 1)) and angle == pytest.approx(0.05, rel=1e-14)


# --- RotationEngine --------------------------------------------------------------------------------

REF_ROT_FIXED = (3.1608383156451789, -0.48199331544028268, 3.3211549997951044)
REF_ROT_FIXED_VEL = (3.0168727670660367, -0.56313130018735835, -2.4537414668786894)
REF_ROT_FREE = (3.1022786751192286, -0.45931938874516776, 3.2570407136259458)
REF_ROT_FREE_VEL = (2.9173084995617327, -0.55675895760234351, -2.460549541959367)


def test_rotation_around_zero_point_velocity_has_the_reference_bits():
    """The velocity of a body turned around zero is the chord of one step's turn over dt, the turn applied as a
    quaternion: the reference's bits (as a rotation matrix the x component was 2e-12 off, and a turning drum's
    facets drifted away from the reference's run)."""
    f = O.bodies.append(sphere((-3.5163770194372694, -2.9530574230317703, 4.0949540886456273), 0.1, fixed=True))
    O.engines = [ForceResetter(), NewtonIntegrator(),  # (in this order in the reference's baraban.py)
                 RotationEngine(ids=[f], rotationAxis=(0, 0, 1), rotateAroundZero=True, angularVelocity=0.5)]
    O.dt = 2e-4
    O.step()
    assert list(O.bodies[f].state.vel) == [1.4766166184809748, -1.7581146803524739, 0]
    O.step()
    assert list(O.bodies[f].state.pos) == [-3.5160816961135732, -2.9534090459678408, 4.0949540886456273]
    # a body whose rotations are all blocked turns as the engine prescribes, by the reference's formula
    # (the spheres' faster one is an ulp off: after 1 000 steps z was 0.049929231695205183)
    O.run(998, True)
    ori = O.bodies[f].state.ori
    assert [ori[i] for i in range(4)] == [0, 0, 0.049929231695205557, 0.99875275810499098]
    assert list(O.bodies[f].state.pos) == [-3.2043248885487756, -3.289035952247461, 4.0949540886456273]


def test_rotation_around_zero_point_follows_the_circle():
    zp = Vector3(0.5, -1, 0.2)
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    c = O.bodies.append(sphere((1, 2, 3), 1))  # dynamic: gravity adds g·dt each step
    O.engines = [ForceResetter(), RotationEngine(angularVelocity=2., rotationAxis=(1, 1, 1), rotateAroundZero=True, zeroPoint=zp, ids=[a, c]),
                 NewtonIntegrator(gravity=(0, 0, -10), damping=0)]
    O.dt = 0.01
    O.run(100, True)
    s = O.bodies[a].state
    # analytic: the relative position turned by ω·t = 2 rad; the distance to the axis is kept
    r0 = Vector3(1, 2, 3) - zp
    assert close(s.pos, rotate(r0, (1, 1, 1), 2.0) + zp, 1e-13)
    u = Vector3(1, 1, 1).normalized()
    dist = lambda r: (r - u * u.dot(r)).norm()
    assert dist(s.pos - zp) == pytest.approx(dist(r0), rel=1e-14)
    axis, angle = s.ori.toAxisAngle()
    assert close(axis, u) and angle == pytest.approx(2.0, rel=1e-13)
    assert close(s.angVel, u * 2.0)
    # the reference's figures, for the fixed body and for the dynamic one under gravity
    assert close(s.pos, REF_ROT_FIXED, 1e-13) and close(s.vel, REF_ROT_FIXED_VEL, 1e-11)
    assert close(O.bodies[c].state.pos, REF_ROT_FREE, 1e-13) and close(O.bodies[c].state.vel, REF_ROT_FREE_VEL, 1e-11)


def test_half_turns_with_dt_one_are_exact():
    # as the reference's engines test: ω = π, dt = 1: the body is on the circle after every step
    i = O.bodies.append(sphere((0, 10, 10), 1, fixed=True))
    O.engines = [RotationEngine(angularVelocity=math.pi, rotationAxis=(0, 1, 0), rotateAroundZero=True, ids=[i]), NewtonIntegrator()]
    O.dt = 1.0
    for k in (1, 2, 3):
        O.step()
        p = O.bodies[i].state.pos
        assert close(p, (10 * math.sin(math.pi * k), 10, 10 * math.cos(math.pi * k)), 1e-13)


# --- HelixEngine -----------------------------------------------------------------------------------

REF_HELIX_Z = (-1.142639663747653, 1.9220755965441767, 3.1500000000000057)
REF_HELIX_X = (1.1499999999999946, -1.4438083426874102, 3.3038488872202119)


@pytest.mark.parametrize('axis,ref', [((0, 0, 1), REF_HELIX_Z), ((1, 0, 0), REF_HELIX_X)])
def test_helix_turns_and_advances(axis, ref):
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    h = HelixEngine(angularVelocity=2., linearVelocity=0.3, rotationAxis=axis, zeroPoint=(0, 0, 0), ids=[a])
    O.engines = [h, NewtonIntegrator()]
    O.dt = 0.01
    O.run(50, True)
    p = O.bodies[a].state.pos
    assert h.angleTurned == pytest.approx(1.0, rel=1e-14) and h.rotateAroundZero
    expected = rotate((1, 2, 3), axis, 1.0) + Vector3(axis) * 0.3 * 0.5
    assert close(p, expected, 1e-13)
    assert close(p, ref, 1e-13)


# --- harmonic engines ------------------------------------------------------------------------------

REF_HM_1 = (1, 1.9682772912310225, 3)
REF_HM_33 = (0.84131441160377218, 2.0096525859476757, 3)
REF_HM_33_VEL = (0.9682554971992281, -2.5660537854195975, 0)
REF_HM_DEFAULT_FI_33 = (1.0746717698424142, 2.0124837035201817, 3)


def test_harmonic_motion():
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    A, f, fi = Vector3(0.1, 0.2, 0), Vector3(2, 3, 1), Vector3(0, 1, 0.5)
    O.engines = [HarmonicMotionEngine(A=A, f=f, fi=fi, ids=[a]), NewtonIntegrator()]
    O.dt = 0.01
    O.step()
    assert close(O.bodies[a].state.pos, REF_HM_1, 1e-14)
    O.run(32, True)
    s = O.bodies[a].state
    assert close(s.pos, REF_HM_33, 1e-13) and close(s.vel, REF_HM_33_VEL, 1e-12)
    # the velocity of the last step is -A·ω·sin(ω·t + fi) at its start, t = 32·dt
    for k in range(3):
        w = 2 * math.pi * f[k]
        assert s.vel[k] == pytest.approx(-A[k] * w * math.sin(w * 0.32 + fi[k]), abs=1e-12)
    # and the position A·(cos(ω·t + fi) - cos(fi)) to first order in dt
    for k in range(3):
        w = 2 * math.pi * f[k]
        exact = (1, 2, 3)[k] + A[k] * (math.cos(w * 0.33 + fi[k]) - math.cos(fi[k]))
        assert s.pos[k] == pytest.approx(exact, abs=A[k] * w * w * 0.01 * 0.33 + 1e-15)


def test_harmonic_motion_default_phase_oscillates_around_the_start():
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    O.engines = [HarmonicMotionEngine(A=(0.1, 0.2, 0), f=(2, 3, 1), ids=[a]), NewtonIntegrator()]
    O.dt = 0.01
    O.run(33, True)
    assert close(O.bodies[a].state.pos, REF_HM_DEFAULT_FI_33, 1e-13)


REF_HR_1 = (1.0149511272469451, 1.9924543179958119, 3)
REF_HR_33 = (1.7315314457683117, 1.4148494097661068, 3)
REF_HR_33_OMEGA = 3.3242732800158432


def test_harmonic_rotation():
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    e = HarmonicRotationEngine(A=0.3, f=2, fi=0.2, rotationAxis=(0, 0, 1), rotateAroundZero=True, zeroPoint=(0, 0, 0), ids=[a])
    O.engines = [e, NewtonIntegrator()]
    O.dt = 0.01
    O.step()
    w = 4 * math.pi
    assert e.angularVelocity == pytest.approx(-0.3 * w * math.sin(0.2), rel=1e-14)
    assert close(O.bodies[a].state.pos, REF_HR_1, 1e-14)
    O.run(32, True)
    assert e.angularVelocity == pytest.approx(REF_HR_33_OMEGA, rel=1e-12)
    assert close(O.bodies[a].state.pos, REF_HR_33, 1e-12)
    # the distance to the axis is kept
    p = O.bodies[a].state.pos
    assert math.hypot(p[0], p[1]) == pytest.approx(math.sqrt(5), rel=1e-13)


# --- CombinedKinematicEngine -----------------------------------------------------------------------

REF_COMBINED_3 = (0.87827252697631497, 2.056365086349853, 3.0299999999999994)


def test_plus_builds_a_combined_engine():
    t = TranslationEngine(velocity=1, translationAxis=(0, 0, 1), ids=[0])
    r = RotationEngine(angularVelocity=2, rotationAxis=(0, 0, 1), rotateAroundZero=True, ids=[1])
    c = t + r
    assert type(c) is CombinedKinematicEngine and c.ids == [0] and c.comb[0] is t and c.comb[1] is r
    c2 = c + TranslationEngine()
    assert c2 is c and [type(x).__name__ for x in c.comb] == ['TranslationEngine', 'RotationEngine', 'TranslationEngine']
    with pytest.raises(TypeError):
        t + 1


@pytest.mark.parametrize('translation_first', [True, False])
def test_combined_motion_is_the_sum(translation_first):
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    t = TranslationEngine(velocity=1, translationAxis=(0, 0, 1), ids=[a])
    r = RotationEngine(angularVelocity=2, rotationAxis=(0, 0, 1), rotateAroundZero=True, zeroPoint=(0, 0, 0), ids=[a])
    O.engines = [t + r if translation_first else r + t, NewtonIntegrator()]
    O.dt = 0.01
    O.run(3, True)
    s = O.bodies[a].state
    assert close(s.pos, rotate((1, 2, 0), (0, 0, 1), 0.06) + Vector3(0, 0, 3.03), 1e-13)
    assert close(s.pos, REF_COMBINED_3, 1e-13)
    assert s.angVel == Vector3(0, 0, 2) and s.vel[2] == 1


def test_combined_engine_acts_on_its_own_ids():
    a = O.bodies.append(sphere((0, 0, 0), 1, fixed=True))
    b = O.bodies.append(sphere((4, 0, 0), 1, fixed=True))
    c = TranslationEngine(velocity=1, translationAxis=(1, 0, 0), ids=[a]) + TranslationEngine(velocity=2, translationAxis=(0, 1, 0), ids=[b])
    O.engines = [c, NewtonIntegrator()]
    O.dt = 0.5
    O.step()
    assert O.bodies[a].state.pos == Vector3(0.5, 1, 0) and O.bodies[b].state.pos == Vector3(4, 0, 0)


# --- ServoPIDController ----------------------------------------------------------------------------

# REF: forces (0.5,0,-4) on body a and (0,0,1) on body b, axis (0,0,2), target 1.5; curVel of steps 1..5
REF_SERVO_CURVEL = {1: [15, 12, 16.5, 21, 25.5], 3: [15, 15, 15, 12, 12]}
REF_SERVO_Z5 = {1: 3.8999999999999999, 3: 3.6899999999999999}


@pytest.mark.parametrize('period', [1, 3])
def test_servo_pid_terms(period):
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    b = O.bodies.append(sphere((1, 5, 3), 1, fixed=True))
    s = ServoPIDController(ids=[a, b], axis=(0, 0, 2), target=1.5, kP=2, kI=3, kD=5, iterPeriod=period, maxVelocity=100)
    O.engines = [ForceResetter(), ForceEngine(force=(0.5, 0, -4), ids=[a]), ForceEngine(force=(0, 0, 1), ids=[b]), s, NewtonIntegrator()]
    O.dt = 0.01
    seen = []
    for k in range(5):
        O.step()
        seen.append(s.curVel)
        assert s.current == Vector3(0, 0, -3) and s.errorCur == 1.5 and s.errorPrev == 1.5
        assert s.translationAxis == Vector3(0, 0, 1) and s.velocity == s.curVel
        assert O.bodies[a].state.vel == Vector3(0, 0, s.curVel)
    assert seen == REF_SERVO_CURVEL[period]
    assert O.bodies[a].state.pos[2] == pytest.approx(REF_SERVO_Z5[period], rel=1e-15)


def test_servo_pid_error_sign_and_clamp():
    # REF: error = |F·axis| - target; the velocity is limited to maxVelocity
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    for target, fz, maxv, expected in ((5, -4, 100, -1), (-5, -4, 100, 9), (5, 4, 100, -1), (1, 4, 0.5, 0.5), (1, 4, 0, 0)):
        s = ServoPIDController(ids=[a], axis=(0, 0, 1), target=target, kP=1, iterPeriod=1, maxVelocity=maxv)
        O.engines = [ForceResetter(), ForceEngine(force=(0.5, 0, fz), ids=[a]), s, NewtonIntegrator()]
        O.step()
        assert s.curVel == expected


def test_servo_pid_reaches_its_target_force():
    # a servo-driven fixed sphere pushes down on a sphere held in place (translations blocked):
    # the contact force on it converges to the target
    top = O.bodies.append(sphere((0, 0, 0.2), 0.1, fixed=True))
    bottom = O.bodies.append(sphere((0, 0, 0), 0.1))
    O.bodies[bottom].state.blockedDOFs = 'xyz'
    servo = ServoPIDController(ids=[top], axis=(0, 0, 1), target=50., kP=1e-3, iterPeriod=1, maxVelocity=1.)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 servo, NewtonIntegrator(damping=0)]
    O.dt = 1e-5
    O.run(1000, True)
    # REF (the same scene; the reference needs O.forces.f(0, sync=True) in a PyRunner before the servo)
    assert O.forces.f(top)[2] == pytest.approx(49.997819633995633, rel=1e-9)
    assert O.bodies[top].state.pos[2] == pytest.approx(0.19995000215856235, rel=1e-12)
    O.run(2000, True)
    assert O.forces.f(top)[2] == pytest.approx(50., rel=1e-6)
    assert abs(servo.curVel) < 1e-6
    i = O.interactions[top, bottom]
    assert i.phys.normalForce.norm() == pytest.approx(50., rel=1e-6)


# --- force engines ---------------------------------------------------------------------------------

def test_force_and_torque_engines_give_the_analytic_accelerations():
    a = O.bodies.append(sphere((0, 0, 0), 0.5))
    m, I = O.bodies[a].state.mass, O.bodies[a].state.inertia[0]
    F, M = Vector3(1, -2, 3), Vector3(0, 0, 4)
    O.engines = [ForceResetter(), ForceEngine(force=F, ids=[a]), TorqueEngine(moment=M, ids=[a]), NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    n = 100
    O.run(n, True)
    s = O.bodies[a].state
    assert close(s.vel, F / m * (n * O.dt), 1e-12)
    assert close(s.pos, F / m * (O.dt ** 2 * n * (n + 1) / 2), 1e-12)  # leapfrog: Σ v_k·dt
    assert close(s.angVel, M / I * (n * O.dt), 1e-12)
    assert close(O.forces.f(a), F) and close(O.forces.t(a), M)


def test_axial_gravity_engine():
    bodies = [O.bodies.append(sphere(p, r, **kw)) for p, r, kw in
              (((1, 2, 3), 1, {}), ((1, 5, 3), 0.5, {'fixed': True}), ((0, 0, 0), 0.5, {}), ((4, 1, -2), 0.7, {'mask': 2}))]
    e = AxialGravityEngine(axisPoint=(0, 1, 0), axisDirection=(2, 0, 0), acceleration=3.)
    O.engines = [ForceResetter(), e, NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    O.step()
    for i in bodies:
        p, m = O.bodies[i].state.pos, O.bodies[i].state.mass
        radial = Vector3(0, p[1] - 1, p[2])
        assert close(O.forces.f(i), radial * (-3 * m / radial.norm()), 1e-14)
    # REF: the force on body 0 and on the fixed body 1
    assert close(O.forces.f(0), (0, -3973.8353063184409, -11921.505918955321), 1e-14)
    assert close(O.forces.f(1), (0, -1256.6370614359175, -942.47779607693792), 1e-14)
    e.mask = 2
    O.step()
    assert O.forces.f(0) == Vector3(0, 0, 0) and O.forces.f(3)[2] == pytest.approx(4310.2651207251947, rel=1e-14)


def test_central_constant_acceleration_engine():
    bodies = [O.bodies.append(sphere(p, r)) for p, r in (((1, 2, 3), 1), ((1, 5, 3), 0.5), ((0, 0, 0), 0.5), ((4, 1, -2), 0.7))]
    e = CentralConstantAccelerationEngine(centralBody=0, accel=2.)
    O.engines = [ForceResetter(), e]
    O.step()
    center = O.bodies[0].state.pos
    total = Vector3(0, 0, 0)
    for i in bodies[1:]:
        s = O.bodies[i].state
        d = center - s.pos
        assert close(O.forces.f(i), d * (2 * s.mass / d.norm()), 1e-14)
        total += O.forces.f(i)
    assert O.forces.f(0) == Vector3(0, 0, 0)
    e.reciprocal = True
    O.step()
    assert close(O.forces.f(0), -total, 1e-14)
    with pytest.warns(DeprecationWarning):
        old = CentralGravityEngine(accel=1.)
    assert type(old) is CentralConstantAccelerationEngine and old.accel == 1.


# --- labels, dead, ids -----------------------------------------------------------------------------

def test_labels_dead_and_bad_ids():
    import builtins
    a = O.bodies.append(sphere((0, 0, 0), 1, fixed=True))
    t = TranslationEngine(velocity=1, translationAxis=(1, 0, 0), ids=[a], label='myTrans')
    r = RotationEngine(label='myRot')
    c = TranslationEngine(label='inner1') + RotationEngine(label='inner2')
    c.label = 'myComb'
    O.engines = [t, r, c, NewtonIntegrator()]
    assert builtins.myTrans is t and builtins.myRot is r and builtins.myComb is c
    assert builtins.inner1 is c.comb[0] and builtins.inner2 is c.comb[1]
    t.dead = True
    O.dt = 1.
    O.step()
    assert O.bodies[a].state.pos == Vector3(0, 0, 0)
    t.dead = False
    t.ids = [a, 55]
    with pytest.raises(IndexError, match='55'):
        O.step()
    O.engines = [ForceEngine(ids=[-1])]
    with pytest.raises(IndexError):
        O.step()
    O.engines = [RotationEngine(ids=[a], rotationAxis=(0, 0, 0), angularVelocity=1.)]
    with pytest.raises(ValueError, match='rotationAxis'):
        O.step()


# --- a facet turned by a RotationEngine, as in a rotating drum --------------------------------------

REF_DRUM = {  # iter: (facet pos, facet angle, sphere pos, sphere vel)
    1000: ((0.021744641219360372, -0.3664176910226058, 0), 0.15000000000000099,
           (0.19247298023523707, -0.0039312589989467326, 0.099975464673608724), (-0.088045459344895452, -0.048267242926948346, -0.0035372157311519821)),
    3000: ((0.083352292905220504, -0.44121497380140756, 0), 0.45000000000000379,
           (0.1760673189417539, -0.013869897784536718, 0.099969180981668015), (-0.073941478714396269, -0.051774853860140094, -5.4602137492784242e-10)),
}


def test_rotating_facet_drags_a_resting_sphere_as_the_reference():
    f = O.bodies.append(facet([(-1, -1, 0), (1, -1, 0), (0, 1.5, 0)], fixed=True))
    s = O.bodies.append(sphere((0.2, 0, 0.0995), 0.1))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 RotationEngine(ids=[f], rotationAxis=(0, 0, 1), rotateAroundZero=True, zeroPoint=(0.3, -0.2, 0), angularVelocity=1.5),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4)]
    O.dt = 1e-4
    for n in (1000, 3000):
        O.run(n - O.iter, True)
        fp, fangle, sp, sv = REF_DRUM[n]
        st = O.bodies[f].state
        assert close(st.pos, fp, 1e-12)
        assert st.ori.toAxisAngle()[1] == pytest.approx(fangle, rel=1e-12)
        assert close(O.bodies[s].state.pos, sp, 1e-9)
        assert close(O.bodies[s].state.vel, sv, 1e-7)
        assert O.interactions.countReal() == 1


def test_engines_survive_save_and_load():
    a = O.bodies.append(sphere((1, 2, 3), 1, fixed=True))
    c = TranslationEngine(velocity=1, translationAxis=(0, 0, 1), ids=[a]) + RotationEngine(angularVelocity=2, rotationAxis=(0, 0, 1), rotateAroundZero=True)
    O.engines = [c, ServoPIDController(axis=(0, 0, 1), kP=2.), HarmonicMotionEngine(A=(1, 0, 0)), ForceEngine(force=(1, 2, 3)), NewtonIntegrator()]
    O.dt = 0.01
    O.saveTmp()
    O.run(3, True)
    first = Vector3(O.bodies[a].state.pos)
    O.loadTmp()
    e = O.engines
    assert [type(x).__name__ for x in e[0].comb] == ['TranslationEngine', 'RotationEngine'] and e[0].ids == [a]
    assert e[1].kP == 2. and e[2].A == Vector3(1, 0, 0) and e[3].force == Vector3(1, 2, 3)
    O.run(3, True)
    assert O.bodies[a].state.pos == first and close(first, REF_COMBINED_3, 1e-13)


def test_rotating_drum_example(tmp_path):
    """examples/rotating-drum.py with the launcher: the drum turns by ω·t and drags the bed up its
    rising side (the reference printed 'drum turned 1.4999 rad' and a displacement of 15.7°; the
    bed's flow is chaotic, ours gives 16.6°)."""
    import os
    import pathlib
    import re
    import subprocess
    repo = pathlib.Path(__file__).resolve().parent.parent
    env = dict(os.environ)
    env.setdefault('YADE_BUILD_DIR', str(repo / 'build'))
    r = subprocess.run(['/usr/bin/python3', str(repo / 'yade'), '-n', '-x', str(repo / 'examples' / 'rotating-drum.py')],
                       capture_output=True, text=True, timeout=300, env=env, cwd=str(tmp_path))
    assert r.returncode == 0, r.stderr
    turned = re.search(r'drum turned ([\d.]+) rad \(omega\*t = ([\d.]+) rad\)', r.stdout)
    assert turned and turned.group(1) == turned.group(2) == '1.4999'
    bed = re.search(r'displaced by ([-\d.]+) degrees', r.stdout)
    assert bed and 8 < float(bed.group(1)) < 25


# --- DragEngine, LinearDragEngine -----------------------------------------------------------------------

def test_drag_engines_as_the_reference():
    from yade import DragEngine, LinearDragEngine
    assert (DragEngine().Rho, DragEngine().Cd, LinearDragEngine().nu) == (1.225, 0.47, 0.001)  # REF defaults
    O.bodies.append([sphere((0, 0, 0), 0.1), sphere((1, 0, 0), 0.2), facet([(5, 5, 5), (6, 5, 5), (5, 6, 5)])])
    O.bodies[0].state.vel = (3, -4, 0)
    O.bodies[1].state.vel = (0, 0, 2)
    O.engines = [ForceResetter(), DragEngine(ids=[0, 1, 2], Rho=1000, Cd=0.5), LinearDragEngine(ids=[1, 2], nu=0.01),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-4
    O.step()
    # -v/|v|·(1/2·rho·|v|²·Cd·pi·r²), and for body 1 also -6·pi·nu·r·v; the facet gets nothing
    assert O.forces.f(0) == Vector3(-117.8097245096172401, 157.0796326794896913, 0)  # REF
    assert O.forces.f(1) == Vector3(0, 0, -125.7391043672778892)  # REF
    assert O.forces.f(2) == Vector3(0, 0, 0)  # REF
    assert O.bodies[0].state.vel == Vector3(2.996624999999999872, -3.995499999999999829, 0)  # REF


def test_linear_drag_terminal_velocity():
    from yade import LinearDragEngine
    O.bodies.append(sphere((0, 0, 0), 0.01))
    O.engines = [ForceResetter(), LinearDragEngine(ids=[0], nu=1.0), NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-5
    O.run(20000, True)
    assert O.bodies[0].state.vel[2] == -0.21783745513911598  # REF (NewtonIntegrator's default damping 0.2)
    # without numerical damping: v(t) = -v_inf (1 - exp(-t/tau)), v_inf = m g / b, tau = m / b
    O.engines = O.engines[:2] + [NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.bodies[0].state.vel = Vector3.Zero
    O.resetTime()
    O.run(20000, True)
    m = O.bodies[0].state.mass
    b = 6 * math.pi * 1.0 * 0.01
    assert O.bodies[0].state.vel[2] == pytest.approx(-m * 9.81 / b * (1 - math.exp(-O.time * b / m)), rel=1e-4)


def test_drag_engines_refuse_ids_of_no_body():
    from yade import DragEngine
    O.bodies.append(sphere((0, 0, 0), 0.1))
    O.engines = [ForceResetter(), DragEngine(ids=[7]), NewtonIntegrator()]
    with pytest.raises(IndexError, match="DragEngine.ids contains 7"):  # (the reference skips it silently)
        O.step()


# --- StepDisplacer --------------------------------------------------------------------------------------

def test_step_displacer_as_the_reference():
    from yade import StepDisplacer
    q = Quaternion((0, 0, 1), 0.1)
    O.bodies.append([sphere((0, 0, 0), 0.1), sphere((1, 0, 0), 0.2)])
    O.bodies[1].state.vel = (1, 2, 3)
    O.engines = [ForceResetter(), StepDisplacer(ids=[0, 1], mov=(0.01, 0, -0.02), rot=q), NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-3
    O.run(3, True)
    assert O.bodies[0].state.pos == Vector3(0.02999999999999999889, 0, -0.06004800000000001109)  # REF
    assert O.bodies[1].state.pos == Vector3(1.032999999999999696, 0.006000000000000000125, -0.05107199999999999934)  # REF
    assert O.bodies[0].state.ori.toAxisAngle()[1] == pytest.approx(0.3, abs=1e-15)
    assert O.bodies[1].state.vel == Vector3(1, 2, 2.963999999999999968)  # REF
    # setVelocities: velocities mov/dt and rot/dt, the integrator moves the bodies (fixed ones too)
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 0.1), sphere((1, 0, 0), 0.2, fixed=True)])
    O.engines = [ForceResetter(), StepDisplacer(ids=[0, 1], mov=(0.01, 0, -0.02), rot=q, setVelocities=True),
                 NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-3
    O.run(3, True)
    assert O.bodies[0].state.pos == Vector3(0.02999999999999999889, 0, -0.06002399999999999403)  # REF
    assert O.bodies[0].state.vel == Vector3(10, 0, -20.00799999999999912)  # REF
    assert O.bodies[1].state.vel == Vector3(10, 0, -20) and O.bodies[1].state.angVel == Vector3(0, 0, 100)  # REF


def test_step_displacer_moves_a_sphere_into_contact():
    from yade import StepDisplacer
    O.bodies.append([sphere((0, 0, 0), 0.5, fixed=True), sphere((1.2, 0, 0), 0.5)])  # (two fixed bodies never interact)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 StepDisplacer(ids=[1], mov=(-0.01, 0, 0)), NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-3
    O.run(25, True)  # the gap of 0.2 closes after 20 steps
    assert O.interactions.countReal() == 1
    # (the contact force pushes body 1 back a little; the loop ran before the last move)
    assert O.bodies[1].state.pos[0] == pytest.approx(1.2 - 0.25, abs=5e-3)
    assert O.interactions[0, 1].geom.penetrationDepth == pytest.approx(0.04, abs=5e-3)
