# Scenes of the periodic cell controllers (PeriTriaxController, PeriIsoCompressor): a plain Yade script
# that runs unchanged in the reference Yade and in this engine. Run as a script it prints one JSON line
# (PERICONTROLLERS {...}) that tests/test_peri_controllers.py compares with:
#     yade -n -x -j1 peri_controllers.py | grep '^PERICONTROLLERS ' | sed 's/^PERICONTROLLERS //' > data/peri_controllers.json
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


def laws(verletDist=None):
    collider = InsertionSortCollider([Bo1_Sphere_Aabb()]) if verletDist is None else InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=verletDist)
    return [ForceResetter(), collider,
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()])]


def fixed_scene(controller, spheres, size=(2, 3, 4)):
    """Spheres that do not move (huge masses, the cell's field not applied to them): the contact forces
    change only through the cell's deformation, so the controller's law is seen alone, step by step."""
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(size[0], 0, 0, 0, size[1], 0, 0, 0, size[2])
    O.bodies.append([sphere(c, r) for c, r in spheres])
    O.engines = laws(verletDist=0) + [controller, NewtonIntegrator()]
    O.cell.homoDeform = 0
    for b in O.bodies:
        b.state.mass = 1e30
        b.state.inertia = (1e30, 1e30, 1e30)
    O.dt = 1e-5


FOUR = [((0.5, 0.5, 0.5), 0.1), ((0.68, 0.55, 0.5), 0.1), ((1.0, 1.0, 1.0), 0.1), ((1.0, 1.17, 1.08), 0.1)]
FOUR_UNEQUAL = FOUR[:3] + [((1.0, 1.17, 1.08), 0.15)]
HOOKS = []


def triax_steps(kw, n, every=1):
    """PeriTriaxController on the fixed scene: per recorded step its stress, stressTensor, strainRate,
    strain, stiff, externalWork, currUnbalanced, the doneHook calls so far and the cell."""
    del HOOKS[:]
    c = PeriTriaxController(doneHook='HOOKS.append(O.iter)', **kw)
    fixed_scene(c, FOUR)
    O.trackEnergy = True
    out = []
    for k in range(n):
        O.step()
        if O.iter % every == 0:
            out.append(dict(iter=O.iter, stress=vec(c.stress), stressTensor=mat(c.stressTensor), strainRate=vec(c.strainRate), strain=vec(c.strain),
                            stiff=vec(c.stiff), externalWork=c.externalWork, velGradWork=O.energy['velGradWork'], hooks=len(HOOKS),
                            hSize=mat(O.cell.hSize), mass=c.mass, currUnbalanced=None if math.isnan(c.currUnbalanced) else c.currUnbalanced))
    return out


# (name, keyword arguments, steps, record every)
TRIAX_CASES = [
    ('stress', dict(goal=(-100, -100, -30), stressMask=7, globUpdate=3, growDamping=0.3, maxStrainRate=(1e3, 1e3, 1e3)), 30, 1),
    ('mixed', dict(goal=(-100, -0.001, -30), stressMask=5, globUpdate=3, growDamping=0.3, maxStrainRate=(1e3, 1e3, 1e3)), 30, 1),
    ('saturated', dict(goal=(-1e3, -1e3, -2e3), stressMask=7, globUpdate=1), 10, 1),
    ('dynCell', dict(goal=(-100, -0.001, -30), stressMask=5, globUpdate=2, growDamping=0.3, maxStrainRate=(1e3, 1e3, 1e3), dynCell=True, mass=1e-4), 60, 3),
    ('dynCellMass', dict(goal=(-100, -0.001, -30), stressMask=5, globUpdate=2, dynCell=True), 20, 1),
    ('strainGoal', dict(goal=(1e-4, 0, 0), stressMask=0, globUpdate=7, maxUnbalanced=1e9, maxStrainRate=(0.1, 1, 1)), 250, 5),
    ('zeroGoal', dict(goal=(0, -100, -30), stressMask=7, globUpdate=1, absStressTol=1e9, relStressTol=1e9, maxUnbalanced=1e9), 5, 1),
]


def iso_steps(kw, n, spheres=FOUR_UNEQUAL, size=(2, 3, 4)):
    """PeriIsoCompressor on the fixed scene: per step sigma, the cell's velGrad and hSize, state, currUnbalanced, doneHook calls."""
    del HOOKS[:]
    c = PeriIsoCompressor(doneHook='HOOKS.append(O.iter)', **kw)
    fixed_scene(c, spheres, size)
    out = []
    for k in range(n):
        O.step()
        out.append(dict(iter=O.iter, sigma=vec(c.sigma), velGrad=mat(O.cell.velGrad), hSize=mat(O.cell.hSize), state=c.state,
                        currUnbalanced=c.currUnbalanced, hooks=len(HOOKS), charLen=c.charLen, maxSpan=c.maxSpan))
    return out


TWO = [((0.4, 0.5, 0.5), 0.1), ((0.59, 0.5, 0.5), 0.1)]
ISO_CASES = [
    ('grow', dict(stresses=[-100, -1000], globalUpdateInt=3), 10, FOUR_UNEQUAL, (2, 3, 4)),
    ('axes', dict(stresses=[-100, -1000], keepProportions=False), 10, FOUR_UNEQUAL, (2, 3, 4)),
    ('capped', dict(stresses=[-1e9]), 5, TWO, (1, 2, 4)),
    ('cappedAxes', dict(stresses=[-1e9], keepProportions=False), 5, TWO, (1, 2, 4)),
    ('noContact', dict(stresses=[-1e3]), 3, [((0.4, 0.5, 0.5), 0.1), ((0.8, 0.5, 0.5), 0.1)], (1, 2, 4)),
    ('reached', dict(stresses=[-5090, -5100, -5060], globalUpdateInt=3, maxUnbalanced=10), 12, FOUR_UNEQUAL, (2, 3, 4)),
    ('unbalanced', dict(stresses=[-5090, -5100, -5060], globalUpdateInt=3), 12, FOUR_UNEQUAL, (2, 3, 4)),
    ('allReached', dict(stresses=[-5090, -5070], globalUpdateInt=1, maxUnbalanced=10), 6, FOUR_UNEQUAL, (2, 3, 4)),
    ('axesNotReached', dict(stresses=[-5090, -5200, -5060], globalUpdateInt=2, keepProportions=False), 12, FOUR_UNEQUAL, (2, 3, 4)),
]


