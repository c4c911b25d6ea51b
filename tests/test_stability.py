"""Numerical stability: the guard in NewtonIntegrator, GlobalStiffnessTimeStepper, refusal of bad
input values and extreme (stiff, tiny, huge, disparate) scenes.

The guard (pkg/dem/NewtonIntegrator.cpp, pkg/dem/CriticalTimeStep.cpp):
  * every step, a body whose new position or velocity would not be finite is not written and the
    run stops with yade.StabilityError (a RuntimeError);
  * every NewtonIntegrator.stabilityCheckPeriod steps (default 10), whenever O.dt changed, and in
    every step for the bodies that got a new contact, O.dt is compared with the stiffness-based
    critical step of the manual (3.5.18-3.5.20)
        Δt_crit = min over dynamic bodies and DOFs of sqrt(2)·sqrt(m / K_ii),
        K_ii = Σ kn·n_i² + ks·(1 - n_i²)   (translations)
        K_ii = Σ ks·(1 - n_i²)·r²          (rotations, r = the body's contact radius)
    and O.dt > Δt_crit stops the run with StabilityError.

For one linear spring the leapfrog is stable up to ω·dt = 2 (ω = sqrt(k/m)); Δt_crit above is
sqrt(2)/ω, so 2×Δt_crit (ω·dt = 2.83) is genuinely unstable and 0.5×Δt_crit (ω·dt = 0.71) is
stable. The tracked energy of a leapfrog spring oscillates, relative to the oscillation energy
½k·A², by (ω·dt)²/4 / (1 - (ω·dt)²/4) (see tests/test_energy.py), i.e. by 1/7 at 0.5×Δt_crit.

Scenes that might crash the process are run in a subprocess (run_isolated) so that a segfault or
a floating-point trap fails the test instead of killing pytest.
"""
import json
import math
import os
import random
import re
import subprocess
import sys
import textwrap
import time

import pytest

import yade
from yade import (O, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ElastMat, ForceResetter, FrictMat, GlobalStiffnessTimeStepper,
                  GravityEngine, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider,
                  InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                  NewtonIntegrator, RotationEngine, Sphere, State, StabilityError, Vector3)
from yade.utils import PWaveTimeStep, kineticEnergy, sphere, wall

G = 9.81
NAN = float('nan')
INF = float('inf')


pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


# ---------------------------------------------------------------------------------- helpers

def engines(gravity=(0, 0, 0), damping=0.0, timeStepper=None, **newton):
    e = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
    ]
    if timeStepper is not None:
        e.append(timeStepper)
    return e + [NewtonIntegrator(gravity=gravity, damping=damping, **newton)]


def mat(young=1e7, poisson=0.3, density=2600, frictionAngle=0.5):
    return O.materials.append(FrictMat(young=young, poisson=poisson, density=density, frictionAngle=frictionAngle))


def rel(a, b):
    return abs(a - b) / abs(b)


def vec_finite(v, n=3):
    return all(math.isfinite(v[i]) for i in range(n))


def all_states_finite():
    """No NaN/inf in any body's position, velocity, angular velocity or orientation."""
    for b in O.bodies:
        s = b.state
        if not (vec_finite(s.pos) and vec_finite(s.vel) and vec_finite(s.angVel)):
            return False
        if not all(math.isfinite(s.ori[i]) for i in range(4)):
            return False
    return True


def sphere_mass(r, rho):
    return 4. / 3. * math.pi * r ** 3 * rho


def hand_critical_step():
    """Δt_crit of (3.5.18-3.5.20) summed by hand over the real interactions of the scene."""
    K = {}
    for I in O.interactions.all():
        if not I.isReal:
            continue
        n, kn, ks = I.geom.normal, I.phys.kn, I.phys.ks
        for side, bid in ((1, I.id1), (2, I.id2)):
            arm = I.geom.refR1 if side == 1 else I.geom.refR2
            kt, kr = K.setdefault(bid, ([0.] * 3, [0.] * 3))
            for c in range(3):
                kt[c] += kn * n[c] ** 2 + ks * (1 - n[c] ** 2)
                kr[c] += ks * (1 - n[c] ** 2) * arm * arm
    best = INF
    for bid, (kt, kr) in K.items():
        b = O.bodies[bid]
        if not b.dynamic:
            continue
        for c in range(3):
            if kt[c] > 0:
                best = min(best, math.sqrt(2) * math.sqrt(b.state.mass / kt[c]))
            if kr[c] > 0:
                best = min(best, math.sqrt(2) * math.sqrt(b.state.inertia[c] / kr[c]))
    return best


ISOLATED_PRELUDE = '''
import json, math
from yade import *
from yade.utils import *
G = 9.81
def engines(gravity=(0, 0, 0), damping=0.0):
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                            [Law2_ScGeom_FrictPhys_CundallStrack()]),
            NewtonIntegrator(gravity=gravity, damping=damping)]
def finite():
    for b in O.bodies:
        s = b.state
        for v in (s.pos, s.vel, s.angVel):
            if not all(math.isfinite(v[i]) for i in range(3)): return False
    return True
def run_guarded(n):
    """Run n steps; returns None or the StabilityError message."""
    try:
        O.run(n, True)
        return None
    except StabilityError as e:
        return str(e)
'''


def run_isolated(code, timeout=300):
    """Runs `code` (after ISOLATED_PRELUDE) in a fresh interpreter; its last stdout line is JSON.
    A crash (segfault, SIGFPE, abort) fails here with the signal number instead of killing pytest."""
    env = dict(os.environ)
    root = os.path.dirname(os.path.dirname(os.path.abspath(yade.__file__)))
    env['PYTHONPATH'] = root + os.pathsep + env.get('PYTHONPATH', '')
    p = subprocess.run([sys.executable, '-c', ISOLATED_PRELUDE + textwrap.dedent(code)], capture_output=True,
                       text=True, timeout=timeout, env=env)
    assert p.returncode == 0, 'subprocess died (rc=%d)\nstdout: %s\nstderr: %s' % (p.returncode, p.stdout[-2000:],
                                                                                   p.stderr[-2000:])
    return json.loads(p.stdout.strip().splitlines()[-1])


