# Regenerate its data: yade -n -x -j1 tests/reference/cohesive.py | grep '^COHESIVE ' | cut -c10- > tests/reference/data/cohesive.json
# Scenes of the cohesive-frictional law with moments (CohFrictMat, Ip2_CohFrictMat_CohFrictMat_CohFrictPhys,
# Ig2_Sphere_Sphere_ScGeom6D, Law2_ScGeom6D_CohFrictPhys_CohesionMoment): a plain Yade script that runs unchanged in
# the reference Yade and in this engine. Run as a script it prints, as JSON, what tests/test_cohesive.py compares.
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *


def vec(v):
    return [float(x) for x in v]


def rotation(b):
    """a body's rotation since the start, as a rotation vector"""
    axis, angle = O.bodies[b].state.ori.toAxisAngle()
    return vec(axis * angle)


def engines(ip2=None, law=None, factor=1.0, damping=0.0):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=factor)],
                        [ip2 or Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionOnNewContacts=True)],
                        [law or Law2_ScGeom6D_CohFrictPhys_CohesionMoment()]),
        NewtonIntegrator(damping=damping)
    ]


def mat(**kw):
    base = dict(young=1e7, poisson=0.3, frictionAngle=0.5, normalCohesion=1e5, shearCohesion=2e5, momentRotationLaw=True)
    base.update(kw)
    return O.materials.append(CohFrictMat(**base))


PHYS = ['kn', 'ks', 'kr', 'ktw', 'tangensOfFrictionAngle', 'normalAdhesion', 'shearAdhesion', 'maxRollPl', 'maxTwistPl', 'unp', 'unpMax']
FLAGS = ['cohesionBroken', 'fragile', 'momentRotationLaw', 'cohesionDisablesFriction', 'initCohesion']


def state(a=0, b=1):
    """the contact's values and the forces on the two bodies, or None when there is no contact"""
    if not (O.interactions.has(a, b) and O.interactions[a, b].isReal):
        return None
    i = O.interactions[a, b]
    p, g = i.phys, i.geom
    return dict(phys=[float(getattr(p, k)) for k in PHYS], flags=[bool(getattr(p, k)) for k in FLAGS],
                forces=vec(p.normalForce) + vec(p.shearForce) + vec(p.moment_twist) + vec(p.moment_bending),
                geom=[float(g.penetrationDepth), float(g.twist)] + vec(g.bending) + vec(g.normal),
                bodies=vec(O.forces.f(a)) + vec(O.forces.t(a)) + vec(O.forces.f(b)) + vec(O.forces.t(b)))


def constants():
    """the Ip2's values for pairs of materials"""
    out = {}
    cases = {
        'same': (dict(), dict(), {}),
        'mixed': (dict(young=1e7, poisson=0.3, frictionAngle=0.4, normalCohesion=1e5, shearCohesion=2e5, alphaKr=1.5, alphaKtw=3.0,
                       etaRoll=0.2, etaTwist=0.5, fragile=False),
                  dict(young=2e7, poisson=0.2, frictionAngle=0.6, normalCohesion=3e5, shearCohesion=1e5, alphaKr=2.5, alphaKtw=1.0,
                       etaRoll=0.4, etaTwist=0.1, momentRotationLaw=False), {}),
        'notFragile': (dict(fragile=False), dict(fragile=False), {}),
        'oneNotCohesive': (dict(isCohesive=False), dict(), {}),
        'noNewCohesion': (dict(), dict(), dict(setCohesionOnNewContacts=False)),
        'matchMakers': (dict(), dict(normalCohesion=3e5), dict(normalCohesion=MatchMaker(algo='val', val=5e5),
                                                                shearCohesion=MatchMaker(matches=((0, 1, 7e5),)),
                                                                frictAngle=MatchMaker(algo='max'))),
        'negativeCohesion': (dict(normalCohesion=-1, shearCohesion=-1), dict(normalCohesion=-1, shearCohesion=-1), {}),
    }
    for name, (k1, k2, ip2kw) in sorted(cases.items()):
        O.reset()
        m1, m2 = mat(**k1), mat(**k2)
        O.bodies.append([sphere((0, 0, 0), 1.0, material=m1), sphere((1.9, 0.1, 0), 0.95, material=m2)])
        kw = dict(setCohesionOnNewContacts=True)
        kw.update(ip2kw)
        engines(ip2=Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(**kw))
        O.dt = 1e-5
        O.step()
        out[name] = state()
    return out


