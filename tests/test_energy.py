"""Energy tracking: O.trackEnergy and O.energy.

Terms (a term appears in O.energy once something has added to it):
  kinetic         instantaneous, NewtonIntegrator, ½m·v_n² + ½ω_n·I·ω_n with the on-step velocity
                  estimate v_n = v_{n-1/2} + a_n·dt/2 (the velocity consistent with the positions x_n)
  gravWork        cumulative, NewtonIntegrator.gravity / GravityEngine: -m·g·(x_n - x_{n-1}) summed
                  (NewtonIntegrator adds it for every dynamic body, 0 without gravity, as Yade does)
  nonviscDamp     cumulative, NewtonIntegrator when damping != 0
  elastPotential  instantaneous, Law2_ScGeom_FrictPhys_CundallStrack: ½(Fn²/kn + Fs²/ks)
  plastDissip     cumulative, the same law: Fs·(plastic slip) when the Coulomb limit is hit and
                  something is dissipated (never for frictionless contacts, as in Yade)
The terms after step n describe the configuration that step computed forces for (x_{n-1} in
O.bodies' numbering: pos - vel·dt), as elastPotential does.

With every force of the scene accounted for, O.energy.total() is constant up to the error of
the time integration. That error is what the bounds below are about; each is derived or
measured, and the measured figure is printed (pytest -s shows it).

Integration error in a nutshell. For a linear spring (a Cundall-Strack contact) the leapfrog
scheme with the on-step velocity estimate conserves exactly a "shadow" energy; the tracked
energy ½m·v_n² + ½k·x_n² oscillates between E and E·(1 - (ω·dt)²/4) (derivation in
test_bounce_on_fixed_sphere). Entering and leaving a contact between two steps adds a further
error of the same order, O((ω·dt)²), of either sign, which stays after the contact ends. In a
gas of many spheres these per-collision errors add up as a random walk. With dt a fixed
fraction of PWaveTimeStep, ω·dt is fixed (≈0.24 for a sphere on a fixed partner, ≈0.35 for
two equal spheres at dt = 0.5·PWaveTimeStep).
"""
import math
import random

import pytest

from yade import (O, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Bo1_Wall_Aabb, ForceResetter, FrictMat, GravityEngine,
                  Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, InsertionSortCollider,
                  InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                  NewtonIntegrator, Vector3, setNumThreads)
from yade import geom, pack
from yade.utils import PWaveTimeStep, sphere, wall

G = 9.81
ALL_TERMS = {'kinetic', 'gravWork', 'nonviscDamp', 'elastPotential', 'plastDissip'}


pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def engines(gravity=(0, 0, 0), damping=0.0):
    return [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                        [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(gravity=gravity, damping=damping),
    ]


def material(frictionAngle=0.5, young=1e7):
    m = FrictMat(young=young, poisson=0.3, frictionAngle=frictionAngle, density=2600)
    O.materials.append(m)
    return m


def largest_term():
    return max(abs(v) for v in O.energy.values())


def gas_scene(seed=4, n=200, frictionAngle=0.0, gravity=(0, 0, 0), damping=0.0, randomVelocities=True):
    """~n spheres (r = 5 cm ± 30 %) in a closed 1 m facet box."""
    material(frictionAngle)
    O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5)))
    sp = pack.SpherePack()
    sp.makeCloud((.05, .05, .05), (.95, .95, .95), rMean=.05, rRelFuzz=.3, num=n, seed=seed)
    ids = sp.toSimulation()
    if randomVelocities:
        rnd = random.Random(seed)
        for i in ids:
            O.bodies[i].state.vel = Vector3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1))
    O.engines = engines(gravity, damping)
    O.dt = .5 * PWaveTimeStep()
    return ids


def max_drift(nSteps):
    """Steps nSteps times after a first step; max over every step of |total - total_1| and the
    largest |term| seen."""
    O.step()
    t0 = O.energy.total()
    drift = biggest = 0.
    for _ in range(nSteps):
        O.step()
        drift = max(drift, abs(O.energy.total() - t0))
        biggest = max(biggest, largest_term())
    return drift, biggest, t0