# ======================================================== 1. guard: sphere resting on a fixed sphere

R, E, NU, RHO = 0.1, 1e7, 0.3, 2600


def resting_sphere(amp=0.5, gravity=G, **newton):
    """A dynamic sphere on a fixed one (same material), placed below the static equilibrium
    2R - d (d = m·g/kn) by amp·d at rest, so that it oscillates about it with amplitude amp·d and
    the contact never opens (amp < 1). Returns (m, kn, ks, d, crit_normal)."""
    mat(young=E, poisson=NU, density=RHO)
    m = sphere_mass(R, RHO)
    kn = 2 * E * R * E * R / (E * R + E * R)  # = E·R, the harmonic mean of equal spheres
    ks = kn * NU
    d = m * gravity / kn
    O.bodies.append(sphere((0, 0, 0), R, fixed=True))
    O.bodies.append(sphere((0, 0, 2 * R - d * (1 + amp)), R))
    O.engines = engines(gravity=(0, 0, -gravity), **newton)
    return m, kn, ks, d, math.sqrt(2 * m / kn)


def test_critical_step_of_the_resting_sphere_is_the_normal_dof():
    m, kn, ks, d, crit = resting_sphere()
    inertia = 2. / 5. * m * R ** 2
    crit_shear = math.sqrt(2 * m / ks)                 # x, y translations: K = ks
    crit_rot = math.sqrt(2 * inertia / (ks * R * R))   # x, y rotations: K = ks·r²
    assert O.bodies[1].state.mass == pytest.approx(m, rel=1e-14)
    assert crit == pytest.approx(4.667087856992756e-3, rel=1e-12)
    assert crit_shear == pytest.approx(crit / math.sqrt(NU), rel=1e-12) and crit_shear > crit
    assert crit_rot == pytest.approx(crit * math.sqrt(0.4 / NU), rel=1e-12) and crit_rot > crit
    O.dt = 0.1 * crit
    O.step()
    assert O.interactions.countReal() == 1
    assert hand_critical_step() == pytest.approx(crit, rel=1e-12)


def test_half_critical_step_runs_5000_steps_with_bounded_energy():
    m, kn, ks, d, crit = resting_sphere(amp=0.5)
    O.dt = 0.5 * crit
    O.trackEnergy = True
    totals, overlaps = [], []
    for i in range(5000):
        O.run(1, True)
        totals.append(O.energy.total())
        overlaps.append(O.interactions[0, 1].geom.penetrationDepth)
        assert vec_finite(O.bodies[1].state.pos) and vec_finite(O.bodies[1].state.vel)
    assert O.iter == 5000
    assert O.interactions.countReal() == 1 and min(overlaps) > 0  # the contact never opened
    # oscillation amplitude ≈ 0.5·d (measured 0.5345·d: leapfrog amplitude of the modified energy)
    assert 0.4 * d < min(overlaps) < 0.5 * d and 1.5 * d < max(overlaps) < 1.6 * d
    e_osc = 0.5 * kn * (0.5 * d) ** 2
    variation = (max(totals) - min(totals)) / e_osc
    h2 = (math.sqrt(kn / m) * O.dt) ** 2  # (ω·dt)² = 0.5
    expected = (h2 / 4) / (1 - h2 / 4)   # = 1/7 ; measured 0.1428571
    print('relative energy variation at 0.5 x crit: %.7f (theory %.7f)' % (variation, expected))
    assert variation < 0.15
    assert variation == pytest.approx(expected, rel=1e-3)
    # and relative to the total energy
    assert (max(totals) - min(totals)) / abs(max(totals)) < 0.02


@pytest.mark.parametrize('factor', [2, 5, 50])
def test_time_step_above_critical_stops_the_run(factor):
    m, kn, ks, d, crit = resting_sphere(amp=0.5)
    O.dt = 0.5 * crit
    O.run(1000, True)
    it = O.iter
    O.dt = factor * crit
    with pytest.raises(StabilityError) as ei:
        O.run(100, True)
    msg = str(ei.value)
    # O.dt changed: the full check runs in the very first step with the new value
    assert O.iter == it
    assert 'O.dt=' in msg and 'critical step' in msg and 'body #1' in msg
    assert 'at step %d' % O.iter in msg
    assert isinstance(ei.value, RuntimeError)
    printed_dt = float(re.search(r'O\.dt=([0-9.e+-]+)', msg).group(1))
    printed_crit = float(re.search(r'critical step ([0-9.e+-]+)', msg).group(1))
    assert printed_dt == pytest.approx(factor * crit, rel=5e-3)  # printed with 3 significant digits
    assert printed_crit == pytest.approx(crit, rel=5e-3)
    assert all_states_finite()
    # lowering O.dt lets the scene run again
    O.dt = 0.5 * crit
    O.run(2000, True)
    assert O.iter == it + 2000
    assert all_states_finite()
    assert kineticEnergy() < 1e3  # nothing blew up (the body weighs 10.9 kg)


def test_time_step_rejection_leaves_the_bodies_before_the_rejected_step():
    m, kn, ks, d, crit = resting_sphere(amp=0.5)
    O.dt = 0.5 * crit
    O.run(1000, True)
    pos, vel, it, t = Vector3(O.bodies[1].state.pos), Vector3(O.bodies[1].state.vel), O.iter, O.time
    O.dt = 1e6 * crit
    with pytest.raises(StabilityError):
        O.run(10, True)
    assert (O.iter, O.time) == (it, t)
    assert O.bodies[1].state.pos == pos
    assert O.bodies[1].state.vel == vel


