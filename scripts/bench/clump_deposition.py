# Clump deposition benchmark: rigid clumps of two or three spheres settling in a box of walls.
# Runs unchanged in any Yade-compatible engine:  yade -n -x -j1 clump_deposition.py [N] [STEPS] [SETTLE]
# N clumps (default 2000, each a dyad or a triad by a seeded coin, with a seeded random
# orientation) on a loose lattice (cell 4 r; every clump fits in a ball of radius 1.8 r, so no
# clump touches another or a wall at the start) fall under gravity onto the floor of a box of 5
# utils.wall planes. SETTLE untimed steps (default 4000: the lower layers have landed, the upper
# ones are landing), then STEPS timed steps (default 2000: the last ones land, the bed settles).
# Prints one line: "N=<clumps> spheres=<members> steps=<n> contacts=<c> iter_per_s=<x>
#   clump_steps_per_s=<y> mean_z=<mean height of the clumps' centres> max_z=<highest centre>"
import sys, time, math, random
from yade.utils import *

args = [a for a in sys.argv[1:] if not a.startswith('-')]
N = int(args[0]) if len(args) > 0 else 2000
STEPS = int(args[1]) if len(args) > 1 else 2000
SETTLE = int(args[2]) if len(args) > 2 else 4000

O.reset()
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='mat'))
r = 0.01
cell = 4 * r
# about 8 layers whatever N: nx = ny columns
nx = max(2, int(round(math.sqrt(N / 8.))))
side = nx * cell
rnd = random.Random(1)


def rotate(q, v):
    # v rotated by the unit quaternion q = (w, x, y, z), in plain Python (the same in both engines)
    w, x, y, z = q
    tx, ty, tz = 2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + y * tz - z * ty, v[1] + w * ty + z * tx - x * tz, v[2] + w * tz + x * ty - y * tx)


def randomQuat():
    # uniform random rotation (Shoemake)
    u1, u2, u3 = rnd.random(), rnd.random(), rnd.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return (b * math.cos(2 * math.pi * u3), a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2), b * math.sin(2 * math.pi * u3))


# member offsets in the clump's frame: a dyad along x (centres 1.2 r apart), a triad in the xy
# plane (centres 0.8 r from the middle): both within 1.8 r of the middle
dyad = [(-.6 * r, 0, 0), (.6 * r, 0, 0)]
triad = [(.8 * r * math.cos(2 * math.pi * k / 3), .8 * r * math.sin(2 * math.pi * k / 3), 0) for k in range(3)]

O.bodies.append([
    wall(0, axis=2, sense=1),
    wall(0, axis=0, sense=1), wall(side, axis=0, sense=-1),
    wall(0, axis=1, sense=1), wall(side, axis=1, sense=-1),
])
clumpIds = []
nSph = 0
for k in range(N):
    i, j, l = k % nx, (k // nx) % nx, k // (nx * nx)
    c = ((i + .5) * cell, (j + .5) * cell, (l + .5) * cell + .5 * r)
    shape = triad if rnd.random() < .5 else dyad
    q = randomQuat()
    members = []
    for off in shape:
        d = rotate(q, off)
        members.append(sphere((c[0] + d[0], c[1] + d[1], c[2] + d[2]), r * (1 - .1 * rnd.random()), material='mat'))
    cid, ids = O.bodies.appendClumped(members)
    clumpIds.append(cid)
    nSph += len(ids)

O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
    InteractionLoop(
        [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
        [Ip2_FrictMat_FrictMat_FrictPhys()],
        [Law2_ScGeom_FrictPhys_CundallStrack()],
    ),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.2),
]
O.dt = .5 * PWaveTimeStep()
# an untimed phase (the lower layers land, first contacts form), then the timed phase
O.run(SETTLE, True)
t0 = time.time()
O.run(STEPS, True)
dt = time.time() - t0
zs = [O.bodies[i].state.pos[2] for i in clumpIds]
print("N=%d spheres=%d steps=%d contacts=%d iter_per_s=%.2f clump_steps_per_s=%.4g mean_z=%.5f max_z=%.5f" % (
    N, nSph, STEPS, sum(1 for i in O.interactions if i.isReal), STEPS / dt, N * STEPS / dt, sum(zs) / len(zs), max(zs)))
