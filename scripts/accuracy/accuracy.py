#!/usr/bin/python3
"""Accuracy suite: cases with known exact answers, each run at a sweep of time steps.

    /usr/bin/python3 scripts/accuracy/accuracy.py DIR [--quick]
    ./yade --accuracy DIR

Every case is run with O.dt = f·PWaveTimeStep() for f in DT_FACTORS; each run is timed
(wall clock of the simulation, Python-side stepping included) and its error against the
exact answer is measured. Writes

    DIR/accuracy.csv   one row per (case, error kind, dt)
    DIR/accuracy.md    a table per case, measured and theoretical convergence orders, a reading
    DIR/accuracy.png   error against wall time (work-precision diagram), log-log

Exit status: 0 when every available case ran, 1 when a case failed to run.

The cases are designed so that the exact answer is the exact answer of the *model* the engine
integrates (linear spring, Coulomb friction), so that the measured error is the integration
error and not a modelling mismatch; each case says how. The torque-free rotation of an asymmetric
top is run once per scheme of NewtonIntegrator.rotAlgorithm against its exact solution (Jacobi's
elliptic functions, written here), with a long run and the cost per body and step.
"""

import argparse
import csv
import datetime
import math
import os
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))


def _import_yade():
    """Import the built package: PYTHONPATH (as set by ./yade) or <repo>/build."""
    try:
        import yade
    except ImportError:
        bdir = os.path.abspath(os.environ.get("YADE_BUILD_DIR") or os.path.join(REPO, "build"))
        sys.path.insert(0, bdir)
        import yade
    import yade.utils
    return yade, yade.utils


yade, yutils = _import_yade()
O = yade.O
sphere, wall, PWaveTimeStep = yutils.sphere, yutils.wall, yutils.PWaveTimeStep

EPS = sys.float_info.epsilon
INTEGRATOR = "leapfrog"   # (a case with its own `integrator` says so: the rotation schemes)


def integratorOf(case):
    return getattr(case, "integrator", None) or INTEGRATOR
DT_FACTORS = (0.025, 0.05, 0.1, 0.2, 0.4, 0.8)       # fractions of PWaveTimeStep()
DT_FACTORS_QUICK = (0.05, 0.1, 0.2, 0.4, 0.8)

# common material and particle: E, ν (= ks/kn), ρ, radius; friction angle for sliding
YOUNG, POISSON, DENSITY, RADIUS = 1e7, 0.3, 2600.0, 0.01
G = 9.81


# ---------------------------------------------------------------------------------- helpers

def material(frictionAngle=0.5):
    m = yade.FrictMat(young=YOUNG, poisson=POISSON, frictionAngle=frictionAngle, density=DENSITY)
    O.materials.append(m)
    return m


def contact_engines(gravity=(0, 0, 0), damping=0.0, walls=False):
    bo1 = [yade.Bo1_Sphere_Aabb()] + ([yade.Bo1_Wall_Aabb()] if walls else [])
    ig2 = [yade.Ig2_Sphere_Sphere_ScGeom()] + ([yade.Ig2_Wall_Sphere_ScGeom()] if walls else [])
    return [
        yade.ForceResetter(),
        yade.InsertionSortCollider(bo1),
        yade.InteractionLoop(ig2, [yade.Ip2_FrictMat_FrictMat_FrictPhys()],
                             [yade.Law2_ScGeom_FrictPhys_CundallStrack()]),
        yade.NewtonIntegrator(gravity=gravity, damping=damping),
    ]


def fresh():
    O.pause()
    O.reset()


class Result:
    """The outcome of one run: errors by kind (relative, dimensionless) plus the bookkeeping."""

    def __init__(self, dt, f, steps, wall_s, errors, values=None, exact=None, floor=None, predicted=None):
        self.dt, self.f, self.steps, self.wall_s = dt, f, steps, wall_s
        self.predicted = predicted or {}      # kind -> error predicted by the analysis of the scheme
        self.errors = errors                  # kind -> relative error
        self.values = values or {}            # kind -> measured value (for the csv)
        self.exact = exact or {}              # kind -> exact value
        self.floor = floor or {}              # kind -> round-off floor of the relative error


# ---------------------------------------------------------------------------------- cases

class FreeFall:
    name = "free_fall"
    title = "Free fall under gravity"
    kinds = [("position_rel", "|z(t) + g t²/2| / (g t²/2)", "1")]
    T_END = 0.2  # s

    description = (
        "One sphere, no contacts, `NewtonIntegrator(gravity=(0,0,-g), damping=0)`, released at rest at "
        "t=0 and integrated to the fixed end time T = {T} s (the number of steps is round(T/dt); the exact "
        "answer uses the time actually reached, O.time). Exact: z(t) = -g t²/2. Error: relative position "
        "error at the end. Yade's leapfrog treats the initial velocity as v(-dt/2), so the first step already "
        "adds the full g·dt: the positions are those of a body launched with -g·dt/2, x_n = -g t_n²/2 - "
        "g t_n dt/2. The relative error is exactly dt/t (first-order start-up of the staggered velocity), "
        "hence the theoretical order 1.")

    def __init__(self, quick=False):
        self.T = self.T_END
        self.description = self.description.format(T=self.T)

    def run(self, f):
        fresh()
        O.bodies.append(sphere((0, 0, 0), RADIUS, material=material()))
        O.engines = [yade.ForceResetter(), yade.NewtonIntegrator(gravity=(0, 0, -G), damping=0)]
        dt = f * PWaveTimeStep()
        O.dt = dt
        n = max(1, int(round(self.T / dt)))
        t0 = time.perf_counter()
        O.run(n, True)
        wall_s = time.perf_counter() - t0
        t = O.time
        z = O.bodies[0].state.pos[2]
        exact = -G * t * t / 2
        err = abs(z - exact) / abs(exact)
        return Result(dt, f, n, wall_s, {"position_rel": err}, {"position_rel": z},
                      {"position_rel": exact}, {"position_rel": n * EPS}, {"position_rel": dt / t})


