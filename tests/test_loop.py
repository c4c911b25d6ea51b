"""The simulation loop: O.run / O.pause / O.wait / O.step / O.stopAtIter, dead engines, labels,
O.engines checks, PeriodicEngine and the bounds computed by BoundDispatcher."""
import builtins
import math
import time

import pytest

from yade import *  # noqa: F401,F403
from yade import (O, Aabb, Body, Bo1_Sphere_Aabb, BoundDispatcher, ForceResetter, FrictMat, PeriodicEngine,
                  Sphere, Vector3)
from yade.utils import sphere


@pytest.fixture(autouse=True)
def fresh_scene():
    O.pause()
    O.reset()
    yield
    O.pause()  # never leave a background run behind
    assert not O.running


def vec(v):
    return tuple(float(x) for x in v)


def wait_until(cond, timeout=10.):
    t0 = time.time()
    while not cond():
        if time.time() - t0 > timeout:
            return False
        time.sleep(.001)
    return True


def busy_scene(n=2000):
    """Bodies and engines so that a step takes some time."""
    O.bodies.append([sphere((i, 0, 0), .4) for i in range(n)])
    O.engines = [ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb()])]


# ------------------------------------------------------------------ run / pause / wait

def test_run_returns_at_once_and_runs_in_the_background():
    busy_scene()
    t0 = time.time()
    O.run()
    elapsed = time.time() - t0
    assert O.running is True
    assert elapsed < 1.
    assert wait_until(lambda: O.iter > 3)
    assert O.running is True
    O.pause()


def test_pause_stops_the_loop():
    busy_scene()
    O.run()
    assert wait_until(lambda: O.iter > 0)
    O.pause()
    assert O.running is False
    it = O.iter
    time.sleep(.1)
    assert O.iter == it


def test_run_can_be_resumed_after_pause():
    busy_scene(100)
    O.run()
    assert wait_until(lambda: O.iter > 0)
    O.pause()
    it = O.iter
    O.run()
    assert wait_until(lambda: O.iter > it + 2)
    O.pause()
    assert O.running is False


def test_run_with_wait_advances_exactly_n_steps():
    busy_scene(100)
    O.run(100, True)
    assert O.iter == 100
    assert O.running is False
    assert O.time == pytest.approx(100 * O.dt, rel=1e-12)


def test_run_with_wait_keyword():
    O.engines = [ForceResetter()]
    O.dt = 1e-3
    O.run(nSteps=20, wait=True)
    assert O.iter == 20
    assert O.time == pytest.approx(.02, rel=1e-12)


def test_run_n_then_wait_advances_exactly_n_steps():
    busy_scene(100)
    O.run(50)
    O.wait()
    assert O.iter == 50
    assert O.running is False


def test_run_n_counts_from_the_current_iteration():
    O.engines = [ForceResetter()]
    for _ in range(7):
        O.step()
    O.run(50)
    O.wait()
    assert O.iter == 57


def test_consecutive_runs_add_up():
    O.engines = [ForceResetter()]
    O.run(10, True)
    O.run(15, True)
    assert O.iter == 25


def test_stop_at_iter_stops_the_loop():
    busy_scene(100)
    O.run(10, True)
    O.stopAtIter = O.iter + 30
    O.run()
    O.wait()
    assert O.iter == 40
    assert O.running is False


def test_wait_returns_at_once_when_not_running():
    t0 = time.time()
    O.wait()
    assert time.time() - t0 < 1.
    assert O.iter == 0


def test_pause_when_not_running_does_nothing():
    O.pause()
    assert O.running is False and O.iter == 0


def test_run_without_engines_advances_time():
    O.dt = .5
    O.run(4, True)
    assert O.iter == 4
    assert O.time == pytest.approx(2.)


# ------------------------------------------------------------------ step

def test_step_advances_one_iteration_and_dt():
    O.dt = 1e-4
    O.engines = [ForceResetter()]
    O.step()
    assert O.iter == 1
    assert O.time == pytest.approx(1e-4)
    O.step()
    assert O.iter == 2
    assert O.time == pytest.approx(2e-4)


def test_step_while_running_raises_runtime_error():
    busy_scene()
    O.run()
    assert O.running
    with pytest.raises(RuntimeError):
        O.step()
    O.pause()
    it = O.iter
    O.step()
    assert O.iter == it + 1


def test_switch_world_while_running_raises_runtime_error():
    busy_scene(200)
    O.run()
    with pytest.raises(RuntimeError):
        O.switchWorld()
    assert O.running
    O.pause()
    assert len(O.bodies) == 200


def test_reset_while_running_stops_the_loop_and_resets():
    busy_scene(200)
    O.run()
    try:
        O.reset()
    finally:
        O.pause()
    assert O.running is False
    assert O.iter == 0 and len(O.bodies) == 0 and list(O.engines) == []


def test_stop_at_iter_is_cleared_once_reached():
    O.engines = [ForceResetter()]
    O.run(50, True)
    assert O.iter == 50
    assert O.stopAtIter == -1


