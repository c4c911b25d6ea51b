# Periodic scenes (3.6): a plain Yade script that runs unchanged in the reference Yade and in this
# engine. Run as a script it prints one JSON line (`PERIODIC {...}`) that tests/test_periodic.py
# compares: `yade -n -x -j1 periodic.py` (tests/reference/regenerate.sh keeps it in data/periodic.json).
import json

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *

import random  # (after the star imports, which bring a `random` of their own)


def flat(m):
    return [m[i, j] for i in range(3) for j in range(3)]


def state():
    return [list(b.state.pos) + list(b.state.vel) + list(b.state.angVel) for b in O.bodies]


def homogeneousField():
    """One free sphere in a deforming cell, for each Cell.homoDeform, with gravity and damping: the
    field's velocity (change of velGrad), its convective term, the damping of the fluctuation."""
    out = {}
    for mode in (0, 1, 2, 3):
        for damping in (0, 0.3):
            O.reset()
            O.periodic = True
            O.cell.hSize = Matrix3(2, 0, 0, 0, 3, 0, 0, 0, 4)
            O.cell.homoDeform = mode
            O.bodies.append(sphere((0.5, 1.0, 1.5), 0.1))
            O.bodies[0].state.vel = (0.1, 0.2, 0.3)
            O.engines = [ForceResetter(), NewtonIntegrator(damping=damping, gravity=(0, -3, -10))]
            O.dt = 0.01
            O.cell.velGrad = Matrix3(0.1, 0.2, 0, 0, -0.3, 0, 0.05, 0, 0.2)
            rows = []
            for i in range(6):
                if i == 3:
                    O.cell.velGrad = Matrix3(0, 0, 0.1, 0, 0, 0, 0, 0, 0)
                O.step()
                rows.append(state()[0] + flat(O.cell.hSize) + flat(O.cell.trsf))
            out['%d %g' % (mode, damping)] = rows
    return out


def packing():
    """A jittered lattice of 48 spheres in a skewed cell, sheared and compressed: contacts across
    the cell's faces, edges and corners (cellDist), then the stress and fabric utilities."""
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(1.2, 0.1, 0, 0, 1.0, 0, 0, 0.05, 0.9)
    rng = random.Random(5)  # (its own stream: utils.sphere draws random colors from the shared one)
    for i in range(4):
        for j in range(4):
            for k in range(3):
                c = Vector3(0.3 * i + 0.02 * rng.random(), 0.25 * j + 0.02 * rng.random(), 0.3 * k + 0.02 * rng.random())
                O.bodies.append(sphere(c, 0.14 + 0.01 * rng.random()))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0.4)]
    O.dt = .5 * PWaveTimeStep()
    O.cell.velGrad = Matrix3(-0.1, 0, 0.2, 0, -0.1, 0, 0, 0, -0.1)
    out = {'steps': []}
    for n in (1, 4, 15):
        O.run(n, True)
        out['steps'].append({'iter': O.iter, 'state': state(), 'hSize': flat(O.cell.hSize),
                             'contacts': sorted([i.id1, i.id2] + list(i.cellDist) for i in O.interactions if i.isReal)})
    out['getStress'] = flat(getStress())
    out['stressTensorOfPeriodicCell'] = flat(stressTensorOfPeriodicCell())
    out['normalShear'] = [flat(m) for m in normalShearStressTensors()]
    out['normalShearSplit'] = [flat(m) for m in normalShearStressTensors(compressionPositive=True, splitNormalTensor=True)]
    out['fabric'] = [flat(m) for m in fabricTensor()]
    out['fabricSplit'] = [flat(m) for m in fabricTensor(splitTensor=True)]
    out['bodyStress'] = [flat(m) for m in bodyStressTensors()]
    out['porosity'] = porosity()
    out['voxelPorosity'] = voxelPorosity(50, (0, 0, 0), (1, 1, 1))
    out['dynamicStress'] = flat(getTotalDynamicStress())
    return out


def cell():
    """The cell's own accessors, on a skewed cell after a deformation."""
    O.reset()
    O.periodic = True
    c = O.cell
    c.hSize = Matrix3(2, 0.5, 0, 0, 3, 0, 0.2, 0, 4)
    c.velGrad = Matrix3(0.1, 0.2, 0, 0, -0.3, 0, 0.05, 0, 0.2)
    O.dt = 0.1
    O.step()
    O.step()
    out = {'hSize': flat(c.hSize), 'trsf': flat(c.trsf), 'refHSize': flat(c.refHSize), 'hSize0': flat(c.hSize0),
           'size': list(c.size), 'volume': c.volume, 'shearTrsf': flat(c.shearTrsf), 'unshearTrsf': flat(c.unshearTrsf),
           'wrap': list(c.wrap((5.1, -1.2, 9.3))), 'wrapPt': list(c.wrapPt((5.1, -1.2, 9.3))),
           'shearPt': list(c.shearPt((1, 1, 1))), 'unshearPt': list(c.unshearPt((1, 1, 1)))}
    c.trsf = Matrix3(1.1, 0.2, 0, 0, 0.9, 0, 0, 0.1, 1)
    out.update({'getDefGrad': flat(c.getDefGrad()), 'getSmallStrain': flat(c.getSmallStrain()),
                'getLagrangianStrain': flat(c.getLagrangianStrain()), 'getEulerianAlmansiStrain': flat(c.getEulerianAlmansiStrain()),
                'getRCauchyGreenDef': flat(c.getRCauchyGreenDef()), 'getLCauchyGreenDef': flat(c.getLCauchyGreenDef()),
                'getRotation': flat(c.getRotation()), 'getRightStretch': flat(c.getRightStretch()),
                'getLeftStretch': flat(c.getLeftStretch()), 'getPolarDecOfDefGrad': [flat(m) for m in c.getPolarDecOfDefGrad()],
                'getSpin': list(c.getSpin())})
    return out


if RUN:
    print('PERIODIC ' + json.dumps({'homogeneousField': homogeneousField(), 'packing': packing(), 'cell': cell()}))
