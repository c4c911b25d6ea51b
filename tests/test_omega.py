"""O's remaining controls, as the manual and the reference name them: O.stopAtTime, O.speed,
O.subStepping / O.subStep, O.exitNoBacktrace, O.forceSyncCount, O.bodies.replace and
O.bodies.insertAtId.

Figures marked "reference" were printed by the reference (yade-double -n -x) on the same script."""

import json
import math
import os
import pathlib
import subprocess
import sys
import textwrap
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(), reason="yade is not built (run bash scripts/setup.sh)")


@pytest.fixture
def y(fresh_scene):
    import yade
    return yade


def falling_sphere(y, engines=None):
    O = y.O
    O.engines = engines or [y.ForceResetter(), y.InsertionSortCollider([y.Bo1_Sphere_Aabb()]),
                            y.InteractionLoop([y.Ig2_Sphere_Sphere_ScGeom()], [y.Ip2_FrictMat_FrictMat_FrictPhys()],
                                              [y.Law2_ScGeom_FrictPhys_CundallStrack()]),
                            y.NewtonIntegrator(gravity=(0, 0, -10))]
    O.bodies.append(y.utils.sphere((0, 0, 0), 1))
    O.dt = 1e-3


# ------------------------------------------------------------------ sub-stepping

def test_substepping_runs_one_engine_per_step(y):
    O = y.O
    falling_sphere(y)
    assert O.subStep == -1 and O.subStepping is False
    O.subStepping = True
    seen = []
    for i in range(7):
        O.step()
        seen.append((O.iter, O.subStep, O.time, O.bodies[0].state.pos[2]))
    # reference (4 engines): the step's start, the engines 0..3, the step's end
    assert [s[:2] for s in seen] == [(0, 0), (0, 1), (0, 2), (0, 3), (0, 4), (1, -1), (1, 0)]
    assert [s[2] for s in seen] == [0, 0, 0, 0, 0, 0.001, 0.001]
    # the integrator (engine 3) moves the sphere: 10 m/s² · 1 ms · (1 - damping 0.2) · 1 ms
    assert [s[3] for s in seen[:4]] == [0, 0, 0, 0]
    assert seen[4][3] == pytest.approx(-8e-6, rel=1e-12) and seen[6][3] == seen[4][3]


def test_step_finishes_a_step_begun_by_substeps(y):
    O = y.O
    falling_sphere(y)
    O.subStepping = True
    O.step()
    O.step()
    O.step()  # engines 0 and 1 have run
    O.subStepping = False
    assert O.subStep == 2  # (the reference keeps it too)
    O.step()  # the rest of that step only
    assert (O.iter, O.subStep, O.time) == (1, -1, 0.001)
    O.subStepping = True
    O.step()
    assert (O.iter, O.subStep) == (1, 0)
    O.run(3, True)  # (reference: iter 2 -> 5 from subStep 0) full steps, the first completing the begun one
    assert (O.iter, O.subStep) == (4, -1)
    assert O.time == pytest.approx(0.004)
    # same trajectory as plain steps: 4 steps of the damped integrator
    v, z = 0.0, 0.0
    for i in range(4):
        v += -10 * 1e-3 * 0.8
        z += v * 1e-3
    assert O.bodies[0].state.pos[2] == pytest.approx(z, rel=1e-12)


def test_substeps_run_each_engine_once_per_step(y):
    O = y.O
    calls = []
    y.__dict__['_substep_calls'] = calls
    falling_sphere(y, [y.ForceResetter(), y.PyRunner(command='import yade; yade._substep_calls.append(yade.O.iter)', iterPeriod=1, initRun=True),
                       y.NewtonIntegrator(gravity=(0, 0, -10))])
    O.subStepping = True
    for i in range(12):  # 3 engines: 5 parts a step (start, engines, end); 12 = 5 + 5 + 2
        O.step()
    assert O.iter == 2 and O.subStep == 1
    assert calls == [0, 1]
    O.step()
    assert calls == [0, 1, 2] and O.subStep == 2


# ------------------------------------------------------------------ stopAtTime

