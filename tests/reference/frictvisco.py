# Scenes of the FrictVisco law (Law2_ScGeom_FrictViscoPhys_CundallStrackVisco): a plain Yade script that
# runs unchanged in the reference Yade and in this engine. Run as a script it prints, as JSON, what
# tests/test_frictvisco.py compares: `yade -n -x -j1 frictvisco.py > data/frictvisco.json`.
import json

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *


def engines(law=None, ip2s=None, gravity=(0, 0, 0), laws=()):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                        ip2s or [Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(), Ip2_FrictMat_FrictViscoMat_FrictViscoPhys()],
                        [law or Law2_ScGeom_FrictViscoPhys_CundallStrackVisco()] + list(laws)),
        NewtonIntegrator(damping=0, gravity=gravity)
    ]


def vec(v):
    return [float(x) for x in v]


def bodies(ids):
    """pos, vel, angVel of the bodies"""
    return [vec(O.bodies[i].state.pos) + vec(O.bodies[i].state.vel) + vec(O.bodies[i].state.angVel) for i in ids]


def phys(a, b):
    """the contact's constants and forces, or None when there is none"""
    if not (O.interactions.has(a, b) and O.interactions[a, b].isReal):
        return None
    p = O.interactions[a, b].phys
    return [p.kn, p.ks, p.cn, p.cn_crit, p.tangensOfFrictionAngle] + vec(p.normalForce) + vec(p.normalViscous) + vec(p.shearForce)


def forces(ids):
    return [vec(O.forces.f(i)) + vec(O.forces.t(i)) for i in ids]


def pair(m1, m2, r1=0.01, r2=0.02, v1=(0, 0, 1.), v2=(0, 0, -0.5), fixed2=False, ip2s=None, gap=-1e-5):
    """two spheres on the z axis touching (overlap -gap), body 0 of material m1, body 1 of m2"""
    O.reset()
    i1, i2 = O.materials.append(m1), O.materials.append(m2)
    O.bodies.append(sphere((0, 0, 0), r1, material=i1))
    O.bodies.append(sphere((0, 0, r1 + r2 + gap), r2, material=i2, fixed=fixed2))
    O.bodies[0].state.vel = v1
    if not fixed2:
        O.bodies[1].state.vel = v2
    engines(ip2s=ip2s)
    O.dt = 1e-6


def fv(betan, density=2000, young=1e7, poisson=0.3, frictionAngle=0.3):
    return FrictViscoMat(betan=betan, density=density, young=young, poisson=poisson, frictionAngle=frictionAngle)


def fm(density=3000, young=2e7, poisson=0.2, frictionAngle=0.5):
    return FrictMat(density=density, young=young, poisson=poisson, frictionAngle=frictionAngle)


def constants():
    """the contact's constants after one step, for the rules of the Ip2 functors"""
    out = {}
    cases = {
        'mean': (fv(0.2), fv(0.6, 3000, 2e7, 0.2, 0.5), {}),
        'first-zero': (fv(0.), fv(0.6, 3000, 2e7, 0.2, 0.5), {}),
        'second-zero': (fv(0.6), fv(0., 3000, 2e7, 0.2, 0.5), {}),
        'both-zero': (fv(0.), fv(0., 3000, 2e7, 0.2, 0.5), {}),
        'negative': (fv(-0.2), fv(0.6, 3000, 2e7, 0.2, 0.5), {}),
        'above-one': (fv(1.5), fv(1.5, 3000, 2e7, 0.2, 0.5), {}),
        'fixed': (fv(0.3), fv(0.3, 3000, 2e7, 0.2, 0.5), dict(fixed2=True)),
        'kn': (fv(0.3), fv(0.3, 3000, 2e7, 0.2, 0.5), dict(ip2s=[Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn=5e4)])),
        'kRatio': (fv(0.3), fv(0.3, 3000, 2e7, 0.2, 0.5), dict(ip2s=[Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(
            kRatio=MatchMaker(matches=((0, 1, 0.7),)), frictAngle=MatchMaker(algo='max'))])),
        'mixed': (fm(), fv(0.4), dict(ip2s=[Ip2_FrictMat_FrictViscoMat_FrictViscoPhys()])),
        'mixed-matchmakers': (fm(), fv(0.4), dict(ip2s=[Ip2_FrictMat_FrictViscoMat_FrictViscoPhys(
            kn=MatchMaker(algo='val', val=5e4), kRatio=0.5, frictAngle=0.1)])),
        'mixed-both-visco': (fv(0.2), fv(0.6, 3000, 2e7, 0.2, 0.5), dict(ip2s=[Ip2_FrictMat_FrictViscoMat_FrictViscoPhys()])),
    }
    for name, (m1, m2, kw) in sorted(cases.items()):
        pair(m1, m2, **kw)
        O.step()
        out[name] = phys(0, 1)
    # the effective mass: a body that is not dynamic counts as infinitely heavy
    # (Body.dynamic=False also zeroes the velocities in the reference, not here: blockedDOFs instead)
    for name, setup in [('reduced', lambda: None), ('first-not-dynamic', lambda: setattr(O.bodies[0].state, 'blockedDOFs', 'xyzXYZ')),
                        ('second-not-dynamic', lambda: setattr(O.bodies[1].state, 'blockedDOFs', 'xyzXYZ')),
                        ('translations-blocked', lambda: setattr(O.bodies[1].state, 'blockedDOFs', 'xyz')),
                        ('mass-set', lambda: setattr(O.bodies[1].state, 'mass', 5.))]:
        pair(fv(0.3), fv(0.3, 3000))
        setup()
        O.step()
        out['mass-' + name] = phys(0, 1)
    return out


