#!/usr/bin/env python3
"""Fuzzing of O.load: mutated saved scenes (binary and XML, plain, .gz and .bz2).

    /usr/bin/python3 scripts/fuzz/fuzz_loader.py --cases 100000 --seed 7
    /usr/bin/python3 scripts/fuzz/fuzz_loader.py --seed 7 --replay 1234     (one case, in this process)

(PYTHONPATH must reach the build, e.g. PYTHONPATH=build.) Each case is a valid scene mutated by
scripts/fuzz/mutate.py. O.load of it must either

  * refuse it with yade.FileFormatError (or OSError) and a message, and leave the current scene
    byte for byte as it was (O.sceneToString() before and after), or
  * load it; then the scene must be valid: every body's position, orientation and velocities
    finite, and three steps must either run and leave it finite or stop with an exception that
    says why (and leave it finite too).

Anything else is a failure: another exception type, a changed scene, a non-finite state, a crash
or a hang (each worker process runs a chunk of cases, see runner.py). The counts per outcome are
printed, with the case number of every failure (replay it with --replay).
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutate  # noqa: E402
import runner  # noqa: E402

STEPS = 3


def buildSeeds():
    """Valid saved scenes (uncompressed bytes, binary and XML) of a few small simulations:
    spheres, facets and a wall with live contacts and their history, energy tracking, a PyRunner,
    a permanent force, tags, an erased body (a hole in the ids), a Hertz-Mindlin contact."""
    from yade import (O, FrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb,
                      Bo1_Wall_Aabb, InteractionLoop, Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom,
                      Ig2_Wall_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                      Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin, NewtonIntegrator,
                      PyRunner, ForceEngine, GlobalStiffnessTimeStepper, geom)
    from yade.utils import sphere, wall, PWaveTimeStep
    seeds = []

    def collider():
        return InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()], label='collider')

    # 1. spheres resting in a facet box on a wall, friction, energy, PyRunner, permanent force
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='granular'))
    O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))
    O.bodies.append(wall((0, 0, -.01), axis=2))
    for i in range(8):
        O.bodies.append(sphere((.15 + .24 * (i % 4), .3 + .3 * (i // 4), .095 + .01 * i), .1))
    O.engines = [ForceResetter(), collider(),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                 [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=.2, label='newton'),
                 PyRunner(command='pass', iterPeriod=2, label='runner')]
    O.dt = .5 * PWaveTimeStep()
    O.trackEnergy = True
    O.tags['description'] = 'fuzz seed 1'
    O.forces.addF(len(O.bodies) - 1, (0, 0, -1), permanent=True)
    for _ in range(20):
        O.step()
    seeds.append(O._toBytes(False))
    seeds.append(O._toBytes(True))

    # 2. two Hertz-Mindlin spheres in contact, an erased body, a force engine, a time stepper
    O.reset()
    O.materials.append(FrictMat(young=1e8, poisson=.25, frictionAngle=.4, density=2000))
    O.bodies.append([sphere((0, 0, 0), .1), sphere((.5, 0, 0), .1), sphere((.19, 0, 0), .1, fixed=True)])
    O.bodies.erase(1)
    O.engines = [ForceResetter(), collider(),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_MindlinPhys()],
                                 [Law2_ScGeom_MindlinPhys_Mindlin()]),
                 ForceEngine(ids=[0], force=(0, 0, 1)),
                 GlobalStiffnessTimeStepper(timeStepUpdateInterval=2),
                 NewtonIntegrator(damping=.1)]
    O.dt = .3 * PWaveTimeStep()
    for _ in range(3):
        O.step()
    seeds.append(O._toBytes(False))
    seeds.append(O._toBytes(True))
    O.reset()
    return seeds


def finiteState(O):
    """None if every body's position, orientation and velocities are finite, else what is not."""
    for b in O.bodies:
        if b is None:
            continue
        s = b.state
        for name in ('pos', 'vel', 'angVel', 'ori'):
            v = getattr(s, name)
            if not all(math.isfinite(x) for x in v):
                return 'body %d: state.%s = %s' % (b.id, name, tuple(v))
    return None


def factory(seed, describeOnly=False):
    """runOne(k) for this seed (see runner.main)."""
    import warnings
    warnings.simplefilter('ignore')
    import yade
    from yade import O
    seeds = buildSeeds()
    O._fromBytes(seeds[0])  # the scene that a failed load must leave untouched
    base = O.sceneToString()
    assert O.sceneToString() == base, 'O.sceneToString() is not repeatable'
    tmp = tempfile.mkdtemp(prefix='fuzz-loader-')
    atexit.register(shutil.rmtree, tmp, True)
    clean = [True]

    def runOne(k):
        rng = mutate.caseRng(seed, k)
        data, suffix, description = mutate.makeCase(rng, seeds)
        if describeOnly:
            return None, description, None
        if not clean[0]:
            O.stringToScene(base)
            clean[0] = True
        path = os.path.join(tmp, 'case%s%s' % ('.xml' if b'<?xml' in data[:8] else '.yade', suffix))
        with open(path, 'wb') as f:
            f.write(data)
        try:
            O.load(path)
        except (yade.FileFormatError, OSError) as e:
            if not str(e):
                return 'FAIL %s without a message' % type(e).__name__, description, ''
            if O.sceneToString() != base:
                clean[0] = False
                return 'FAIL scene changed by a refused load', description, str(e)[:200]
            return 'refused: %s' % type(e).__name__, description, str(e)[:200]
        except Exception as e:
            clean[0] = O.sceneToString() == base
            return 'FAIL wrong exception %s' % type(e).__name__, description, str(e)[:300]
        clean[0] = False
        bad = finiteState(O)
        if bad:
            return 'FAIL loaded a non-finite state', description, bad
        stepError = None
        try:
            for _ in range(STEPS):
                O.step()
        except Exception as e:
            stepError = e
        bad = finiteState(O)
        if bad:
            return 'FAIL non-finite state after %s' % ('steps' if stepError is None else 'a refused step'), description, \
                bad + ('' if stepError is None else ' (%s: %s)' % (type(stepError).__name__, str(stepError)[:150]))
        if stepError is None:
            return 'loaded, ran %d steps' % STEPS, description, ''
        # (an engine's own check of what it was given: ForceEngine.ids naming a body that is not there
        # raises IndexError, as the same ids assigned from Python do)
        if not str(stepError) or not isinstance(stepError, (RuntimeError, ValueError, IndexError)):
            return 'FAIL step raised %s' % type(stepError).__name__, description, str(stepError)[:300]
        return 'loaded, step refused: %s' % type(stepError).__name__, description, str(stepError)[:200]

    return runOne


if __name__ == '__main__':
    sys.exit(runner.main(os.path.abspath(__file__), 'fuzz_loader', 1000, factory))