def pair(steps, fragile=True, etaRoll=-1, etaTwist=-1, law=None, cohesive=True, cdf=False, unpMax=None, **matkw):
    """sphere 1 (radius 1, so heavy that it does not move: two bodies that are not dynamic never interact in this engine) and sphere 2
    (radius 1, moved as `steps` say), cohesive; the contact at every step.
    steps: (n, vel, angVel) rows, body 2 moved at these velocities for n steps."""
    O.reset()
    m = mat(fragile=fragile, etaRoll=etaRoll, etaTwist=etaTwist, **matkw)
    heavy = mat(fragile=fragile, etaRoll=etaRoll, etaTwist=etaTwist, density=1e20, **matkw)
    O.bodies.append([sphere((0, 0, 0), 1.0, material=heavy), sphere((1.99, 0, 0), 1.0, material=m)])
    O.bodies[1].state.blockedDOFs = 'xyzXYZ'
    engines(ip2=Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionOnNewContacts=cohesive), law=law)
    O.dt = 1e-3
    O.step()
    if O.interactions.has(0, 1):
        O.interactions[0, 1].phys.cohesionDisablesFriction = cdf
        if unpMax is not None:
            O.interactions[0, 1].phys.unpMax = unpMax
    rows = [state()]
    for n, vel, angVel in steps:
        O.bodies[1].state.vel = vel
        O.bodies[1].state.angVel = angVel
        for k in range(n):
            O.step()
            rows.append(state())
    return rows


def motions():
    Z = (0, 0, 0)
    return {
        'twist': pair([(3, Z, (0.5, 0, 0))]),
        'bend': pair([(3, Z, (0, 0, 0.5))]),
        'pullFragile': pair([(24, (1., 0, 0), Z)]),
        'pullPlasticUnpMax0': pair([(24, (1., 0, 0), Z)], fragile=False),
        'pullPlastic': pair([(26, (1., 0, 0), Z), (5, (-1., 0, 0), Z)], fragile=False, unpMax=-1),
        'pullPlasticUnpMax': pair([(30, (1., 0, 0), Z)], fragile=False, unpMax=0.005),
        'shearFragile': pair([(14, (0, 10., 0), Z)]),
        'shearPlastic': pair([(26, (0, 10., 0), Z), (3, Z, Z), (3, (0, -1, 0), Z)], fragile=False),
        'shearCohesionDisablesFriction': pair([(12, (0, 10., 0), Z)], cdf=True),
        'shearNegativeCohesion': pair([(6, (0, 10., 0), Z)], normalCohesion=-1, shearCohesion=-1),
        'rollCap': pair([(6, Z, (0, 0, 10.))], etaRoll=0.01),
        'twistCap': pair([(6, Z, (10., 0, 0))], etaTwist=0.01),
        'rollCapInTension': pair([(12, (1., 0, 0), Z), (4, Z, (0, 0, 1.))], etaRoll=0.01),
        'rollThenBreak': pair([(12, (0.5, 0, 0), (0, 0, 10.))], etaRoll=0.01),
        'incremental': pair([(8, Z, (3., 0, 7.))], etaRoll=0.01, law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True)),
        'incrementalTumbling': pair([(6, (0, 0.5, 0.2), (1., -2, 3.)), (6, (0.2, -0.5, 0), (-2., 1, 0.5))],
                                    law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True)),
        'totalTumbling': pair([(6, (0, 0.5, 0.2), (1., -2, 3.)), (6, (0.2, -0.5, 0), (-2., 1, 0.5))]),
        'alwaysMoments': pair([(3, Z, (0, 0, 1.))], cohesive=False,
                              law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(always_use_moment_law=True)),
        'noMomentsWithoutCohesion': pair([(3, Z, (0, 0, 1.))], cohesive=False),
        'frictionalPull': pair([(13, (1., 0, 0), Z)], cohesive=False),
        'shearCreep': pair([(4, (0, 1., 0.2), (0, 0.5, 0)), (5, Z, Z)], law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(shear_creep=True,
                                                                                                                  creep_viscosity=1e4)),
    }