class ElasticImpact:
    name = "elastic_impact"
    title = "Normal elastic impact of two spheres"
    kinds = [("contact_duration_rel", "contact duration, overlap zero crossings interpolated", "2"),
             ("contact_duration_steps_rel", "contact duration = steps with a real interaction × dt", "1"),
             ("rebound_velocity_rel", "|restitution - 1| (rebound / approach relative velocity)", "2")]
    V = 1.0        # each sphere's approach speed (relative 2V)
    N_FREE = 3     # whole free-flight steps before the contact

    description = (
        "Two equal spheres (r = {r} m) approach head-on at ±{V} m/s, no gravity, no damping. Exact (linear "
        "spring Kn = E·r between two spheres of mass m, m* = m/2): contact duration T = π·sqrt(m*/Kn), "
        "restitution 1. Each dt is run for {K} entry phases: the initial gap puts the first contact at a "
        "fraction (j+½)/{K} of a step, and the errors are RMS over the phases (they depend on where in a step "
        "the contact starts and ends). Measured every step from the "
        "positions x_n: overlap u_n = 2r - (x2 - x1); the contact starts and ends at the sign changes of u_n, "
        "located by linear interpolation between the two steps around each change (exactly where the "
        "force-free flight before and after the contact crosses u = 0). The leapfrog solution of the spring "
        "is a sinusoid of frequency ω̃ = (2/dt)·asin(ω·dt/2) ≈ ω(1 + (ω dt)²/24): the interpolated duration is "
        "short by ≈ (ω dt)²/24, order 2. Counting the steps whose interaction is real (the duration at the "
        "resolution dt) is also reported: order 1. Rebound: the relative velocity after separation is "
        "compared with the approach velocity; the scheme is time-reversible and the error comes only from the "
        "steps in which the contact opens and closes, |e - 1| ≤ (ω dt)²/8 with a phase-dependent sign, order 2 "
        "(for the envelope: the exit phase follows from the entry phase and the fractional part of T/dt, "
        "so the RMS is modulated by it). The column 'predicted' is the closed-form leapfrog solution of the "
        "spring for the same phases (see ElasticImpact.predicted).")

    def __init__(self, quick=False):
        self.K = 8 if quick else 16
        self.description = self.description.format(r=RADIUS, V=self.V, K=self.K)

    def one(self, f, phase):
        fresh()
        m = material()
        O.bodies.append([sphere((-2 * RADIUS, 0, 0), RADIUS, material=m),
                         sphere((2 * RADIUS, 0, 0), RADIUS, material=m)])
        O.engines = contact_engines()
        dt = f * PWaveTimeStep()
        O.dt = dt
        s1, s2 = O.bodies[0].state, O.bodies[1].state
        V = 2 * self.V
        gap = V * dt * (self.N_FREE + phase)  # u_0 = -gap; first u > 0 at step N_FREE+1, (1-phase)·V·dt
        s1.pos, s2.pos = (-RADIUS - gap / 2, 0, 0), (RADIUS + gap / 2, 0, 0)
        s1.vel, s2.vel = (self.V, 0, 0), (-self.V, 0, 0)
        mass = s1.mass
        kn = 2 * YOUNG * RADIUS * YOUNG * RADIUS / (YOUNG * RADIUS + YOUNG * RADIUS)
        T = math.pi * math.sqrt(mass / 2 / kn)
        us, nReal = [], 0
        maxSteps = int(10 * (T / dt + self.N_FREE + 10))
        t0 = time.perf_counter()
        for _ in range(maxSteps):
            us.append(2 * RADIUS - (s2.pos[0] - s1.pos[0]))  # u_n, used by the coming step
            O.step()
            if O.interactions.countReal() > 0:              # real iff u_n > 0
                nReal += 1
            elif nReal:
                break
        else:
            raise RuntimeError("elastic_impact: no complete contact within %d steps" % maxSteps)
        wall_s = time.perf_counter() - t0
        us.append(2 * RADIUS - (s2.pos[0] - s1.pos[0]))
        pos = [i for i, u in enumerate(us) if u > 0]
        a, b = pos[0], pos[-1]
        if any(u <= 0 for u in us[a:b + 1]) or b - a + 1 != nReal:
            raise RuntimeError("elastic_impact: interaction real / overlap sign mismatch")
        tIn = (a - 1 + (-us[a - 1]) / (us[a] - us[a - 1])) * dt
        tOut = (b + us[b] / (us[b] - us[b + 1])) * dt
        vOut = s2.vel[0] - s1.vel[0]
        return dict(T=T, dur=tOut - tIn, durSteps=nReal * dt, e=-vOut / (-V), steps=O.iter, wall=wall_s, dt=dt)

    def run(self, f):
        runs = [self.one(f, (j + 0.5) / self.K) for j in range(self.K)]
        T = runs[0]["T"]

        def rms(xs):
            return math.sqrt(sum(x * x for x in xs) / len(xs))

        errs = {"contact_duration_rel": rms([(r["dur"] - T) / T for r in runs]),
                "contact_duration_steps_rel": rms([(r["durSteps"] - T) / T for r in runs]),
                "rebound_velocity_rel": rms([r["e"] - 1 for r in runs])}
        vals = {"contact_duration_rel": sum(r["dur"] for r in runs) / len(runs),
                "contact_duration_steps_rel": sum(r["durSteps"] for r in runs) / len(runs),
                "rebound_velocity_rel": sum(r["e"] for r in runs) / len(runs)}
        exact = {"contact_duration_rel": T, "contact_duration_steps_rel": T, "rebound_velocity_rel": 1.0}
        n = sum(r["steps"] for r in runs)
        floor = {k: 100 * EPS for k in errs}
        return Result(runs[0]["dt"], f, n, sum(r["wall"] for r in runs), errs, vals, exact, floor,
                      self.predicted(runs[0]["dt"]))

    def predicted(self, dt):
        """Errors of the leapfrog solution of the contact spring, from its closed form. In contact the
        overlap is u_k = A·sin(θ·k + φ) with cos θ = 1 - (ω dt)²/2; the duration is π/θ steps; entering
        and leaving, the velocity is A·[sin(·) - sin(· - θ)]/dt, so the restitution is cos β / cos α, α and
        β the offsets (within ±θ/2) of the last free step before and the first one after the contact."""
        mass = 4. / 3. * math.pi * RADIUS ** 3 * DENSITY
        om = math.sqrt(YOUNG * RADIUS / (mass / 2))
        th = 2 * math.asin(om * dt / 2)
        T = math.pi / om
        es, ds, cs = [], [], []
        for j in range(self.K):
            p = (j + 0.5) / self.K                         # u_{n-1} = -p·V·dt, u_n = (1-p)·V·dt
            phi = math.atan2(1.0, (math.cos(th) + p / (1 - p)) / math.sin(th))
            k = math.floor((math.pi - phi) / th)           # last step in contact
            psi = phi + k * th
            es.append(abs(math.cos(psi + th / 2)) / math.cos(phi - th / 2) - 1)
            # interpolated zero crossings of the sampled sinusoid
            tIn = -(math.sin(phi) / (math.sin(phi) - math.sin(phi - th)))
            tOut = k + math.sin(psi) / (math.sin(psi) - math.sin(psi + th))
            ds.append(((tOut - tIn) * dt - T) / T)
            cs.append(((k + 1) * dt - T) / T)             # steps n..n+k have a real interaction

        def rms(xs):
            return math.sqrt(sum(x * x for x in xs) / len(xs))
        return {"contact_duration_rel": rms(ds), "contact_duration_steps_rel": rms(cs),
                "rebound_velocity_rel": rms(es)}


class Settling:
    name = "settling"
    title = "Sphere settling on a plane (damped)"
    kinds = [("static_overlap_rel", "|u - m g/Kn| / (m g/Kn) after a fixed settling time", "none (exact)")]
    DAMPING = 0.2
    PERIODS = 100

    description = (
        "A sphere (r = {r} m) released at rest touching a wall (infinite plane z = 0, sphere-wall Kn = E·r), "
        "gravity, `NewtonIntegrator(damping={d})` (non-viscous damping). Exact: static overlap u = m·g/Kn. "
        "Error: relative overlap error after a fixed physical time of {P} periods 2π·sqrt(m/Kn) of the "
        "sphere on its contact spring (the damping removes a fixed fraction of the motion per oscillation, "
        "independently of dt). At rest the leapfrog balance Kn·u = m·g holds exactly, so the scheme has no "
        "discretisation error at equilibrium: after the transient has decayed the error is round-off, "
        "bounded by the spacing of doubles around z ≈ r divided by u (u = r - z is a difference of "
        "numbers of size r), ≈ ε·r/u. No convergence order is meaningful then (theory: none, exact).")

    def __init__(self, quick=False):
        self.P = self.PERIODS
        self.description = self.description.format(r=RADIUS, d=self.DAMPING, P=self.P)

    def run(self, f):
        fresh()
        m = material()
        O.bodies.append([wall((0, 0, 0), axis=2), sphere((0, 0, RADIUS), RADIUS, material=m)])
        O.engines = contact_engines(gravity=(0, 0, -G), damping=self.DAMPING, walls=True)
        dt = f * PWaveTimeStep()
        O.dt = dt
        s = O.bodies[1].state
        kn = YOUNG * RADIUS
        u_ex = s.mass * G / kn
        period = 2 * math.pi * math.sqrt(s.mass / kn)
        n = int(round(self.P * period / dt))
        t0 = time.perf_counter()
        O.run(n, True)
        wall_s = time.perf_counter() - t0
        i = O.interactions[0, 1]
        if abs(i.phys.kn - kn) > 1e-12 * kn:
            raise RuntimeError("settling: sphere-wall kn %g differs from E·r = %g" % (i.phys.kn, kn))
        u = RADIUS - s.pos[2]
        err = abs(u - u_ex) / u_ex
        ulp = math.ulp(RADIUS) if hasattr(math, "ulp") else EPS * RADIUS
        return Result(dt, f, n, wall_s, {"static_overlap_rel": err}, {"static_overlap_rel": u},
                      {"static_overlap_rel": u_ex}, {"static_overlap_rel": ulp / u_ex})


