# The dense lattice of shared/bench/dense.py in a periodic cell instead of a facet box: N spheres on a
# simple cubic lattice filling the cell, each overlapping its six neighbours (the images across the
# cell's faces included) by 1 % of the radius, FrictMat / Cundall-Strack, Cundall damping, no gravity.
# About 3 N contacts, all live, a third of the layers' contacts through the cell's faces.
# Runs unchanged here and in the reference:  yade -n -x -j1 periodic_dense.py [N] [STEPS]
# Prints one line: "N=<spheres> steps=<n> contacts=<c> iter_per_s=<x> particle_steps_per_s=<y> crossing=<c>"
import sys, time
from yade.utils import *

args = [a for a in sys.argv[1:] if not a.startswith('-')]
N = int(args[0]) if len(args) > 0 else 5000
STEPS = int(args[1]) if len(args) > 1 else 500

O.reset()
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='mat'))
r = 0.01
a = 2 * r * 0.995                      # lattice spacing: overlap of 1 % of the radius
n = max(3, int(round(N ** (1. / 3.))))
nz = max(3, N // (n * n))
O.periodic = True
O.cell.setBox(n * a, n * a, nz * a)
for k in range(nz):
    for j in range(n):
        for i in range(n):
            O.bodies.append(sphere(((i + .5) * a, (j + .5) * a, (k + .5) * a), r))
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom()],
        [Ip2_FrictMat_FrictMat_FrictPhys()],
        [Law2_ScGeom_FrictPhys_CundallStrack()],
    ),
    NewtonIntegrator(damping=0.4),
]
O.dt = .5 * PWaveTimeStep()
O.cell.velGrad = Matrix3(-1e-3, 0, 0, 0, -1e-3, 0, 0, 0, -1e-3)  # (a slow compression: the cell deforms every step)
nSph = n * n * nz
O.run(20, True)                        # untimed: contacts are created
t0 = time.time()
O.run(STEPS, True)
dt = time.time() - t0
real = [i for i in O.interactions if i.isReal]
print("N=%d steps=%d contacts=%d iter_per_s=%.2f particle_steps_per_s=%.4g crossing=%d" % (nSph, STEPS, len(real), STEPS / dt,
      nSph * STEPS / dt, sum(1 for i in real if tuple(i.cellDist) != (0, 0, 0))))
