# A cantilever of bonded spheres (CohFrictMat, Law2_ScGeom6D_CohFrictPhys_CohesionMoment): a chain of n spheres, the first one
# clamped, a transverse force on the last one; a damped run settles to the deflection of the beam made of the contacts' springs.
#
#   ./yade -n -x examples/cohesive-cantilever.py
#
# Prints the tip's deflection and rotation next to the discrete beam theory: at contact j the bending moment is
# F·r·(2(n-1-j) - 1), the rotation jumps by M/kr, and the shear spring adds F/ks to the relative displacement of the contact
# points (doc/cohesive.md).
from yade import *
from yade.utils import *

n, r, force = 6, 0.01, 1e-2
m = O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=2600, normalCohesion=1e8, shearCohesion=1e8, momentRotationLaw=True))
O.bodies.append([sphere((2 * r * i, 0, 0), r, material=m, fixed=(i == 0)) for i in range(n)])
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=1.01)]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=1.01)],  # (bonds between spheres that just touch)
                    [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionOnNewContacts=True)],
                    [Law2_ScGeom6D_CohFrictPhys_CohesionMoment()]),
    NewtonIntegrator(damping=0.8)
]
O.dt = 0.2 * PWaveTimeStep()
O.step()
O.forces.setPermF(n - 1, (0, force, 0))
O.run(16000, True)

p = O.interactions[n - 2, n - 1].phys
w, th = 0.0, 0.0
for j in range(n - 1):
    th1 = th + force * r * (2 * (n - 1 - j) - 1) / p.kr
    w, th = w + r * (th + th1) + force / p.ks, th1
axis, angle = O.bodies[n - 1].state.ori.toAxisAngle()
print('tip deflection %.8g m (beam of the contact springs: %.8g m)' % (O.bodies[n - 1].state.pos[1], w))
print('tip rotation   %.8g rad (beam of the contact springs: %.8g rad)' % ((axis * angle)[2], th))
