# A drained triaxial test with TriaxialStressController: a plain Yade script that runs unchanged in
# the reference Yade and in this engine. Run as a script it prints one JSON line (TRIAXIAL {...}) that
# tests/test_triaxial.py compares; its data file is made with
#   yade -n -x -j1 tests/reference/triaxial.py | grep ^TRIAXIAL > tests/reference/data/triaxial.json
# The packing is generated here with a small linear congruential generator, the same in both engines.
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *


class LCG:
    """x -> (1103515245 x + 12345) mod 2^31, as a number in [0, 1)"""

    def __init__(self, seed):
        self.x = seed

    def __call__(self):
        self.x = (1103515245 * self.x + 12345) % 2147483648
        return self.x / 2147483648.0


def build(n=6, seed=7, young=5e6):
    """n^3 spheres on a jittered lattice of spacing 1 in six walls (ids 0-5, as aabbWalls gives them)"""
    O.reset()
    rnd = LCG(seed)
    O.materials.append(FrictMat(young=young, poisson=0.5, frictionAngle=math.radians(30), density=2600, label='spheres'))
    O.materials.append(FrictMat(young=young, poisson=0.5, frictionAngle=0, density=0, label='walls'))
    O.bodies.append(aabbWalls([Vector3(0, 0, 0), Vector3(n, n, n)], thickness=.1, material='walls'))
    for i in range(n):
        for j in range(n):
            for k in range(n):
                c = Vector3(i + .5 + .1 * (rnd() - .5), j + .5 + .1 * (rnd() - .5), k + .5 + .1 * (rnd() - .5))
                O.bodies.append(sphere(c, .35 * (1 + .3 * (rnd() - .5)), material='spheres'))
    triax = TriaxialStressController(stressMask=7, internalCompaction=True, goal1=-1e4, goal2=-1e4, goal3=-1e4,
                                     maxMultiplier=1.005, finalMaxMultiplier=1.0005, max_vel=1, label='triax')
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 triax, NewtonIntegrator(damping=.2)]
    O.dt = 1e-3
    return triax


def state(t):
    """the controller's quantities and the walls' positions"""
    return dict(iter=O.iter, walls=[O.bodies[i].state.pos[i // 2] for i in range(6)], stress=[t.stress(i)[i // 2] for i in range(6)],
                meanStress=t.meanStress, strain=list(t.strain), ev=t.volumetricStrain, porosity=t.porosity, size=[t.width, t.height, t.depth],
                externalWork=t.externalWork, multiplier=t.previousMultiplier, radius=O.bodies[10].shape.radius)


def triaxial(compaction=800, consolidation=700, shear=700, every=50):
    """internal compaction to 10 kPa, consolidation by the walls, then shear at constant lateral stress (goal2 a strain rate)"""
    t = build()
    out = dict(early=[], compaction=[], curve=[])
    for k in range(30):
        O.step()
        out['early'].append(state(t))
    O.run(compaction - 30, True)
    out['compaction'].append(state(t))
    t.internalCompaction = False
    O.run(consolidation, True)
    out['compaction'].append(state(t))
    t.stressMask = 5
    t.goal2 = -0.2
    e0 = list(t.strain)
    for k in range(shear // every):
        O.run(every, True)
        s = state(t)
        s['q'] = -(t.stress(2)[1] + t.stress(3)[1]) / 2 + (t.stress(0)[0] + t.stress(1)[0] + t.stress(4)[2] + t.stress(5)[2]) / 4
        s['axial'] = -(t.strain[1] - e0[1])
        out['curve'].append(s)
    return out


if RUN:
    print('TRIAXIAL ' + json.dumps(dict(triaxial=triaxial())))
