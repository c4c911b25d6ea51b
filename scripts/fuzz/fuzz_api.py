#!/usr/bin/env python3
"""Fuzzing of the Python interface: random calls with random arguments.

    /usr/bin/python3 scripts/fuzz/fuzz_api.py --cases 20000 --seed 7
    /usr/bin/python3 scripts/fuzz/fuzz_api.py --seed 7 --replay 1234 --verbose   (one case, each call printed)

(PYTHONPATH must reach the build, e.g. PYTHONPATH=build.) A case starts from a small scene (spheres on
a wall in a facet box, contacts, engines), makes 1 to 8 random calls (appending, erasing and
indexing bodies with ids such as -1, -2**31, 2**63 or erased ones; setting state, shape, material,
engine and O attributes to NaN, infinities, wrong types or lengths; forces on bad ids; interactions
with bad ids; views of bodies, states, vectors and arrays kept past the erasure of their body or past
O.reset(); engines replaced during a background run...), then runs three steps. It must

  * never crash or hang (each worker process runs a chunk of cases, see runner.py);
  * answer every refused call with an ordinary exception that has a message (TypeError, ValueError,
    IndexError, KeyError, AttributeError, OverflowError, RuntimeError and their subclasses);
  * never leave a non-finite position, orientation or velocity in any body: a non-finite value is
    refused when set, and a step that cannot give a finite state stops with an exception.

The counts per outcome are printed, with the case number of every failure.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import runner  # noqa: E402

NAN, INF = float('nan'), float('inf')
CLEAR = (TypeError, ValueError, IndexError, KeyError, AttributeError, OverflowError, RuntimeError)
STEPS = 3


def factory(seed, describeOnly=False):
    import random
    import warnings
    warnings.simplefilter('ignore')
    import yade
    from yade import (O, Vector3, Quaternion, Matrix3, FrictMat, Sphere, State, Body, ForceResetter,
                      InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, Bo1_Wall_Aabb, InteractionLoop,
                      Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom,
                      Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator,
                      PyRunner, ForceEngine, GravityEngine, TranslationEngine, RotationEngine, geom, setNumThreads)
    from yade import utils

    def engines():
        return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
                InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                NewtonIntegrator(gravity=(0, 0, -9.81), damping=.2)]

    setNumThreads(1)
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))
    O.bodies.append(utils.wall((0, 0, -.01), axis=2))
    for i in range(6):
        O.bodies.append(utils.sphere((.15 + .3 * (i % 3), .3 + .3 * (i // 3), .095), .1))
    O.engines = engines()
    O.dt = .5 * utils.PWaveTimeStep()
    O.step()
    base = O.sceneToString()

    class Case:
        """The random choices of one case, and what it holds across calls (views, ids)."""

        def __init__(self, rng):
            self.rng = rng
            self.views = []  # bodies, states, shapes, vectors, arrays, interactions kept across calls
            self.erased = []
            # a non-finite value written into an item of a view (a NumPy array of O.bodies.arrays(), or the
            # Vector3 / Quaternion that b.state.pos or b.state.ori returns): unchecked, see doc/fuzzing.md
            self.rawNonFinite = False

        def choice(self, xs):
            return self.rng.choice(xs)

        def id(self):
            n = len(O.bodies)
            return self.choice([0, 1, n - 1, n, n + 3, -1, -2, -2 ** 31, 2 ** 31, 2 ** 63, -2 ** 63 - 1, 2 ** 64,
                                self.choice(self.erased or [0]), self.rng.randrange(max(n, 1)),
                                self.rng.randrange(max(n, 1)), 1.5, NAN, '3', None, True])

        def liveId(self):
            ids = [b.id for b in O.bodies if b is not None]
            return self.choice(ids) if ids else 0

        def real(self):
            return self.choice([NAN, INF, -INF, -1., 0., 1e308, -1e308, 5e-324, 1e-3, 1., 2.5, 2 ** 63, -7,
                                'x', None, (1, 2), True, Vector3(1, 2, 3)])

        def vector(self):
            x = self.choice([0., 1., -1., .1, 1e-3])
            return self.choice([(x, 0, 0), (NAN, 0, 0), (0, INF, 0), (0, 0, -INF), (1e308, 1e308, 1e308), (1, 2),
                                (1, 2, 3, 4), 'abc', None, 3., [x, x, x], Vector3(x, 0, NAN), Vector3(0, x, 0),
                                Quaternion((1, 0, 0), .1), (1, 'a', 3), ()])

        def quaternion(self):
            return self.choice([Quaternion((0, 0, 1), .5), Quaternion(NAN, 0, 0, 1), Quaternion(0, 0, 0, 0),
                                Quaternion(1e308, 1e308, 0, 0), (0, 0, 0, 1), (1, 0, 0), None, Vector3(0, 0, 1)])

        def matrix(self):
            return self.choice([Matrix3(1, 0, 0, 0, 1, 0, 0, 0, 1), Matrix3(NAN, 0, 0, 0, 1, 0, 0, 0, 1), (1, 2, 3),
                                None])

        def view(self):
            return self.choice(self.views) if self.views else None

    # ------------------------------------------------------------------ the calls
    # Each takes the Case and returns a short description; an exception it raises is its outcome.

    def appendSphere(c):
        center, radius = c.choice([(.5, .5, .3), c.vector()]), c.choice([.05, c.real()])
        kw = c.choice([{}, {'fixed': c.choice([True, 1, 'x', None])}, {'material': c.choice([0, -1, 99, 'x', None])},
                       {'color': c.vector()}, {'mask': c.choice([1, -1, 2 ** 40, 'x'])}])
        desc = 'O.bodies.append(sphere(%r, %r, **%r))' % (center, radius, kw)
        b = utils.sphere(center, radius, **kw)
        c.views.append(b)
        O.bodies.append(b)
        return desc

    def appendOther(c):
        what = c.choice(['wall', 'facet', 'box', 'body', 'list', 'none', 'same', 'int'])
        if what == 'wall':
            return 'wall', O.bodies.append(utils.wall(c.choice([0, c.real()]), axis=c.choice([0, 2, 3, -1, 'x'])))
        if what == 'facet':
            return 'facet', O.bodies.append(utils.facet([c.vector(), c.vector(), c.vector()]))
        if what == 'box':
            return 'box', O.bodies.append(utils.box((.5, .5, .5), c.vector()))
        if what == 'body':  # a bare Body: no shape, no material
            return 'Body()', O.bodies.append(Body())
        if what == 'list':
            return 'list', O.bodies.append([utils.sphere((.2, .2, .5), .05), c.choice([None, 1, Body()])])
        if what == 'none':
            return 'None', O.bodies.append(None)
        if what == 'same':  # a body already in the scene
            return 'twice', O.bodies.append(O.bodies[c.liveId()])
        return 'int', O.bodies.append(c.id())

    def erase(c):
        i = c.choice([c.liveId(), c.liveId(), c.id()])
        keep = c.rng.random() < .5
        if keep and isinstance(i, int) and 0 <= i < len(O.bodies) and O.bodies[i] is not None:
            b = O.bodies[i]
            c.views += [b, b.state, b.shape, b.state.pos, b.state.vel]
        r = O.bodies.erase(i)
        c.erased.append(i)
        return 'O.bodies.erase(%r) -> %r' % (i, r)

    def getBody(c):
        i = c.id()
        b = O.bodies[i]
        c.views.append(b)
        if b is not None:
            c.views += [b.state, b.shape, b.material, b.bound, b.state.pos]
        return 'O.bodies[%r]' % (i,)

    def setState(c):
        b = O.bodies[c.liveId()]
        name = c.choice(['pos', 'vel', 'angVel', 'mass', 'inertia', 'ori', 'blockedDOFs', 'refPos', 'refOri',
                         'densityScaling', 'angMom', 'se3', 'isDamped'])
        if name == 'ori' or name == 'refOri':
            v = c.quaternion()
        elif name in ('mass', 'densityScaling'):
            v = c.real()
        elif name == 'blockedDOFs':
            v = c.choice(['xyzXYZ', 'q', '', 'xx', None, 3, 'x'])
        elif name == 'se3':
            v = c.choice([(c.vector(), c.quaternion()), (1, 2), None])
        elif name == 'isDamped':
            v = c.choice([True, 'x', NAN])
        else:
            v = c.vector()
        setattr(b.state, name, v)
        return 'body %d state.%s = %r' % (b.id, name, v)

    def replaceState(c):
        b = O.bodies[c.liveId()]
        s = c.choice([State(), State(mass=c.real()), None, 1, O.bodies[c.liveId()].state])
        b.state = s
        return 'body %d state = %r' % (b.id, s)

    def setShape(c):
        b = O.bodies[c.liveId()]
        name = c.choice(['radius', 'color', 'wire', 'highlight', 'vertices', 'extents', 'axis', 'sense'])
        v = c.choice([c.real(), c.vector(), [c.vector()] * 3, -1, 5, 'x'])
        setattr(b.shape, name, v)
        return 'body %d shape.%s = %r' % (b.id, name, v)

    def replaceShape(c):
        b = O.bodies[c.liveId()]
        s = c.choice([Sphere(), Sphere(radius=c.real()), None, yade.Facet(), yade.Wall(), yade.Box(), 'x'])
        b.shape = s
        return 'body %d shape = %r' % (b.id, s)

    def setBody(c):
        b = O.bodies[c.liveId()]
        name = c.choice(['id', 'groupMask', 'mask', 'material', 'bound', 'clumpId', 'flags', 'dynamic', 'aspherical'])
        v = c.choice([c.id(), c.real(), None, O.materials[0], True])
        setattr(b, name, v)
        return 'body %d .%s = %r' % (b.id, name, v)

    def setDt(c):
        v = c.choice([NAN, INF, -1., 0., -0., 1e-300, 1e300, 'x', None, 1e-5, 2 ** 63])
        O.dt = v
        return 'O.dt = %r' % (v,)

    def setMaterial(c):
        m = c.choice([O.materials[0], O.bodies[c.liveId()].material])
        name = c.choice(['young', 'poisson', 'density', 'frictionAngle', 'id', 'label'])
        v = c.real()
        setattr(m, name, v)
        return 'material.%s = %r' % (name, v)

    def materials(c):
        what = c.choice(['append', 'get', 'set', 'index'])
        if what == 'append':
            v = c.choice([FrictMat(), None, 1, Sphere(), FrictMat(density=c.real())])
            return 'O.materials.append(%r) -> %r' % (v, O.materials.append(v))
        if what == 'get':
            return 'O.materials[%r]' % (c.id(),), O.materials[c.id()]
        if what == 'set':
            i = c.id()
            O.materials[i] = c.choice([FrictMat(), None, 'x'])
            return 'O.materials[%r] = ...' % (i,)
        return 'O.materials.index', O.materials.index(c.choice(['x', None, 3]))

    def forces(c):
        i, v = c.choice([c.liveId(), c.id()]), c.vector()
        what = c.choice(['addF', 'addT', 'f', 't', 'permF', 'addFperm'])
        if what == 'addF':
            O.forces.addF(i, v)
        elif what == 'addT':
            O.forces.addT(i, v)
        elif what == 'addFperm':
            O.forces.addF(i, v, permanent=True)
        else:
            getattr(O.forces, what)(i)
        return 'O.forces.%s(%r, %r)' % (what, i, v)

    def interactions(c):
        i, j = c.choice([c.liveId(), c.id()]), c.choice([c.liveId(), c.id()])
        what = c.choice(['get', 'get', 'erase', 'withBody', 'nth', 'iterate', 'clear', 'has'])
        if what == 'get':
            I = O.interactions[i, j]
            c.views.append(I)
            if I is not None:
                c.views += [I.geom, I.phys]
        elif what == 'erase':
            O.interactions.erase(i, j)
        elif what == 'withBody':
            O.interactions.withBody(i)
        elif what == 'nth':
            O.interactions.nth(i)
        elif what == 'iterate':
            for I in O.interactions:
                c.views.append(I)
                c.views.append(I.phys)
        elif what == 'clear':
            O.interactions.clear()
        else:
            O.interactions.has(i, j)
        return 'O.interactions %s(%r, %r)' % (what, i, j)

    def useView(c):
        """A view kept from an earlier call: its body may be erased, the scene reset."""
        v = c.view()
        if v is None:
            return 'no view'
        name = c.choice(['pos', 'vel', 'mass', 'radius', 'id', 'state', 'shape', 'geom', 'phys', 'normalForce',
                         'penetrationDepth', 'ori', 0, 1, 'sum', 'dict', 'str', 'young', 'isReal'])
        desc = 'view %s.%s' % (type(v).__name__, name)
        if name == 'dict' and hasattr(v, 'dict'):
            v.dict()
        elif name == 'str':
            str(v), repr(v)
        elif isinstance(name, int):
            if hasattr(v, '__getitem__'):
                x = v[name]
                if c.rng.random() < .5:
                    y = c.choice([1., NAN, 'x'])
                    v[name] = y
                    c.rawNonFinite |= y is NAN  # (an item of a view: written as it is, see rawNonFinite)
                    return desc + ' = %r, set to %r' % (x, y)
                return desc + ' = %r' % (x,)
        elif hasattr(v, name):
            x = getattr(v, name)
            if callable(x):
                x = x()
            if c.rng.random() < .5:
                setattr(v, name, c.choice([x, c.real(), c.vector()]))
                desc += ' set'
        return desc

    def arrays(c):
        a = O.bodies.arrays()
        c.views.append(a)
        col = c.choice(['pos', 'vel', 'angVel', 'mass', 'inertia', 'ori', 'force'])
        x = getattr(a, col)
        c.views.append(x)
        if c.rng.random() < .5 and len(x):
            v = c.choice([NAN, INF, 0., 1.])
            x[c.rng.randrange(len(x))] = v
            c.rawNonFinite |= not math.isfinite(v) or (col == 'ori' and v == 0)  # (a zero quaternion: NaN once normalized)
            return 'O.bodies.arrays().%s[...] = %r' % (col, v)
        return 'O.bodies.arrays().%s' % col

    def oldArray(c):
        """An array kept from an earlier call, used after its scene changed."""
        xs = [v for v in c.views if hasattr(v, 'shape') and hasattr(v, 'dtype')]
        if not xs:
            return 'no array'
        x = c.choice(xs)
        float(x.sum())
        if len(x) and c.rng.random() < .5:
            x[-1] = 1.
        return 'old array'

    def replaceEngines(c):
        """O.engines replaced, possibly during a background run."""
        running = c.rng.random() < .6
        new = c.choice([engines(), engines()[:2], [], [NewtonIntegrator()], [None], [1], [Sphere()],
                        engines() + [ForceEngine(ids=[c.id() if isinstance(c.id(), int) else 0], force=(0, 0, 1))],
                        engines() + [GravityEngine(gravity=(0, 0, -10))],
                        engines() + [TranslationEngine(ids=[c.liveId()], velocity=1, translationAxis=(1, 0, 0))],
                        engines() + [RotationEngine(ids=[c.liveId()], angularVelocity=1, rotationAxis=(0, 0, 1))],
                        engines() + [PyRunner(command='O.bodies.erase(%d)' % c.liveId(), iterPeriod=1)],
                        engines() + [PyRunner(command='O.engines = O.engines[:2]', iterPeriod=1)]])
        if running:
            O.run()
        try:
            O.engines = new
        finally:
            if running:
                O.pause()
        return 'O.engines = %d engines%s' % (len(new), ' during a run' if running else '')

    def engineIds(c):
        """Ids of a partial engine set to bad values, then a step."""
        e = c.choice([ForceEngine(force=(0, 0, 1)), TranslationEngine(velocity=1, translationAxis=(1, 0, 0)),
                      RotationEngine(angularVelocity=1, rotationAxis=(0, 0, 1))])
        ids = c.choice([[c.id()], [c.liveId(), c.id()], [], 'x', None, [NAN]])
        e.ids = ids
        O.engines = engines() + [e]
        O.step()
        return '%s.ids = %r; step' % (type(e).__name__, ids)

    def engineAttr(c):
        e = c.choice(O.engines) if len(O.engines) else None
        if e is None:
            return 'no engine'
        names = [k for k in e.dict() if k not in ('label',)]
        name = c.choice(names) if names else 'dead'
        v = c.choice([c.real(), c.vector(), [], None, [c.id()]])
        setattr(e, name, v)
        return '%s.%s = %r' % (type(e).__name__, name, v)

    def run(c):
        what = c.choice(['step', 'run', 'runwait', 'pause', 'wait', 'subStep'])
        if what == 'step':
            O.step()
        elif what == 'run':
            O.run(c.choice([1, 5, -1, 0, 2 ** 63, 'x']))
            O.pause()
        elif what == 'runwait':
            O.run(c.choice([1, 3]), True)
        elif what == 'pause':
            O.pause()
        elif what == 'wait':  # (O.wait() during a run without end waits for ever, as it should)
            O.run(2)
            O.wait()
        else:
            O.subStepping = True
            O.step()
            O.step()
            O.subStepping = False
        return 'O.' + what

    def resetOrReplace(c):
        what = c.choice(['reset', 'stringToScene', 'switchWorld', 'saveTmp', 'load'])
        if what == 'reset':
            O.reset()
        elif what == 'stringToScene':
            O.stringToScene(base)
        elif what == 'switchWorld':
            O.switchWorld()
            if c.rng.random() < .7:
                O.switchWorld()
        elif what == 'saveTmp':
            O.saveTmp('fuzz')
            O.loadTmp('fuzz')
        else:
            O.stringToScene(c.choice([b'', b'x', base[:len(base) // 2], None, 3]))
        return 'O.' + what

    def utilsCalls(c):
        what = c.choice(['sphere', 'facet', 'wall', 'box', 'PWaveTimeStep', 'aabbExtrema', 'kineticEnergy',
                         'unbalancedForce', 'sumForces'])
        if what == 'sphere':
            utils.sphere(c.vector(), c.real(), material=c.choice([0, -1, 5, 'x', None, FrictMat()]))
        elif what == 'facet':
            utils.facet(c.choice([[c.vector()] * 3, [c.vector()], None, 'abc']))
        elif what == 'wall':
            utils.wall(c.real(), axis=c.choice([0, 3, -1, NAN, 'y']), sense=c.choice([0, 1, -1, 2, 'x']))
        elif what == 'box':
            utils.box(c.vector(), c.vector())
        elif what == 'sumForces':
            utils.sumForces(c.choice([[c.id()], [], None]), c.vector())
        else:
            getattr(utils, what)()
        return 'utils.' + what

    def switchBodies(c):
        what = c.choice(['clear', 'replace', 'insertAtId', 'setitem', 'contains', 'iterate', 'len'])
        if what == 'clear':
            O.bodies.clear()
        elif what == 'replace':
            O.bodies.replace(c.choice([[utils.sphere((0, 0, 1), .1)], [], None, [None], [1]]))
        elif what == 'insertAtId':
            O.bodies.insertAtId(utils.sphere((0, 0, 1), .1), c.id())
        elif what == 'setitem':
            O.bodies[c.id()] = c.choice([utils.sphere((0, 0, 1), .1), None])
        elif what == 'contains':
            return 'in', c.id() in O.bodies
        elif what == 'iterate':
            for b in O.bodies:
                if b is not None:
                    b.state.pos
        else:
            len(O.bodies)
        return 'O.bodies.' + what

    CALLS = [appendSphere, appendOther, erase, erase, getBody, setState, setState, setState, replaceState, setShape,
             replaceShape, setBody, setDt, setMaterial, materials, forces, forces, interactions, interactions, useView,
             useView, useView, arrays, oldArray, replaceEngines, engineIds, engineAttr, run, run, resetOrReplace,
             utilsCalls, switchBodies]

    def finiteState():
        for b in O.bodies:
            if b is None or b.state is None:  # (state None, as the reference allows: the next step refuses it)
                continue
            s = b.state
            for name in ('pos', 'vel', 'angVel', 'ori'):
                v = getattr(s, name)
                if not all(math.isfinite(x) for x in v):
                    return 'body %d: state.%s = %s' % (b.id, name, tuple(v))
        return None

    verbose = '--verbose' in sys.argv

    def runOne(k):
        rng = random.Random('%d:%d' % (seed, k))
        c = Case(rng)
        calls = [rng.choice(CALLS) for _ in range(rng.randint(1, 8))]
        description = ' '.join(f.__name__ for f in calls)
        if describeOnly:
            return None, description, None
        O.pause()
        setNumThreads(1)
        O.resetAllScenes()  # (the other world of O.switchWorld too: nothing is left from the case before)
        O.stringToScene(base)
        O.subStepping = False
        done = []
        for f in calls:
            try:
                r = f(c)
                done.append(r if isinstance(r, str) else r[0] if isinstance(r, tuple) else f.__name__)
            except CLEAR as e:
                if not str(e) or str(e).startswith('Unable to cast'):  # (pybind11's message names neither value nor type)
                    O.pause()
                    return 'FAIL %s without a clear message' % type(e).__name__, description, \
                        ' | '.join(done + ['%s: %s' % (f.__name__, str(e)[:80])])
                done.append('%s: %s: %s' % (f.__name__, type(e).__name__, str(e)[:80]))
            except Exception as e:
                O.pause()
                return 'FAIL %s raised %s' % (f.__name__, type(e).__name__), description, str(e)[:300]
            if verbose:
                print('   ', done[-1], flush=True)
        O.pause()
        O.subStepping = False
        bad = finiteState()
        if bad and not c.rawNonFinite:
            return 'FAIL non-finite state after the calls', description, bad + ' | ' + ' | '.join(done)
        stepError = None
        try:
            for _ in range(STEPS):
                O.step()
        except Exception as e:
            stepError = e
        O.pause()
        if bad:  # written into an item of a view (unchecked): a step must notice it and stop
            if stepError is None:
                if not any(type(e).__name__ == 'NewtonIntegrator' for e in O.engines):
                    return 'view item made the state non-finite, no integrator to notice', description, bad
                return 'FAIL a non-finite state written into a view went unnoticed', description, \
                    finiteState() or bad + ' | ' + ' | '.join(done)
            if not isinstance(stepError, CLEAR) or not str(stepError):
                return 'FAIL step raised %s' % type(stepError).__name__, description, str(stepError)[:300]
            return 'view item made the state non-finite, step refused: %s' % type(stepError).__name__, description, \
                str(stepError)[:200]
        bad = finiteState()
        if bad:
            return 'FAIL non-finite state after the steps', description, bad + ' | ' + ' | '.join(done)
        if stepError is not None:
            if not isinstance(stepError, CLEAR) or not str(stepError):
                return 'FAIL step raised %s' % type(stepError).__name__, description, str(stepError)[:300]
            return 'ran, step refused: %s' % type(stepError).__name__, description, str(stepError)[:200]
        return 'ran', description, ''

    return runOne


if __name__ == '__main__':
    sys.exit(runner.main(os.path.abspath(__file__), 'fuzz_api', 1000, factory))
