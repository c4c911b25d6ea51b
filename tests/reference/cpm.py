# Scenes of the concrete particle model (CpmMat, CpmPhys, CpmState, Ip2_CpmMat_CpmMat_CpmPhys, Ip2_FrictMat_CpmMat_FrictPhys,
# Law2_ScGeom_CpmPhys_Cpm, CpmStateUpdater, UniaxialStrainer): a plain Yade script that runs unchanged in the reference Yade and
# in this engine. Run as a script it prints one JSON line that tests/test_concrete.py compares; its data file is made with
#   yade -n -x -j1 cpm.py 2>/dev/null | grep '^CPM ' | sed 's/^CPM //' > data/cpm.json
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *

R = 1e-3  # sphere radius of the specimen [m]
NX, NY, NZ = 5, 5, 12  # the specimen's spheres along x, y, z (300)


def vec(v):
    return [float(x) for x in v]


def concrete(**kw):
    args = dict(young=24e9, poisson=.2, sigmaT=3.5e6, frictionAngle=math.atan(.8), epsCrackOnset=1e-4, relDuctility=30, density=4800)
    args.update(kw)
    return CpmMat(**args)


def engines(extra=(), intRadius=1.5, damping=.4, ip2=None, law=None):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=intRadius, label='bo1s'), Bo1_Facet_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=intRadius, label='ig2ss'), Ig2_Facet_Sphere_ScGeom()],
                        [ip2 or Ip2_CpmMat_CpmMat_CpmPhys(), Ip2_FrictMat_CpmMat_FrictPhys(), Ip2_FrictMat_FrictMat_FrictPhys()],
                        [law or Law2_ScGeom_CpmPhys_Cpm(), Law2_ScGeom_FrictPhys_CundallStrack()]),
    ] + list(extra) + [NewtonIntegrator(damping=damping)]


def jitter(i, j, k, axis):
    """a deterministic offset of the lattice site, in [-0.04, 0.04]·R (integer arithmetic: the same in both engines)"""
    return ((i * 7 + j * 13 + k * 29 + axis * 17) % 11 - 5) / 5. * 0.04 * R


def specimen():
    """a prism of NX·NY·NZ spheres of radius R on a simple cubic lattice of spacing 2R, each site moved a little; the ids of
    the bottom (negIds) and top (posIds) layers"""
    O.materials.append(concrete())
    neg, pos = [], []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                c = (2 * R * i + jitter(i, j, k, 0), 2 * R * j + jitter(i, j, k, 1), 2 * R * k + jitter(i, j, k, 2))
                b = O.bodies.append(sphere(c, R))
                if k == 0: neg.append(b)
                if k == NZ - 1: pos.append(b)
    return neg, pos