def test_new_contact_is_checked_in_the_step_it_appears():
    """stabilityCheckPeriod=1000: only the new-contact check can catch a sphere falling with
    O.dt = 2 x the critical step of the contact it is about to make."""
    mat(young=E, poisson=NU, density=RHO)
    m = sphere_mass(R, RHO)
    crit = math.sqrt(2 * m / (E * R))
    O.bodies.append(sphere((0, 0, 0), R, fixed=True))
    O.bodies.append(sphere((0, 0, 2 * R + 0.05), R))
    O.engines = engines(gravity=(0, 0, -G), stabilityCheckPeriod=1000)
    O.dt = 2 * crit
    with pytest.raises(StabilityError) as ei:
        for i in range(1000):
            assert O.interactions.countReal() == 0
            O.step()
    # contact at step 11 (fall of 5 cm at dt = 9.3 ms: z(n) = 0.25 - g·dt²·n(n+1)/2 < 0.2 from n = 11)
    assert O.iter == 11
    assert O.interactions.countReal() == 1
    assert 'at step 11' in str(ei.value) and 'body #1' in str(ei.value)
    assert all_states_finite()


def test_periodic_check_catches_a_stiffness_change_at_the_next_multiple_of_the_period():
    """Lowering a body's moments of inertia from Python makes the rotational critical step of its
    contact smaller without a new contact or a new O.dt (and without disturbing the normal
    oscillation, so the contact stays closed): only the full check every stabilityCheckPeriod=10
    steps sees it. (Lowering the mass instead lifts the sphere off and the new-contact check at
    the landing fires first.)"""
    m, kn, ks, d, crit = resting_sphere(amp=0.5, stabilityCheckPeriod=10)
    O.dt = 0.5 * crit
    O.run(1003, True)
    inertia = O.bodies[1].state.inertia[0]
    crit_rot = math.sqrt(2 * (inertia / 20) / (ks * R * R))  # 1.2e-3 s < O.dt = 2.33e-3 s
    O.bodies[1].state.inertia = O.bodies[1].state.inertia / 20
    for i in range(6):  # iters 1003..1008
        O.step()
        assert O.interactions.countReal() == 1
    with pytest.raises(StabilityError) as ei:
        O.run(100, True)
    assert O.iter == 1010
    assert O.interactions.countReal() == 1
    assert 'at step 1010' in str(ei.value)
    printed_crit = float(re.search(r'critical step ([0-9.e+-]+)', str(ei.value)).group(1))
    assert printed_crit == pytest.approx(crit_rot, rel=5e-3)
    assert all_states_finite()


def test_without_the_check_twice_the_critical_step_pumps_energy():
    """stabilityCheckPeriod=0 disables the time-step check: at 2 x crit (ω·dt = 2.83 > 2) the
    oscillation grows by ~5.8 per step until the sphere is ejected; the states stay finite."""
    m, kn, ks, d, crit = resting_sphere(amp=0.5, stabilityCheckPeriod=0)
    O.dt = 2 * crit
    O.run(200, True)  # no StabilityError
    assert all_states_finite()
    assert O.interactions.countReal() == 0
    e0 = 0.5 * kn * (1.5 * d) ** 2  # elastic energy at the start (measured KE after ejection ~48 J)
    assert kineticEnergy() > 1e3 * e0
    assert O.bodies[1].state.pos[2] > 2 * R + 1  # ejected by more than a metre (measured 3.9 m)


# ======================================================== 2. guard: non-finite state

def light_pair():
    mat(young=1e7, density=1000)
    O.bodies.append(sphere((0, 0, 0), 0.01))   # m = 4.19e-3 kg: 1e308 N / m overflows
    O.bodies.append(sphere((1, 0, 0), 0.01))
    O.bodies[0].state.vel = (0, 1, 0)
    O.bodies[1].state.vel = (0, 1, 0)
    O.engines = engines()
    O.dt = 1e-4


def test_huge_force_stops_the_run_with_the_last_finite_state():
    light_pair()
    O.run(10, True)
    pos0, vel0 = Vector3(O.bodies[0].state.pos), Vector3(O.bodies[0].state.vel)
    pos1 = Vector3(O.bodies[1].state.pos)
    assert pos0[0] == 0 and pos0[2] == 0 and pos0[1] == pytest.approx(1e-3, rel=1e-12)
    O.forces.addF(0, (1e308, 0, 0), permanent=True)
    with pytest.raises(StabilityError) as ei:
        O.run(10, True)
    msg = str(ei.value)
    assert 'not finite' in msg and 'body #0' in msg and 'at step 10' in msg
    assert O.iter == 10
    st = O.bodies[0].state
    assert st.pos == pos0 and st.vel == vel0  # the last finite state, not written over
    assert all_states_finite()
    # as described: only the diverging body is held back; body #1 made its step (+v·dt)
    assert O.bodies[1].state.pos[1] == pytest.approx(pos1[1] + 1e-4, rel=1e-12)
    assert math.isfinite(kineticEnergy())
    # the same error from O.step() and from a background run through O.wait()
    with pytest.raises(StabilityError):
        O.step()
    assert O.bodies[0].state.pos == pos0
    O.run(5)
    with pytest.raises(StabilityError):
        O.wait()
    assert O.bodies[0].state.pos == pos0 and all_states_finite()


def test_stability_error_is_exported_and_a_runtime_error():
    assert yade.StabilityError is StabilityError
    assert issubclass(StabilityError, RuntimeError)


def test_energy_stays_finite_after_a_non_finite_rejection():
    light_pair()
    O.engines = engines(damping=0.2, gravity=(0, 0, -G))
    O.trackEnergy = True
    O.run(10, True)
    O.forces.addF(0, (1e308, 0, 0), permanent=True)
    with pytest.raises(StabilityError):
        O.run(10, True)
    assert all_states_finite()
    assert all(math.isfinite(v) for k, v in O.energy.items())
    assert math.isfinite(O.energy.total())


