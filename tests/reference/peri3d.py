# Scenes of Peri3dController: a plain Yade script that runs unchanged in the reference Yade and in this
# engine. Run as a script it prints one JSON line (PERI3D {...}) that tests/test_peri3d.py compares with:
#     yade -n -x -j1 peri3d.py | grep '^PERI3D ' | sed 's/^PERI3D //' > data/peri3d.json
# (tests/reference/regenerate.sh). doc/periodic.md says what was found and how well it agrees.
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *
from yade import pack


def vec(v):
    return [float(x) for x in v]


def mat(m):
    return [float(m[i, j]) for i in range(3) for j in range(3)]


def laws():
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=0),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()])]


FOUR = [((0.5, 0.5, 0.5), 0.1), ((0.68, 0.55, 0.5), 0.1), ((1.0, 1.0, 1.0), 0.1), ((1.0, 1.17, 1.08), 0.1)]
HOOKS = []


def fixed_scene(controller, spheres=FOUR, size=(2, 3, 4)):
    """Spheres that do not move (huge masses, the cell's field not applied to them): the contact forces
    change only through the cell's deformation, so the controller's law is seen alone, step by step."""
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(size[0], 0, 0, 0, size[1], 0, 0, 0, size[2])
    O.bodies.append([sphere(c, r) for c, r in spheres])
    O.engines = laws() + [controller, NewtonIntegrator()]
    O.cell.homoDeform = 0
    for b in O.bodies:
        b.state.mass = 1e30
        b.state.inertia = (1e30, 1e30, 1e30)
    O.dt = 1e-5


def record(c):
    return dict(iter=O.iter, progress=c.progress, dead=c.dead, hooks=len(HOOKS), stress=vec(c.stress), strain=vec(c.strain),
                strainRate=vec(c.strainRate), stressRate=vec(c.stressRate), stressIdeal=vec(c.stressIdeal), velGrad=mat(O.cell.velGrad),
                trsf=mat(O.cell.trsf), pathsCounter=[int(x) for x in c.pathsCounter], pe=[int(x) for x in c.pe], ps=[int(x) for x in c.ps],
                lenPe=c.lenPe, lenPs=c.lenPs, pathSizes=[int(x) for x in c.pathSizes], stressGoal=vec(c.stressGoal), strainGoal=vec(c.strainGoal))


def fixed_steps(kw, n, trsf=None):
    del HOOKS[:]
    c = Peri3dController(**kw)
    fixed_scene(c)
    if trsf is not None:  # a cell already deformed (and rotated): the polar decomposition's rotation counts
        O.cell.trsf = trsf
    out = []
    for k in range(n):
        O.step()
        out.append(record(c))
    return out


# (name, keyword arguments, steps)
FIXED_CASES = [
    ('strain', dict(goal=(1e-3, -2e-3, 0, 4e-3, 0, 0), stressMask=0, nSteps=4), 6),
    ('mixed', dict(goal=(1e-3, -300, -50, 0, 0, 0), stressMask=0b000110, nSteps=5), 7),
    ('allStress', dict(goal=(100, -300, 50, 70, 0, -20), stressMask=0b111111, nSteps=5), 6),
    ('shearStress', dict(goal=(0, 0, 0, 70, 0, 0), stressMask=0b001000, nSteps=5, poissonEstimation=.3, youngEstimation=1e9), 5),
    ('softEstimation', dict(goal=(1e-3, -300, 0, 0, 2e-3, 0), stressMask=0b000010, nSteps=5, youngEstimation=1e5), 6),
    ('paths', dict(goal=(2e-3, -300, 0, 0, 0, 0), stressMask=2, nSteps=10, xxPath=[(2, 3), (4, 1), (5, 2)], yyPath=[(1, 1), (3, -1), (4, 2)]), 12),
    ('shearPaths', dict(goal=(0, 0, -1e-3, 0, 3e-3, 20), stressMask=0b100000, nSteps=8, zxPath=[(1, -1), (2, 1)], xyPath=[(3, 2), (4, 1)]), 10),
    ('hook', dict(goal=(1e-3, 0, 0, 0, 0, 0), nSteps=3, doneHook='HOOKS.append(O.iter)'), 5),
    ('maxStrain', dict(goal=(1e-2, 0, 0, 0, 0, 0), nSteps=10, maxStrain=2.5e-3), 5),
    ('maxStrainRate', dict(goal=(1e-3, -300, 0, 0, 0, 0), stressMask=2, nSteps=4, maxStrainRate=30, youngEstimation=1e5), 5),
    ('mod', dict(goal=(1e-3, -300, -20, 0, 0, 0), stressMask=6, nSteps=6, mod=.35), 6),
    ('shortSegments', dict(goal=(3e-3, 0, 0, 0, 0, 0), nSteps=5, xxPath=[(.5, 1), (1, 2), (10, 3)]), 7),
]
ROTATION = Quaternion(Vector3(.2, .3, .9).normalized(), .4).toRotationMatrix()
# (name, keyword arguments, steps, the cell's trsf at the start)
ROTATED_CASES = [
    ('rotatedStrain', dict(goal=(1e-3, -2e-3, 5e-4, 4e-3, -1e-3, 2e-3), nSteps=4), 5, ROTATION * Matrix3(1.01, .002, 0, .002, .99, .001, 0, .001, 1.02)),
    ('rotatedMixed', dict(goal=(1e-3, -300, -50, 0, 1e-3, 30), stressMask=0b100110, nSteps=5), 6, ROTATION),
]


def packing(kw, n, every, seed=5):
    """A periodic cloud (makeCloud, the same in both engines) deformed by Peri3dController: the first
    steps, before rounding differences grow as in any dense packing."""
    O.reset()
    O.periodic = True
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, rRelFuzz=.2, periodic=True, seed=seed)
    sp.toSimulation()
    c = Peri3dController(**kw)
    O.engines = laws() + [c, NewtonIntegrator(damping=.2)]
    O.dt = .5 * PWaveTimeStep()
    out = []
    for k in range(n):
        O.step()
        if O.iter % every == 0:
            out.append(dict(iter=O.iter, progress=c.progress, stress=vec(c.stress), strain=vec(c.strain), strainRate=vec(c.strainRate),
                            stressIdeal=vec(c.stressIdeal), hSize=mat(O.cell.hSize), contacts=O.interactions.countReal()))
    return out


def defaults():
    out = {}
    for k, v in Peri3dController().dict().items():
        if isinstance(v, (bool, int, float, str)):
            out[k] = v
        elif isinstance(v, list):
            out[k] = [vec(x) for x in v]
        else:
            out[k] = vec(v)
    return out


def everything():
    return dict(defaults=defaults(),
                fixed={name: fixed_steps(kw, n) for name, kw, n in FIXED_CASES},
                rotated={name: fixed_steps(kw, n, trsf) for name, kw, n, trsf in ROTATED_CASES},
                packingStrain=packing(dict(goal=(-.2, -.2, -.25, .05, 0, 0), nSteps=400), 400, 20),
                packingMixed=packing(dict(goal=(-1e4, -1e4, -.3, 0, 0, 0), stressMask=3, nSteps=600, maxStrainRate=2), 400, 20))


if RUN:
    print('PERI3D ' + json.dumps(everything()))