def headOn():
    """two spheres of two materials meet head on and part (the normal force pulls before they part)"""
    pair(fv(0.3), fv(0.5, 3000, 2e7, 0.2, 0.5))
    out = {}
    for k in range(80):
        O.run(10, True)
        if O.iter in (10, 250, 500, 700):
            out['phys%d' % O.iter] = phys(0, 1)
    out['bodies'] = bodies([0, 1])
    out['real'] = O.interactions.countReal()
    return out


def oblique(neverErase=False):
    """a spinning sphere slides on a fixed one, the normal force pulls, the spheres part"""
    O.reset()
    m = O.materials.append(fv(0.8 if not neverErase else 0.3, frictionAngle=0.3 if not neverErase else 0.6))
    O.bodies.append(sphere((0, 0, 0), 0.01, material=m, fixed=True))
    O.bodies.append(sphere((0.0005, 0, 0.02 - 2e-5), 0.01, material=m))
    O.bodies[1].state.vel = (0.3, 0.05, -0.5)
    O.bodies[1].state.angVel = (0, 5, 0)
    engines(law=Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(neverErase=neverErase))
    O.dt = 2e-6
    out = {}
    for k in range(14):
        O.run(50, True)
        out['%d' % O.iter] = [phys(0, 1), bodies([1])[0], forces([1])[0]]
    return out


def facetAndWall(sphericalBodies):
    """spheres thrown with spin on a facet and on a wall, under gravity"""
    O.reset()
    m = O.materials.append(fv(0.4, frictionAngle=0.4))
    O.bodies.append(facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m))
    O.bodies.append(sphere((0, 0, 0.0101), 0.01, material=m))
    O.bodies.append(wall(0.5, axis=0, material=m))
    O.bodies.append(sphere((0.4898, 0.2, 0.3), 0.01, material=m))
    O.bodies[1].state.vel = (0.3, 0.1, -0.4)
    O.bodies[1].state.angVel = (0, 20, 0)
    O.bodies[3].state.vel = (0.2, 0.1, 0)
    O.bodies[3].state.angVel = (5, 0, 10)
    engines(law=Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(sphericalBodies=sphericalBodies), gravity=(0, 0, -9.81))
    O.dt = 2e-6
    out = {}
    for k in range(16):
        O.run(50, True)
        out['%d' % O.iter] = [phys(0, 1), phys(2, 3), bodies([1, 3]), forces([0, 1, 2, 3])]
    O.run(700, True)
    out['bodies'] = bodies([1, 3])
    return out


def pile():
    """spheres of both materials fall into a box of walls and settle (the FrictMat bodies first: the reference
    stops on a failed assertion for a FrictViscoMat body #1 with a FrictMat body #2)"""
    O.reset()
    a = O.materials.append(fv(0.5, frictionAngle=0.4))
    b = O.materials.append(fm(density=2000, young=1e7, poisson=0.3, frictionAngle=0.4))
    O.bodies.append([wall(0, axis=2, material=b), wall(-0.03, axis=0, material=b), wall(0.03, axis=0, material=b),
                     wall(-0.03, axis=1, material=b), wall(0.03, axis=1, material=b)])
    centers = [(-0.018 + 0.018 * i + 0.001 * h, -0.018 + 0.018 * j, 0.012 + 0.02 * h + 0.001 * i) for i in range(3) for j in range(3) for h in range(2)]
    for k, c in enumerate(centers):
        if k % 3 == 0:
            O.bodies.append(sphere(c, 0.008, material=b))
    for k, c in enumerate(centers):
        if k % 3:
            O.bodies.append(sphere(c, 0.008, material=a))
    engines(ip2s=[Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(), Ip2_FrictMat_FrictViscoMat_FrictViscoPhys(), Ip2_FrictMat_FrictMat_FrictPhys()],
            gravity=(0, 0, -9.81), laws=[Law2_ScGeom_FrictPhys_CundallStrack()])
    O.dt = 2e-5
    out = {}
    for k in range(5):
        O.run(1000, True)
        out['%d' % O.iter] = [bodies(range(5, len(O.bodies))), O.interactions.countReal()]
    return out


def energy():
    """the energy terms of the sliding scene of oblique(), for O.trackEnergy and the law's traceEnergy"""
    out = {}
    for track, trace in ((True, False), (False, True), (True, True)):
        O.reset()
        law = Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(traceEnergy=trace)
        m = O.materials.append(fv(0.8))
        O.bodies.append(sphere((0, 0, 0), 0.01, material=m, fixed=True))
        O.bodies.append(sphere((0.0005, 0, 0.02 - 2e-5), 0.01, material=m))
        O.bodies[1].state.vel = (0.3, 0.05, -0.5)
        O.bodies[1].state.angVel = (0, 5, 0)
        engines(law=law)
        O.dt = 2e-6
        O.trackEnergy = track
        rows = []
        for k in range(8):
            O.run(50, True)
            rows.append([sorted([n, float(v)] for n, v in O.energy.items()), law.plasticDissipation(), law.elasticEnergy()])
        out['track=%d trace=%d' % (track, trace)] = rows
    return out


def everything():
    return {'constants': constants(), 'headOn': headOn(), 'oblique': oblique(), 'neverErase': oblique(neverErase=True),
            'facetAndWall': facetAndWall(True), 'facetAndWallArms': facetAndWall(False), 'pile': pile(), 'energy': energy()}


if RUN:
    print('FRICTVISCO ' + json.dumps(everything(), sort_keys=True))