class Sliding:
    name = "sliding"
    title = "Frictional sliding to rest"
    kinds = [("stopping_distance_rel", "|x_stop - v²/(2μg)| / (v²/(2μg))", "1")]
    V0 = 2.0
    PHI = 0.5

    description = (
        "A sphere (r = {r} m, rotations blocked with blockedDOFs='XYZ' so that it slides without rolling) "
        "rests on a wall at its static overlap m·g/Kn (no normal oscillation) and is launched along x at "
        "v0 = {v0} m/s; gravity, no damping, μ = tan({phi}) = {mu:.4f}. Exact (Coulomb friction): stopping "
        "distance v0²/(2μg) = {X:.6f} m. (The Cundall-Strack shear spring adds μ·m·g/(2Ks) = {el:.2e} of it in "
        "the continuum, but the spring reaches the Coulomb limit within the first step for every dt of the "
        "sweep, Ks·v0·dt > μ·m·g down to dt = {dtmin:.2g}·PWaveTimeStep, so the discrete model is rigid-plastic "
        "Coulomb sliding and v0²/(2μg) is its exact answer.) Stop detection: run until the velocity changes "
        "sign; the leapfrog trajectory under the constant friction deceleration is exactly a parabola "
        "through the positions x_n with on-step velocity v_n = (v_{{n-1/2}} + v_{{n+1/2}})/2, whose maximum "
        "x_n + v_n²/(2a) is taken as the stopping point (so the granularity of the detection does not "
        "enter). What remains is the start-up error of the staggered velocity, as in free fall: friction "
        "acts from step 0 with v(-dt/2) = v0, the stopping point is short by v0·dt/2. Order 1.")

    def __init__(self, quick=False):
        mu = math.tan(self.PHI)
        mass = 4. / 3. * math.pi * RADIUS ** 3 * DENSITY
        ks = POISSON * YOUNG * RADIUS
        X = self.V0 ** 2 / (2 * mu * G)
        dtp = RADIUS / math.sqrt(YOUNG / DENSITY)
        self.description = self.description.format(
            r=RADIUS, v0=self.V0, phi=self.PHI, mu=mu, X=X, el=mu * mass * G / (2 * ks) / X,
            dtmin=mu * mass * G / (ks * self.V0) / dtp)

    def run(self, f):
        fresh()
        m = material(frictionAngle=self.PHI)
        O.bodies.append([wall((0, 0, -RADIUS), axis=2), sphere((0, 0, 0), RADIUS, material=m)])
        O.engines = contact_engines(gravity=(0, 0, -G), damping=0, walls=True)
        dt = f * PWaveTimeStep()
        O.dt = dt
        s = O.bodies[1].state
        mu = math.tan(self.PHI)
        kn, ks = YOUNG * RADIUS, POISSON * YOUNG * RADIUS
        s.pos = (0, 0, -s.mass * G / kn)
        s.blockedDOFs = "XYZ"
        s.vel = (self.V0, 0, 0)
        if ks * self.V0 * dt <= mu * s.mass * G:
            raise RuntimeError("sliding: dt too small, the shear spring is resolved (see the description)")
        X = self.V0 ** 2 / (2 * mu * G)
        tStop = self.V0 / (mu * G)
        t0 = time.perf_counter()
        O.run(max(0, int(tStop / dt) - 5), True)   # bulk, then step by step to the reversal
        vPrev, xPrev = s.vel[0], s.pos[0]          # v_{n-1/2}, x_n
        for _ in range(100000):
            O.step()
            if s.vel[0] <= 0:
                break
            vPrev, xPrev = s.vel[0], s.pos[0]
        else:
            raise RuntimeError("sliding: the sphere did not stop")
        wall_s = time.perf_counter() - t0
        vNext = s.vel[0]                           # v_{n+1/2}, from the force at x_n
        if vPrev <= 0:
            raise RuntimeError("sliding: stopped before the step-by-step phase")
        a = (vPrev - vNext) / dt
        if abs(a / (mu * G) - 1) > 1e-6:
            raise RuntimeError("sliding: deceleration %g is not μ·g = %g" % (a, mu * G))
        vn = 0.5 * (vPrev + vNext)
        xStop = xPrev + vn * vn / (2 * a) * (1 if vn >= 0 else -1)
        err = abs(xStop - X) / X
        return Result(dt, f, O.iter, wall_s, {"stopping_distance_rel": err}, {"stopping_distance_rel": xStop},
                      {"stopping_distance_rel": X}, {"stopping_distance_rel": O.iter * EPS},
                      {"stopping_distance_rel": self.V0 * dt / 2 / X})


# ---------------------------------------------------------------------------------- torque-free rotation

def ellipj(u, m):
    """Jacobi's sn, cn, dn and the amplitude am of u, parameter m in [0, 1), by the arithmetic-geometric mean
    (the descending Landen transformation, Abramowitz & Stegun 16.4): a, b, c from (1, sqrt(1-m), sqrt(m))
    until c vanishes, φ = 2^N·a_N·u, then back φ_{k-1} = (φ_k + asin(c_k/a_k·sin φ_k))/2; sn = sin φ_0."""
    if m == 0:
        return math.sin(u), math.cos(u), 1.0, u
    a, c, b = [1.0], [math.sqrt(m)], math.sqrt(1 - m)
    while abs(c[-1]) > 4e-16 * a[-1] and len(a) < 20:   # (c squares each time: 5 or 6 rounds)
        a0 = a[-1]
        a.append(0.5 * (a0 + b))
        c.append(0.5 * (a0 - b))
        b = math.sqrt(a0 * b)
    n = len(a) - 1
    phi = 2 ** n * a[n] * u
    for k in range(n, 0, -1):
        phi = 0.5 * (phi + math.asin(c[k] / a[k] * math.sin(phi)))
    s = math.sin(phi)
    return s, math.cos(phi), math.sqrt(1 - m * s * s), phi


def ellipk(m):
    """The complete elliptic integral of the first kind K(m) = π / (2·AGM(1, sqrt(1-m)))."""
    a, b = 1.0, math.sqrt(1 - m)
    while abs(a - b) > 4e-16 * a:
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return math.pi / (2 * a)


