# Tutorial 2.6.1: a sphere falls on a fixed one, bounces and settles (damping 0.1).
from yade import *
from yade.utils import *


def dumpState(out):
    # one line per body: iter id x y z vx vy vz wx wy wz
    for b in O.bodies:
        s = b.state
        out.append('%d %d %s' % (O.iter, b.id, ' '.join('%.17g' % x for x in (tuple(s.pos) + tuple(s.vel) + tuple(s.angVel)))))


O.bodies.append([sphere(center=(0, 0, 0), radius=.5, fixed=True), sphere((0, 0, 2), .5)])
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.1)
]
O.dt = .5 * PWaveTimeStep()
out = []
for k in range(60):
    O.run(100, True)
    dumpState(out)
print('\n'.join(out))