def test_huge_finite_angular_velocity_does_not_put_nan_in_the_orientation():
    mat(young=1e7, density=1000)
    O.bodies.append(sphere((0, 0, 0), 0.01))
    O.engines = engines()
    O.dt = 1e-4
    O.bodies[0].state.angVel = (1e160, 0, 0)
    try:
        O.run(1, True)
    except StabilityError:
        pass
    q = O.bodies[0].state.ori
    assert all(math.isfinite(q[i]) for i in range(4))


# ======================================================== 3. placed overlapping

@pytest.mark.parametrize('overlap', [0.8, 1.8])
def test_spheres_placed_overlapping_fly_apart_stably(overlap):
    """Two free spheres overlapping by 80% (180%) of the radius with O.dt = 0.5 x crit: no
    StabilityError (the linear law has no problem with a large overlap); they separate with the
    stored elastic energy ½kn·δ² as kinetic energy (measured ratio 1.00000 for both)."""
    mat(young=E, density=RHO)
    O.bodies.append(sphere((0, 0, 0), R))
    O.bodies.append(sphere(((2 - overlap) * R, 0, 0), R))
    m, kn = sphere_mass(R, RHO), E * R
    O.engines = engines()
    O.dt = 0.5 * math.sqrt(2 * m / kn)
    O.trackEnergy = True
    e0 = 0.5 * kn * (overlap * R) ** 2
    kes = []
    for i in range(20):
        O.run(100, True)
        kes.append(kineticEnergy())
        assert all_states_finite()
    assert O.iter == 2000
    assert O.interactions.countReal() == 0
    assert max(kes) < e0 * 1.01
    assert kes[-1] == pytest.approx(e0, rel=1e-2)
    # momentum conserved: symmetric velocities
    assert O.bodies[0].state.vel[0] == pytest.approx(-O.bodies[1].state.vel[0], rel=1e-12)
    print('overlap %g%%: KE after separation / ½kn·δ² = %.5f' % (100 * overlap, kes[-1] / e0))


def test_coincident_spheres_stop_with_stability_error_naming_the_overlap():
    """Centers at the same point: the contact normal is 0/0; the guard stops the first step and
    keeps the bodies finite. (The NaN force and NaN contact normal remain visible in O.forces and
    the interaction's geometry.)"""
    mat(young=E, density=RHO)
    O.bodies.append(sphere((0, 0, 0), R))
    O.bodies.append(sphere((0, 0, 0), R))
    O.engines = engines()
    O.dt = 0.5 * math.sqrt(2 * sphere_mass(R, RHO) / (E * R))
    with pytest.raises(StabilityError) as ei:
        O.run(100, True)
    assert 'not finite' in str(ei.value) and 'overlap of 200%' in str(ei.value)
    assert O.iter == 0
    assert all_states_finite()
    assert O.bodies[0].state.pos == Vector3(0, 0, 0) and O.bodies[1].state.pos == Vector3(0, 0, 0)


# ======================================================== 4. extreme cases (subprocesses)

@pytest.mark.parametrize('target', ['sphere', 'wall'])
def test_stiff_100_m_per_s_impact(target):
    res = run_isolated('''
        r, E, rho = 0.1, 1e12, 2600
        O.materials.append(FrictMat(young=E, poisson=0.3, density=rho, frictionAngle=0.5))
        O.bodies.append(%s)
        O.bodies.append(sphere((2 * r + 1e-4, 0, 0), r))
        O.bodies[1].state.vel = (-100, 0, 0)
        O.engines = engines()
        O.dt = .3 * PWaveTimeStep()
        err, maxov, touched, n = None, 0, False, 0
        while n < 5000 and err is None:
            err = run_guarded(1); n += 1
            if O.interactions.countReal():
                touched = True
                maxov = max(maxov, O.interactions[0, 1].geom.penetrationDepth)
            elif touched:
                break
        m = O.bodies[1].state.mass
        print(json.dumps(dict(err=err, finite=finite(), n=n, touched=touched, vel=list(O.bodies[1].state.vel),
                              maxov=maxov, theory=100 * math.sqrt(m / (E * r)), dt=O.dt, crit=math.sqrt(2 * m / (E * r)))))
    ''' % ("sphere((0, 0, 0), r, fixed=True)" if target == 'sphere' else "wall(r, 0)"))
    assert res['err'] is None and res['finite'] and res['touched']
    assert res['dt'] < 0.2 * res['crit']  # 0.3·PWaveTimeStep = 0.104·crit
    vx, vy, vz = res['vel']
    assert vx > 0  # it rebounded
    assert math.hypot(vx, vy, vz) <= 100 * (1 + 1e-3)
    assert vx > 99  # elastic (damping 0): measured 99.82 m/s
    # max overlap of an elastic impact: v·sqrt(m/kn) = 1.04 mm (1% of r); measured 0.11% below, the
    # peak falling between two of the ~21 steps of the contact
    assert res['maxov'] == pytest.approx(res['theory'], rel=5e-3)