_GL = math.sqrt(10. / 7)
GAUSS5 = [(0., 128. / 225),                       # 5-point Gauss-Legendre on [-1, 1]: nodes, weights
          (math.sqrt(5 - 2 * _GL) / 3, (322 + 13 * math.sqrt(70)) / 900), (-math.sqrt(5 - 2 * _GL) / 3, (322 + 13 * math.sqrt(70)) / 900),
          (math.sqrt(5 + 2 * _GL) / 3, (322 - 13 * math.sqrt(70)) / 900), (-math.sqrt(5 + 2 * _GL) / 3, (322 - 13 * math.sqrt(70)) / 900)]


def qmul(a, b):
    """Product of quaternions given as (w, x, y, z)."""
    return (a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0])


def qconj(a):
    return (a[0], -a[1], -a[2], -a[3])


def qturn(q, v):
    """v turned by the unit quaternion q (w, x, y, z)."""
    return qmul(qmul(q, (0.,) + tuple(v)), qconj(q))[1:]


def qabout(axis, angle):
    return (math.cos(angle / 2),) + tuple(math.sin(angle / 2) if i == axis else 0. for i in range(3))


def qangle(a, b):
    """The angle of the rotation from a to b [rad] (either sign of either quaternion)."""
    d = qmul(qconj(a), b)
    return 2 * math.atan2(math.sqrt(d[1] ** 2 + d[2] ** 2 + d[3] ** 2), abs(d[0]))


class FreeTop:
    """The exact torque-free rotation of a rigid body of principal moments I1 < I2 < I3 from the spin w0
    (body frame) and the orientation q0 (w, x, y, z) at t = 0, when L² > 2E·I2 (the spin circles the axis of
    I3; Landau & Lifshitz, Mechanics §37): w1 = s·A1·cn(λt + τ0), w2 = A2·sn(λt + τ0), w3 = s·A3·dn(λt + τ0),
    s = sign(w3(0)), A1² = (2E·I3 - L²)/(I1(I3 - I1)), A2² = (2E·I3 - L²)/(I2(I3 - I2)), A3² = (L² - 2E·I1)/(I3(I3 - I1)),
    λ² = (I3 - I2)(L² - 2E·I1)/(I1·I2·I3), m = (I2 - I1)(2E·I3 - L²)/((I3 - I2)(L² - 2E·I1)); τ0 from am(τ0) =
    atan2(w2/A2, w1/(s·A1)) by Newton's method (am' = dn). The orientation by its Euler angles (z-x-z, the
    fixed z axis along L): cos θ = I3·w3/L, tan ψ = I1·w1/(I2·w2), φ' = L(I1·w1² + I2·w2²)/(I1²w1² + I2²w2²), φ
    integrated by Gauss-Legendre quadrature (40 panels per period of φ')."""

    def __init__(self, I, w0, q0):
        I1, I2, I3 = I
        if not I1 < I2 < I3:
            raise ValueError("FreeTop: the moments must increase")
        L2 = sum((I[i] * w0[i]) ** 2 for i in range(3))
        E2 = sum(I[i] * w0[i] ** 2 for i in range(3))
        if not L2 > E2 * I2:
            raise ValueError("FreeTop: the spin must circle the axis of the largest moment (L² > 2E·I2)")
        self.I, self.q0, self.L, self.E = I, q0, math.sqrt(L2), E2 / 2
        self.A = (math.sqrt((E2 * I3 - L2) / (I1 * (I3 - I1))), math.sqrt((E2 * I3 - L2) / (I2 * (I3 - I2))),
                  math.sqrt((L2 - E2 * I1) / (I3 * (I3 - I1))))
        self.lam = math.sqrt((I3 - I2) * (L2 - E2 * I1) / (I1 * I2 * I3))
        self.m = (I2 - I1) * (E2 * I3 - L2) / ((I3 - I2) * (L2 - E2 * I1))
        self.s = 1.0 if w0[2] >= 0 else -1.0
        self.K = ellipk(self.m)
        target = math.atan2(w0[1] / self.A[1], w0[0] / (self.s * self.A[0]))
        tau = target
        for _ in range(60):
            _, _, dn, am = ellipj(tau, self.m)
            step = (am - target) / dn
            tau -= step
            if abs(step) < 1e-16 * max(1., abs(tau)):
                break
        self.tau0 = tau
        self.period = 2 * self.K / self.lam       # of w1², w2², hence of φ'
        self.frame = qmul(q0, qconj(self._euler(0., w0)))   # q(t) = frame·R(t): R(0) = the rotation from L's frame to q0
        self.tPhi, self.phi = 0., 0.
        self.Lglobal = qturn(q0, [I[i] * w0[i] for i in range(3)])

    def spin(self, t):
        """The spin at time t, body frame."""
        sn, cn, dn, _ = ellipj(math.fmod(self.lam * t + self.tau0, 4 * self.K), self.m)
        return (self.s * self.A[0] * cn, self.A[1] * sn, self.s * self.A[2] * dn)

    def _phiDot(self, t):
        w, I = self.spin(t), self.I
        return self.L * (I[0] * w[0] ** 2 + I[1] * w[1] ** 2) / ((I[0] * w[0]) ** 2 + (I[1] * w[1]) ** 2)

    def _phiAt(self, t):
        if t < self.tPhi:
            self.tPhi, self.phi = 0., 0.
        a, b = self.tPhi, t
        n = max(1, int(math.ceil((b - a) / self.period * 40)))
        h = (b - a) / n
        for k in range(n):
            c = a + (k + 0.5) * h
            self.phi += 0.5 * h * sum(wt * self._phiDot(c + 0.5 * h * x) for x, wt in GAUSS5)
        self.tPhi = t
        return self.phi

    def _euler(self, phi, w):
        I = self.I
        theta = math.acos(max(-1., min(1., I[2] * w[2] / self.L)))
        psi = math.atan2(I[0] * w[0], I[1] * w[1])
        return qmul(qmul(qabout(2, phi), qabout(0, theta)), qabout(2, psi))

    def orientation(self, t):
        """The orientation at time t (w, x, y, z); fastest for times asked in increasing order."""
        return qmul(self.frame, self._euler(self._phiAt(t), self.spin(t)))


def _wxyz(q):
    return (q[3], q[0], q[1], q[2])   # (a Quaternion indexes as x, y, z, w)


