# Oblique frictional impacts with spin: three free spheres of two materials collide, slide
# (Mohr-Coulomb) and roll; no gravity, no damping.
from yade import *
from yade.utils import *


def dumpState(out):
    # one line per body: iter id x y z vx vy vz wx wy wz
    for b in O.bodies:
        s = b.state
        out.append('%d %d %s' % (O.iter, b.id, ' '.join('%.17g' % x for x in (tuple(s.pos) + tuple(s.vel) + tuple(s.angVel)))))


O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=1000, label='a'))
O.materials.append(FrictMat(young=3e7, poisson=.2, frictionAngle=.3, density=2500, label='b'))
ids = O.bodies.append([sphere((0, 0, 0), .5, material='a'), sphere((.95, .25, .3), .3, material='b'), sphere((-.3, -.9, .2), .4, material='a')])
b1 = O.bodies[ids[1]]
b1.state.vel = (-2, -.3, -.5)
b1.state.angVel = (10, -5, 30)
b2 = O.bodies[ids[2]]
b2.state.vel = (.5, 2.5, 0)
b2.state.angVel = (0, 0, -20)
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(damping=0)
]
O.dt = .3 * PWaveTimeStep()
out = []
for k in range(40):
    O.run(100, True)
    dumpState(out)
print('\n'.join(out))