# ====================================================================== on / off, which terms

def test_tracking_is_off_by_default_and_energy_stays_empty():
    assert O.trackEnergy is False
    gas_scene(n=50, frictionAngle=.5, gravity=(0, 0, -G), damping=.2)
    O.run(300, True)
    assert O.interactions.countReal() > 0
    assert len(O.energy) == 0
    assert O.energy.keys() == [] and O.energy.values() == [] and O.energy.items() == []
    assert O.energy.total() == 0
    assert dict(**O.energy) == {}
    with pytest.raises(KeyError):
        O.energy['kinetic']


def test_all_terms_appear_with_gravity_damping_and_frictional_contacts():
    gas_scene(n=100, frictionAngle=.5, gravity=(0, 0, -G), damping=.2)
    O.trackEnergy = True
    O.run(2000, True)
    assert set(O.energy.keys()) == ALL_TERMS
    e = dict(O.energy.items())
    assert e['kinetic'] > 0 and e['elastPotential'] > 0
    assert e['gravWork'] < 0  # the spheres went down: gravity did positive work
    assert e['nonviscDamp'] > 0 and e['plastDissip'] > 0  # dissipated
    assert O.energy.total() == pytest.approx(sum(O.energy.values()), rel=1e-14)


def test_terms_depend_on_what_the_scene_does():
    # undamped: no nonviscDamp; free flight: no contact terms
    material()
    O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = 1e-4
    O.trackEnergy = True
    O.run(10, True)
    assert set(O.energy.keys()) == {'kinetic', 'gravWork'}
    O.engines = engines(gravity=(0, 0, -G), damping=.3)
    O.run(10, True)
    assert set(O.energy.keys()) == {'kinetic', 'gravWork', 'nonviscDamp'}


def test_gravWork_term_exists_without_gravity_as_in_yade():
    # Reference Yade 2023.02a, same scene: keys ['gravWork', 'kinetic']. (Was a bug: NewtonIntegrator
    # added to gravWork only when gravity != 0.)
    material()
    O.bodies.append(sphere((0, 0, 0), .1))
    O.bodies[0].state.vel = (1, 0, 0)
    O.engines = engines(gravity=(0, 0, 0), damping=0)
    O.dt = 1e-4
    O.trackEnergy = True
    O.run(10, True)
    assert sorted(O.energy.keys()) == ['gravWork', 'kinetic']
    assert O.energy['gravWork'] == 0


def test_no_plastDissip_term_for_frictionless_contacts_as_in_yade():
    # Reference Yade 2023.02a, same scene (a sphere resting on and sliding over another, frictionAngle=0):
    # keys ['elastPotential', 'gravWork', 'kinetic']. (Was a bug: the law added 0 to plastDissip for
    # frictionless contacts; the reference adds the dissipation only when it is > 0.)
    material(frictionAngle=0)
    O.bodies.append([sphere((0, 0, 0), .1, fixed=True), sphere((0, 0, .199), .1)])
    O.bodies[1].state.vel = (.1, 0, 0)
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = 1e-5
    O.trackEnergy = True
    O.run(20, True)
    assert sorted(O.energy.keys()) == ['elastPotential', 'gravWork', 'kinetic']


# ====================================================================== conservation