def uniaxial(strainRate, steps, every=10, **strainerArgs):
    """the uniaxial test of examples/concrete/uniax.py on the specimen: (strain, avgStress) every `every` steps, and what the
    bodies and contacts hold at the end"""
    O.reset()
    neg, pos = specimen()
    strainer = UniaxialStrainer(strainRate=strainRate, axis=2, asymmetry=0, posIds=pos, negIds=neg, crossSectionArea=(2 * R) ** 2 * NX * NY,
                                blockDisplacements=False, blockRotations=False, setSpeeds=True, stressUpdateInterval=every, label='strainer',
                                **strainerArgs)
    updater = CpmStateUpdater(iterPeriod=100)
    engines([strainer, updater])
    O.dt = 0.5 * R / math.sqrt(24e9 / 4800)  # (half the P-wave time step: this engine stops a run above a body's critical one)
    O.step()
    bo1s.aabbEnlargeFactor = ig2ss.interactionDetectionFactor = 1.  # the contacts of the first step stay, no new cohesive ones
    contacts0 = sum(1 for i in O.interactions if i.isReal)
    curve = []
    for n in range(steps // every):
        O.run(every, True)
        curve.append([strainer.strain, strainer.avgStress])
    updater.iterPeriod = 1
    O.step()
    omegas = sorted(i.phys.omega for i in O.interactions if i.isReal)
    states = [[b.state.normDmg, b.state.numBrokenCohesive] + vec(b.state.stress.diagonal()) for b in O.bodies]
    return dict(curve=curve, contacts0=contacts0, contacts=len(omegas), meanOmega=sum(omegas) / len(omegas), maxOmega=omegas[-1],
                originalLength=strainer.originalLength, avgRelResidual=updater.avgRelResidual, states=states, dt=O.dt)


def phys(a, b):
    if not (O.interactions.has(a, b) and O.interactions[a, b].isReal):
        return None
    p = O.interactions[a, b].phys
    if not isinstance(p, CpmPhys):
        return [p.kn, p.ks, p.tangensOfFrictionAngle] + vec(p.normalForce) + vec(p.shearForce)
    return [p.E, p.G, p.crossSection, p.refLength, p.refPD, p.kn, p.ks, p.epsFracture, p.undamagedCohesion, p.tanFrictionAngle,
            p.epsCrackOnset, p.relDuctility, p.isoPrestress, float(p.isCohesive), float(p.neverDamage), p.epsN, p.sigmaN, p.omega,
            p.kappaD, p.Fn, p.relResidualStrength] + vec(p.epsT) + vec(p.sigmaT) + vec(p.normalForce) + vec(p.shearForce)


def pair(mat1, mat2, x2, r1=1e-3, r2=1.2e-3, velocity=(0, 0, 0), steps=30, ip2=None, law=None, spin=(0, 0, 0)):
    """two spheres made at a distance, the second then moved at a constant velocity and spin: the contact every 3 steps"""
    O.reset()
    m1 = O.materials.append(mat1)
    m2 = O.materials.append(mat2) if mat2 is not None else m1
    O.bodies.append([sphere((0, 0, 0), r1, material=m1, fixed=True), sphere(x2, r2, material=m2)])
    O.bodies[1].state.blockedDOFs = 'xyz'  # (dynamic: the reference's collider pairs two bodies that are not, this engine's does not)
    engines(intRadius=1.5, damping=0, ip2=ip2, law=law)
    O.dt = 1e-7
    O.step()
    O.bodies[1].state.vel, O.bodies[1].state.angVel = velocity, spin
    out = []
    for n in range(steps // 3):
        O.run(3, True)
        out.append([O.iter, phys(0, 1), vec(O.forces.f(0)), vec(O.forces.t(0)), vec(O.forces.t(1))])
    return out


def pairs():
    s = {}
    # tension through the crack onset into softening (exponential law), with some shear and spin
    s['tension'] = pair(concrete(), None, (1e-4, 2e-4, 2.1e-3), velocity=(0.02, -0.01, 0.3), spin=(3, -2, 1), steps=300)
    s['linear'] = pair(concrete(damLaw=0, relDuctility=5), None, (0, 0, 2.1e-3), velocity=(0, 0, 0.3), steps=150)
    # two materials: the means; prestress
    s['mixed'] = pair(concrete(), concrete(young=30e9, poisson=.3, sigmaT=2e6, frictionAngle=.5, epsCrackOnset=2e-4, relDuctility=10,
                                           isoPrestress=1e5), (0, 1.1e-4, 2.0e-3), velocity=(0.05, 0, 0.1), steps=60)
    # compression and shear past the yield surface
    s['shear'] = pair(concrete(), None, (0, 0, 2.2e-3), velocity=(0.4, 0.1, -0.2), steps=150)
    # not cohesive: ends when the bodies part
    s['noncohesive'] = pair(concrete(), None, (0, 0, 2.15e-3), velocity=(0, 0.01, 0.6), ip2=Ip2_CpmMat_CpmMat_CpmPhys(cohesiveThresholdIter=0),
                            steps=60)
    # broken at omegaThreshold, counted on both bodies
    s['broken'] = pair(concrete(relDuctility=3), None, (0, 0, 2.2e-3), velocity=(0, 0, 1.), law=Law2_ScGeom_CpmPhys_Cpm(omegaThreshold=.7),
                       steps=90)
    s['brokenStates'] = [[b.state.numBrokenCohesive, b.state.normDmg] for b in O.bodies]
    s['neverDamage'] = pair(concrete(neverDamage=True), None, (0, 0, 2.2e-3), velocity=(0, 0, 1.), steps=60)
    # FrictMat against CpmMat
    s['frict'] = pair(FrictMat(young=20e9, poisson=.3, frictionAngle=.4), concrete(), (0, 0, 2.1e-3), velocity=(0.1, 0, -0.3), steps=30)
    return s


def facet_contact():
    """a sphere on a facet of CpmMat, pulled away"""
    O.reset()
    m = O.materials.append(concrete())
    O.bodies.append([facet([(-3e-3, -3e-3, 0), (3e-3, -3e-3, 0), (0, 3e-3, 0)], material=m), sphere((0, 0, 0.95e-3), 1e-3, material=m)])
    O.bodies[1].state.blockedDOFs = 'xyz'
    engines(intRadius=1., damping=0)
    O.dt = 1e-7
    O.step()
    O.bodies[1].state.vel = (0.01, 0, 0.3)
    out = []
    for n in range(10):
        O.run(3, True)
        out.append([O.iter, phys(0, 1), vec(O.forces.f(1)), vec(O.forces.t(1))])
    return out


def updater_states():
    """CpmStateUpdater on a small damaged cluster: normDmg, stress, damageTensor of each body"""
    O.reset()
    O.materials.append(concrete(relDuctility=3))
    O.bodies.append([sphere((0, 0, 0), 1e-3), sphere((1e-4, 2e-4, 1.9e-3), 1e-3), sphere((0, 0, 3.8e-3), 1.1e-3),
                     sphere((1.2e-3, 1.0e-3, 2.1e-3), 0.9e-3)])
    strainer = UniaxialStrainer(strainRate=20., axis=2, posIds=[2], negIds=[0], crossSectionArea=4e-6)
    up = CpmStateUpdater(iterPeriod=1)
    engines([strainer, up], intRadius=1.)
    O.dt = 1e-7
    O.run(40, True)
    return dict(avgRelResidual=up.avgRelResidual, strain=strainer.strain, avgStress=strainer.avgStress,
                states=[[b.state.normDmg] + vec(b.state.stress.row(0)) + vec(b.state.stress.row(1)) + vec(b.state.stress.row(2))
                        + vec(b.state.damageTensor.row(0)) + vec(b.state.damageTensor.row(1)) + vec(b.state.damageTensor.row(2))
                        for b in O.bodies])


def updater_broken():
    """CpmStateUpdater while contacts break (omegaThreshold .7) and come back not cohesive: normDmg, numBrokenCohesive,
    avgRelResidual"""
    O.reset()
    O.materials.append(concrete(relDuctility=3))
    O.bodies.append([sphere((0, 0, 0), 1e-3, fixed=True), sphere((0, 0, 2.2e-3), 1.2e-3), sphere((0, 2.0e-3, 0), 1e-3)])
    O.bodies[1].state.blockedDOFs = O.bodies[2].state.blockedDOFs = 'xyz'
    up = CpmStateUpdater(iterPeriod=1)
    engines([up], intRadius=1.5, damping=0, law=Law2_ScGeom_CpmPhys_Cpm(omegaThreshold=.7))
    O.dt = 1e-7
    O.step()
    O.bodies[1].state.vel, O.bodies[2].state.vel = (0, 0, 1.), (0, .02, 0)
    out = []
    for k in range(8):
        O.run(5, True)
        out.append([O.iter, up.avgRelResidual] + [x for b in O.bodies for x in (b.state.numBrokenCohesive, b.state.normDmg)])
    return out


def strainer_runs():
    """UniaxialStrainer's kinematics on three free spheres (no contacts): variants of its attributes"""
    out = {}
    for name, kw in [('symmetric', dict(strainRate=.1)), ('absSpeed', dict(absSpeed=.2)), ('asym1', dict(strainRate=-.1, asymmetry=1, blockDisplacements=True)),
                     ('asym-1', dict(strainRate=.1, asymmetry=-1, blockRotations=True)), ('setSpeeds', dict(strainRate=.1, setSpeeds=True)),
                     ('setSpeedsAsym', dict(strainRate=-.2, setSpeeds=True, asymmetry=1))]:
        O.reset()
        O.materials.append(concrete())
        O.bodies.append([sphere((0, 0, 0), 1), sphere((0, 0, 3.8), 1), sphere((5, 0, 3.8), 1), sphere((9, 1, 1.3), 1), sphere((-9, 1, 5.), 1)])
        st = UniaxialStrainer(axis=2, posIds=[1, 2], negIds=[0], crossSectionArea=2., **kw)
        O.engines = [ForceResetter(), st, NewtonIntegrator(damping=0)]
        O.dt = 1e-3
        rows = []
        for n in range(4):
            O.step()
            rows.append([st.strain, st.currentStrainRate, st.originalLength, st.absSpeed, st.strainRate] +
                        [x for b in O.bodies for x in vec(b.state.pos) + vec(b.state.vel)] + [b.state.blockedDOFs for b in O.bodies])
        out[name] = rows
    return out


def all_scenes():
    return dict(tension=uniaxial(1., 2000), compression=uniaxial(-5., 4000, every=20), pairs=pairs(), facet=facet_contact(),
                updater=updater_states(), updaterBroken=updater_broken(), strainer=strainer_runs())


if RUN:
    print('CPM ' + json.dumps(all_scenes()))