def test_stopAtTime_stops_the_run(y):
    O = y.O
    falling_sphere(y)
    assert O.stopAtTime == 0  # (reference default)
    O.stopAtTime = 0.0105
    O.run()
    O.wait()
    assert (O.iter, O.stopAtTime) == (11, -1)  # reference: 11, time 0.011, stopAtTime -1.0
    O.stopAtTime = 0.02
    O.run()
    O.wait()
    assert (O.iter, O.stopAtTime) == (20, -1)  # reference: 20
    assert O.time == pytest.approx(0.02)


def test_stopAtTime_and_stopAtIter_are_independent(y):
    O = y.O
    falling_sphere(y)
    O.stopAtTime = 0.0255
    O.stopAtIter = 40
    O.run()
    O.wait()
    assert (O.iter, O.stopAtTime, O.stopAtIter) == (26, -1, 40)  # stopAtIter is kept (reference)
    O.stopAtTime = 1
    O.run()
    O.wait()
    assert (O.iter, O.stopAtTime, O.stopAtIter) == (40, 1, -1)  # and stopAtTime when stopAtIter stops it


@pytest.mark.parametrize("value", [0, -1])
def test_stopAtTime_not_positive_never_stops(y, value):
    O = y.O
    falling_sphere(y)
    O.run(3, True)
    O.stopAtTime = value
    O.run(50, True)
    assert O.iter == 53 and O.stopAtTime == value


def test_stopAtTime_is_checked_after_each_step_of_a_run_only(y):
    O = y.O
    falling_sphere(y)
    O.stopAtTime = 0.005
    for i in range(20):
        O.step()  # O.step ignores it (reference: iter 40 past 0.025, stopAtTime kept)
    assert O.iter == 20 and O.stopAtTime == 0.005
    O.run()
    O.wait()  # already past: one step, then it stops (reference)
    assert O.iter == 21 and O.stopAtTime == -1
    with pytest.raises(ValueError):
        O.stopAtTime = float('nan')


def test_stopAtTime_is_saved(y, tmp_path):
    O = y.O
    falling_sphere(y)
    O.stopAtTime = 0.125
    O.save(str(tmp_path / "s.yade"))
    O.reset()
    assert O.stopAtTime == 0
    O.load(str(tmp_path / "s.yade"))
    assert O.stopAtTime == 0.125


# ------------------------------------------------------------------ speed

def test_speed_is_the_mean_rate_of_the_last_ten_steps(y):
    O = y.O
    falling_sphere(y)
    O.run(2000, True)
    assert O.speed > 1000  # steps of a few microseconds
    y.__dict__['_sleep'] = time.sleep
    y.__dict__['_sleepTime'] = 0.02
    O.engines = O.engines + [y.PyRunner(command='import yade; yade._sleep(yade._sleepTime)', iterPeriod=1)]
    O.run(10, True)
    assert 40 < O.speed <= 50.5  # ten steps of 20 ms (a little more when the machine is busy): 50 per second
    assert O.speed == O.speed  # (reading it does not change it)
    y._sleepTime = 0.04
    O.run(5, True)
    assert 30 < O.speed < 38  # five rates of 50, five of 25: 37.5
    O.run(5, True)
    assert 20 < O.speed <= 25.5  # ten of 25


# ------------------------------------------------------------------ forceSyncCount

def test_forceSyncCount_counts_and_can_be_set(y):
    O = y.O
    falling_sphere(y)
    O.bodies.append(y.utils.sphere((1.5, 0, 0), 1))  # overlapping: a contact adds forces every step
    O.forceSyncCount = 0
    O.run(5, True)
    n = O.forceSyncCount
    assert n >= 5
    O.forceSyncCount = 7
    assert O.forceSyncCount == 7


# ------------------------------------------------------------------ O.bodies.replace / insertAtId

