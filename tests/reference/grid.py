# Scenes of the grid elements (yade.gridpfacet): a plain Yade script that runs unchanged in the reference Yade and in this
# engine. Run as a script it prints, as JSON, what tests/test_grid.py compares:
#   cd tests/reference && yade -n -x -j1 grid.py | grep '^GRID ' | cut -c6- > data/grid.json
import json

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade import gridpfacet


def engines(damping=0.1, gravity=(0, 0, -9.81)):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_GridConnection_Aabb()]),
        InteractionLoop([Ig2_GridNode_GridNode_GridNodeGeom6D()],
                        [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=True, setCohesionOnNewContacts=False)],
                        [Law2_ScGeom6D_CohFrictPhys_CohesionMoment()]),
        NewtonIntegrator(damping=damping, gravity=gravity)
    ]


def vec(v):
    return [float(x) for x in v]


def chain(n=6, steps=3000, every=500, damping=0.1):
    """a horizontal chain of n nodes 0.1 m apart (cylinderConnection), node 0 fixed, falling under gravity: the nodes'
    positions and velocities and the forces and moments of the bonds every `every` steps"""
    O.reset()
    engines(damping)
    O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=1000, frictionAngle=0.5, normalCohesion=1e12, shearCohesion=1e12,
                                   momentRotationLaw=True, label='int'))
    O.materials.append(FrictMat(young=1e7, poisson=0.3, density=1000, frictionAngle=0.5, label='ext'))
    nodes, cyls = [], []
    gridpfacet.cylinderConnection([(0.1 * i, 0, 0) for i in range(n)], 0.02, nodes, cyls, intMaterial='int', extMaterial='ext')
    O.bodies[nodes[0]].state.blockedDOFs = 'xyzXYZ'
    O.dt = 1e-4
    out = {'mass': [O.bodies[i].state.mass for i in nodes], 'inertia': [vec(O.bodies[i].state.inertia) for i in nodes],
           'connMass': [O.bodies[i].state.mass for i in cyls], 'rows': []}
    for k in range(steps // every):
        O.run(every, True)
        row = {'nodes': [vec(O.bodies[i].state.pos) + vec(O.bodies[i].state.vel) + vec(O.bodies[i].state.angVel) for i in nodes],
               'bonds': [vec(i.phys.normalForce) + vec(i.phys.shearForce) + vec(i.phys.moment_bending) + vec(i.phys.moment_twist) +
                         [i.geom.penetrationDepth] for i in sorted(O.interactions, key=lambda i: (i.id1, i.id2))]}
        out['rows'].append(row)
    out['bounds'] = [vec(O.bodies[i].bound.min) + vec(O.bodies[i].bound.max) for i in cyls]
    out['length'] = [O.bodies[i].shape.getLength() if hasattr(O.bodies[i].shape, 'getLength') else None for i in cyls]
    return out


def everything():
    return {'chain': chain(), 'undamped': chain(n=4, steps=2000, damping=0.0)}


if RUN:
    print('GRID ' + json.dumps(everything(), sort_keys=True))