class TorqueFreeRotation:
    """One case per scheme of NewtonIntegrator.rotAlgorithm (the subclasses)."""
    title = "Torque-free rotation of an asymmetric body"
    integrator = None                     # NewtonIntegrator.rotAlgorithm
    SPIN = (1.0, 0.5, 0.9)                # the initial spin's direction, body frame
    RATE = 0.025                          # |ω|·PWaveTimeStep(): ω·dt from 6e-4 to 0.02 rad over the sweep
    TURNS = {False: 20., True: 10.}       # radians of rotation per run (quick: True)
    LONG = {False: 2000., True: 400.}     # radians of the long run, at dt = LONG_F·PWaveTimeStep()
    LONG_F = 0.1
    COST_BODIES = {False: 1000, True: 300}
    Q0 = (0.5907507033036815, 0.21564084004695758, 0.43128168009391515, 0.6469225201408727)   # (w, x, y, z)
    description = (
        "One body of principal moments (1, 2, 3)·I0 (a sphere of r = {r} m given those moments: aspherical for the "
        "integrator), no torque, no damping, `NewtonIntegrator(rotAlgorithm='{scheme}')`, spinning with |ω| = "
        "{rate}/PWaveTimeStep about the body-frame direction (1, 0.5, 0.9) from a turned orientation, for {turns:g} "
        "radians of rotation (m = {m:.4f}: the spin circles the axis of the largest moment, period of the body-frame "
        "spin {period:.3g} s). Exact: Euler's equations solved by Jacobi's elliptic functions (sn, cn, dn and K(m) "
        "by the arithmetic-geometric mean, written in this script), the orientation by its Euler angles about L "
        "(the precession angle by Gauss-Legendre quadrature): checked against RK4 on Euler's equations and the "
        "quaternion kinematics in tests/test_accuracy.py. {start} Errors at the end (t = N·dt): `angvel_rel` "
        "the stored spin in the body frame against the exact spin half a step before (the integrator keeps "
        "mid-step spins), relative to |ω|; `orientation_rad` the angle of the rotation between the computed and "
        "exact orientations; `energy_rel` and `angular_momentum_rel` the largest drift of E and L (global frame) "
        "over 20 samples from their exact values, {invariants}")

    def __init__(self, quick=False):
        self.quick = quick
        self.turns = self.TURNS[quick]
        mass = 4. / 3. * math.pi * RADIUS ** 3 * DENSITY
        self.I = tuple(0.4 * mass * RADIUS ** 2 * k for k in (1., 2., 3.))
        top = FreeTop(self.I, self._w0(1.), self.Q0)
        self.description = self.description.format(
            r=RADIUS, scheme=self.integrator, rate=self.RATE, turns=self.turns, m=top.m,
            period=top.period * (RADIUS / math.sqrt(YOUNG / DENSITY)), start=self.START, invariants=self.INVARIANTS)
        self.longRun = self.cost = None

    def _w0(self, dtp):
        n = math.sqrt(sum(x * x for x in self.SPIN))
        return tuple(self.RATE / dtp * x / n for x in self.SPIN)

    def _scene(self, f, bodies=1):
        fresh()
        mat = material()
        O.bodies.append([sphere((3 * RADIUS * k, 0, 0), RADIUS, material=mat) for k in range(bodies)])
        O.engines = [yade.ForceResetter(), yade.NewtonIntegrator(gravity=(0, 0, 0), damping=0, rotAlgorithm=self.integrator)]
        dtp = PWaveTimeStep()
        dt = f * dtp
        O.dt = dt
        w0 = self._w0(dtp)
        top = FreeTop(self.I, w0, self.Q0)
        q0 = yade.Quaternion(*self.Q0)
        for b in O.bodies:
            s = b.state
            s.inertia = self.I
            s.ori = q0
            self.start(s, top, q0, dt)
        return top, dt

    def _invariants(self, s):
        """On-step E and L (global frame) of the body whose state is s."""
        raise NotImplementedError

    def run(self, f):
        top, dt = self._scene(f)
        s = O.bodies[0].state
        n = int(round(self.turns / math.sqrt(sum(x * x for x in top.spin(0))) / dt))
        errL = errE = wall_s = 0.
        done = 0
        for c in range(20):
            k = (n * (c + 1)) // 20 - done
            t0 = time.perf_counter()
            O.run(k - self.SAMPLE_STEPS, True)
            E, L = self._invariants(s)
            wall_s += time.perf_counter() - t0
            done += k
            errL = max(errL, math.sqrt(sum((L[i] - top.Lglobal[i]) ** 2 for i in range(3))) / top.L)
            errE = max(errE, abs(E - top.E) / top.E)
        q = _wxyz(s.ori)
        t = O.iter * dt
        w = qturn(qconj(q), s.angVel)
        wEx = top.spin(t - dt / 2)
        errW = math.sqrt(sum((w[i] - wEx[i]) ** 2 for i in range(3))) / math.sqrt(sum(x * x for x in top.spin(0)))
        errQ = qangle(top.orientation(t), q)
        errs = {"angvel_rel": errW, "orientation_rad": errQ, "energy_rel": errE, "angular_momentum_rel": errL}
        return Result(dt, f, n, wall_s, errs, dict(errs), {k: 0. for k in errs}, {k: n * EPS for k in errs})

    def finish(self, factors):
        """The long run (energy and momentum over LONG radians at LONG_F) and the cost per body and step."""
        top, dt = self._scene(self.LONG_F)
        s = O.bodies[0].state
        n = int(round(self.LONG[self.quick] / math.sqrt(sum(x * x for x in top.spin(0))) / dt))
        samples, done, worstE, worstL, series = 100, 0, 0., 0., []
        t0 = time.perf_counter()
        for c in range(samples):
            k = (n * (c + 1)) // samples - done
            O.run(k - self.SAMPLE_STEPS, True)
            E, L = self._invariants(s)
            done += k
            dE = (E - top.E) / top.E
            series.append((O.iter * dt, dE))
            worstE = max(worstE, abs(dE))
            worstL = max(worstL, math.sqrt(sum((L[i] - top.Lglobal[i]) ** 2 for i in range(3))) / top.L)
        wall = time.perf_counter() - t0
        mt, me = sum(t for t, _ in series) / samples, sum(e for _, e in series) / samples   # least-squares line
        slope = sum((t - mt) * (e - me) for t, e in series) / sum((t - mt) ** 2 for t, _ in series)
        trend = slope * (series[-1][0] - series[0][0])
        self.longRun = dict(f=self.LONG_F, steps=n, turns=self.LONG[self.quick], energy=worstE, momentum=worstL, trend=trend,
                            wall=wall)
        nb, steps = self.COST_BODIES[self.quick], 200
        self._scene(0.1, nb)
        O.run(5, True)
        t0 = time.perf_counter()
        O.run(steps, True)
        self.cost = dict(bodies=nb, ns=(time.perf_counter() - t0) / (nb * steps) * 1e9, spheres=sphereCost(nb, steps))

    def extra_md(self):
        if not self.longRun:
            return []
        r, c = self.longRun, self.cost
        return ["- Long run: %g radians at dt = %g·PWaveTimeStep (%d steps, %.2f s): largest drift of E %.2e, of L %.2e; "
                "the least-squares line through the energy errors rises by %.1e over the run (a secular drift when "
                "comparable to the largest, a bounded oscillation when much smaller)." % (r["turns"], r["f"], r["steps"], r["wall"], r["energy"],
                                                                     r["momentum"], r["trend"]),
                "- Cost: %.0f ns per body and step for %d such bodies without contacts (the whole step: ForceResetter "
                "and NewtonIntegrator), against %.0f ns for as many spheres." % (c["ns"], c["bodies"], c["spheres"])]


_sphereCost = {}