def test_bodies_replace(y):
    O = y.O
    falling_sphere(y)
    O.bodies.append([y.utils.sphere((1.5, 0, 0), 1), y.utils.sphere((6, 0, 0), 1)])
    O.step()
    assert O.interactions.countReal() == 1
    old = O.bodies[0]
    new = [y.utils.sphere((0, 0, 10), 1), y.utils.sphere((0, 0, 20), 1)]
    assert O.bodies.replace(new) == [0, 1]  # reference: [0, 1]
    assert len(O.bodies) == 2 and [b.id for b in O.bodies] == [0, 1]
    assert O.bodies[1] is new[1] and O.bodies[1].state.pos[2] == 20
    assert old.id == -1
    assert len(O.interactions) == 0  # (the reference keeps the old bodies' interactions)
    O.step()
    assert O.bodies[0].state.pos[2] < 10
    assert O.bodies.replace([]) == [] and len(O.bodies) == 0  # reference: [] 0


def test_bodies_replace_refuses_bad_input_and_changes_nothing(y):
    O = y.O
    falling_sphere(y)
    kept = O.bodies[0]
    with pytest.raises(TypeError):
        O.bodies.replace(kept)  # a list is needed (reference: ArgumentError, a TypeError)
    with pytest.raises(TypeError):
        O.bodies.replace([1, 2])
    with pytest.raises(IndexError, match="already has id 0"):
        O.bodies.replace([kept, y.utils.sphere((1, 1, 1), 1)])  # (reference: IndexError, same text)
    b = y.utils.sphere((1, 1, 1), 1)
    with pytest.raises(IndexError):
        O.bodies.replace([b, b])
    assert len(O.bodies) == 1 and O.bodies[0] is kept and kept.id == 0 and b.id == -1


def test_bodies_insertAtId(y):
    O = y.O
    falling_sphere(y)
    O.bodies.append(y.utils.sphere((3, 0, 0), 1))
    O.bodies.erase(0)
    b = y.utils.sphere((9, 9, 9), 1)
    assert O.bodies.insertAtId(b, 0) == 0 and b.id == 0 and len(O.bodies) == 2  # reference: 0 0 2
    assert O.bodies[0] is b and O.bodies[0].state.pos == y.Vector3(9, 9, 9)
    c = y.utils.sphere((20, 0, 0), 1)
    assert O.bodies.insertAtId(c, 5) == 5 and len(O.bodies) == 6  # reference: 5 6, ids [0, 1, 5]
    assert [x.id for x in O.bodies] == [0, 1, 5]
    assert [O.bodies[i] is None for i in range(6)] == [False, False, True, True, True, False]
    assert O.bodies.insertAtId(y.utils.sphere((30, 0, 0), 1), 2) == 2
    assert [x.id for x in O.bodies] == [0, 1, 2, 5]
    d = y.utils.sphere((40, 0, 0), 1)
    assert O.bodies.append(d) == 6  # appending goes on after the last id
    O.run(3, True)  # the inserted bodies fall with the others
    assert O.bodies[5].state.pos[2] < 0 and O.bodies[5].state.vel[2] < 0
    assert len(O.forces.f(5)) == 3


def test_bodies_insertAtId_refuses_bad_input(y):
    O = y.O
    falling_sphere(y)
    n = len(O.bodies)
    with pytest.raises(IndexError, match="taken"):
        O.bodies.insertAtId(y.utils.sphere((1, 1, 1), 1), 0)  # (reference: logs an error, returns -1)
    with pytest.raises(IndexError):
        O.bodies.insertAtId(y.utils.sphere((1, 1, 1), 1), -1)  # (reference: crashes)
    with pytest.raises(IndexError, match="already has id"):
        O.bodies.insertAtId(O.bodies[0], 3)  # (reference: the body is then in the container twice)
    with pytest.raises((ValueError, IndexError)):
        O.bodies.insertAtId(y.utils.sphere((1, 1, 1), 1), 1 << 30)
    assert len(O.bodies) == n


# ------------------------------------------------------------------ exitNoBacktrace

def run_script(tmp_path, body, timeout=60):
    script = tmp_path / "s.py"
    script.write_text(textwrap.dedent(body))
    env = dict(os.environ, YADE_BUILD_DIR=str(BUILD))
    t = time.time()
    r = subprocess.run([sys.executable, str(LAUNCHER), "-n", "-x", str(script)], capture_output=True, text=True,
                       timeout=timeout, env=env, cwd=str(tmp_path))
    return r, time.time() - t