def test_elastic_gas_conserves_energy():
    """200 spheres with random velocities in a closed facet box, frictionless, undamped, no gravity,
    dt = 0.5·PWaveTimeStep, 10 000 steps: max |total - total_1| < 0.2 % of the largest term.

    Measured 0.128 % for this scene (seed 4). The drift is the random walk of the per-collision
    errors described in the module docstring (test_single_collision_errors_are_unbiased checks that
    they have no systematic sign), so it depends on the collision history: over makeCloud seeds 1-5
    this engine gives 0.13-0.63 % (seed 4: 0.128 %, seed 5: 0.134 %); the reference Yade, whose
    kinetic term uses mid-step velocities, gives 0.54-1.10 % on the same scenes."""
    ids = gas_scene(seed=4)
    assert len(ids) == 200
    O.trackEnergy = True
    drift, biggest, t0 = max_drift(10000)
    e = dict(O.energy.items())
    print('\nelastic gas: max |total - total0| = %.4f %% of the largest term (%.4g J); final terms %s'
          % (100 * drift / biggest, biggest, e))
    # frictionless: nothing dissipated, so no plastDissip term; no gravity: gravWork stays 0 (as in Yade)
    assert set(e) == {'kinetic', 'elastPotential', 'gravWork'}
    assert e['gravWork'] == 0
    assert O.interactions.countReal() > 0
    assert drift / biggest < 2e-3


def test_single_collision_errors_are_unbiased():
    """The energy error left by one collision of two equal spheres (random impact parameter and
    phase of the contact onset relative to the steps) has zero mean and is small: the random walk
    of the gas test is not a hidden systematic loss. Measured over these 200 collisions: mean
    -1.2e-4, standard deviation 1.35e-3, largest 2.6e-3 (relative to the kinetic energy); the
    bound is the amplitude (ω·dt)²/4 ≈ 0.030 of the in-contact oscillation."""
    rnd = random.Random(0)
    errs = []
    for _ in range(200):
        O.reset()
        material(frictionAngle=0)
        O.bodies.append([sphere((0, 0, 0), .05),
                         sphere((.12 + rnd.uniform(0, .01), rnd.uniform(-.05, .05), 0), .05)])
        O.bodies[0].state.vel = (1, 0, 0)
        O.engines = engines()
        O.dt = .5 * PWaveTimeStep()
        O.trackEnergy = True
        O.step()
        t0 = O.energy.total()
        O.run(600, True)
        assert O.interactions.countReal() == 0  # the collision is over
        assert O.bodies[1].state.vel.norm() > 0  # and it happened
        errs.append((O.energy.total() - t0) / t0)
    n = len(errs)
    mean = sum(errs) / n
    sd = math.sqrt(sum((e - mean) ** 2 for e in errs) / (n - 1))
    m = O.bodies[0].state.mass
    kn = 1e7 * .05  # Ip2: harmonic mean of E·r for equal spheres
    omegaDt = math.sqrt(kn / (m / 2)) * O.dt
    print('\nsingle collisions: mean %.3e sd %.3e max %.3e (bound (w.dt)^2/4 = %.3e)'
          % (mean, sd, max(map(abs, errs)), omegaDt ** 2 / 4))
    assert abs(mean) < 3 * sd / math.sqrt(n)
    assert max(map(abs, errs)) < omegaDt ** 2 / 4


def test_deposition_with_friction_and_damping_balances():
    """200 spheres falling into a facet box: friction 0.5, damping 0.2, gravity, 10 000 steps.
    All five terms take part; max |total - total_1| < 1 % of the largest term (gravWork).
    Measured 0.19 % at commit 55910cb, 0.27 % with the contact-geometry changes after it (the
    figure follows the collision history, as in the gas test)."""
    gas_scene(seed=1, frictionAngle=.5, gravity=(0, 0, -G), damping=.2, randomVelocities=False)
    O.trackEnergy = True
    drift, biggest, t0 = max_drift(10000)
    e = dict(O.energy.items())
    print('\ndeposition: max |total - total0| = %.4f %% of the largest term (%.4g J); final terms %s'
          % (100 * drift / biggest, biggest, e))
    assert set(e) == ALL_TERMS
    assert biggest == pytest.approx(abs(e['gravWork']), rel=1e-3)  # the largest term is the work of gravity
    assert drift / biggest < 1e-2


