"""HarmonicForceEngine, RadialForceEngine, InterpolatingDirectedForceEngine, InterpolatingHelixEngine
and DomainLimiter: the reference's numbers (printed by the reference Yade 2023.02a for the same
scripts) and their analytic forms."""
import math

import pytest

from yade import (O, ForceResetter, NewtonIntegrator, HarmonicForceEngine, RadialForceEngine, InterpolatingDirectedForceEngine,
                  InterpolatingHelixEngine, DomainLimiter, HelixEngine, ForceEngine)
from yade.utils import sphere, facet

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def run(engines, n=3, steps=5, dt=1e-3, fixed=False):
    O.bodies.append([sphere((1 + i, .5 * i, -.3 * i), .1, fixed=fixed) for i in range(n)])
    O.engines = [ForceResetter()] + engines + [NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = dt
    O.run(steps, True)
    return [(tuple(b.state.pos), tuple(b.state.vel), tuple(O.forces.f(b.id))) for b in O.bodies]


def test_harmonic_force_as_the_reference():
    r = run([HarmonicForceEngine(ids=[0, 2], A=(1, 2, 3), f=(10, 20, 5), fi=(0, .5, 1))])
    # the reference's force and state of body 0 after 5 steps (the force of the step at t = 0.004)
    assert r[0] == ((1.0000002388497364, 3.5019319692684117e-06, 7.4142989699871875e-06),
                    (0.00011921245501977163, 0.0012831928562675502, 0.0025006006556697715),
                    (0.2486898871648548, 1.6858048511615467, 2.7076607095625684))
    assert r[2][2] == r[0][2] and r[1][2] == (0, 0, 0)
    assert r[0][2][1] == pytest.approx(2 * math.sin(2 * math.pi * 20 * .004 + .5), rel=1e-15)


def test_radial_force_as_the_reference():
    r = run([RadialForceEngine(ids=[0, 1, 2], axisPt=(0, 0, 0), axisDir=(0, 0, 2), fNorm=3.)])
    assert r[0][2] == (3.0, 0.0, 0.0)
    assert r[1] == ((2.0000083377606175, 0.5000020844401544, -0.3), (0.002779253539229868, 0.000694813384807467, 0.0),
                    (2.910427500435995, 0.7276068751089988, 0.0))
    assert r[2][2] == (2.8460498941515415, 0.9486832980505138, 0.0)


def test_interpolating_directed_force_as_the_reference():
    r = run([InterpolatingDirectedForceEngine(ids=[1], times=[0, .002, .004], magnitudes=[1, 5, 2], direction=(0, 3, 4))], steps=6)
    assert r[1] == ((2.0, 0.5000065890146439, -0.29999121464714135), (0.0, 0.0018907607239317162, 0.002521014298575622), (0.0, 1.2, 1.6))


def force_at(t, **kw):
    """The engine's force in a step at simulated time t."""
    O.reset()
    O.bodies.append(sphere((0, 0, 0), .1))
    e = InterpolatingDirectedForceEngine(ids=[0], direction=(1, 0, 0), **kw)
    O.engines = [ForceResetter(), e]
    O.dt = t
    O.run(1, True)  # (a step at t = 0)
    O.dt = 1e-9
    O.run(1, True)
    return O.forces.f(0)[0]


def test_interpolation_and_wrap_as_the_reference():
    table = dict(times=[1, 2, 4], magnitudes=[10, 20, 40])
    # (the reference's figures: the first value before the table, the last after it; with wrap the
    # table repeats with the period 4 - 1 = 3)
    assert [force_at(t, wrap=False, **table) for t in (.5, 1.5, 3, 4.5)] == [10, 15, 30, 40]
    assert [force_at(t, wrap=True, **table) for t in (.5, 1.5, 3, 4.5, 5, 5.5, 7, 9.9, 4., 1., 2.)] == \
        pytest.approx([35, 15, 30, 15, 20, 25, 10, 39, 10, 10, 20], rel=1e-12)
    for bad, match in [(dict(times=[1, 2], magnitudes=[1]), "same length"), (dict(times=[2, 1], magnitudes=[1, 2]), "must not decrease"),
                       (dict(times=[], magnitudes=[]), "non-empty")]:
        with pytest.raises(ValueError, match=match):
            force_at(1, **bad)


def test_interpolating_helix_as_the_reference():
    e = InterpolatingHelixEngine(ids=[0, 1], times=[0, .002, .004], angularVelocities=[1, 3, 2], rotationAxis=(0, 0, 1), zeroPoint=(0, 0, 0),
                                 rotateAroundZero=True, slope=.5)
    r = run([e], steps=6, fixed=True)
    # the reference: angularVelocity 2 (after the table), angleTurned 0.0125 (the sum of the steps' 1, 2, 3, 2.5, 2, 2 rad/s
    # over 1 ms), linearVelocity = slope * angularVelocity
    assert (e.angularVelocity, e.linearVelocity) == (2.0, 1.0) and e.angleTurned == pytest.approx(.0125, rel=1e-14)
    ref = [((0.9999218760172474, 0.012499674481709785, 0.00625), (-0.0229994892116947, 1.999867418146223, 1.0)),
           ((1.9935939147936395, 0.5249602869720432, -0.29375), (-1.0459326874967534, 3.988235091686554, 1.0))]
    for (pos, vel, _), (rpos, rvel) in zip(r, ref):
        assert pos == pytest.approx(rpos, rel=1e-14, abs=1e-16) and vel == pytest.approx(rvel, rel=1e-11)
    assert isinstance(e, HelixEngine)


def test_domain_limiter_as_the_reference():
    O.bodies.append([sphere((5, 0, 0), .1, mask=1), sphere((6, 0, 0), .1, mask=3), sphere((7, 0, 0), .1, mask=2, fixed=True),
                     facet([(5, 0, 0), (6, 0, 0), (5, 1, 0)])])
    d = DomainLimiter(lo=(0, -1, -1), hi=(2.5, 1, 1), iterPeriod=1, mask=2)
    O.engines = [d]
    O.run(2, True)
    # the reference: the two spheres of mask 2 erased (the fixed one too), their mass and volume counted
    assert (d.nDeleted, d.mDeleted, d.vDeleted) == (2, 8.377580409572783, 0.008377580409572783)
    assert [O.bodies[i] is None for i in range(4)] == [False, True, True, False]
    d = DomainLimiter(lo=(0, -1, -1), hi=(2.5, 1, 1), iterPeriod=1)
    O.engines = [d]
    O.run(2, True)
    assert (d.nDeleted, d.mDeleted) == (1, 4.188790204786391) and [O.bodies[i] is None for i in range(4)] == [True, True, True, False]


def test_domain_limiter_erases_falling_spheres_with_their_contacts():
    from yade import InsertionSortCollider, InteractionLoop, Bo1_Sphere_Aabb, Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, \
        Law2_ScGeom_FrictPhys_CundallStrack
    O.bodies.append([sphere((0, 0, z), .1) for z in (0, .19, .38)])
    d = DomainLimiter(lo=(-1, -1, -.5), hi=(1, 1, 1), iterPeriod=10)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81)), d]
    O.dt = 1e-4
    O.run(5000, True)  # falling for 0.5 s: 1.2 m down, out of the box
    assert d.nDeleted == 3 and len([b for b in O.bodies if b]) == 0 and O.interactions.countReal() == 0


