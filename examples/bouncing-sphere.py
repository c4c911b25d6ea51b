# Tutorial 2.6.1 of the Yade manual: a sphere falls on a fixed one, bounces and settles.
#
#   ./yade -n -x examples/bouncing-sphere.py
#
# Prints the height of the first rebound, next to what the non-viscous damping of the
# integrator predicts, and the overlap at rest, next to m·g/Kn.
import math

from yade import *
from yade.utils import *

# a fixed sphere at the origin and a free one 1 m above touching it
O.bodies.append([
    sphere(center=(0, 0, 0), radius=.5, fixed=True),
    sphere((0, 0, 2), .5)
])

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom()],           # contact geometry of two spheres
        [Ip2_FrictMat_FrictMat_FrictPhys()],    # stiffnesses from the materials
        [Law2_ScGeom_FrictPhys_CundallStrack()]  # linear elastic contact with friction
    ),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.1)
]
O.dt = .5 * PWaveTimeStep()

ball = O.bodies[1]
g, damping = 9.81, O.engines[-1].damping
touching = ball.shape.radius + O.bodies[0].shape.radius  # centre height at first touch
h0 = ball.state.pos[2] - touching

# run step by step, following the ball: count the contacts and find the top of the first rebound
contacts, wasInContact, firstTop = 0, False, -math.inf
for i in range(5000):
    O.step()
    inContact = O.interactions.countReal() > 0
    if inContact and not wasInContact:
        contacts += 1
    if contacts == 1 and not inContact:  # in flight between the first and the second contact
        firstTop = max(firstTop, ball.state.pos[2])
    wasInContact = inContact

mat = ball.material
r1, r2 = O.bodies[0].shape.radius, ball.shape.radius
kn = 2 * mat.young * r1 * mat.young * r2 / (mat.young * r1 + mat.young * r2)
m = ball.state.mass
restOverlap = m * g / kn

# (3.5.12) multiplies the net force by (1-λ) while the potential energy U falls and by (1+λ)
# while it rises: from the release to the deepest compression to the top of the rebound,
# U - Umin shrinks twice by (1-λ)/(1+λ); U - Umin = m·g·(h + δs/2) at h above touching.
ratio = ((1 - damping) / (1 + damping)) ** 2
predicted = ratio * (h0 + restOverlap / 2) - restOverlap / 2

print('bouncing sphere: %d steps, dt = %.4g s, t = %.3f s' % (O.iter, O.dt, O.time))
print('  dropped from %.4f m above touching; %d contacts (bounces) so far' % (h0, contacts))
print('  first rebound: top at %.5f m above touching; damping %.2f predicts %.5f m (deviation %.2g)'
      % (firstTop - touching, damping, predicted, (firstTop - touching) / predicted - 1))
if O.interactions.countReal():
    i = O.interactions[0, 1]
    print('  at rest: overlap %.6e m, m·g/Kn = %.6e m (deviation %.2g), Kn = %.6g N/m (formula %.6g)'
          % (i.geom.penetrationDepth, restOverlap, i.geom.penetrationDepth / restOverlap - 1, i.phys.kn, kn))
    print('           normal force %.6g N, weight m·g = %.6g N; ball speed %.2g m/s'
          % (i.phys.normalForce.norm(), m * g, ball.state.vel.norm()))
else:
    print('  the ball is still bouncing (not in contact at the end)')