@pytest.mark.parametrize('gravityEngine', [False, True])
@pytest.mark.parametrize('v0', [(0, 0, 0), (1, 2, 3)])
def test_free_fall_kinetic_plus_gravwork_is_constant(gravityEngine, v0):
    """Constant force: the on-step kinetic energy changes by exactly m·g·v_{n-1/2}·dt per step, the
    amount gravWork records, so the sum is constant up to rounding (measured 1e-14 - 6e-14)."""
    material()
    O.bodies.append(sphere((0, 0, 0), .1))
    O.bodies[0].state.vel = v0
    if gravityEngine:
        O.engines = [ForceResetter(), GravityEngine(gravity=(0, 0, -G)), NewtonIntegrator(damping=0)]
    else:
        O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
    O.dt = 1e-4
    O.trackEnergy = True
    drift, biggest, t0 = max_drift(1000)
    assert set(O.energy.keys()) == {'kinetic', 'gravWork'}
    # gravWork = -m·g·Δz, the same sum of v·dt as the positions, for the configuration the last
    # step computed forces for: x_{n-1} = pos - vel·dt (the terms describe the start of the step,
    # as elastPotential does); it starts from the virtual x_{-1} = x_0 - v0·dt
    s = O.bodies[0].state
    zPrev, zStart = s.pos[2] - s.vel[2] * O.dt, 0 - v0[2] * O.dt
    assert O.energy['gravWork'] == pytest.approx(s.mass * G * (zPrev - zStart), rel=1e-12)
    assert drift / biggest < 1e-9


def drop_on_fixed_sphere(dtFactor, h=.1):
    """A sphere dropped from height h (gap) onto a fixed equal sphere, no damping, until it has
    bounced and left the contact. Returns (max |total - total_1| / largest term, (ω·dt)²/4)."""
    O.reset()
    material()
    O.bodies.append([sphere((0, 0, 0), .1, fixed=True), sphere((0, 0, .2 + h), .1)])
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = dtFactor * PWaveTimeStep()
    O.trackEnergy = True
    O.step()
    t0 = O.energy.total()
    drift = biggest = 0.
    kn = None
    hadContact = False
    for _ in range(int(2 * math.sqrt(2 * h / G) / O.dt)):
        O.step()
        drift = max(drift, abs(O.energy.total() - t0))
        biggest = max(biggest, largest_term())
        if O.interactions.countReal():
            hadContact = True
            kn = O.interactions[0, 1].phys.kn
    assert hadContact and O.interactions.countReal() == 0 and O.bodies[1].state.vel[2] > 0
    omegaDt = math.sqrt(kn / O.bodies[1].state.mass) * O.dt
    return drift / biggest, omegaDt ** 2 / 4


def test_bounce_on_fixed_sphere_conserves_energy_to_O_dt2():
    """kinetic + elastPotential + gravWork for a bounce without damping.

    Bound. In contact the sphere is a mass on a linear spring of stiffness kn (the partner is
    fixed), ω = √(kn/m). Leapfrog gives x_n = A·cos(θ_n) with cos(Ω·dt) = 1 - (ω·dt)²/2, and the
    on-step velocity v_n = (x_{n+1} - x_{n-1})/(2dt) = -A·sin(θ_n)·sin(Ω·dt)/dt with
    sin²(Ω·dt) = (ω·dt)²·(1 - (ω·dt)²/4). Hence ½m·v_n² + ½kn·x_n² =
    ½kn·A²·(1 - sin²θ_n·(ω·dt)²/4): the tracked energy dips by up to (ω·dt)²/4 of the contact
    energy (≈ the largest term, the kinetic energy at impact), an O(dt²) error that vanishes
    again after the contact except for the onset/exit part, of the same order.

    Measured on 20 random drop heights: max error 0.54-0.96 of (ω·dt)²/4 at dt = 0.5, 0.25 and
    0.125·PWaveTimeStep; here 1.36e-2 of the 1.49e-2 bound at 0.5·PWaveTimeStep and 6.0e-4 of
    9.3e-4 at 0.125·PWaveTimeStep. Asserted: ≤ (ω·dt)²/4, and the error shrinks
    as dt² (a 4 times smaller dt gives a 16 times smaller bound, which it must respect too)."""
    err, bound = drop_on_fixed_sphere(.5)
    errFine, boundFine = drop_on_fixed_sphere(.125)
    print('\nbounce: max error %.3e (bound %.3e) at dt=0.5·PWave; %.3e (bound %.3e) at 0.125·PWave'
          % (err, bound, errFine, boundFine))
    assert boundFine == pytest.approx(bound / 16, rel=1e-9)
    assert err <= bound
    assert errFine <= boundFine
    assert err > .3 * bound  # the bound is the actual size of the error, not a loose guess
    assert err / errFine > 8  # O(dt²)