@pytest.mark.parametrize("axis,radius,vel", [  # the reference's velocities after one step (fi 0.3 -> 0.31)
    ((0, 0, 1), .2, (0.6005838479785364, -1.907685956420789, 0.0)),
    ((1, 0, 0), -1, (-4.440892098500626e-16, 9.538429782103952, 3.0029192398925986)),
    ((1, 1, 1), .2, (0.8768070251159319, -1.6314627792833936, 0.7546557541674622)),
    ((0, 0, -1), -1, (-3.0029192398925986, -9.538429782103952, 0.0)),
])
def test_bicycle_pedal_as_the_reference(axis, radius, vel):
    from yade import BicyclePedalEngine
    O.bodies.append(sphere((1, .5, .3), .1, fixed=True))
    b = BicyclePedalEngine(ids=[0], angularVelocity=10, rotationAxis=axis, radius=radius, fi=.3)
    O.engines = [b, NewtonIntegrator()]
    O.dt = 1e-3
    O.run(1, True)
    assert tuple(O.bodies[0].state.vel) == vel and b.fi == .31 and b.rotationAxis.norm() == pytest.approx(1, rel=1e-15)


def test_bicycle_pedal_closes_its_circle_without_turning():
    from yade import BicyclePedalEngine
    O.bodies.append(sphere((1, .5, .3), .1, fixed=True))
    O.engines = [BicyclePedalEngine(ids=[0], angularVelocity=2 * math.pi, rotationAxis=(0, 1, 1), radius=.2), NewtonIntegrator()]
    O.dt = 1e-3
    O.run(500, True)  # half a turn: across the circle, 2 radii from the start, in the plane normal to the axis
    d = O.bodies[0].state.pos - (1, .5, .3)
    assert d.norm() == pytest.approx(.4, rel=1e-5) and abs(d.dot((0, 1, 1))) < 1e-12
    O.run(500, True)
    assert (O.bodies[0].state.pos - (1, .5, .3)).norm() < 1e-12 and O.bodies[0].state.angVel.norm() == 0