def test_exitNoBacktrace(tmp_path):
    r, _ = run_script(tmp_path, """
        import atexit, sys
        atexit.register(lambda: print('ATEXIT'))
        print('before')
        sys.stderr.write('err\\n')
        O.exitNoBacktrace(3)
        print('after')
    """)
    # reference: status 3, 'before' and 'err' written (also to a file), nothing after, no atexit
    assert r.returncode == 3
    assert "before" in r.stdout and "err" in r.stderr
    assert "after" not in r.stdout and "ATEXIT" not in r.stdout


def test_exitNoBacktrace_while_running(tmp_path):
    r, took = run_script(tmp_path, """
        O.engines = [ForceResetter(), NewtonIntegrator()]
        O.bodies.append(sphere((0, 0, 0), 1))
        O.run()
        O.exitNoBacktrace()
    """)
    assert r.returncode == 0  # (the reference hangs here)
    assert took < 30


# ------------------------------------------------------------------ the reference's other O methods

def test_labeledEngine_runEngine_dynDtAvailable(y):
    O = y.O
    falling_sphere(y, [y.ForceResetter(), y.NewtonIntegrator(gravity=(0, 0, -10), label='nn')])
    assert O.labeledEngine('nn') is O.engines[1]
    with pytest.raises(ValueError, match="No engine labeled"):
        O.labeledEngine('zz')  # (reference: ValueError, same text)
    O.runEngine(O.engines[1])  # reference: O.iter 0, vel (0, 0, -0.008)
    assert O.iter == 0 and O.time == 0
    assert O.bodies[0].state.vel[2] == pytest.approx(-0.008, rel=1e-12)
    assert O.dynDtAvailable is False
    O.engines = O.engines + [y.GlobalStiffnessTimeStepper()]
    assert O.dynDtAvailable is True


def test_scene_strings_and_tmp(y, tmp_path):
    O = y.O
    falling_sphere(y)
    O.run(3, True)
    data = O.sceneToString()
    O.saveTmp('a')
    O.run(2, True)
    O.stringToScene(data)
    assert O.iter == 3 and len(O.bodies) == 1
    xml = O.tmpToString('a')
    assert xml.lstrip().startswith('<') and 'iter="3"' in xml
    f = tmp_path / 'a.xml'
    O.tmpToFile(str(f), 'a')
    O.reset()
    O.load(str(f))
    assert O.iter == 3
    name = O.tmpFilename()
    assert name != O.tmpFilename() and os.path.isdir(os.path.dirname(name))


def test_scene_switching_names(y):
    O = y.O
    assert O.thisScene == 0
    O.bodies.append(y.utils.sphere((0, 0, 0), 1))
    O.switchScene()
    assert O.thisScene == 1 and len(O.bodies) == 0
    O.bodies.append(y.utils.sphere((0, 0, 0), 1))
    O.switchScene()
    O.resetThisScene()
    assert O.thisScene == 0 and len(O.bodies) == 0
    O.switchScene()
    assert len(O.bodies) == 1
    O.resetAllScenes()
    assert O.thisScene == 1 and len(O.bodies) == 0
    O.switchScene()


def test_subStep_inside_a_whole_step_and_engine_lists(y):
    # (as the reference's regression test core.py TestLoop: O.subStep reads 0 inside a whole step)
    O = y.O
    seen = []
    y.__dict__['_seen_substeps'] = seen
    falling_sphere(y, [y.PyRunner(command='import yade; yade._seen_substeps.append(yade.O.subStep)', iterPeriod=1, initRun=True)])
    O.step()
    O.run(2, True)
    assert seen == [0, 0, 0] and O.subStep == -1
    # O.engines assigned inside a step: _nextEngines until the step ends, _currEngines after
    O.engines = [y.PyRunner(command='import yade; yade.O.engines = [yade.ForceResetter()] * 3', iterPeriod=1, initRun=True),
                 y.ForceResetter()]
    O.subStepping = True
    O.step()
    O.step()
    assert O.subStep == 1 and len(O.engines) == 3 and len(O._nextEngines) == 3 and len(O._currEngines) == 2
    O.step()
    O.step()
    assert O.subStep == -1
    O.step()
    assert O.subStep == 0 and len(O._nextEngines) == 0 and len(O._currEngines) == 3
    O.saveTmp(quiet=True)  # (accepted, as the reference's tests call it)
    O.loadTmp(quiet=True)