# ====================================================================== dissipation

def test_sliding_to_rest_dissipates_the_initial_kinetic_energy():
    """A sphere with blocked rotations slides on a wall (friction 0.5) from v0 = 4 m/s until it
    stops: plastDissip = ½m·v0² within 1e-3.

    It starts at rest vertically at the static overlap m·g/kn, so no vertical motion, no gravity
    work. Two small errors remain (measured 3.8e-4 together): the first step slides over a whole
    v0·dt while the kinetic term starts from the on-step velocity, an O(μ·g·dt/v0) = 3e-4 offset;
    and the shear increment of the reference (see the next test) scales the relative velocity by
    α = (r1+r2)/(r1+r2-overlap), which makes plastDissip exceed the friction work by
    α-1 = overlap/(2r) = 5e-5 here. The residual elastic shear energy after stopping is
    ≈ (μ·m·g)²/(2ks) = 6e-4 J, 1e-5 of ½m·v0²."""
    E = 1e8
    material(young=E)
    O.bodies.append(wall((0, 0, 0), axis=2))
    b = O.bodies.append(sphere((0, 0, .1), .1))
    s = O.bodies[b].state
    s.blockedDOFs = 'XYZ'
    kn = E * .1
    v0 = 4.
    s.pos = (0, 0, .1 - s.mass * G / kn)
    s.vel = (v0, 0, 0)
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = .5 * PWaveTimeStep()
    O.trackEnergy = True
    KE0 = .5 * s.mass * v0 ** 2
    tStop = v0 / (math.tan(.5) * G)
    O.run(int(1.5 * tStop / O.dt), True)
    assert O.interactions[0, 1].phys.kn == pytest.approx(kn, rel=1e-12)
    e = dict(O.energy.items())
    print('\nsliding: plastDissip/KE0 - 1 = %.3e; terms %s' % (e['plastDissip'] / KE0 - 1, e))
    assert s.vel.norm() < 1e-2 * v0  # stopped (left: a small elastic oscillation on the shear spring)
    assert e['kinetic'] < 1e-4 * KE0
    assert abs(e['gravWork']) < 1e-12 * KE0
    assert e['plastDissip'] == pytest.approx(KE0, rel=1e-3)


