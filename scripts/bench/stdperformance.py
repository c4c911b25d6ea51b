# The standard performance test, run by `./yade --stdperformance N [-j T]` (or directly:
# ./yade -n -x scripts/bench/stdperformance.py [N] [ITERS]).
#
# The scene of the reference's `yade --stdperformance` (read off a run of the reference, not from its
# files): 10 009 spheres of radius 0.01625 in a regular hexagonal packing filling a ball of radius
# 0.5 (gap half a radius), inside a box of 12 facets; ViscElMat (tc 1 ms, en = et = 0.003, friction
# angle 35°, density 2300), gravity 9.81 along -y, no damping, dt 1e-4. They fall and pile up during
# 7 000 steps. Each of the N runs builds the scene again and times the steps; the summary gives
# the mean iter/s and its spread.
#
# scripts/bench/stdperformance_bench.py times the reference's own script in both engines.
import math
import sys
import time

from yade import O, pack, geom, utils
from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_ViscElMat_ViscElMat_ViscElPhys,
                          Law2_ScGeom_ViscElPhys_Basic, NewtonIntegrator, ViscElMat)

RADIUS = 0.01625


def build():
    """The scene, into O (after O.reset()); returns the number of bodies."""
    O.reset()
    mat = O.materials.append(ViscElMat(young=1e9, poisson=.25, frictionAngle=math.radians(35), density=2300,
                                       tc=0.001, en=0.003, et=0.003))
    spheres = pack.regularHexa(pack.inSphere((0, 0, 0), 0.5), radius=RADIUS, gap=0.5 * RADIUS, material=mat)
    O.bodies.append(spheres)
    O.bodies.append(geom.facetBox((0, 0, 0), (0.52, 0.52, 0.52), material=mat))
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                        [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
        NewtonIntegrator(damping=0, gravity=(0, -9.81, 0)),
    ]
    O.dt = 1e-4
    return len(O.bodies)


def main(runs=1, iters=7000):
    speeds = []
    for k in range(runs):
        n = build()
        t0 = time.time()
        O.run(iters, True)
        speeds.append(iters / (time.time() - t0))
        print("run %d: %d bodies, %d steps, %.1f iter/s, %d contacts" % (k + 1, n, iters, speeds[-1], O.interactions.countReal()),
              flush=True)
    mean = sum(speeds) / len(speeds)
    spread = math.sqrt(sum((s - mean) ** 2 for s in speeds) / (len(speeds) - 1)) if len(speeds) > 1 else 0.0
    print("stdperformance: %d spheres, %d runs of %d steps: %.1f iter/s +/- %.1f %% (%d threads)"
          % (n - 12, runs, iters, mean, 100 * spread / mean, O.numThreads))
    return speeds


if __name__ == '__main__':
    import yade.runtime
    argv = [a for a in sys.argv[1:] if not a.startswith('-')]
    runs = getattr(yade.runtime.opts, 'stdperformance', None) or (int(argv[0]) if argv else 1)
    main(runs, int(argv[1]) if len(argv) > 1 else 7000)