@pytest.mark.parametrize('mode', ['radius', 'density'])
def test_mass_ratio_1e6_small_sphere_settles_on_big_one(mode):
    """Small sphere on a big one (radius ratio 100, or density ratio 1e6) resting on a wall, both
    dynamic; the small one starts just touching, the big one at its equilibrium overlap."""
    res = run_isolated('''
        mode = %r
        E = 1e9
        if mode == 'radius':
            rb, rs, rhob, rhos = 1.0, 0.01, 2600, 2600
        else:
            rb, rs, rhob, rhos = 0.1, 0.1, 2600, 2600e-6
        mb_ = O.materials.append(FrictMat(young=E, poisson=0.3, density=rhob, frictionAngle=0.5))
        ms_ = O.materials.append(FrictMat(young=E, poisson=0.3, density=rhos, frictionAngle=0.5))
        O.bodies.append(wall(0, 2, material=mb_))
        O.bodies.append(sphere((0, 0, rb), rb, material=mb_))
        O.bodies.append(sphere((0, 0, 2 * rb + rs), rs, material=ms_))
        mb, ms = O.bodies[1].state.mass, O.bodies[2].state.mass
        knw, kss = E * rb, 2 * E * rb * E * rs / (E * rb + E * rs)
        db, ds = (mb + ms) * G / knw, ms * G / kss
        O.bodies[1].state.pos = (0, 0, rb - db)
        O.bodies[2].state.pos = (0, 0, 2 * rb - db + rs)
        O.engines = engines(gravity=(0, 0, -G), damping=0.3)
        O.dt = 0.5 * PWaveTimeStep()
        err = run_guarded(2000)
        print(json.dumps(dict(err=err, finite=finite(), ratio=mb / ms, iter=O.iter,
                              ovb=O.interactions[0, 1].geom.penetrationDepth / db,
                              ovs=O.interactions[1, 2].geom.penetrationDepth / ds,
                              vs=O.bodies[2].state.vel.norm())))
    ''' % mode)
    assert res['err'] is None and res['finite'] and res['iter'] == 2000
    assert res['ratio'] == pytest.approx(1e6, rel=1e-12)
    assert res['ovb'] == pytest.approx(1, abs=1e-3)
    # measured 2.4e-8 (radius) and 2.8e-5 (density: ds = 1e-12 m at z = 0.3 m, cancellation eps·z/ds)
    assert res['ovs'] == pytest.approx(1, abs=1e-3)
    assert res['vs'] < 1e-6


@pytest.mark.parametrize('r,young', [(1e-6, 1e9), (1e3, 1e10)], ids=['micrometre', 'kilometre'])
def test_tiny_and_huge_particles_settle_on_a_wall(r, young):
    """Overlap at rest = m·g/kn with kn = E·r for sphere-wall (measured rel. error 4.9e-7 for
    r = 1 µm, where the overlap 1.1e-16 m sits on a position of 1e-6 m, and 2e-15 for r = 1 km)."""
    res = run_isolated('''
        r, E = %r, %r
        O.materials.append(FrictMat(young=E, poisson=0.3, density=2600, frictionAngle=0.5))
        O.bodies.append(wall(0, 2))
        O.bodies.append(sphere((0, 0, r), r))
        O.engines = engines(gravity=(0, 0, -G), damping=0.3)
        O.dt = 0.5 * PWaveTimeStep()
        m, kn = O.bodies[1].state.mass, E * r
        err = run_guarded(2000)
        print(json.dumps(dict(err=err, finite=finite(), iter=O.iter, d=m * G / kn,
                              ov=O.interactions[0, 1].geom.penetrationDepth, z=O.bodies[1].state.pos[2],
                              ke=0.5 * m * O.bodies[1].state.vel.squaredNorm(), epot=m * G * m * G / kn)))
    ''' % (r, young))
    assert res['err'] is None and res['finite'] and res['iter'] == 2000
    assert res['ov'] == pytest.approx(res['d'], rel=1e-3)
    assert (r - res['z']) == pytest.approx(res['d'], rel=1e-3)
    assert res['ke'] < 1e-6 * res['epot']  # settled


def test_time_step_update_interval_zero_is_refused_and_never_crashes():
    res = run_isolated('''
        O.materials.append(FrictMat(young=1e7, density=2600))
        O.bodies.append(sphere((0, 0, 0), 1))
        refused = []
        for v in (0, -1):
            try:
                GlobalStiffnessTimeStepper(timeStepUpdateInterval=v)
            except ValueError as e:
                refused.append('timeStepUpdateInterval' in str(e))
        ts = GlobalStiffnessTimeStepper()
        try:
            ts.timeStepUpdateInterval = 0
        except ValueError as e:
            refused.append('timeStepUpdateInterval' in str(e))
        O.engines = [ForceResetter(), ts, NewtonIntegrator()]
        O.run(2, True)
        print(json.dumps(dict(refused=refused, interval=ts.timeStepUpdateInterval, iter=O.iter)))
    ''')
    assert res['refused'] == [True, True, True]
    assert res['interval'] == 1 and res['iter'] == 2


# ======================================================== 5. GlobalStiffnessTimeStepper

def tilted_contact(timeStepper):
    """A dynamic sphere on a fixed one along n = (0.6, 0, 0.8), with gravity along -n so that it
    oscillates about its equilibrium overlap d = m·g/kn (placed at 1.5·d) and the contact stays
    closed: the stiffness diagonals mix kn and ks, K_xx = 0.36kn + 0.64ks, K_zz = 0.64kn + 0.36ks,
    K_yy = ks; rotations K = ks·(1 - n_i²)·r²."""
    mat(young=E, poisson=NU, density=RHO)
    n = Vector3(0.6, 0, 0.8)
    d = sphere_mass(R, RHO) * G / (E * R)
    O.bodies.append(sphere((0, 0, 0), R, fixed=True))
    O.bodies.append(sphere(n * (2 * R - 1.5 * d), R))
    O.engines = engines(gravity=-G * n, timeStepper=timeStepper)