def test_memory_slots_as_file_names(y):
    # reference: O.filename ':memory:x' after O.saveTmp('x') or O.loadTmp('x'), ':memory:' for the
    # default slot; O.reload() then reloads the slot
    O = y.O
    falling_sphere(y)
    O.saveTmp('x')
    assert O.filename == ':memory:x'
    O.step()
    O.reload(quiet=True)
    assert O.iter == 0 and O.filename == ':memory:x'
    O.saveTmp()
    assert O.filename == ':memory:'
    O.step()
    O.load(':memory:x')
    assert O.iter == 0


def test_dyndt_can_be_set_as_in_the_reference(fresh_scene):
    # yade-double -n -x: O.dynDt = False without a time stepper is accepted, True raises; with one it
    # switches the stepper's `active`
    from yade import O, ForceResetter, NewtonIntegrator, GlobalStiffnessTimeStepper
    O.engines = [ForceResetter(), NewtonIntegrator()]
    O.dynDt = False
    assert O.dynDt is False
    with pytest.raises(RuntimeError, match='No TimeStepper found in O.engines'):
        O.dynDt = True
    O.engines = [ForceResetter(), GlobalStiffnessTimeStepper(), NewtonIntegrator()]
    O.dynDt = True
    assert O.dynDt is True and O.engines[1].active
    O.dynDt = False
    assert O.dynDt is False and not O.engines[1].active



def test_time_stepper_base_class_as_in_the_reference(fresh_scene):
    # yade-double -n -x: TimeStepper (a GlobalEngine) is GlobalStiffnessTimeStepper's base, with
    # active=True and timeStepUpdateInterval=1; run bare, the reference aborts the process
    # ("terminate called without an active exception"): here a clear error stops the run
    from yade import O, TimeStepper, GlobalEngine, GlobalStiffnessTimeStepper, ForceResetter, NewtonIntegrator
    assert TimeStepper.__bases__ == (GlobalEngine,) and GlobalStiffnessTimeStepper.__bases__ == (TimeStepper,)
    t = TimeStepper()
    assert t.active is True and t.timeStepUpdateInterval == 1
    g = GlobalStiffnessTimeStepper(timeStepUpdateInterval=7, active=False)
    assert isinstance(g, TimeStepper) and g.timeStepUpdateInterval == 7 and not g.active
    O.engines = [ForceResetter(), t, NewtonIntegrator()]
    O.dt = 1e-3
    with pytest.raises(RuntimeError, match='TimeStepper is the base class'):
        O.run(1, True)
    assert O.iter == 0
    # O.dt < 0 and O.dynDt find any time stepper, the base class included
    t.active = False
    O.dt = -1
    assert t.active and O.dt == 1e-3 and O.dynDt

# ------------------------------------------------------------------ O.forces during a background run

def test_forces_read_and_added_while_running_in_the_background(y):
    """O.forces.f/t/addF/permF from the main thread while O.run() runs: each call waits for the end of
    a step (no data race with the loop's threads, which ThreadSanitizer checks in the tsan stage) and
    the run goes on; a permanent force added then acts from the next step on."""
    O = y.O
    falling_sphere(y, [y.ForceResetter(), y.NewtonIntegrator(gravity=(0, 0, 0), damping=0)])
    O.bodies.append(y.utils.sphere((5, 0, 0), 1))
    m = O.bodies[0].state.mass
    O.run()
    try:
        seen = [tuple(O.forces.f(0)) + tuple(O.forces.t(1)) for _ in range(200)]
        assert O.running
        before = O.iter
        O.forces.addF(0, (m, 0, 0), permanent=True)  # an acceleration of 1 m/s² from the next step
        it0 = O.iter  # (the run goes on meanwhile: steps may pass between the two reads, many of them when slowed by a sanitizer)
        assert tuple(O.forces.permF(0)) == (m, 0, 0)
        while O.iter < it0 + 50:
            O.forces.f(1)
            time.sleep(0.001)
    finally:
        O.pause()
    assert set(seen) == {(0, 0, 0, 0, 0, 0)}
    # the force acted in a whole number of steps: those after it was added (one of them may already have begun)
    v = O.bodies[0].state.vel[0]
    assert any(v == pytest.approx(k * O.dt, rel=1e-12) for k in range(O.iter - it0 - 1, O.iter - before + 1))
    assert O.bodies[1].state.vel == y.Vector3(0, 0, 0)