def test_sliding_on_a_wall_dissipates_what_the_reference_yade_dissipates():
    """The scene of the previous test, step for step as in this script run by the reference Yade
    2023.02a (yade -n -x -j1), which printed plastDissip = 87.16012059750219, kinetic =
    0.0004928139435200321, elastPotential = 0.0006218807333469279 and the final velocity
    x = -0.009923275243739530793 after 4392 steps:

        O.materials.append(FrictMat(young=1e8, poisson=.3, frictionAngle=.5, density=2600))
        O.bodies.append(utils.wall((0, 0, 0), axis=2)); b = O.bodies.append(sphere((0, 0, .1), .1))
        s = O.bodies[b].state; s.blockedDOFs = 'XYZ'; s.pos = (0, 0, .1 - s.mass*9.81/1e7); s.vel = (4, 0, 0)
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                     [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
        O.dt = .5*PWaveTimeStep(); O.trackEnergy = True
        O.step(); O.run(int(1.5*4/(math.tan(.5)*9.81)/O.dt), True)

    This engine reproduced these numbers bitwise at commit 55910cb. They depend on the shear
    increment of the wall contact: the reference scales the relative velocity by
    α = (r1+r2)/(r1+r2-overlap) (its granular-ratcheting correction, with refR1 = refR2 = r for a
    wall), which makes plastDissip 5e-5 larger than the friction work here; without α it is
    87.15546 (5e-5 off the reference) and the velocity -0.0099108. Tolerance 1e-9: summation order only.
    (The kinetic term differs by design: the reference uses mid-step velocities.)"""
    E = 1e8
    material(young=E)
    O.bodies.append(wall((0, 0, 0), axis=2))
    b = O.bodies.append(sphere((0, 0, .1), .1))
    s = O.bodies[b].state
    s.blockedDOFs = 'XYZ'
    s.pos = (0, 0, .1 - s.mass * G / (E * .1))
    s.vel = (4, 0, 0)
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = .5 * PWaveTimeStep()
    O.trackEnergy = True
    O.step()
    O.run(int(1.5 * 4 / (math.tan(.5) * G) / O.dt), True)
    assert O.iter == 4392
    assert O.energy['plastDissip'] == pytest.approx(87.16012059750219, rel=1e-9)
    assert O.energy['elastPotential'] == pytest.approx(0.0006218807333469279, rel=1e-6)
    assert s.vel[0] == pytest.approx(-0.009923275243739530793, rel=1e-9)


def test_sliding_sphere_ends_rolling_after_dissipating_two_sevenths():
    """The same sphere with free rotations: friction spins it up until it rolls without slipping at
    v = 5/7·v0 (solid sphere, I = 2/5·m·r²); the slip dissipates 2/7 of ½m·v0². Measured 1.3e-3 off
    (the same O(dt) start-up offset plus the end of slipping falling between steps)."""
    E = 1e8
    material(young=E)
    O.bodies.append(wall((0, 0, 0), axis=2))
    b = O.bodies.append(sphere((0, 0, .1), .1))
    s = O.bodies[b].state
    v0 = 4.
    s.pos = (0, 0, .1 - s.mass * G / (E * .1))
    s.vel = (v0, 0, 0)
    O.engines = engines(gravity=(0, 0, -G), damping=0)
    O.dt = .5 * PWaveTimeStep()
    O.trackEnergy = True
    KE0 = .5 * s.mass * v0 ** 2
    O.run(int(v0 / (math.tan(.5) * G) / O.dt), True)
    e = dict(O.energy.items())
    print('\nrolling: plastDissip/(2/7·KE0) - 1 = %.3e' % (e['plastDissip'] / (2 / 7 * KE0) - 1))
    assert s.vel[0] == pytest.approx(5 / 7 * v0, rel=1e-3)
    assert s.angVel[1] * .1 == pytest.approx(s.vel[0], rel=2e-3)  # rolling: ω·r = v
    assert e['plastDissip'] == pytest.approx(2 / 7 * KE0, rel=3e-3)