def test_time_stepper_without_contact_uses_p_wave_step():
    mat()
    O.bodies.append(sphere((0, 0, 0), 0.05))
    O.bodies.append(sphere((1, 0, 0), 0.1))
    ts = GlobalStiffnessTimeStepper()
    O.engines = engines(timeStepper=ts)
    assert (ts.active, ts.timeStepUpdateInterval, ts.timestepSafetyCoefficient, ts.defaultDt, ts.maxDt) == \
        (True, 1, 0.8, -1, INF)
    O.dt = 1e-9
    O.step()
    pw = 0.05 / math.sqrt(1e7 / 2600)
    assert PWaveTimeStep() == pytest.approx(pw, rel=1e-12)
    assert O.dt == pytest.approx(0.8 * PWaveTimeStep(), rel=1e-12)
    # as in the reference: the first update sets defaultDt from the P-wave step, once (a heavier
    # sphere afterwards does not change it); previousDt is the last step found from contacts: none
    assert ts.defaultDt == O.dt and ts.previousDt == INF
    O.bodies[0].state.mass *= 4
    O.dt = 1e-5
    O.step()
    assert O.dt == pytest.approx(0.8 * pw, rel=1e-12)
    ts.defaultDt = 2e-5
    O.step()
    assert O.dt == 2e-5


def test_time_stepper_without_contact_uses_default_dt():
    mat()
    O.bodies.append(sphere((0, 0, 0), 0.05))
    ts = GlobalStiffnessTimeStepper(defaultDt=3e-5)
    O.engines = engines(timeStepper=ts)
    O.step()
    assert O.dt == 3e-5 and ts.previousDt == INF  # (previousDt: the last step found from contacts, none here)


def test_time_stepper_with_a_contact_uses_the_critical_step_by_hand():
    ts = GlobalStiffnessTimeStepper()
    tilted_contact(ts)
    O.dt = 1e-7
    O.step()
    I = O.interactions[0, 1]
    n, kn, ks = I.geom.normal, I.phys.kn, I.phys.ks
    assert kn == pytest.approx(E * R, rel=1e-14) and ks == pytest.approx(NU * E * R, rel=1e-14)
    assert n[0] == pytest.approx(0.6, rel=1e-12) and n[2] == pytest.approx(0.8, rel=1e-12)
    st = O.bodies[1].state
    crits = []
    for i in range(3):
        crits.append(math.sqrt(2) * math.sqrt(st.mass / (kn * n[i] ** 2 + ks * (1 - n[i] ** 2))))
        if 1 - n[i] ** 2 > 0:
            crits.append(math.sqrt(2) * math.sqrt(st.inertia[i] / (ks * (1 - n[i] ** 2) * R * R)))
    crit = min(crits)
    # x, y, z translations 6.28, 8.52, 5.396 ms; rotations 6.74, 5.389, 8.98 ms: the y rotation
    # (K = ks·r², n_y = 0) is the smallest, just below the z translation
    assert crit == pytest.approx(math.sqrt(2) * math.sqrt(st.inertia[1] / (ks * R * R)), rel=1e-12)
    assert crit == pytest.approx(5.389088861132803e-3, rel=1e-12)
    assert O.dt == pytest.approx(0.8 * crit, rel=1e-9)
    assert ts.previousDt == O.dt
    assert hand_critical_step() == pytest.approx(crit, rel=1e-12)
    # the safety coefficient
    ts.timestepSafetyCoefficient = 0.5
    O.step()
    assert O.dt == pytest.approx(0.5 * hand_critical_step(), rel=1e-9)


def test_time_stepper_max_dt_caps():
    ts = GlobalStiffnessTimeStepper(maxDt=1e-4)
    tilted_contact(ts)
    O.dt = 1e-7
    O.step()
    assert O.dt == 1e-4 and ts.previousDt == 1e-4
    O.reset()
    mat()
    O.bodies.append(sphere((0, 0, 0), 0.05))
    ts = GlobalStiffnessTimeStepper(defaultDt=1e-3, maxDt=2e-5)
    O.engines = engines(timeStepper=ts)
    O.step()
    assert O.dt == 1e-3  # maxDt caps steps found from contacts, not defaultDt (the reference: 0.001 too)


def test_time_stepper_grows_at_most_5_percent_per_update():
    """The contact's stiffness divided by 4 doubles the critical step: O.dt follows it 5 % per
    update, as in the reference (1.05^4 = 1.2155 after four updates; the reference's figures on the
    same script: 0.00186185, 0.00195495, 0.00205269, 0.00215533, 0.00226309, i.e. the same ratios)."""
    ts = GlobalStiffnessTimeStepper()
    tilted_contact(ts)
    O.dt = 1e-7
    O.step()
    first = O.dt
    assert first == pytest.approx(0.8 * hand_critical_step(), rel=1e-9)
    I = O.interactions[0, 1]
    I.phys.kn /= 4
    I.phys.ks /= 4
    seen = []
    for i in range(4):
        O.step()
        seen.append(O.dt / first)
        assert O.dt == ts.previousDt
    assert seen == pytest.approx([1.05, 1.05 ** 2, 1.05 ** 3, 1.05 ** 4], rel=1e-12)
    assert O.dt < 0.8 * hand_critical_step()
    I.phys.kn *= 40  # stiffer: the step drops at once
    I.phys.ks *= 40
    O.step()
    assert O.dt == pytest.approx(0.8 * hand_critical_step(), rel=1e-9)


def test_time_stepper_keeps_dt_once_contacts_are_gone():
    """Once the contacts gave a step, an update without contacts leaves O.dt as it is (the reference
    does the same: it does not go back to the P-wave step)."""
    ts = GlobalStiffnessTimeStepper()
    tilted_contact(ts)
    O.dt = 1e-7
    O.step()
    contact = O.dt
    O.bodies[1].state.pos = (0, 0, 1)  # far away: the contact ends at the next step
    O.step()
    assert O.interactions.countReal() == 0
    assert O.dt == contact != pytest.approx(0.8 * PWaveTimeStep())
    O.dt = 3e-6  # what the script sets stays, too
    O.run(3, True)
    assert O.dt == 3e-6 and ts.previousDt == contact


def test_time_stepper_without_spheres_leaves_dt():
    """No sphere with an elastic material: no P-wave step to start from and nothing it would move;
    O.dt is left as it is (the reference sets 0.8 s there)."""
    ts = GlobalStiffnessTimeStepper()
    O.engines = engines(timeStepper=ts)
    O.dt = 1e-6
    O.run(3, True)
    assert O.dt == 1e-6 and ts.defaultDt == -1


