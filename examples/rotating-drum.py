# A drum of facets turned by a RotationEngine around its axis, half filled with spheres.
#
#   ./yade -n -x examples/rotating-drum.py
#
# The drum's facets are non-dynamic bodies: the RotationEngine sets their velocities every step
# (turning them around zeroPoint with rotateAroundZero=True) and NewtonIntegrator moves them.
# Friction drags the bed up the rising side; the script prints the angle turned by the drum
# (ω·t) and the angle by which the bed's centre of mass has moved from below the axis.
import math

from yade import *
from yade.utils import *
from yade import geom

R, L, omega = 0.1, 0.04, 3.0  # drum radius and length [m], angular velocity [rad/s]
# the drum's axis along y: facetCylinder builds around local z, turned by 90° about x
drum = O.bodies.append(geom.facetCylinder((0, 0, 0), R, L, orientation=Quaternion((1, 0, 0), math.pi / 2),
                                          segmentsNumber=24, wallMask=7, fixed=True))
sp = pack.SpherePack()
sp.makeCloud((-0.6 * R, -0.4 * L, -0.7 * R), (0.6 * R, 0.4 * L, 0.2 * R), rMean=0.006, rRelFuzz=0.2, seed=1)
grains = O.bodies.append([sphere(c, r) for c, r in sp])

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                    [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    RotationEngine(ids=drum, rotationAxis=(0, 1, 0), rotateAroundZero=True, zeroPoint=(0, 0, 0),
                   angularVelocity=omega, label='turner', dead=True),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),
]
O.dt = 0.5 * PWaveTimeStep()

O.run(int(0.3 / O.dt), True)  # settle the bed
turner.dead = False
t0 = O.time
O.run(int(0.5 / O.dt), True)  # turn the drum


def bedAngle():
    """Angle about y of the bed's centre of mass, measured from straight below the axis."""
    m = sum(O.bodies[i].state.mass for i in grains)
    c = sum((O.bodies[i].state.pos * O.bodies[i].state.mass for i in grains), Vector3(0, 0, 0)) / m
    return math.degrees(math.atan2(-c[0], -c[2]))


facetAngle = O.bodies[drum[0]].state.ori.toAxisAngle()[1]
print('drum turned %.4f rad (omega*t = %.4f rad)' % (facetAngle, omega * (O.time - t0)))
print('bed centre of mass displaced by %.1f degrees in the sense of rotation; %d spheres, %d contacts'
      % (bedAngle(), len(grains), O.interactions.countReal()))