def sphereCost(nb, steps):
    """ns per body and step of nb free spinning spheres (the spherical update), measured once."""
    if (nb, steps) not in _sphereCost:
        fresh()
        mat = material()
        O.bodies.append([sphere((3 * RADIUS * k, 0, 0), RADIUS, material=mat) for k in range(nb)])
        for b in O.bodies:
            b.state.angVel = (1, 2, 3)
        O.engines = [yade.ForceResetter(), yade.NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
        O.dt = 0.1 * PWaveTimeStep()
        O.run(5, True)
        t0 = time.perf_counter()
        O.run(steps, True)
        _sphereCost[(nb, steps)] = (time.perf_counter() - t0) / (nb * steps) * 1e9
    return _sphereCost[(nb, steps)]


class _ByMomentum:
    """Fincham's scheme: the state is the angular momentum (global frame)."""
    SAMPLE_STEPS = 0
    START = ("The state is the angular momentum: State.angMom = q0·I·ω(0), exact and constant; the spin follows.")
    INVARIANTS = ("L being State.angMom (the scheme's state: constant to round-off without torque) and E = ½·l·I⁻¹·l, "
                  "l = q⁻¹·L in the body frame at the step's orientation.")

    def start(self, s, top, q0, dt):
        w = top.spin(0.)
        s.angMom = q0 * yade.Vector3(*[self.I[i] * w[i] for i in range(3)])
        s.angVel = q0 * yade.Vector3(*w)

    def _invariants(self, s):
        L = s.angMom
        l = qturn(qconj(_wxyz(s.ori)), L)
        return 0.5 * sum(l[i] ** 2 / self.I[i] for i in range(3)), L


class _BySpin:
    """SPIRAL and Omelyan: the state is the mid-step spin."""
    SAMPLE_STEPS = 1
    START = ("The state is the mid-step spin: State.angVel = q0·ω(-dt/2), the exact spin half a step before the first "
             "step (so the start adds no error of its own).")
    INVARIANTS = ("on-step: L = q_n·I·w, E = ½·w·I·w, w = the mean of the body-frame spins of the half steps around "
                  "t_n (one more step at each sample).")

    def start(self, s, top, q0, dt):
        w = top.spin(-dt / 2)
        s.angVel = q0 * yade.Vector3(*w)
        s.angMom = q0 * yade.Vector3(*[self.I[i] * w[i] for i in range(3)])

    def _invariants(self, s):
        q = _wxyz(s.ori)
        w1 = qturn(qconj(q), s.angVel)
        O.step()
        w2 = qturn(qconj(_wxyz(s.ori)), s.angVel)
        w = [0.5 * (a + b) for a, b in zip(w1, w2)]
        return 0.5 * sum(self.I[i] * w[i] ** 2 for i in range(3)), qturn(q, [self.I[i] * w[i] for i in range(3)])


class TorqueFreeFincham(_ByMomentum, TorqueFreeRotation):
    name = "torque_free_fincham"
    integrator = "Fincham1992"
    kinds = [("angvel_rel", "|w - w_exact(t - dt/2)| / |w| at the end, body frame", "2 (manual)"),
             ("orientation_rad", "rotation angle between q(t) and q_exact(t) at the end [rad]", "2 (manual)"),
             ("energy_rel", "max |E - E0| / E0 over the run", "2 (manual)"),
             ("angular_momentum_rel", "max |L - L0| / |L0| over the run (State.angMom)", "exact (the state)")]


class TorqueFreeSpiral(_BySpin, TorqueFreeRotation):
    name = "torque_free_spiral"
    integrator = "delValle2023"
    kinds = [("angvel_rel", "|w - w_exact(t - dt/2)| / |w| at the end, body frame", "3 (manual)"),
             ("orientation_rad", "rotation angle between q(t) and q_exact(t) at the end [rad]", "3 (manual)"),
             ("energy_rel", "max |E - E0| / E0 over the run (on-step)", "3 (manual)"),
             ("angular_momentum_rel", "max |L - L0| / |L0| over the run (on-step)", "3 (manual)")]


class TorqueFreeOmelyan(_BySpin, TorqueFreeRotation):
    name = "torque_free_omelyan"
    integrator = "Omelyan1998"
    kinds = TorqueFreeSpiral.kinds


CASES = [FreeFall, ElasticImpact, Settling, Sliding, TorqueFreeFincham, TorqueFreeSpiral, TorqueFreeOmelyan]


# ---------------------------------------------------------------------------------- analysis

def fit_order(dts, errs, floors, factor=10.0):
    """Least-squares slope of log(error) against log(dt) over the points whose error is above
    factor × its round-off floor. Returns (slope, number of points used); slope None if < 3 points."""
    pts = [(math.log(d), math.log(e)) for d, e, fl in zip(dts, errs, floors)
           if e > 0 and math.isfinite(e) and e > factor * fl]
    if len(pts) < 3:
        return None, len(pts)
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    return sxy / sxx, len(pts)


def fmt_order(o, npts):
    return "n/a (%d points above round-off)" % npts if o is None else "%.2f" % o


# ---------------------------------------------------------------------------------- output

CSV_COLUMNS = ["case", "integrator", "dt", "dt_over_critical", "steps", "wall_s", "error", "error_kind",
               "value", "exact", "roundoff_floor", "predicted_error"]


def write_csv(path, results):
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_COLUMNS)
        for case, runs in results:
            for kind, _, _ in case.kinds:
                for r in runs:
                    w.writerow([case.name, integratorOf(case), "%.9e" % r.dt, "%g" % r.f, r.steps, "%.6f" % r.wall_s,
                                "%.6e" % r.errors[kind], kind, "%.12e" % r.values.get(kind, float("nan")),
                                "%.12e" % r.exact.get(kind, float("nan")), "%.3e" % r.floor.get(kind, 0.0),
                                "%.6e" % r.predicted[kind] if kind in r.predicted else ""])


def orders_of(case, runs):
    out = {}
    for kind, _, theory in case.kinds:
        out[kind] = fit_order([r.dt for r in runs], [r.errors[kind] for r in runs],
                              [r.floor.get(kind, 0.0) for r in runs])
    return out


def write_png(path, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    nLines = sum(len(case.kinds) for case, _ in results)
    rows = (nLines + 2) // 3 + 1                      # (the legend below: three columns, the slopes included)
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(15, 6 + 0.22 * rows))
    colors = plt.get_cmap("tab20").colors
    ax.set_prop_cycle(color=colors)
    ax2.set_prop_cycle(color=colors)
    markers = "osD^vP*Xh"
    styles = {}
    i = 0
    for case, runs in results:
        for kind, label, theory in case.kinds:
            styles[(case.name, kind)] = markers[i % len(markers)]
            i += 1
    lines = []
    for case, runs in results:
        for kind, label, theory in case.kinds:
            walls = [max(r.wall_s, 1e-7) for r in runs]
            errs = [r.errors[kind] for r in runs]
            floor = min(r.floor.get(kind, EPS) for r in runs)
            shown = [e if e > 0 else floor for e in errs]   # exact zeros drawn at the round-off floor
            lab = "%s: %s (%s)" % (case.name, kind.replace("_rel", ""), integratorOf(case))
            l, = ax.loglog(walls, shown, "-" + styles[(case.name, kind)], label=lab, ms=5)
            lines.append(l)
            # annotate the extreme time steps
            for r, e in ((runs[0], shown[0]), (runs[-1], shown[-1])):
                ax.annotate("%g" % r.f, (max(r.wall_s, 1e-7), e), textcoords="offset points", xytext=(4, 3),
                            fontsize=7, color=l.get_color())
            ax2.loglog([r.f for r in runs], shown, "-" + styles[(case.name, kind)], color=l.get_color(),
                       label=lab, ms=5)
    ax.set_xlabel("wall time of the run [s]")
    ax.set_ylabel("relative error")
    ax.set_title("Work-precision diagram (labels: dt / PWaveTimeStep)")
    ax.grid(True, which="major", alpha=0.5)
    ax.grid(True, which="minor", alpha=0.15)
    # reference slopes on the right panel
    fs = sorted({r.f for _, runs in results for r in runs})
    f0, f1 = fs[0], fs[-1]
    for order, y1 in ((1, 3e-2), (2, 3e-3)):
        ax2.loglog([f0, f1], [y1 * (f0 / f1) ** order, y1], "k--" if order == 1 else "k:", lw=1,
                   label="slope %d" % order)
    ax2.set_xlabel("dt / PWaveTimeStep()")
    ax2.set_ylabel("relative error")
    ax2.set_title("Convergence: error against time step (reference slopes 1 and 2)")
    ax2.set_xticks(fs)
    ax2.set_xticklabels(["%g" % f for f in fs])
    ax2.minorticks_off()
    ax2.grid(True, which="major", alpha=0.5)
    for axis in (ax, ax2):
        for case, runs in results:
            if case.name == "settling":
                axis.text(0.02, 0.12, "settling: at the round-off floor (exact equilibrium)", transform=axis.transAxes,
                          fontsize=8, color="0.3")
    handles, labels = ax2.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=3, fontsize=9, frameon=False)
    fig.suptitle("Yade-compatible engine: accuracy suite (%s integrator; the rotation schemes as named; one line per "
                 "case and error)" % INTEGRATOR)
    fig.tight_layout(rect=(0, 0.22 * rows / (6 + 0.22 * rows) + 0.02, 1, 1))
    fig.savefig(path, dpi=110)
    plt.close(fig)