def test_time_stepper_accepts_the_references_other_attributes():
    ts = GlobalStiffnessTimeStepper(parallelMode=True, viscEl=False, targetDt=2e-4, densityScaling=False)
    assert (ts.parallelMode, ts.viscEl, ts.targetDt, ts.densityScaling) == (True, False, 2e-4, False)
    tilted_contact(ts)
    ts.densityScaling = True
    with pytest.raises(ValueError, match='densityScaling is not supported'):
        O.step()


def test_time_stepper_inactive_leaves_dt():
    ts = GlobalStiffnessTimeStepper(active=False)
    tilted_contact(ts)
    O.dt = 1.234e-6
    O.run(20, True)
    assert O.dt == 1.234e-6
    assert ts.previousDt == INF


def test_time_stepper_update_interval():
    ts = GlobalStiffnessTimeStepper(timeStepUpdateInterval=10)
    tilted_contact(ts)
    O.dt = 1e-7
    O.step()  # iter 0: updated
    first = O.dt
    assert first == pytest.approx(0.8 * hand_critical_step(), rel=1e-9)
    O.dt = 2e-6
    seen = []
    for i in range(1, 10):  # iters 1..9: untouched
        O.step()
        seen.append(O.dt)
    assert seen == [2e-6] * 9
    O.step()  # iter 10
    assert O.dt == pytest.approx(0.8 * hand_critical_step(), rel=1e-9) and O.dt != 2e-6
    O.dt = 3e-6
    O.run(9, True)
    assert O.dt == 3e-6 and O.iter == 20
    O.step()
    assert O.dt != 3e-6 and O.dt == ts.previousDt
    assert O.dt == pytest.approx(0.8 * hand_critical_step(), rel=1e-9)
    assert O.interactions.countReal() == 1  # the contact stayed closed throughout


def test_previous_dt_is_read_only():
    ts = GlobalStiffnessTimeStepper()
    with pytest.raises(AttributeError, match='previousDt'):
        ts.previousDt = 1.0


def test_stiff_scene_with_time_stepper_never_trips_the_guard():
    """72 spheres, E = 1e10, thrown at 3 m/s into a box (5 walls), damping 0.4, 5000 steps."""
    random.seed(1)
    mat(young=1e10, poisson=0.3, density=2600)
    for w in (wall(0, 2), wall(0, 0), wall(0.6, 0), wall(0, 1), wall(0.6, 1)):
        O.bodies.append(w)
    for i in range(3):
        for j in range(3):
            for k in range(8):
                b = sphere((0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.1 + 0.2 * k), 0.1 * random.uniform(0.9, 0.99))
                b.state.vel = (random.uniform(-1, 1), random.uniform(-1, 1), -3)
                O.bodies.append(b)
    ts = GlobalStiffnessTimeStepper()
    O.engines = engines(gravity=(0, 0, -G), damping=0.4, timeStepper=ts)
    O.dt = 1e-8
    maxContacts, dts = 0, []
    for i in range(50):
        O.run(100, True)  # a StabilityError would fail the test here
        maxContacts = max(maxContacts, O.interactions.countReal())
        dts.append(O.dt)
        if O.interactions.countReal():  # (at most the critical step: it grows 5 % per step at most)
            assert O.dt <= 0.8 * hand_critical_step() * (1 + 1e-9)
    assert O.iter == 5000
    assert all_states_finite()
    assert maxContacts >= 40  # measured 71
    assert max(b.state.pos[2] for b in O.bodies) < 5
    print('stiff scene: dt in [%.3g, %.3g], max contacts %d' % (min(dts), max(dts), maxContacts))


# ======================================================== 6. refusals

@pytest.mark.parametrize('value', [-1, 0, NAN, INF])
def test_sphere_shape_radius_refused(value):
    with pytest.raises(ValueError, match='radius'):
        Sphere(radius=value)
    s = Sphere(radius=0.5)
    with pytest.raises(ValueError, match='radius'):
        s.radius = value
    assert s.radius == 0.5


@pytest.mark.parametrize('value', [-1, 0, NAN, INF])
def test_sphere_function_radius_refused(value):
    with pytest.raises(ValueError, match='radius'):
        sphere((0, 0, 0), value)
    assert len(O.bodies) == 0


@pytest.mark.parametrize('center', [(NAN, 0, 0), (0, INF, 0), (0, 0, -INF)])
def test_sphere_function_center_refused(center):
    with pytest.raises(ValueError, match='center'):
        sphere(center, 1)


@pytest.mark.parametrize('attr', ['pos', 'vel', 'angVel'])
@pytest.mark.parametrize('bad', [(INF, 0, 0), (0, NAN, 0)])
def test_state_vectors_refuse_non_finite(attr, bad):
    b = sphere((1, 2, 3), 1)
    b.state.vel = (4, 5, 6)
    b.state.angVel = (7, 8, 9)
    before = Vector3(getattr(b.state, attr))
    with pytest.raises(ValueError, match=attr):
        setattr(b.state, attr, bad)
    assert getattr(b.state, attr) == before
    with pytest.raises(ValueError, match=attr):
        State(**{attr: bad})


@pytest.mark.parametrize('cls', [FrictMat, ElastMat])
@pytest.mark.parametrize('param', ['density', 'young'])
@pytest.mark.parametrize('value', [0, -1, NAN])
def test_material_refuses_non_positive(cls, param, value):
    if (param, value) == ('density', 0):  # (accepted, as in the reference: walls of density 0)
        assert cls(density=0).density == 0
        return
    with pytest.raises(ValueError, match=param):
        cls(**{param: value})
    m = cls(density=2000, young=1e7)
    with pytest.raises(ValueError, match=param):
        setattr(m, param, value)
    assert (m.density, m.young) == (2000, 1e7)


