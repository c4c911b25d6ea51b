"""Rotation of aspherical bodies (the manual, 3.5.2): a body with unequal principal moments of inertia (a box of
unequal sides) turns by Euler's equations in its principal frame (NewtonIntegrator.exactAsphericalRot, on by
default), by the scheme NewtonIntegrator.rotAlgorithm chooses: 'Fincham1992' (the default: the reference
2023.02a's scheme, driven by State.angMom), 'delValle2023' (SPIRAL) or 'Omelyan1998' (both driven by
State.angVel; pkg/dem/AsphericalRotation.hpp).

Agreement with the reference: the scenes are tests/reference/aspherical.py, a plain Yade script;
tests/reference/data/aspherical.json is what the reference printed running it (tests/reference/regenerate.sh):
the same bits here. The mechanics of a free rigid body: angular momentum and energy kept to each scheme's
measured order, the intermediate-axis flip, steady spin about a major axis, a constant torque about a principal
axis. scripts/accuracy/accuracy.py measures the schemes against the exact solution (./yade --accuracy)."""
import importlib.util
import json
import os

import pytest

from yade import O, ForceResetter, NewtonIntegrator, TorqueEngine, Quaternion, Vector3
from yade.utils import box, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

SCHEMES = ['Fincham1992', 'delValle2023', 'Omelyan1998']
HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('aspherical_scenes', os.path.join(HERE, 'reference', 'aspherical.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'aspherical.json')) as _f:
    REFERENCE = json.load(_f)

# a box of half-sides 0.1, 0.2, 0.3 (density 1000): principal moments 2.08, 1.6, 0.8 kg·m²
TURNED = Quaternion(*scenes.TURNED)


def spinning_box(angVel, scheme='Fincham1992', exact=True, dt=1e-4, ori=None, damping=0):
    """A free box spinning at angVel: given both the spin (which SPIRAL and Omelyan read) and the angular
    momentum of that spin (which Fincham's scheme reads)."""
    b = box((0, 0, 0), (.1, .2, .3))
    if ori is not None:
        b.state.ori = ori
    O.bodies.append(b)
    b.state.angVel = angVel
    q, I = Quaternion(b.state.ori), b.state.inertia
    w = q.conjugate() * Vector3(*angVel)
    b.state.angMom = q * Vector3(I[0] * w[0], I[1] * w[1], I[2] * w[2])
    O.engines = [ForceResetter(), NewtonIntegrator(damping=damping, exactAsphericalRot=exact, rotAlgorithm=scheme)]
    O.dt = dt
    return b


def body_spin(b):
    return Quaternion(b.state.ori).conjugate() * b.state.angVel


def invariants_now(b, scheme):
    """L (global frame) and E at the on-step time. Fincham's state is L itself (State.angMom), and E follows from
    it at the current orientation; SPIRAL and Omelyan keep mid-step spins: the body-frame spins of the half
    steps around the current time averaged (runs one step)."""
    I, q = b.state.inertia, Quaternion(b.state.ori)
    if scheme == 'Fincham1992':
        L = Vector3(b.state.angMom)
        l = q.conjugate() * L
        return L, .5 * sum(l[i] ** 2 / I[i] for i in range(3))
    w1 = body_spin(b)
    O.run(1, True)
    w = .5 * (w1 + body_spin(b))
    return q * Vector3(I[0] * w[0], I[1] * w[1], I[2] * w[2]), .5 * sum(I[i] * w[i] ** 2 for i in range(3))


def worst_drift(scheme, dt, seconds=2., exact=True):
    b = spinning_box((3, -2, 5), scheme, dt=dt, ori=TURNED, exact=exact)
    L0, E0 = invariants_now(b, scheme)
    dL = dE = 0
    for _ in range(20):
        O.run(int(seconds / dt / 20) - (scheme != 'Fincham1992'), True)
        L, E = invariants_now(b, scheme)
        dL, dE = max(dL, (L - L0).norm() / L0.norm()), max(dE, abs(E - E0) / E0)
    return dL, dE


# ---------------------------------------------------------------- the attributes


def test_the_schemes_and_the_default():
    n = NewtonIntegrator()
    assert n.rotAlgorithm == 'Fincham1992' and n.normalizeEvery == 1 and n.exactAsphericalRot
    for s in SCHEMES:
        n.rotAlgorithm = s
        assert n.rotAlgorithm == s
        assert NewtonIntegrator(rotAlgorithm=s).rotAlgorithm == s


def test_a_bad_scheme_is_a_value_error_naming_the_choices():
    n = NewtonIntegrator(rotAlgorithm='Omelyan1998')
    with pytest.raises(ValueError) as e:
        n.rotAlgorithm = 'SPIRAL'
    msg = str(e.value)
    assert "'SPIRAL'" in msg and all("'%s'" % s in msg for s in SCHEMES)
    assert n.rotAlgorithm == 'Omelyan1998'  # (the old value kept)
    with pytest.raises(ValueError, match='Fincham1992'):
        NewtonIntegrator(rotAlgorithm='fincham')
    with pytest.raises(ValueError):
        NewtonIntegrator(normalizeEvery=-1)


def test_inertia_of_the_box():
    b = box((0, 0, 0), (.1, .2, .3))
    assert tuple(b.state.inertia) == pytest.approx((2.08, 1.6, .8), rel=1e-14)
    # the reference's bits (m/12·(b² + c²), ...): 51.20000000000002, not the 51.20000000000001 of (b² + c²)/12·m
    assert REFERENCE['inertia'] == [66.56000000000002, 51.20000000000002, 25.600000000000012]
    assert list(box((0, 0, 0), (.2, .4, .6)).state.inertia) == REFERENCE['inertia']


# ---------------------------------------------------------------- agreement with the reference


@pytest.mark.parametrize('name', [name for name, _ in scenes.CASES])
def test_the_default_gives_the_references_bits(name):
    """The reference's ori, angVel, angMom, pos and vel after 1, 2, 3, 10, 100 and 1000 steps of 1e-3 s, every
    number equal: free, turned, with a torque, damped (the damping reads the stored spin), with gravity, with a
    spin set alone (nothing turns)."""
    kw = dict(scenes.CASES)[name]
    here = scenes.run(kw)
    there = REFERENCE['cases'][name]
    assert [r['iter'] for r in here] == [r['iter'] for r in there] == list(scenes.SNAPSHOTS)
    for a, b in zip(here, there):
        for key in ('ori', 'angVel', 'angMom', 'pos', 'vel'):
            assert a[key] == b[key], (name, a['iter'], key)


def test_the_references_numbers():
    """A few of the stored numbers, as the reference printed them."""
    free = REFERENCE['cases']['free']
    assert free[0]['angVel'] == [0.15024038461538458, 0.3906249999999999, 1.1718749999999996]  # (10, 20, 30)/I
    assert free[-1]['angMom'] == [10.0, 20.0, 30.0]  # (Fincham's state: kept exactly without torque)
    assert free[-1]['angVel'] == [0.38516584802989506, 0.29322057302261106, 1.1586275385478708]
    damped = REFERENCE['cases']['dampedSpinSet'][0]['angMom']
    assert damped[0] == pytest.approx(10 - 1.2, rel=1e-15)  # -1000·dt·(1 + 0.2): torque·(stored spin) < 0
    assert REFERENCE['cases']['spinOnly'][-1]['angVel'] == [0, 0, 0]


# ---------------------------------------------------------------- conservation, by scheme


# (scheme, |ΔL|/L at dt 4e-4 and 2e-4 over 2 s of tumbling, ΔE/E likewise: measured, 7 Dec 2026)
DRIFTS = [('Fincham1992', (0, 0), (1.947e-3, 9.863e-4)),
          ('delValle2023', (3.681e-7, 9.202e-8), (2.418e-7, 6.047e-8)),
          ('Omelyan1998', (3.415e-7, 8.538e-8), (4.836e-7, 1.209e-7))]


@pytest.mark.parametrize('scheme,dL,dE', DRIFTS)
def test_a_free_top_keeps_its_momentum_and_energy_to_its_order(scheme, dL, dE):
    """Fincham's scheme keeps L exactly (its state) and E to first order: the reference's step finds the
    mid-step spin at the on-step orientation (first order: doc/compatibility.md); SPIRAL and Omelyan keep both
    to second order."""
    coarse, fine = worst_drift(scheme, 4e-4), worst_drift(scheme, 2e-4)
    for k, want in ((0, dL), (1, dE)):
        assert coarse[k] == pytest.approx(want[0], rel=1e-3, abs=1e-16) and fine[k] == pytest.approx(want[1], rel=1e-3, abs=1e-16)
    order = 1 if scheme == 'Fincham1992' else 2
    assert coarse[1] / fine[1] == pytest.approx(2 ** order, rel=.02)
    if order == 2:
        assert coarse[0] / fine[0] == pytest.approx(4, rel=.02)


def test_the_spherical_update_does_not_conserve_it():
    dL, _ = worst_drift('delValle2023', 1e-4, exact=False)
    assert dL > .4  # (treating the box as a sphere: 50 % off within 2 s)


@pytest.mark.parametrize('scheme', SCHEMES)
def test_spin_about_the_intermediate_axis_flips_and_about_the_major_one_stays(scheme):
    b = spinning_box((.01, 10, .01), scheme)
    flipped = False
    for _ in range(200):
        O.run(100, True)
        flipped |= body_spin(b)[1] < -9
    assert flipped  # (the tennis-racket theorem: y, of the middle moment, is unstable)
    O.reset()
    b = spinning_box((10, .01, .01), scheme)
    for _ in range(200):
        O.run(100, True)
        w = body_spin(b)
        assert w[0] > 9.999 and abs(w[1]) < .05 and abs(w[2]) < .05


def test_the_spherical_update_does_not_flip():
    b = spinning_box((.01, 10, .01), exact=False)
    O.run(20000, True)
    assert body_spin(b)[1] == pytest.approx(10, rel=1e-12)


# (scheme, the tolerance of the angle turned: SPIRAL turns by exactly ω·dt; Omelyan's Cayley form by
# 2·atan(ω·dt/2), Fincham's update of q by ω·dt(1 + O((ω·dt)²)): relative errors of (ω·dt)²/12, 4e-9 here)
@pytest.mark.parametrize('scheme,rel', [('Fincham1992', 1e-8), ('delValle2023', 1e-12), ('Omelyan1998', 1e-8)])
def test_constant_torque_about_a_principal_axis(scheme, rel):
    b = spinning_box((0, 0, 0), scheme, dt=1e-3)
    O.engines = [ForceResetter(), TorqueEngine(ids=[0], moment=(0, 0, 1.6)), NewtonIntegrator(damping=0, rotAlgorithm=scheme)]
    O.run(100, True)
    # ω = T/I·t about z (I = 0.8): 2 rad/s² for 0.1 s; the angle is the sum of the mid-step spins
    assert tuple(b.state.angVel) == pytest.approx((0, 0, .2), abs=1e-12)
    angle = sum(2 * 1e-3 * k for k in range(1, 101)) * 1e-3
    assert b.state.ori.toAngleAxis()[0] == pytest.approx(angle, rel=rel)
    assert tuple(b.state.angMom) == pytest.approx((0, 0, .16), abs=1e-14)


@pytest.mark.parametrize('scheme', SCHEMES)
def test_spheres_and_blocked_rotations_keep_the_spherical_update(scheme):
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
        O.engines = [ForceResetter(), TorqueEngine(ids=[0, 1], moment=(.1, .2, .3)),
                     NewtonIntegrator(damping=.2, exactAsphericalRot=exact, rotAlgorithm=scheme)]
        O.dt = 1e-4
        O.run(100, True)
        results.append([(tuple(x.state.angVel), tuple(x.state.ori)) for x in O.bodies])
    assert results[0] == results[1]


@pytest.mark.parametrize('scheme', SCHEMES)
def test_damping_and_energy_terms_of_a_tumbling_box(scheme):
    b = spinning_box((3, -2, 5), scheme, damping=.2, ori=TURNED)
    O.engines = [ForceResetter(), TorqueEngine(ids=[0], moment=(.5, .5, .5)), NewtonIntegrator(damping=.2, kinSplit=True, rotAlgorithm=scheme)]
    O.trackEnergy = True
    O.run(2000, True)
    e = dict(O.energy.items())
    w = body_spin(b)
    I = b.state.inertia
    assert e['kinTrans'] == 0 and e['nonviscDamp'] > 0
    assert e['kinRot'] == pytest.approx(.5 * (I[0] * w[0] ** 2 + I[1] * w[1] ** 2 + I[2] * w[2] ** 2), rel=1e-2)


# (the spin and orientation after 1 s, tolerance of each, by scheme)
RK4 = [('Fincham1992', 4e-3, 2e-3), ('delValle2023', 1.5e-3, 1e-4), ('Omelyan1998', 1.5e-3, 1e-4)]


@pytest.mark.parametrize('scheme,dw,dq', RK4)
def test_tumbling_follows_an_independent_integration(scheme, dw, dq):
    """The state after 1 s against Euler's equations and the quaternion kinematics integrated with RK4 (step
    1e-5, in NumPy): spin (3.05806, -4.39632, 3.06435) rad/s, orientation (x, y, z, w) (-0.587860, -0.170638,
    -0.176223, -0.770875), from the spin (3, -2, 5) at Quaternion((1, 2, 3), .7). SPIRAL and Omelyan keep
    mid-step spins and take the spin they are given as that of the half step before the first (within 1e-3
    here at dt = 1e-4); Fincham's scheme, first order, is 3e-3 and 1.5e-3 off."""
    b = spinning_box((3, -2, 5), scheme, ori=Quaternion((1, 2, 3), .7))
    O.run(10000, True)
    assert tuple(b.state.angVel) == pytest.approx((3.05806, -4.39632, 3.06435), abs=dw)
    assert tuple(b.state.ori) == pytest.approx((-0.587860, -0.170638, -0.176223, -0.770875), abs=dq)


# ---------------------------------------------------------------- what drives each scheme


def test_fincham_is_driven_by_the_angular_momentum():
    """As in the reference: a spin set alone is overwritten (nothing turns), and the spin follows from the
    momentum, which stays exact without torque. The reference after 100 steps of 1e-3 s from angMom (10, 20, 30):
    angVel (0.168278, 0.376862, 1.175048), here the same bits; RK4 on Euler's equations (step 1e-5): (0.1684609,
    0.3767196, 1.1750717), 1e-3 off (the scheme's first order)."""
    O.bodies.append([box((0, 0, 0), (.2, .4, .6)), box((3, 0, 0), (.2, .4, .6))])
    O.bodies[0].state.angVel = (1, 2, 3)
    O.bodies[1].state.angMom = (10, 20, 30)
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
    O.dt = 1e-3
    O.run(100, True)
    a, b = O.bodies[0].state, O.bodies[1].state
    assert tuple(a.angVel) == (0, 0, 0) and a.ori == Quaternion.Identity
    assert tuple(b.angMom) == (10, 20, 30)
    assert tuple(b.angVel) == pytest.approx((0.168278, 0.376862, 1.175048), abs=1e-6)
    assert tuple(b.angVel) == pytest.approx((0.1684609, 0.3767196, 1.1750717), rel=2e-3)


@pytest.mark.parametrize('scheme', ['delValle2023', 'Omelyan1998'])
def test_spiral_and_omelyan_are_driven_by_the_spin(scheme):
    """A spin set alone turns the body (the newer Yade's SPIRAL and Omelyan), State.angMom following it: the
    momentum of the new spin at the new orientation."""
    b = box((0, 0, 0), (.2, .4, .6))
    O.bodies.append(b)
    b.state.angVel = (1, 2, 3)
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, 0), damping=0, rotAlgorithm=scheme)]
    O.dt = 1e-3
    O.run(100, True)
    I, q = b.state.inertia, b.state.ori
    w = q.conjugate() * b.state.angVel
    assert b.state.ori.toAngleAxis()[0] == pytest.approx(.1 * 14 ** .5, rel=2e-2)  # (|ω|·t, roughly: it tumbles)
    assert tuple(b.state.angMom) == pytest.approx(tuple(q * Vector3(I[0] * w[0], I[1] * w[1], I[2] * w[2])), rel=1e-14)
    L0 = Vector3(I[0] * 1, I[1] * 2, I[2] * 3)
    assert (Vector3(b.state.angMom) - L0).norm() / L0.norm() < 2e-3


@pytest.mark.parametrize('scheme', ['delValle2023', 'Omelyan1998'])
def test_normalize_every(scheme):
    """SPIRAL and Omelyan keep |q| (to round-off) without normalizing: normalizeEvery=0 leaves it within 1e-13
    of 1 over 20000 steps, and the motion within 1e-10 of the one normalized every step (the two runs round
    differently: the random walk of the energy shifts the phase, 5e-11 measured; a turn by Eigen's q*v, which
    assumes |q| = 1, had put them 6e-9 apart)."""
    out = []
    for every in (0, 1, 7):
        O.reset()
        b = spinning_box((3, -2, 5), scheme, ori=TURNED)
        O.engines[-1].normalizeEvery = every
        O.run(20000, True)
        out.append((b.state.ori, Vector3(b.state.angVel)))
    for q, w in out:
        assert abs(q.norm() - 1) < 1e-13
        assert (w - out[1][1]).norm() < 1e-10 and abs(q.dot(out[1][0]) / q.norm()) == pytest.approx(1, abs=1e-14)