@pytest.mark.parametrize('n', [1000, 10000])
def test_damping_dissipation_equals_the_kinetic_energy_lost(n):
    """A sphere falling under gravity with damping 0.2: gravity did the work W = -gravWork, the
    sphere has only kinetic - kinetic_1 of it; nonviscDamp is the rest.

    Not to rounding (as without damping) but to 1/n after n steps: gravWork sums m·g·v_{k-1/2}·dt
    while nonviscDamp sums the damping force times the on-step velocity v_k = v_{k-1/2} + a·dt/2,
    so per step they differ by m·d·(1-d)·g²·dt²/2, relatively 1/n of nonviscDamp after n steps
    (measured: 1.0e-3 at n=1000, 1.0e-4 at n=10000; an O(dt) error). The analytic dissipation,
    damping force d·m·g times the height fallen, is matched to the same 1/n."""
    d = .2
    material()
    b = O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -G), damping=d)]
    O.dt = 1e-4
    O.trackEnergy = True
    s = O.bodies[b].state
    O.step()
    k1 = O.energy['kinetic']
    O.run(n, True)
    e = dict(O.energy.items())
    lost = -e['gravWork'] - (e['kinetic'] - k1)
    print('\ndamping, n=%d: nonviscDamp/lost - 1 = %.3e' % (n, e['nonviscDamp'] / lost - 1))
    assert e['nonviscDamp'] > 0
    assert e['nonviscDamp'] == pytest.approx(lost, rel=1.5 / n)
    assert e['nonviscDamp'] == pytest.approx(d * s.mass * G * -s.pos[2], rel=1.5 / n)
    # the sphere falls with (1-d)·g (dampGravity=True): kinetic energy (1-d)² of the undamped one
    assert s.vel[2] == pytest.approx(-(1 - d) * G * (n + 1) * O.dt, rel=1e-12)


# ====================================================================== cumulative vs instantaneous

def test_kinetic_is_instantaneous_gravwork_is_cumulative():
    material()
    b = O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
    O.dt = 1e-4
    O.trackEnergy = True
    O.run(500, True)
    w = O.energy['gravWork']
    assert w < 0 and O.energy['kinetic'] > 0
    s = O.bodies[b].state
    s.vel = (0, 0, 0)
    O.bodies[b].dynamic = False  # stopped: the integrator no longer moves nor accelerates it
    O.run(10, True)
    assert O.energy['kinetic'] == 0  # instantaneous: recomputed every step, nothing moves
    assert O.energy['gravWork'] == w  # cumulative: keeps what was done
    assert set(O.energy.keys()) == {'kinetic', 'gravWork'}  # a term once there stays listed


def test_elastic_energy_is_instantaneous_plastic_is_cumulative():
    # a sphere slides over a fixed one, then flies off: elastPotential returns to 0, plastDissip stays
    material(frictionAngle=.1)
    O.bodies.append([sphere((0, 0, 0), .1, fixed=True), sphere((0, 0, .199), .1)])
    O.bodies[1].state.vel = (1, 0, 1)
    O.engines = engines(damping=0)
    O.dt = .2 * PWaveTimeStep()
    O.trackEnergy = True
    O.step()
    O.step()
    assert O.energy['elastPotential'] > 0 and O.energy['plastDissip'] > 0
    O.run(200, True)
    assert O.interactions.countReal() == 0
    p = O.energy['plastDissip']
    O.run(10, True)
    assert O.energy['elastPotential'] == 0
    assert O.energy['plastDissip'] == p > 0


# ====================================================================== the O.energy object

def test_clear_removes_all_terms_and_they_come_back_from_zero():
    material()
    b = O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
    O.dt = 1e-4
    O.trackEnergy = True
    O.run(100, True)
    assert len(O.energy) == 2
    O.energy.clear()
    assert len(O.energy) == 0 and O.energy.keys() == [] and O.energy.total() == 0
    assert dict(**O.energy) == {}
    s = O.bodies[b].state
    zPrev = s.pos[2] - s.vel[2] * O.dt
    O.run(100, True)
    assert set(O.energy.keys()) == {'kinetic', 'gravWork'}
    # gravWork counts from the clear on: the 100 moves since, -m·g·Δz (of the configurations the
    # steps computed forces for, x_{n-1} = pos - vel·dt; see the free-fall test)
    assert O.energy['gravWork'] == pytest.approx(s.mass * G * (s.pos[2] - s.vel[2] * O.dt - zPrev), rel=1e-12)
    assert O.energy.total() == pytest.approx(O.energy['kinetic'] + O.energy['gravWork'], rel=1e-15)