def test_stop_at_iter_defaults_to_zero():
    assert O.stopAtIter == 0


# ------------------------------------------------------------------ dead engines

def test_dead_bound_dispatcher_is_skipped():
    O.bodies.append(sphere((1, 2, 3), .5))
    O.engines = [ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb()], dead=True)]
    O.step()
    b = O.bodies[0]
    assert b.bound is None or all(math.isnan(x) for x in b.bound.min)
    assert O.iter == 1


def test_dead_engine_runs_again_when_revived():
    O.bodies.append(sphere((1, 2, 3), .5))
    bd = BoundDispatcher([Bo1_Sphere_Aabb()], dead=True)
    O.engines = [bd]
    O.step()
    bd.dead = False
    O.step()
    assert vec(O.bodies[0].bound.min) == (.5, 1.5, 2.5)


def test_dead_force_resetter_leaves_forces():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.engines = [ForceResetter(dead=True)]
    O.forces.addF(0, (1, 2, 3))
    O.step()
    assert vec(O.forces.f(0)) == (1, 2, 3)


# ------------------------------------------------------------------ O.engines and labels

def test_engines_are_kept_in_order_and_are_the_same_objects():
    fr, bd = ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb()])
    O.engines = [fr, bd]
    assert len(O.engines) == 2
    assert O.engines[0] is fr and O.engines[1] is bd


def test_engine_label_becomes_a_name():
    O.engines = [ForceResetter(label='fr')]
    assert builtins.fr is O.engines[0]
    assert fr is O.engines[0]  # noqa: F821  (injected into builtins)
    assert fr.label == 'fr'  # noqa: F821


def test_functor_labels_inside_a_dispatcher_are_injected():
    O.engines = [ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb(label='myBo1')], label='myBd')]
    assert myBd is O.engines[1]  # noqa: F821
    assert myBo1 is O.engines[1].functors[0]  # noqa: F821
    assert isinstance(myBo1, Bo1_Sphere_Aabb)  # noqa: F821


def test_label_refers_to_the_engine_of_the_latest_assignment():
    O.engines = [ForceResetter(label='relabeled')]
    first = O.engines[0]
    O.engines = [ForceResetter(label='relabeled')]
    assert builtins.relabeled is O.engines[0]
    assert builtins.relabeled is not first


def test_non_engine_in_engines_raises_type_error():
    O.engines = [ForceResetter()]
    before = O.engines[0]
    with pytest.raises(TypeError):
        O.engines = [1]
    with pytest.raises(TypeError):
        O.engines = [ForceResetter(), FrictMat()]
    with pytest.raises(TypeError):
        O.engines = [ForceResetter(), None]
    with pytest.raises(TypeError):
        O.engines = ForceResetter()
    assert len(O.engines) == 1 and O.engines[0] is before


def test_empty_engine_list():
    O.engines = [ForceResetter()]
    O.engines = []
    assert list(O.engines) == []


# ------------------------------------------------------------------ PeriodicEngine

def test_periodic_engine_defaults():
    pe = PeriodicEngine()
    assert pe.iterPeriod == 0
    assert pe.nDo == -1
    assert pe.initRun is False
    assert pe.nDone == 0


def run_periodic(before, n, **kw):
    """Runs `before` steps, then adds a PeriodicEngine(**kw) and runs n more steps."""
    O.engines = [ForceResetter()]
    if before:
        O.run(before, True)
    pe = PeriodicEngine(**kw)
    O.engines = [pe]
    O.run(n, True)
    return pe


def test_periodic_engine_runs_every_iter_period():
    # Yade (PyRunner, same PeriodicEngine base): runs at iterations 10 and 20 of 0..29
    pe = run_periodic(0, 30, iterPeriod=10)
    assert pe.iterLast == 20


def test_periodic_engine_with_init_run_runs_when_first_reached():
    # Yade: first reached at iteration 5, runs at 5, 15, 25
    pe = run_periodic(5, 30, iterPeriod=10, initRun=True)
    assert pe.iterLast == 25
    assert pe.nDone == 3


def test_periodic_engine_runs_at_most_n_do_times():
    pe = run_periodic(0, 30, iterPeriod=10, initRun=True, nDo=1)
    assert pe.nDone == 1
    assert pe.iterLast == 0


def test_periodic_engine_due_when_first_reached_runs_at_once():
    # Yade: added at iteration 15 with iterPeriod 10, runs at 15, 25, 35
    pe = run_periodic(15, 30, iterPeriod=10)
    assert pe.iterLast == 35
    assert pe.nDone == 3


def test_periodic_engine_added_later_counts_its_period_from_when_it_is_first_reached():
    pe = run_periodic(5, 30, iterPeriod=10)
    assert pe.iterLast == 25


def test_periodic_engine_runs_first_at_first_iter_run():
    pe = run_periodic(0, 30, iterPeriod=10, firstIterRun=5)
    assert pe.iterLast == 25
    assert pe.nDone == 3