def reading(results, orders):
    """A short interpretation of the measured numbers."""
    R = {case.name: (case, runs) for case, runs in results}
    o = {(c.name, k): orders[c.name][k] for c, _ in results for k, _, _ in c.kinds}
    lines = []

    def od(name, kind):
        v, n = o[(name, kind)]
        return "n/a" if v is None else "%.2f" % v

    def dev(runs, kind):
        d = [abs(r.errors[kind] / r.predicted[kind] - 1) for r in runs
             if r.predicted.get(kind) and r.errors[kind] > 10 * r.floor.get(kind, 0)]
        return max(d) if d else float("nan")

    if "free_fall" in R:
        case, runs = R["free_fall"]
        lines.append(
            "- **Free fall**: measured order %s (theory 1). The error is exactly the leapfrog start-up error "
            "g·t·dt/2 (relative dt/t; measured/predicted - 1 within %.0e): the initial velocity is taken as "
            "v(-dt/2), a first-order start; the staggered scheme itself is exact for a constant force (starting "
            "from v(-dt/2) = v(0) - g·dt/2 would remove the error)." % (od("free_fall", "position_rel"),
                                                                         dev(runs, "position_rel")))
    if "elastic_impact" in R:
        case, runs = R["elastic_impact"]
        big, lo = runs[-1], runs[0]
        lines.append(
            "- **Elastic impact**: the interpolated contact duration converges with order %s (theory 2): it is "
            "the phase error of the leapfrog spring, frequency (2/dt)·asin(ω·dt/2) instead of ω, so the contact "
            "is short by ≈ (ω·dt)²/24: %.1e at %g·dt_crit, %.1e at %g·dt_crit. Counting the steps with a real "
            "interaction instead gives order %s (theory 1; resolution one dt, %.0f× the integration error at "
            "%g·dt_crit). The restitution error has order %s (theory 2) and stays below %.1e up to %g·dt_crit: "
            "it arises only in the steps where the contact opens and closes, and its sign depends on where in "
            "a step they fall, so it is modulated by the fractional part of T/dt (the points scatter under the "
            "envelope (ω·dt)²/8 and the fitted slope is only indicative). All three errors agree with the "
            "closed-form leapfrog solution of the linear spring to %.0e relative or better: the engine "
            "integrates the contact exactly as the analysis of the scheme says."
            % (od("elastic_impact", "contact_duration_rel"), big.errors["contact_duration_rel"], big.f,
               lo.errors["contact_duration_rel"], lo.f, od("elastic_impact", "contact_duration_steps_rel"),
               lo.errors["contact_duration_steps_rel"] / lo.errors["contact_duration_rel"], lo.f,
               od("elastic_impact", "rebound_velocity_rel"),
               max(r.errors["rebound_velocity_rel"] for r in runs), big.f,
               max(dev(runs, k) for k in ("contact_duration_rel", "contact_duration_steps_rel",
                                          "rebound_velocity_rel"))))
    if "settling" in R:
        case, runs = R["settling"]
        errs = [r.errors["static_overlap_rel"] for r in runs]
        fl = max(r.floor["static_overlap_rel"] for r in runs)
        v, n = o[("settling", "static_overlap_rel")]
        lines.append(
            "- **Settling**: after %d oscillation periods every run is at the exact static overlap m·g/Kn up to "
            "%.1e relative, the round-off level (floor ε·r/u ≈ %.1e: u = r - z is computed from positions of "
            "size r). The leapfrog equilibrium has no discretisation error and the damping decides how fast it "
            "is reached per oscillation, independently of dt; the error therefore does not depend on dt and %s."
            % (case.P, max(errs), fl,
               "no convergence order is meaningful (%d of %d points above 10× the floor)" % (n, len(runs))
               if v is None else "the fitted slope %.2f reflects round-off noise, not an order" % v))
    if "sliding" in R:
        case, runs = R["sliding"]
        lines.append(
            "- **Sliding to rest**: measured order %s (theory 1). The stopping point is interpolated (maximum "
            "of the discrete parabola), so the detection granularity does not enter; what remains is the "
            "start-up error v0·dt/2 of the staggered velocity (friction acts from step 0 on v(-dt/2) = v0), "
            "matched within %.0e relative (the rest is second order). Without interpolation the last sampled "
            "position would differ from the stop by up to μ·g·dt²/8 more."
            % (od("sliding", "stopping_distance_rel"), dev(runs, "stopping_distance_rel")))
    rot = [(c, runs) for c, runs in results if isinstance(c, TorqueFreeRotation)]
    if rot:
        parts = []
        for c, runs in rot:
            big = runs[-1]
            parts.append("%s: orders %s (spin), %s (orientation), %s (energy), %s (momentum); at %g·dt_crit (ω·dt = %.3g "
                         "rad) the orientation is off by %.1e rad after %g rad of rotation%s"
                         % (c.integrator, od(c.name, "angvel_rel"), od(c.name, "orientation_rad"), od(c.name, "energy_rel"),
                            od(c.name, "angular_momentum_rel"), big.f, c.RATE * big.f, big.errors["orientation_rad"], c.turns,
                            "; long run: E drifts by %.1e, L by %.1e; %.0f ns per body and step" % (
                                c.longRun["energy"], c.longRun["momentum"], c.cost["ns"]) if c.longRun else ""))
        lines.append(
            "- **Torque-free rotation of an asymmetric body** (one case per NewtonIntegrator.rotAlgorithm): " + "; ".join(parts) + ". "
            "Fincham1992 is the reference 2023.02a's scheme, bit for bit (tests/test_aspherical_rotation.py), and "
            "measures first order, not the second the manual gives: it finds the mid-step spin from the angular "
            "momentum at the on-step orientation, where Fincham's scheme takes the half-step one (a Python copy of the "
            "step with the half-step orientation is second order: 6e-6 rad instead of 5e-2 off after 20 s at dt = "
            "1e-3 s for moments (1, 2, 3) and spin (1, 0.5, 0.9)), so its energy drifts secularly, in proportion to dt. SPIRAL's spin is third order, its "
            "orientation second (the manual says third for both); Omelyan's is second order throughout (the manual "
            "says third). SPIRAL and Omelyan keep E and L to a bounded oscillation over long runs, at a higher cost "
            "per step than Fincham's (the costs above: the whole step of bodies without contacts).")
    lines.append(
        "- **Work-precision**: the wall time is proportional to the number of steps (1/dt), so a method of "
        "order p divides the error by 2^p for twice the work: ×2 wall time per halving of the error for free "
        "fall and sliding (order 1, limited by the first-order start of the staggered velocity, not by the "
        "scheme), ×1.4 for the contact duration and restitution (order 2). The interpolated contact duration "
        "and the restitution errors stay below "
        "%.1f %% up to 0.8·PWaveTimeStep (the critical step of the contact spring itself is 2/ω ≈ 2.9·"
        "PWaveTimeStep here); at small dt the start-up errors, not the contacts, dominate."
        % (100 * max((r.errors[k] for c, runs in results if c.name == "elastic_impact" for r in runs
                      for k in ("contact_duration_rel", "rebound_velocity_rel")), default=0)))
    return "\n".join(lines)