def cloud(seed=3, size=1.0, rMean=.1, rRelFuzz=.2):
    O.reset()
    O.periodic = True
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (size, size, size), rMean=rMean, rRelFuzz=rRelFuzz, periodic=True, seed=seed)
    sp.toSimulation()


def packing_triax(dynCell, n, every):
    """A loose periodic cloud compressed by PeriTriaxController (the tutorial's settings, goal -10 kPa):
    the first steps, where the two engines agree to rounding (later, rounding differences grow as in
    any dense packing)."""
    cloud()
    c = PeriTriaxController(goal=(-1e4, -1e4, -1e4), stressMask=7, dynCell=dynCell, maxStrainRate=(10, 10, 10), maxUnbalanced=.1, relStressTol=1e-3)
    O.engines = laws() + [c, NewtonIntegrator(damping=.2)]
    O.dt = .5 * PWaveTimeStep()
    out = []
    for k in range(n):
        O.step()
        if O.iter % every == 0:
            out.append(dict(iter=O.iter, stress=vec(c.stress), stressTensor=mat(c.stressTensor), strainRate=vec(c.strainRate), strain=vec(c.strain),
                            hSize=mat(O.cell.hSize), externalWork=c.externalWork, maxBodySpan=vec(c.maxBodySpan), contacts=O.interactions.countReal()))
    return out


def packing_iso(keepProportions, n, every):
    """The same cloud compressed by PeriIsoCompressor (the first steps, as packing_triax)."""
    cloud()
    c = PeriIsoCompressor(stresses=[-3e4, -6e4], globalUpdateInt=5, keepProportions=keepProportions)
    O.engines = laws() + [c, NewtonIntegrator(damping=.4)]
    O.dt = .5 * PWaveTimeStep()
    out = []
    for k in range(n):
        O.step()
        if O.iter % every == 0:
            out.append(dict(iter=O.iter, sigma=vec(c.sigma), velGrad=mat(O.cell.velGrad), hSize=mat(O.cell.hSize), charLen=c.charLen, maxSpan=c.maxSpan))
    return out


TUTORIAL = {}


def tutorial(size=1.5, seed=1):
    """The manual's periodic triaxial test (2.6.6) on a smaller seeded cloud: isotropic compaction to
    -100 kPa with dynCell, then (compactionFinished) stress on x and y and strain -0.1 on z. Returns the
    step and state at the end of each phase."""
    TUTORIAL.clear()
    cloud(seed=seed, size=size, rRelFuzz=.3)
    sigmaIso = -1e5
    O.engines = laws() + [
        PeriTriaxController(label='triax', goal=(sigmaIso, sigmaIso, sigmaIso), stressMask=7, dynCell=True, maxStrainRate=(10, 10, 10),
                            maxUnbalanced=.1, relStressTol=1e-3, doneHook='compactionFinished()'),
        NewtonIntegrator(damping=.2)]
    O.dt = .5 * PWaveTimeStep()
    O.run(100000, True)
    return dict(TUTORIAL, bodies=len(O.bodies))


def compactionFinished():
    t = O.engines[3]
    TUTORIAL['compacted'] = dict(iter=O.iter, stress=vec(t.stress), strain=vec(t.strain), size=vec(O.cell.size))
    O.cell.trsf = Matrix3.Identity
    t.goal = (-1e5, -1e5, -.1)
    t.stressMask = 3
    t.maxStrainRate = (1., 1., 1.)
    t.doneHook = 'triaxFinished()'
    t.maxUnbalanced = 10


def triaxFinished():
    t = O.engines[3]
    TUTORIAL['finished'] = dict(iter=O.iter, stress=vec(t.stress), strain=vec(t.strain), size=vec(O.cell.size), externalWork=t.externalWork)
    O.pause()


def defaults():
    def plain(d):
        out = {}
        for k, v in d.items():
            if isinstance(v, (bool, int, float, str)):
                out[k] = None if isinstance(v, float) and math.isnan(v) else v
            elif isinstance(v, list):
                out[k] = [float(x) for x in v]
            else:
                try:
                    out[k] = vec(v)
                except TypeError:
                    out[k] = mat(v)
        return out
    return dict(PeriTriaxController=plain(PeriTriaxController().dict()), PeriIsoCompressor=plain(PeriIsoCompressor().dict()))


def everything():
    return dict(defaults=defaults(),
                triax={name: triax_steps(kw, n, every) for name, kw, n, every in TRIAX_CASES},
                iso={name: iso_steps(kw, n, spheres, size) for name, kw, n, spheres, size in ISO_CASES},
                packingTriax=packing_triax(True, 300, 10), packingTriaxStiff=packing_triax(False, 300, 10),
                packingIso=packing_iso(True, 400, 20), packingIsoAxes=packing_iso(False, 400, 20),
                tutorial=tutorial())


if RUN:
    print('PERICONTROLLERS ' + json.dumps(everything()))
