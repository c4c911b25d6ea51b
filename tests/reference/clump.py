# Clump scenes: a plain Yade script that runs unchanged in the reference Yade and in this engine. Run as a
# script it prints one JSON line (CLUMP {...}) that tests/test_clump.py compares with:
#     yade -n -x -j1 clump.py | grep '^CLUMP ' | sed 's/^CLUMP //' > data/clump.json
# (tests/reference/regenerate.sh). Each scene is a function, so the tests run the same scene here.
import json

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *


def vec(v):
    return [float(x) for x in v]


def mat(m):
    return [float(m[i, j]) for i in range(3) for j in range(3)]


def drop():
    """Two spheres clumped (summed mass and inertia), falling on a wall without damping: 2000 steps."""
    O.reset()
    O.bodies.append(wall(-1, axis=2))
    cid, ids = O.bodies.appendClumped([sphere((0, 0, 0), 1), sphere((1.5, .3, .2), .5)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -10), damping=0)]
    O.dt = 1e-4
    start = {'mass': O.bodies[cid].state.mass, 'pos': vec(O.bodies[cid].state.pos), 'inertia': vec(O.bodies[cid].state.inertia)}
    O.run(2000, True)
    return {'start': start, 'bodies': [[vec(b.state.pos), vec(b.state.vel), vec(b.state.angVel), vec(b.state.angMom)] for b in O.bodies],
            'force': vec(O.forces.f(cid)), 'torque': vec(O.forces.t(cid))}


def tumble():
    """Three spheres clumped, free, given an angular momentum: the orientation every 200 steps of 1 ms."""
    O.reset()
    cid, ids = O.bodies.appendClumped([sphere((0, 0, 0), 1), sphere((1.5, .3, .2), .5), sphere((0, 1.2, 0), .7)])
    O.bodies[cid].state.angMom = (3000, -1000, 5000)
    O.engines = [ForceResetter(), NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    out = []
    for k in range(5):
        O.run(200, True)
        out.append([mat(O.bodies[cid].state.ori.toRotationMatrix()), vec(O.bodies[cid].state.angVel), vec(O.bodies[ids[2]].state.pos)])
    return {'inertia': vec(O.bodies[cid].state.inertia), 'series': out}


def discretized():
    """Mass, centroid and principal inertia of two overlapping spheres integrated on grids of N cells."""
    out = {}
    for n in (5, 10, 20, 40):
        O.reset()
        cid, ids = O.bodies.appendClumped([sphere((0, 0, 0), 1), sphere((1, 0, 0), 1)], discretization=n)
        s = O.bodies[cid].state
        out[str(n)] = [s.mass, vec(s.pos), vec(s.inertia)]
        O.reset()
        cid, ids = O.bodies.appendClumped([sphere((0, 0, 0), 1), sphere((1, 0, 0), .5)], discretization=n)
        s = O.bodies[cid].state
        out['unequal' + str(n)] = [s.mass, vec(s.pos), vec(s.inertia)]
    return out


if RUN:
    print('CLUMP ' + json.dumps({'drop': drop(), 'tumble': tumble(), 'discretized': discretized()}))
