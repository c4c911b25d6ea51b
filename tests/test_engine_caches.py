"""Data the engines keep from step to step (the integrator's contiguous positions, the collider's
boxes, the interaction loop's radii) must follow every change made from Python between steps:
attribute setters, in-place changes through vector views, new or erased bodies, and changes made
from a PyRunner inside a run. Each test compares with what a fresh scene does with the same state.
"""
import pytest

from yade import *  # noqa: F401,F403
from yade import O, Vector3
from yade.utils import sphere, wall


pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def makeScene(gap=0.05, pyRunner=None):
    """Two spheres of radius 0.01 on the x axis, `gap` apart, no gravity; a third far away."""
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((0, 0, 0), .01), sphere((0.02 + gap, 0, 0), .01), sphere((1, 1, 1), .01)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)] + ([pyRunner] if pyRunner else [])
    O.dt = 1e-6
    O.run(20, True)  # several steps: the caches are filled and in use
    assert not O.interactions.has(0, 1) or not O.interactions[0, 1].isReal


def touching():
    return O.interactions.has(0, 1) and O.interactions[0, 1].isReal


def test_teleport_by_setter_is_seen_by_collider_and_loop():
    makeScene()
    O.bodies[1].state.pos = (0.019, 0, 0)  # overlapping body 0 now
    O.step()
    assert touching()
    assert O.forces.f(0)[0] < 0  # pushed apart


def test_an_item_written_into_a_copy_of_pos_moves_nothing_as_in_the_reference():
    makeScene()
    O.bodies[1].state.pos[0] = 0.019  # State.pos is read as a copy there and here: the body stays
    O.step()
    assert not touching()


def test_in_place_operator_on_pos_is_seen():
    makeScene()
    O.bodies[1].state.pos -= Vector3(0.051, 0, 0)  # (read, subtract, assign)
    O.step()
    assert touching()


def test_teleport_through_the_positions_array_is_seen():
    import numpy as np
    makeScene()
    np.asarray(O.bodies.arrays().pos)[1, 0] = 0.019  # in place, through a writable view of the column
    O.step()
    assert touching()


def test_radius_change_is_seen_by_the_fast_path():
    makeScene(gap=0.005)
    O.bodies[1].shape.radius = 0.02  # now reaches body 0 (gap 0.005 < 0.01 more radius)
    O.step()
    assert touching()


def test_change_made_by_a_pyrunner_inside_a_run_is_seen():
    runner = PyRunner(command='import yade\nif yade.O.iter == 30: yade.O.bodies[1].state.pos = (0.019, 0, 0)', iterPeriod=1)
    makeScene(pyRunner=runner)
    O.run(15, True)  # the runner moves body 1 at step 30 (after the integrator), the next step sees it
    assert touching()


def test_new_body_overlapping_is_seen():
    makeScene()
    O.bodies.append(sphere((0, 0.019, 0), .01))
    O.step()
    assert O.interactions.has(0, 3) and O.interactions[0, 3].isReal


def test_positions_of_the_integrator_match_the_states():
    """The contiguous copy the collider uses is the integrator's own result: after many steps
    with motion, the collider ran when needed (the moving sphere hits the resting one)."""
    makeScene(gap=0.05)
    O.bodies[1].state.vel = (-5, 0, 0)  # 0.05 m at 5 m/s: contact after 10 000 steps of 1e-6 s
    O.run(10500, True)
    assert touching() or O.bodies[1].state.vel[0] > 0  # in contact, or already bounced back
    assert O.bodies[0].state.vel[0] < 0  # body 0 was pushed


def test_engines_reused_in_a_new_scene_start_afresh():
    """The same engine objects after O.reset(), in a scene built the same way (same counters) but
    with bigger spheres: their cached radii, boxes and thread lists are not reused."""
    makeScene(gap=0.05)
    engines = O.engines
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((0, 0, 0), .04), sphere((0.07, 0, 0), .04), sphere((1, 1, 1), .01)])  # overlapping
    O.engines = engines
    O.dt = 1e-6
    O.step()
    assert touching()


def test_a_move_between_the_collider_and_the_integrator_is_seen():
    """A PyRunner placed after the collider moves body 1 onto body 0: the integrator's step then
    starts from other positions than its last ones, and the collider must look at the bodies at
    the next step (not trust the integrator's bound on how far they went)."""
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((0, 0, 0), .01), sphere((0.07, 0, 0), .01), sphere((1, 1, 1), .01)])
    runner = PyRunner(command='import yade\nif yade.O.iter == 30: yade.O.bodies[1].state.pos = (0.019, 0, 0)', iterPeriod=1)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), runner,
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.run(32, True)
    assert touching()