def cohesionNow():
    """setCohesionNow and initCohesion on existing contacts (and the flag's life)"""
    out = []
    O.reset()
    m = mat()
    m2 = mat(normalCohesion=3e5, shearCohesion=4e5)
    heavy = mat(density=1e20)
    O.bodies.append([sphere((0, 0, 0), 1.0, material=heavy), sphere((1.99, 0, 0), 1.0, material=m2)])
    O.bodies[1].state.blockedDOFs = 'xyzXYZ'
    ip2 = Ip2_CohFrictMat_CohFrictMat_CohFrictPhys()
    engines(ip2=ip2)
    O.dt = 1e-3
    O.bodies[1].state.angVel = (1, 0, 2)
    O.bodies[1].state.vel = (0, 0.5, 0)
    O.run(3, True)
    out.append([state(), bool(ip2.setCohesionNow)])
    O.bodies[1].state.angVel = (0, 0.3, 0)
    O.bodies[1].state.vel = (0, 0, 0)
    ip2.setCohesionNow = True
    for k in range(3):
        O.step()
        out.append([state(), bool(ip2.setCohesionNow)] + vec(O.interactions[0, 1].geom.initialOrientation2))
    p = O.interactions[0, 1].phys
    p.cohesionBroken = True
    p.normalAdhesion = 0
    p.initCohesion = True
    for k in range(2):
        O.step()
        out.append([state(), bool(ip2.setCohesionNow)] + vec(O.interactions[0, 1].geom.initialOrientation2))
    return out


def cantilever(n=6, r=0.01, force=1e-2, steps=16000):
    """a chain of n cohesive spheres touching, sphere 0 fixed, a transverse force on the last one; the tip's deflection
    and the rotations after `steps` steps of a damped run (near the static state)"""
    O.reset()
    m = O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=2600, frictionAngle=0.5, normalCohesion=1e8, shearCohesion=1e8,
                                       momentRotationLaw=True))
    for i in range(n):
        O.bodies.append(sphere((2 * r * i, 0, 0), r, material=m, fixed=(i == 0)))
    engines(factor=1.01, damping=0.8)
    O.dt = 0.2 * PWaveTimeStep()
    O.step()
    O.forces.setPermF(n - 1, (0, force, 0))
    rows = []
    for k in range(4):
        O.run(steps // 4, True)
        rows.append([vec(O.bodies[i].state.pos) + rotation(i) for i in range(n)])
    p = O.interactions[n - 2, n - 1].phys
    return dict(rows=rows, dt=float(O.dt), kn=float(p.kn), ks=float(p.ks), kr=float(p.kr), ktw=float(p.ktw),
                contacts=len([i for i in O.interactions if i.isReal]))


def distant():
    """spheres 5 % apart bonded with interactionDetectionFactor 1.1: the chain holds under gravity-free pulling"""
    O.reset()
    m = mat(normalCohesion=1e8, shearCohesion=1e8)
    O.bodies.append([sphere((2.1 * i, 0, 0), 1.0, material=m, fixed=(i == 0)) for i in range(3)])
    engines(factor=1.1)
    O.dt = 1e-4
    O.step()
    O.bodies[2].state.vel = (0.5, 0.1, 0)
    rows = []
    for k in range(3):
        O.run(20, True)
        rows.append([state(0, 1), state(1, 2)] + vec(O.bodies[1].state.pos) + vec(O.bodies[1].state.vel))
    return rows


def facetContact():
    """a very heavy sphere on a fixed facet, cohesive, moved at imposed velocities (rolling, twisting, sliding, then pulled off)"""
    O.reset()
    m = mat(etaRoll=0.05)
    heavy = mat(etaRoll=0.05, density=1e20)
    O.bodies.append(facet([(-5, -5, 0), (5, -5, 0), (0, 5, 0)], material=m))
    O.bodies.append(sphere((0.3, 0.2, 0.99), 1.0, material=heavy))
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop([Ig2_Facet_Sphere_ScGeom6D()], [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionOnNewContacts=True)],
                        [Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True)]),
        NewtonIntegrator()
    ]
    O.dt = 1e-3
    O.step()
    rows = [state()]
    for n, vel, angVel in [(4, (0, 0.5, 0), (0.3, 0, 0.2)), (4, (0.2, 0, 0), (0, -2, 1)), (30, (0, 0, 1), (0, 0, 0))]:
        for k in range(n):
            O.bodies[1].state.vel = vel
            O.bodies[1].state.angVel = angVel
            O.step()
            rows.append([state(), vec(O.bodies[1].state.pos)])
    return rows