def write_md(path, results, orders, failed, unavailable, total_s, factors, quick):
    L = []
    L.append("# Accuracy suite")
    L.append("")
    L.append("Generated %s by `scripts/accuracy/accuracy.py`%s (engine version %s). Integrator: `%s` "
             "(NewtonIntegrator). Every case is run at dt = f·PWaveTimeStep() for f in %s; the wall time is "
             "that of the simulation (Python stepping included where a case steps one by one). Errors are "
             "relative. Measured order = least-squares slope of log(error) against log(dt) over the points "
             "whose error is above 10× the round-off floor (at least 3 needed). Total run time of the suite: "
             "%.1f s."
             % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), " --quick" if quick else "",
                _version(), INTEGRATOR, ", ".join("%g" % f for f in factors), total_s))
    L.append("")
    L.append("Common particle: sphere r = %g m, FrictMat(young=%g, poisson=%g, density=%g); g = %g m/s²; "
             "PWaveTimeStep() = %.4e s." % (RADIUS, YOUNG, POISSON, DENSITY, G,
                                             RADIUS / math.sqrt(YOUNG / DENSITY)))
    L.append("")
    L.append("## Summary")
    L.append("")
    L.append("| case | error | integrator | measured order | theoretical order |")
    L.append("|---|---|---|---|---|")
    for case, runs in results:
        for kind, label, theory in case.kinds:
            v, n = orders[case.name][kind]
            L.append("| %s | %s | %s | %s | %s |" % (case.name, kind, integratorOf(case), fmt_order(v, n), theory))
    for case, why in unavailable:
        L.append("| %s | %s | — | %s | %s |" % (case.name, ", ".join(k for k, _, _ in case.kinds), why,
                                               ", ".join(t for _, _, t in case.kinds)))
    for case, why in failed:
        L.append("| %s | — | %s | FAILED: %s | |" % (case.name, integratorOf(case), why))
    L.append("")
    for case, runs in results:
        L.append("## %s (`%s`)" % (case.title, case.name))
        L.append("")
        L.append(case.description)
        L.append("")
        cols = []
        for k, _, _ in case.kinds:
            cols.append(("error " + k, k, "errors"))
            if any(k in r.predicted for r in runs):
                cols.append(("predicted", k, "predicted"))
        L.append("| dt/dt_crit | dt [s] | steps | wall [s] | " + " | ".join(c[0] for c in cols) + " |")
        L.append("|" + "---|" * (4 + len(cols)))
        for r in runs:
            cells = []
            for _, k, what in cols:
                d = getattr(r, what)
                cells.append("%.3e" % d[k] if k in d else "")
            L.append("| %g | %.4e | %d | %.4f | %s |" % (r.f, r.dt, r.steps, r.wall_s, " | ".join(cells)))
        L.append("")
        for kind, label, theory in case.kinds:
            v, n = orders[case.name][kind]
            dev = [abs(r.errors[kind] / r.predicted[kind] - 1) for r in runs
                   if r.predicted.get(kind) and r.errors[kind] > 10 * r.floor.get(kind, 0)]
            L.append("- `%s` (%s): measured order **%s**, theory **%s**; round-off floor ≈ %.1e%s."
                     % (kind, label, fmt_order(v, n), theory, max(r.floor.get(kind, 0) for r in runs),
                        "; measured/predicted error - 1 within %.1e" % max(dev) if dev else ""))
        if hasattr(case, "extra_md"):
            L.extend(case.extra_md())
        L.append("")
    for case, why in unavailable:
        L.append("## %s (`%s`)" % (case.title, case.name))
        L.append("")
        L.append("**%s.** %s" % (why[0].upper() + why[1:], case.description))
        L.append("")
    for case, why in failed:
        L.append("## %s (`%s`)" % (case.title, case.name))
        L.append("")
        L.append("**FAILED to run**: `%s`" % why)
        L.append("")
    L.append("## Reading")
    L.append("")
    L.append(reading(results, orders))
    L.append("")
    with open(path, "w") as fh:
        fh.write("\n".join(L))


def _version():
    v = getattr(yade, "version", None)
    try:
        v = v() if callable(v) else v
    except Exception:
        v = None
    return str(v) if v else "unknown"


# ---------------------------------------------------------------------------------- main

def main(argv=None):
    p = argparse.ArgumentParser(description="Accuracy suite: cases with exact answers over a sweep of time "
                                            "steps; writes DIR/accuracy.csv, accuracy.md, accuracy.png.")
    p.add_argument("dir", help="output directory (created if missing)")
    p.add_argument("--quick", action="store_true",
                   help="fewer time steps (%s), fewer impact phases, shorter runs"
                        % ", ".join("%g" % f for f in DT_FACTORS_QUICK))
    p.add_argument("--cases", default=None, help="comma-separated subset of case names")
    a = p.parse_args(argv)
    quick = a.quick or os.environ.get("YADE_ACCURACY_QUICK", "") not in ("", "0")
    factors = DT_FACTORS_QUICK if quick else DT_FACTORS
    os.makedirs(a.dir, exist_ok=True)
    want = set(a.cases.split(",")) if a.cases else None

    tStart = time.perf_counter()
    results, failed, unavailable = [], [], []
    for cls in CASES:
        if want is not None and cls.name not in want:
            continue
        case = cls(quick=quick)
        runs = []
        try:
            for f in factors:
                r = case.run(f)
                runs.append(r)
                print("%-22s dt=%.3e (%5.3g dt_crit) steps=%7d wall=%.4fs  %s" % (
                    case.name, r.dt, f, r.steps, r.wall_s,
                    "  ".join("%s=%.3e" % (k, r.errors[k]) for k, _, _ in case.kinds)), flush=True)
                for k, _, _ in case.kinds:
                    if not (math.isfinite(r.errors[k]) and r.errors[k] >= 0):
                        raise RuntimeError("%s: error %s is not finite and non-negative" % (k, r.errors[k]))
            if hasattr(case, "finish"):
                case.finish(factors)
                for line in case.extra_md():
                    print("%-22s %s" % (case.name, line[2:]))
        except Exception as e:
            traceback.print_exc()
            failed.append((case, "%s: %s" % (type(e).__name__, e)))
            continue
        results.append((case, runs))
    fresh()
    orders = {case.name: orders_of(case, runs) for case, runs in results}
    total_s = time.perf_counter() - tStart

    write_csv(os.path.join(a.dir, "accuracy.csv"), results)
    write_md(os.path.join(a.dir, "accuracy.md"), results, orders, failed, unavailable, total_s, factors, quick)
    write_png(os.path.join(a.dir, "accuracy.png"), results)

    print()
    for case, runs in results:
        for kind, _, theory in case.kinds:
            v, n = orders[case.name][kind]
            print("order %-22s %-28s measured %-32s theory %s" % (case.name, kind, fmt_order(v, n), theory))
    for case, why in failed:
        print("FAILED %s: %s" % (case.name, why))
    print("wrote %s/accuracy.{csv,md,png}; total %.1f s" % (a.dir, time.perf_counter() - tStart))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