def test_periodic_engine_does_not_run_before_first_iter_run():
    pe = run_periodic(0, 4, iterPeriod=1, firstIterRun=5)
    assert pe.nDone == 0


def test_dead_periodic_engine_does_not_count():
    pe = run_periodic(0, 30, iterPeriod=1, dead=True)
    assert pe.nDone == 0


# ------------------------------------------------------------------ BoundDispatcher

def test_bound_dispatcher_computes_aabb_of_spheres_after_one_step():
    O.bodies.append([sphere((1, 2, 3), .5), sphere((-4, 0, 10), 2)])
    O.engines = [ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb()])]
    O.step()
    b0, b1 = O.bodies[0], O.bodies[1]
    assert isinstance(b0.bound, Aabb)
    assert vec(b0.bound.min) == (.5, 1.5, 2.5)
    assert vec(b0.bound.max) == (1.5, 2.5, 3.5)
    assert vec(b1.bound.min) == (-6, -2, 8)
    assert vec(b1.bound.max) == (-2, 2, 12)


def test_bounds_follow_the_body_at_the_next_step():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.engines = [BoundDispatcher([Bo1_Sphere_Aabb()])]
    O.step()
    O.bodies[0].state.pos = (10, 0, 0)
    assert vec(O.bodies[0].bound.min) == (-1, -1, -1)
    O.step()
    assert vec(O.bodies[0].bound.min) == (9, -1, -1)
    assert vec(O.bodies[0].bound.max) == (11, 1, 1)


def test_bound_dispatcher_creates_a_missing_bound():
    b = Body(shape=Sphere(radius=2), material=FrictMat())
    b.state.pos = (1, 1, 1)
    O.bodies.append(b)
    assert b.bound is None
    O.engines = [BoundDispatcher([Bo1_Sphere_Aabb()])]
    O.step()
    assert isinstance(b.bound, Aabb)
    assert vec(b.bound.min) == (-1, -1, -1) and vec(b.bound.max) == (3, 3, 3)


def test_aabb_enlarge_factor_scales_the_box():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.engines = [BoundDispatcher([Bo1_Sphere_Aabb(aabbEnlargeFactor=1.5)])]
    O.step()
    assert vec(O.bodies[0].bound.min) == (-1.5, -1.5, -1.5)
    assert vec(O.bodies[0].bound.max) == (1.5, 1.5, 1.5)


def test_body_without_shape_is_skipped_by_bound_dispatcher():
    O.bodies.append([Body(), sphere((0, 0, 0), 1)])
    O.engines = [BoundDispatcher([Bo1_Sphere_Aabb()])]
    O.step()
    assert O.bodies[0].bound is None
    assert vec(O.bodies[1].bound.min) == (-1, -1, -1)


def test_bound_dispatcher_without_functors_leaves_bounds_unset():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.engines = [BoundDispatcher()]
    O.step()
    b = O.bodies[0]
    assert b.bound is None or all(math.isnan(x) for x in b.bound.min)


def test_erased_bodies_are_skipped_by_the_loop():
    O.bodies.append([sphere((0, 0, 0), 1), sphere((5, 0, 0), 1)])
    O.bodies.erase(0)
    O.engines = [ForceResetter(), BoundDispatcher([Bo1_Sphere_Aabb()])]
    O.run(3, True)
    assert O.iter == 3
    assert vec(O.bodies[1].bound.min) == (4, -1, -1)


def test_bounds_of_a_background_run():
    busy_scene(500)
    O.run(5, True)
    for i in (0, 250, 499):
        assert vec(O.bodies[i].bound.min) == (i - .4, -.4, -.4)


def test_timing_counts_each_engine_run_only_when_enabled():
    import io
    from yade import timing
    O.bodies.append([sphere((0, 0, 0), .1), sphere((0, 0, .25), .1)])
    import yade
    O.engines = [ForceResetter(), yade.InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 yade.NewtonIntegrator(gravity=(0, 0, -10), label='newton')]
    O.timingEnabled = False
    O.run(5, True)
    assert [e.execCount for e in O.engines] == [0, 0, 0] and [e.execTime for e in O.engines] == [0, 0, 0]
    try:
        O.timingEnabled = True
        O.run(7, True)
        assert [e.execCount for e in O.engines] == [7, 7, 7]
        assert all(e.execTime > 0 for e in O.engines)
        out = io.StringIO()
        rows = timing.stats(out)
        assert [r[0] for r in rows] == ['ForceResetter', 'InsertionSortCollider', 'newton']
        assert 'TOTAL' in out.getvalue() and 'newton' in out.getvalue()
        assert timing.runtime() == sum(e.execTime for e in O.engines) == sum(r[2] for r in rows) > 0
        timing.reset()
        assert [e.execCount for e in O.engines] == [0, 0, 0] and timing.runtime() == 0
    finally:
        O.timingEnabled = False