def countRunsExactly(x0, v, dt, sweep, steps):
    """Collider runs of a body moving along x at constant speed: whenever it is farther than the
    sweep from where the bounds were made (the arithmetic of the integrator, pos + vel·dt)."""
    runs, ref, x = 1, x0, x0  # the first step builds the lists
    for _ in range(steps - 1):
        x = x + v * dt
        if (x - ref) ** 2 > sweep ** 2:
            runs, ref = runs + 1, x
    return runs


@pytest.mark.parametrize("threads", [1, 2])
def test_collider_reruns_exactly_when_a_body_moved_beyond_the_sweep(threads):
    """The collider skips its per-body check while the integrator's bound (the fastest body's
    |v|·dt, summed) is below the sweep: it must still rerun at the very step a body has moved
    farther than the sweep, never later."""
    setNumThreads(threads)
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((0, 0, 0), .01), sphere((0.5, 0, 0), .01), sphere((1, 1, 1), .01)])
    O.bodies[1].state.vel = (3.7, 0, 0)
    O.bodies[2].state.vel = (0, -1.3, 0)  # slower: the bound follows the fastest body
    collider = InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=1e-4)
    O.engines = [ForceResetter(), collider,
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    for steps in (1, 27, 28, 29, 500, 1000):  # runs about every 27 steps
        O.run(steps - O.iter, True) if steps > O.iter else None
        assert collider.numAction == countRunsExactly(0.5, 3.7, 1e-6, 1e-4, steps), steps
    assert collider.numAction > 30


@pytest.mark.parametrize("threads", [1, 2])
def test_potential_interactions_are_the_overlapping_bounds(threads):
    """After many collider runs in a settling packing, O.interactions holds exactly the pairs of
    bodies that may collide and whose bounds overlap, plus the real contacts (the collider looks
    up only pairs whose bounds stopped overlapping and had overlapped at its previous run)."""
    import numpy as np
    from yade import pack
    setNumThreads(threads)
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.16, .16, .25), rMean=.01, rRelFuzz=.2, num=300, seed=3)
    sp.toSimulation()
    O.bodies.append(wall((0, 0, 0), axis=2))
    collider = InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()])
    O.engines = [ForceResetter(), collider,
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4)]
    O.dt = .5 * PWaveTimeStep()
    O.run(3000, True)
    assert collider.numAction > 20 and O.interactions.countReal() > 50
    lo = np.array([tuple(b.bound.min) for b in O.bodies])
    hi = np.array([tuple(b.bound.max) for b in O.bodies])
    overlap = np.all((lo[:, None, :] <= hi[None, :, :]) & (lo[None, :, :] <= hi[:, None, :]), axis=2)
    dynamic = np.array([b.dynamic for b in O.bodies])
    expected = {(a, b) for a, b in zip(*np.nonzero(np.triu(overlap, 1))) if dynamic[a] or dynamic[b]}
    have = {(min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions.all()}
    real = {(min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions}  # (iterating gives the real ones)
    assert have - real <= expected  # no stale potential interaction
    assert expected <= have          # none missing


@pytest.mark.parametrize("threads", [1, 2])
def test_an_erased_body_leaves_no_trace_in_the_skin_and_the_collider(threads):
    """The collider and the loop's skin read the bodies' pos column while the integrator's positions
    are current (core/MotionRecord.hpp), holes included, whose entries mean nothing: a scene whose
    last body was erased (a hole, its old position right where the others meet) runs to the same
    bits as one that never had it."""
    def run(withHole):
        O.reset()
        O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
        O.bodies.append([sphere((0, 0, 0), .01), sphere((0.05, 0.001, 0), .01), sphere((1, 1, 1), .01)])
        if withHole:
            O.bodies.append(sphere((0.025, 0, 0), .01))
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     NewtonIntegrator(damping=0)]
        O.dt = 1e-6
        O.bodies[1].state.vel = (-5, 0, 0)
        O.run(50, True)
        if withHole:
            O.bodies.erase(3)
        O.run(7000, True)  # the gap of 0.03 closes after 6 000 steps: a contact, then a bounce
        return [tuple(O.bodies[i].state.pos) + tuple(O.bodies[i].state.vel) for i in range(3)], O.interactions.countReal()
    setNumThreads(threads)
    try:
        plain, withHole = run(False), run(True)
    finally:
        setNumThreads(1)
    assert plain == withHole
    assert plain[0][0][3] < 0  # body 0 was pushed: they met
