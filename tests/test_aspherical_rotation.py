"""Rotation of aspherical bodies (the manual, 3.5.2): a body with unequal principal moments of inertia
(a box of unequal sides) turns by Euler's equations in its principal frame, the SPIRAL scheme
(NewtonIntegrator.exactAsphericalRot, on by default). Checked against the mechanics of a free rigid
body: angular momentum and kinetic energy conserved (second order in dt), the intermediate-axis
flip, steady spin about a major axis, a constant torque about a principal axis."""
import pytest

from yade import O, ForceResetter, NewtonIntegrator, TorqueEngine, Quaternion, Vector3
from yade.utils import box, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

# a box of half-sides 0.1, 0.2, 0.3 (density 1000): principal moments 2.08, 1.6, 0.8 kg·m²


def spinning_box(angVel, exact=True, dt=1e-4, ori=None, damping=0):
    b = box((0, 0, 0), (.1, .2, .3))
    if ori is not None:
        b.state.ori = ori
    O.bodies.append(b)
    b.state.angVel = angVel
    # an aspherical body is driven by its angular momentum (as in the reference): the one of that spin
    q, I = Quaternion(b.state.ori), b.state.inertia
    w = q.conjugate() * Vector3(*angVel)
    b.state.angMom = q * Vector3(I[0] * w[0], I[1] * w[1], I[2] * w[2])
    O.engines = [ForceResetter(), NewtonIntegrator(damping=damping, exactAsphericalRot=exact)]
    O.dt = dt
    return b


def body_spin(b):
    return Quaternion(b.state.ori).conjugate() * b.state.angVel


def momentum_now(b):
    """L at the on-step time: the orientation now, the body-frame spin averaged over the half steps
    around it (the integrator keeps mid-step velocities); runs one step."""
    I = b.state.inertia
    q, w1 = Quaternion(b.state.ori), body_spin(b)
    O.run(1, True)
    w = .5 * (w1 + body_spin(b))
    return q * Vector3(I[0] * w[0], I[1] * w[1], I[2] * w[2]), .5 * (I[0] * w[0] ** 2 + I[1] * w[1] ** 2 + I[2] * w[2] ** 2)


def worst_drift(dt, exact=True, seconds=2.):
    b = spinning_box((3, -2, 5), exact=exact, dt=dt, ori=Quaternion((1, 2, 3), .7))
    L0, E0 = momentum_now(b)
    dL = dE = 0
    for _ in range(20):
        O.run(int(seconds / dt / 20) - 1, True)
        L, E = momentum_now(b)
        dL, dE = max(dL, (L - L0).norm() / L0.norm()), max(dE, abs(E - E0) / E0)
    return dL, dE


def test_inertia_of_the_box():
    b = box((0, 0, 0), (.1, .2, .3))
    assert tuple(b.state.inertia) == pytest.approx((2.08, 1.6, .8), rel=1e-14)


def test_free_tumbling_conserves_angular_momentum_and_energy_to_second_order():
    coarse, fine = worst_drift(2e-4), worst_drift(1e-4)
    # measured over 2 s of tumbling (dt 2e-4, 1e-4): |ΔL|/L 9.4e-9, 2.3e-9; ΔE/E 7.0e-9, 1.8e-9 (with the
    # on-step spin estimated as the mean of the two half steps': the estimate's own error, second order too)
    assert coarse[0] < 2e-8 and fine[0] < 5e-9 and coarse[0] / fine[0] > 3.5
    assert coarse[1] < 1.5e-8 and fine[1] < 4e-9 and coarse[1] / fine[1] > 3.5


def test_the_spherical_update_does_not_conserve_it():
    dL, _ = worst_drift(1e-4, exact=False)
    assert dL > .1  # (treating the box as a sphere: 50 % off within 2 s)


def test_spin_about_the_intermediate_axis_flips_and_about_the_major_one_stays():
    b = spinning_box((.01, 10, .01))
    flipped = False
    for _ in range(200):
        O.run(100, True)
        flipped |= body_spin(b)[1] < -9
    assert flipped  # (the tennis-racket theorem: y, of the middle moment, is unstable)
    O.reset()
    b = spinning_box((.01, 10, .01), exact=False)
    O.run(20000, True)
    assert body_spin(b)[1] == pytest.approx(10, rel=1e-12)  # (the spherical update: no flip)
    O.reset()
    b = spinning_box((10, .01, .01))
    for _ in range(200):
        O.run(100, True)
        w = body_spin(b)
        assert w[0] > 9.999 and abs(w[1]) < .05 and abs(w[2]) < .05