# ------------------------------------------------------------------ the engines at start-up

def test_default_engines_at_start_up(tmp_path):
    """A script starts with the reference's default engines (its simple-scene-default-engines.py example
    sets typedEngine('NewtonIntegrator').gravity and appends bodies without setting O.engines); O.reset()
    empties the list. The figures after 11 steps are the reference's run of the same lines: two default
    spheres of radius 1 overlapping by 0.1 fly apart at 4.41 m/s (the step differs by 0.27 %: the reference
    uses 1.41044 for the manual's sqrt(2) in eq. 3.5.18, doc/compatibility.md)."""
    r, _ = run_script(tmp_path, """
        import json
        names = [e.__class__.__name__ for e in O.engines]
        labels = [e.label for e in O.engines]
        il = O.engines[2]
        res = dict(names=names, labels=labels, dynDt=O.dynDt, dt0=O.dt, damping=newton.damping,
                   bo1=[f.__class__.__name__ for f in collider.boundDispatcher.functors],
                   ig2=[f.__class__.__name__ for f in il.geomDispatcher.functors],
                   ip2=[f.__class__.__name__ for f in il.physDispatcher.functors],
                   law=[f.__class__.__name__ for f in il.lawDispatcher.functors],
                   interval=timeStepper.timeStepUpdateInterval, coeff=timeStepper.timestepSafetyCoefficient,
                   typed=typedEngine('NewtonIntegrator') is newton)
        O.bodies.append(sphere((0, 0, 0), 1)); O.bodies.append(sphere((0, 0, 1.9), 1))
        O.run(11, True)
        res.update(dt=O.dt, z=O.bodies[1].state.pos[2], vz=O.bodies[1].state.vel[2], contacts=O.interactions.countReal())
        O.reset()
        res.update(afterReset=len(O.engines))
        print('RES', json.dumps(res))
    """)
    assert r.returncode == 0, r.stderr[-2000:]
    res = json.loads(r.stdout.split('RES ', 1)[1])
    assert res['names'] == ['ForceResetter', 'InsertionSortCollider', 'InteractionLoop', 'GlobalStiffnessTimeStepper', 'NewtonIntegrator']
    assert res['labels'] == ['', 'collider', 'interactionLoop', 'timeStepper', 'newton']
    assert res['dynDt'] is True and res['dt0'] == 1e-8 and res['damping'] == 0.2 and res['typed']
    assert res['bo1'] == ['Bo1_Sphere_Aabb', 'Bo1_Facet_Aabb', 'Bo1_Box_Aabb']
    assert res['ig2'] == ['Ig2_Sphere_Sphere_ScGeom', 'Ig2_Facet_Sphere_ScGeom', 'Ig2_Box_Sphere_ScGeom']
    assert res['ip2'] == ['Ip2_FrictMat_FrictMat_FrictPhys'] and res['law'] == ['Law2_ScGeom_FrictPhys_CundallStrack']
    assert (res['interval'], res['coeff']) == (10, 0.8)
    # the reference: dt 0.0230934547513, z 3.0204, vz 4.41052; here sqrt(2) for its 1.41044
    assert res['dt'] == pytest.approx(0.0230934547513 * 2 ** 0.5 / 1.41044, rel=1e-9)
    assert res['contacts'] == 0 and res['vz'] == pytest.approx(4.41052, rel=5e-3)
    assert res['z'] == pytest.approx(3.0204, rel=1e-2)
    assert res['afterReset'] == 0
