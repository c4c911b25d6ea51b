# A cloud of a few hundred spheres with random velocities in free space (no gravity, no
# damping), colliding with the Cundall-Strack law (linear elastic contact with friction).
#
#   ./yade -n -x examples/colliding-spheres.py
#
# Prints the number of contacts over time and checks that the total linear momentum Σ m·v
# and the angular momentum about the origin Σ (x × m·v + I·ω) are conserved: every contact
# gives the two bodies opposite forces and torques whose moments cancel, so both stay
# constant up to rounding. The kinetic energy is not conserved: friction dissipates it.
import math
import random

from yade import *
from yade.utils import *

N = 400                      # number of spheres
rMin, rMax = 0.008, 0.012    # radii [m]
box = 0.09                   # they start in the cube [-box, box]³
rng = random.Random(1)       # fixed seed: the same run every time


def randomCloud(n, rMin, rMax, box):
    """Spheres without overlaps, by rejection sampling: draw a centre and a radius and keep
    them if they overlap no sphere placed before (a cell grid keeps the check local)."""
    cell = 2 * rMax
    grid, placed = {}, []
    tries = 0
    while len(placed) < n:
        tries += 1
        if tries > 1000 * n:
            raise RuntimeError('could not place %d spheres in the box; make it larger' % n)
        r = rng.uniform(rMin, rMax)
        c = tuple(rng.uniform(-box + r, box - r) for _ in range(3))
        key = tuple(int(math.floor(x / cell)) for x in c)
        neighbours = (grid.get((key[0] + i, key[1] + j, key[2] + k), ())
                      for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1))
        if any(math.dist(c, c2) <= r + r2 for cellList in neighbours for c2, r2 in cellList):
            continue
        grid.setdefault(key, []).append((c, r))
        placed.append((c, r))
    return placed


O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='grains'))
for c, r in randomCloud(N, rMin, rMax, box):
    b = sphere(c, r, material='grains')
    # random velocity, plus a common drift and a rigid spin so that the totals are not ~0
    b.state.vel = Vector3(*(rng.gauss(0, .5) for _ in range(3))) + Vector3(.1, -.05, 0) + Vector3(0, 0, 2).cross(b.state.pos)
    b.state.angVel = Vector3(*(rng.gauss(0, 20) for _ in range(3)))
    O.bodies.append(b)

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom()],
        [Ip2_FrictMat_FrictMat_FrictPhys()],
        [Law2_ScGeom_FrictPhys_CundallStrack()]
    ),
    NewtonIntegrator(gravity=(0, 0, 0), damping=0)
]
O.dt = .2 * PWaveTimeStep()


def totals():
    """Linear momentum, angular momentum about the origin, kinetic energy."""
    P, L, Ek = Vector3.Zero, Vector3.Zero, 0.
    for b in O.bodies:
        s = b.state
        Iw = Vector3(*(s.inertia[k] * s.angVel[k] for k in range(3)))
        P += s.mass * s.vel
        L += s.pos.cross(s.mass * s.vel) + Iw
        Ek += .5 * s.mass * s.vel.squaredNorm() + .5 * Iw.dot(s.angVel)
    return P, L, Ek


P0, L0, E0 = totals()
print('%d spheres, dt = %.3g s; |P| = %.6g kg·m/s, |L| = %.6g kg·m²/s, Ek = %.6g J' % (len(O.bodies), O.dt, P0.norm(), L0.norm(), E0))
print('%8s %10s %9s %9s %12s %12s %10s' % ('iter', 'time [s]', 'contacts', 'collided', '|ΔP|/|P|', '|ΔL|/|L|', 'Ek/Ek0'))
collided = set()  # pairs that have been in contact at least once
steps, every = 10000, 1000
for k in range(steps // every):
    for j in range(every // 10):
        O.run(10, True)
        collided.update((i.id1, i.id2) for i in O.interactions)
    P, L, Ek = totals()
    print('%8d %10.4f %9d %9d %12.2e %12.2e %10.4f' % (O.iter, O.time, O.interactions.countReal(), len(collided),
                                                     (P - P0).norm() / P0.norm(), (L - L0).norm() / L0.norm(), Ek / E0))

P, L, Ek = totals()
ok = (P - P0).norm() < 1e-10 * P0.norm() and (L - L0).norm() < 1e-8 * L0.norm()
print('momentum %s: linear to %.1e, angular to %.1e (relative); %.1f %% of the kinetic energy was dissipated by friction'
      % ('conserved' if ok else 'NOT CONSERVED', (P - P0).norm() / P0.norm(), (L - L0).norm() / L0.norm(), 100 * (1 - Ek / E0)))