def test_constant_torque_about_a_principal_axis():
    b = spinning_box((0, 0, 0), dt=1e-3)
    O.engines = [ForceResetter(), TorqueEngine(ids=[0], moment=(0, 0, 1.6)), NewtonIntegrator(damping=0)]
    O.run(100, True)
    # ω = T/I·t about z (I = 0.8): 2 rad/s² for 0.1 s; the angle is the sum of the mid-step spins
    assert tuple(b.state.angVel) == pytest.approx((0, 0, .2), abs=1e-12)
    angle = sum(2 * 1e-3 * k for k in range(1, 101)) * 1e-3
    assert b.state.ori.toAngleAxis()[0] == pytest.approx(angle, rel=1e-12)


def test_spheres_and_blocked_rotations_keep_the_spherical_update():
    results = []
    for exact in (True, False):
        O.reset()
        s = sphere((0, 0, 0), .1)
        O.bodies.append(s)
        s.state.angVel = (3, -2, 5)
        b = box((1, 0, 0), (.1, .2, .3))
        b.state.blockedDOFs = 'XY'
        O.bodies.append(b)
        b.state.angVel = (3, -2, 5)
        O.engines = [ForceResetter(), TorqueEngine(ids=[0, 1], moment=(.1, .2, .3)), NewtonIntegrator(damping=.2, exactAsphericalRot=exact)]
        O.dt = 1e-4
        O.run(100, True)
        results.append([(tuple(x.state.angVel), tuple(x.state.ori)) for x in O.bodies])
    assert results[0] == results[1]


def test_damping_and_energy_terms_of_a_tumbling_box():
    b = spinning_box((3, -2, 5), damping=.2, ori=Quaternion((1, 2, 3), .7))
    O.engines = [ForceResetter(), TorqueEngine(ids=[0], moment=(.5, .5, .5)), NewtonIntegrator(damping=.2, kinSplit=True)]
    O.trackEnergy = True
    O.run(2000, True)
    e = dict(O.energy.items())
    w = body_spin(b)
    I = b.state.inertia
    assert e['kinTrans'] == 0 and e['nonviscDamp'] > 0
    assert e['kinRot'] == pytest.approx(.5 * (I[0] * w[0] ** 2 + I[1] * w[1] ** 2 + I[2] * w[2] ** 2), rel=1e-2)


def test_tumbling_follows_an_independent_integration():
    """The state after 1 s against Euler's equations and the quaternion kinematics integrated with RK4
    (step 1e-5, in NumPy): spin (3.05806, -4.39632, 3.06435) rad/s, orientation (x, y, z, w)
    (-0.587860, -0.170638, -0.176223, -0.770875). The integrator keeps mid-step spins, and takes the
    spin it is given as that of the half step before the first: within 1e-3 here at dt = 1e-4.
    (The reference 2023.02a, whose angVel had been set alone, gives (1.32, -3.46, 4.27).)"""
    b = spinning_box((3, -2, 5), ori=Quaternion((1, 2, 3), .7))
    O.run(10000, True)
    assert tuple(b.state.angVel) == pytest.approx((3.05806, -4.39632, 3.06435), abs=1.5e-3)
    q = b.state.ori
    assert tuple(q) == pytest.approx((-0.587860, -0.170638, -0.176223, -0.770875), abs=1e-4)


def test_driven_by_the_angular_momentum_as_the_reference():
    """As in the reference, State.angMom drives an aspherical body (exactAsphericalRot): a spin set alone is
    overwritten (nothing turns), and the spin follows from the momentum. (State.angMom holds the momentum of
    the integrator's mid-step spin at the step's orientation: within O(dt) of the constant one, 2.4e-5 here.)
    The same script in the reference: body 0 still, angVel (0, 0, 0); body 1 (0.168278, 0.376862, 1.175048)
    after 100 steps of 1e-3 s (its Fincham scheme); Euler's equations integrated by RK4 (step 1e-5):
    (0.1684609, 0.3767196, 1.1750717)."""
    O.bodies.append([box((0, 0, 0), (.2, .4, .6)), box((3, 0, 0), (.2, .4, .6))])
    O.bodies[0].state.angVel = (1, 2, 3)
    O.bodies[1].state.angMom = (10, 20, 30)
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-3
    O.run(100, True)
    a, b = O.bodies[0].state, O.bodies[1].state
    assert tuple(a.angVel) == (0, 0, 0) and a.ori == Quaternion.Identity
    assert tuple(b.angMom) == pytest.approx((10, 20, 30), rel=3e-5)
    assert tuple(b.angVel) == pytest.approx((0.1684609, 0.3767196, 1.1750717), rel=1e-4)  # (the reference: 1e-3 off)