def periodic():
    """a bonded pair in a periodic cell, inside the cell and across its face (body 2 seen through the boundary)"""
    out = []
    for x0 in (4.0, 8.5):
        O.reset()
        O.periodic = True
        O.cell.setBox(10, 10, 10)
        m = mat(etaRoll=0.05)
        O.bodies.append([sphere((x0, 5, 5), 1.0, material=m), sphere((x0 + 1.99, 5, 5), 1.0, material=m)])
        engines(law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True))
        O.dt = 1e-4
        O.step()
        O.bodies[1].state.vel = (0.2, 0.5, -0.3)
        O.bodies[1].state.angVel = (1, 2, 3)
        O.run(50, True)
        out.append([state(), vec(O.bodies[1].state.vel), vec(O.bodies[1].state.angVel)])
    return out


def energy():
    """O.energy's dissipation terms (O.trackEnergy), plasticDissipation() (traceEnergy or O.trackEnergy) and the elastic energies of
    a frictional contact with moments that slides, rolls and twists beyond its strengths"""
    out = {}
    for trace in (False, True):
        for track in (False, True):
            O.reset()
            m = mat(etaRoll=0.01, etaTwist=0.02)
            heavy = mat(etaRoll=0.01, etaTwist=0.02, density=1e20)
            O.bodies.append([sphere((0, 0, 0), 1.0, material=heavy), sphere((1.99, 0, 0), 1.0, material=m)])
            O.bodies[1].state.blockedDOFs = 'xyzXYZ'
            law = Law2_ScGeom6D_CohFrictPhys_CohesionMoment(traceEnergy=trace, useIncrementalForm=True, always_use_moment_law=True)
            engines(law=law, ip2=Ip2_CohFrictMat_CohFrictMat_CohFrictPhys())
            O.trackEnergy = track
            O.dt = 1e-3
            O.step()
            O.bodies[1].state.vel = (0, 1, 0)
            O.bodies[1].state.angVel = (1, 0, 10)
            rows = []
            for k in range(12):
                O.step()
                terms = dict((n, float(v)) for n, v in O.energy.items() if n in ('shearDissip', 'bendingDissip', 'twistDissip'))
                rows.append([[terms.get(n, 0.0) for n in ('shearDissip', 'bendingDissip', 'twistDissip')], law.plasticDissipation(),
                             law.elasticEnergy(), law.normElastEnergy(), law.shearElastEnergy(), law.bendingElastEnergy(),
                             law.twistElastEnergy()])
            out['trace=%d track=%d' % (trace, track)] = rows
    return out


def everything():
    return {'constants': constants(), 'motions': motions(), 'cohesionNow': cohesionNow(), 'cantilever': cantilever(), 'distant': distant(),
            'energy': energy(), 'facet': facetContact(), 'periodic': periodic()}


if RUN:
    print('COHESIVE ' + json.dumps(everything(), sort_keys=True))