def test_energy_mapping_interface():
    gas_scene(n=30, frictionAngle=.5, gravity=(0, 0, -G), damping=.2)
    O.trackEnergy = True
    O.run(500, True)
    keys = O.energy.keys()
    assert len(O.energy) == len(keys) >= 3
    d = dict(**O.energy)
    assert list(d) == keys
    assert d == dict(O.energy.items())
    assert list(d.values()) == O.energy.values()
    assert all(d[k] == O.energy[k] for k in keys)
    assert list(iter(O.energy)) == keys
    assert 'kinetic' in O.energy and 'nonsense' not in O.energy
    with pytest.raises(KeyError, match='nonsense'):
        O.energy['nonsense']
    assert O.energy.total() == pytest.approx(sum(d.values()), rel=1e-14, abs=1e-14 * sum(map(abs, d.values())))
    assert all(isinstance(v, float) for v in d.values())


@pytest.mark.parametrize('threads', [1, 2])
def test_tracking_energy_does_not_change_the_trajectory(threads):
    def run(track):
        O.reset()
        setNumThreads(threads)
        gas_scene(seed=2, n=100, frictionAngle=.5, gravity=(0, 0, -G), damping=.2)
        O.trackEnergy = track
        O.run(3000, True)
        return [(tuple(b.state.pos), tuple(b.state.vel), tuple(b.state.angVel), tuple(b.state.ori)) for b in O.bodies]
    a = run(False)
    assert len(O.energy) == 0
    b = run(True)
    assert len(O.energy) == 5
    assert a == b  # bitwise


def test_kinSplit_gives_translational_and_rotational_terms_that_add_up_to_kinetic():
    """NewtonIntegrator.kinSplit (the reference's): kinTrans + kinRot instead of kinetic."""
    from yade import ForceResetter, NewtonIntegrator
    from yade.utils import sphere
    totals = []
    for split in (False, True):
        O.reset()
        O.bodies.append(sphere((0, 0, 0), .1))
        O.bodies[0].state.angVel = (1, 2, 3)
        O.bodies[0].state.vel = (.5, 0, 0)
        O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10), kinSplit=split, damping=0)]
        O.trackEnergy = True
        O.dt = 1e-3
        O.run(3, True)
        totals.append(dict(O.energy.items()))
    plain, split = totals
    assert 'kinetic' in plain and 'kinTrans' not in plain
    assert 'kinetic' not in split and {'kinTrans', 'kinRot', 'gravWork'} <= set(split)
    b = O.bodies[0]
    m, I = b.state.mass, b.state.inertia[0]
    # (no torque: the spin is constant; kinTrans with the on-step velocity, as kinetic)
    assert split['kinRot'] == pytest.approx(.5 * I * (1 + 4 + 9), rel=1e-14)
    v = b.state.vel - 0.5 * O.dt * Vector3(0, 0, -10)
    assert split['kinTrans'] == pytest.approx(.5 * m * v.squaredNorm(), rel=1e-12)
    assert split['kinTrans'] + split['kinRot'] == pytest.approx(plain['kinetic'], rel=1e-14)


def test_a_missing_force_resetter_is_reported_once_per_run_of_such_steps():
    import warnings
    from yade import ForceEngine
    O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [ForceEngine(ids=[0], force=(1, 0, 0)), NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        O.run(3, True)
        said = [str(x.message) for x in w if 'ForceResetter' in str(x.message)]
        assert len(said) == 1 and "O.forces last reset in step -1, while the current step is 0" in said[0]
        # (without a reset the force adds up step by step, as in the reference: 1, 2, 3 N)
        assert O.forces.f(0)[0] == 3
        O.engines[-1].warnNoForceReset = False
        O.run(2, True)
        O.engines = [ForceResetter()] + O.engines
        O.engines[-1].warnNoForceReset = True
        O.run(2, True)
        assert len([x for x in w if 'ForceResetter' in str(x.message)]) == 1
    assert NewtonIntegrator().exactAsphericalRot is True and NewtonIntegrator(exactAsphericalRot=False).exactAsphericalRot is False
