# Uniaxial tension, then compression, of a small concrete specimen with the concrete particle model (doc/concrete.md), as the
# reference's examples/concrete/uniax.py does on a larger one. Runs unchanged in the reference Yade: yade -n -x concrete-uniax.py
import math
from yade import *
from yade.utils import *

R, NX, NY, NZ = 1e-3, 5, 5, 12  # sphere radius, spheres along x, y, z


def specimen():
    O.materials.append(CpmMat(young=24e9, poisson=.2, sigmaT=3.5e6, frictionAngle=math.atan(.8), epsCrackOnset=1e-4, relDuctility=30))
    neg, pos = [], []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                b = O.bodies.append(sphere((2 * R * i, 2 * R * j, 2 * R * k + R * .02 * ((i + 2 * j) % 3)), R))  # (bodies get a CpmState)
                (neg if k == 0 else pos if k == NZ - 1 else []).append(b)
    return neg, pos


def run(strainRate, steps):
    O.reset()
    neg, pos = specimen()
    strainer = UniaxialStrainer(strainRate=strainRate, axis=2, posIds=pos, negIds=neg, crossSectionArea=(2 * R) ** 2 * NX * NY, setSpeeds=True)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=1.5, label='bo1s')]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=1.5, label='ig2ss')], [Ip2_CpmMat_CpmMat_CpmPhys()],
                                 [Law2_ScGeom_CpmPhys_Cpm()]),
                 strainer, CpmStateUpdater(iterPeriod=100), NewtonIntegrator(damping=.4)]
    O.dt = .5 * R / math.sqrt(24e9 / 4800)
    O.step()
    bo1s.aabbEnlargeFactor = ig2ss.interactionDetectionFactor = 1.  # cohesive contacts only between the first step's neighbours
    curve = []
    for n in range(steps // 10):
        O.run(10, True)
        curve.append((strainer.strain, strainer.avgStress))
    e, s = max(curve, key=lambda p: abs(p[1]))
    damaged = sum(1 for b in O.bodies if b.state.normDmg > .5)
    print('%s: peak stress %.3g MPa at strain %.3g; %d bodies with normDmg > 0.5' % ('tension' if strainRate > 0 else 'compression', s / 1e6, e, damaged))


run(1., 2000)
run(-5., 4000)