def test_zero_dt_steps_in_place():
    """O.dt = 0 is accepted, as in the reference (whose own utilsModule test steps with it to create
    contacts without moving anything): the step finds contacts and computes forces, positions and
    time stay; a RotationEngine turning around a point gives its bodies the limit velocity w x r."""
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 0.5), sphere((0.99, 0, 0), 0.5), sphere((0, 0, 3), 0.5, fixed=True)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 RotationEngine(ids=[2], rotationAxis=(0, 1, 0), angularVelocity=2, rotateAroundZero=True, zeroPoint=(0, 0, 0)),
                 NewtonIntegrator()]
    O.dt = 0
    assert O.dt == 0
    O.step()
    assert O.time == 0 and O.iter == 1
    assert O.bodies[1].state.pos == Vector3(0.99, 0, 0)
    i = O.interactions[0, 1]
    assert i.isReal and i.geom.penetrationDepth == pytest.approx(0.01)
    assert O.forces.f(0)[0] < 0 and O.forces.f(0)[0] == -O.forces.f(1)[0]
    assert O.bodies[2].state.vel == Vector3(6, 0, 0)  # (0, 2, 0) x (0, 0, 3)
    assert O.bodies[2].state.pos == Vector3(0, 0, 3)


@pytest.mark.parametrize('value', [NAN, INF, -INF])  # (-1: the time stepper, test_negative_dt_hands_the_step_to_the_time_stepper)
def test_dt_refused(value):
    O.dt = 1.5e-3
    with pytest.raises(ValueError, match='dt'):
        O.dt = value
    assert O.dt == 1.5e-3


@pytest.mark.parametrize('cls', [NewtonIntegrator, GravityEngine])
@pytest.mark.parametrize('bad', [(NAN, 0, 0), (0, 0, INF)])
def test_gravity_refused(cls, bad):
    with pytest.raises(ValueError, match='gravity'):
        cls(gravity=bad)
    e = cls(gravity=(0, 0, -G))
    with pytest.raises(ValueError, match='gravity'):
        e.gravity = bad
    assert e.gravity == Vector3(0, 0, -G)


def test_refused_values_leave_a_running_scene_unchanged():
    """A failed assignment in the middle of a simulation changes nothing: the run continues
    identically to one without the attempt."""
    def build():
        O.reset()
        mat()
        O.bodies.append(wall(0, 2))
        O.bodies.append(sphere((0, 0, 0.11), 0.1))
        O.engines = engines(gravity=(0, 0, -G), damping=0.2)
        O.dt = 0.5 * PWaveTimeStep()

    build()
    O.run(300, True)
    reference = Vector3(O.bodies[1].state.pos)
    build()
    O.run(100, True)
    for attempt in (lambda: setattr(O, 'dt', NAN), lambda: setattr(O.bodies[1].state, 'pos', (INF, 0, 0)),
                    lambda: setattr(O.bodies[1].state, 'vel', (NAN, 0, 0)),
                    lambda: setattr(O.engines[-1], 'gravity', (0, 0, NAN)),
                    lambda: setattr(O.bodies[1].shape, 'radius', -1),
                    lambda: setattr(O.materials[0], 'density', -1)):
        with pytest.raises(ValueError):
            attempt()
    O.run(200, True)
    assert O.bodies[1].state.pos == reference


# ======================================================== 7. guard cost

def deposition(period):
    random.seed(2)
    mat()
    O.bodies.append(wall(0, 2))
    for i in range(10):
        for j in range(10):
            for k in range(10):
                O.bodies.append(sphere((0.02 * i, 0.02 * j, 0.01 + 0.02 * k), 0.01 * random.uniform(0.9, 1.0)))
    O.engines = engines(gravity=(0, 0, -G), damping=0.4, stabilityCheckPeriod=period)
    O.dt = 0.5 * PWaveTimeStep()


def test_guard_cost():
    times, finals = {}, {}
    for period in (0, 10, 1):
        best = INF
        for rep in range(3):
            O.reset()
            deposition(period)
            O.run(20, True)  # warm up, first contacts
            t0 = time.perf_counter()
            O.run(500, True)
            best = min(best, time.perf_counter() - t0)
        times[period] = best
        finals[period] = [Vector3(b.state.pos) for b in O.bodies]
        contacts = O.interactions.countReal()
    assert len(O.bodies) == 1001 and contacts > 100  # measured 205
    # the guard does not change the trajectories
    assert finals[0] == finals[10] == finals[1]
    print('guard cost, 1000 spheres x 500 steps: period 0: %.4f s, period 10: %.4f s (ratio %.3f), '
          'period 1: %.4f s (ratio %.3f)' % (times[0], times[10], times[10] / times[0], times[1],
                                              times[1] / times[0]))


def test_negative_dt_hands_the_step_to_the_time_stepper():
    """(manual: O.dt < 0 activates the TimeStepper in O.engines; the reference, without one,
    raises RuntimeError 'No TimeStepper found in O.engines.')"""
    mat()
    O.bodies.append(sphere((0, 0, 0), 0.05))
    O.engines = engines()
    O.dt = 2e-6
    with pytest.raises(RuntimeError, match="No TimeStepper found in O.engines"):
        O.dt = -1
    assert O.dt == 2e-6 and not O.dynDt
    ts = GlobalStiffnessTimeStepper(active=False, defaultDt=3e-5)
    O.engines = engines(timeStepper=ts)
    O.step()
    assert O.dt == 2e-6 and not O.dynDt  # (inactive: the step stays the user's)
    O.dt = -1
    assert ts.active and O.dynDt and O.dt == 2e-6  # (set by the stepper when it runs)
    O.step()
    assert O.dt == 3e-5 and ts.previousDt == INF  # (previousDt: the last step found from contacts, none here)
    with pytest.raises(ValueError):
        O.dt = float("nan")
