"""The contiguous body store seen from Python: State objects as views of the columns, NumPy views
of the columns (O.bodies.arrays()) and arrays of the real contacts (O.interactions.arrays())."""
import numpy as np
import pytest

from yade import *
from yade.utils import kineticEnergy, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")

R = 0.01


def lattice(n=4, seed=1):
    """n³ spheres on a compressed cubic lattice with random velocities and spins, run 30 steps."""
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    a = 2 * R * 0.99
    for k in range(n):
        for j in range(n):
            for i in range(n):
                O.bodies.append(sphere((i * a, j * a, k * a), R))
    rng = np.random.default_rng(seed)
    for b in O.bodies:
        b.state.vel = tuple(rng.normal(0, 0.01, 3))
        b.state.angVel = tuple(rng.normal(0, 1, 3))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0.1)]
    O.dt = 1e-6
    O.run(30, True)


def test_kinetic_energy_from_the_arrays_equals_kineticEnergy():
    lattice()
    a = O.bodies.arrays()
    assert a.pos.shape == (64, 3) and a.mass.shape == (64,)
    # spheres: the inertia is isotropic, so the global-frame rotation does not matter
    ek = 0.5 * (a.mass * (a.vel ** 2).sum(axis=1)).sum() + 0.5 * (a.inertia * a.angVel ** 2).sum()
    assert ek > 0
    assert ek == pytest.approx(kineticEnergy(), rel=1e-12)
    loop = sum(0.5 * b.state.mass * b.state.vel.squaredNorm() + 0.5 * b.state.inertia[0] * b.state.angVel.squaredNorm()
               for b in O.bodies)
    assert ek == pytest.approx(loop, rel=1e-12)


def test_stress_from_the_contact_arrays_equals_the_per_contact_loop():
    lattice()
    a, c = O.bodies.arrays(), O.interactions.arrays()
    n = len(c["id1"])
    assert n == O.interactions.countReal() and n >= 3 * 4 * 4 * 3  # (at least the lattice bonds)
    f = c["normalForce"] + c["shearForce"]            # on body 2
    branch = a.pos[c["id2"]] - a.pos[c["id1"]]
    V = 1.0
    sigma = np.einsum("ki,kj->ij", f, branch) / V    # Love-Weber: sum of f ⊗ l
    loop = np.zeros((3, 3))
    for i in O.interactions:
        fi = i.phys.normalForce + i.phys.shearForce
        li = O.bodies[i.id2].state.pos - O.bodies[i.id1].state.pos
        loop += np.outer(np.array(fi), np.array(li))
    assert np.abs(sigma).max() > 0
    assert np.allclose(sigma, loop, rtol=1e-12, atol=1e-15 * np.abs(loop).max())
    assert np.all(c["penetrationDepth"] > 0)
    # forces in the body arrays are the sums of the contact forces (no gravity, no other load)
    total = np.zeros((64, 3))
    np.add.at(total, c["id1"], -f)
    np.add.at(total, c["id2"], f)
    assert np.allclose(a.force, total, rtol=1e-9, atol=1e-12 * np.abs(total).max())


def test_writes_through_the_views_reach_the_engine():
    lattice(n=2)
    a = O.bodies.arrays()
    a.vel[3] = (0.5, 0, 0)
    assert tuple(O.bodies[3].state.vel) == (0.5, 0, 0)
    a.pos[5] = (1.0, 1.0, 1.0)                         # far from everything
    O.bodies[5].state.vel = (0, 0, 0)
    O.bodies[5].state.angVel = (0, 0, 0)
    O.step()
    assert tuple(O.bodies[5].state.pos) == (1.0, 1.0, 1.0)
    assert len(O.bodies[5].intrs()) == 0               # the collider and the loop saw the move
    a.mass[0] = 2 * a.mass[0]
    assert O.bodies[0].state.mass == a.mass[0]


def test_read_only_views_refuse_writes():
    lattice(n=2)
    a = O.bodies.arrays()
    for name in ("force", "torque", "radius", "exists"):
        with pytest.raises(ValueError):
            getattr(a, name)[0] = 1
    with pytest.raises(AttributeError, match="no array 'positions'"):
        a.positions


def test_a_view_covers_the_bodies_of_its_time_and_outlives_the_scene():
    lattice(n=2)
    a = O.bodies.arrays()
    O.bodies.append(sphere((5, 5, 5), R))
    assert len(a.pos) == 8 and len(O.bodies.arrays().pos) == 9
    assert np.all(a.radius == R)
    O.bodies.erase(2)
    assert not a.exists[2] and a.exists[3]
    kept = a.pos.copy()
    O.reset()                                          # the columns stay alive with the view
    assert np.array_equal(np.delete(a.pos, 2, axis=0), np.delete(kept, 2, axis=0))


def test_state_made_before_the_body_joins_the_scene():
    st = State(pos=(1, 2, 3), vel=(4, 5, 6), mass=2)
    b = Body(shape=Sphere(radius=R), state=st, material=FrictMat())
    O.bodies.append(b)
    assert tuple(O.bodies.arrays().pos[0]) == (1, 2, 3)
    st.pos = (7, 8, 9)                                 # the same object, now a view of the column
    assert tuple(O.bodies.arrays().vel[0]) == (4, 5, 6) and tuple(O.bodies.arrays().pos[0]) == (7, 8, 9)
    v = st.vel                                         # a vector view into the column
    v[0] = 10
    assert O.bodies.arrays().vel[0][0] == 10


def test_a_state_keeps_its_values_when_its_body_leaves():
    b = sphere((1, 2, 3), R)
    O.bodies.append(b)
    st = b.state
    st.vel = (1, 1, 1)
    O.bodies.erase(b.id)
    assert tuple(st.pos) == (1, 2, 3) and tuple(st.vel) == (1, 1, 1)
    st.pos = (0, 0, 0)                                 # its own copy now
    assert tuple(st.pos) == (0, 0, 0)


def test_a_new_state_of_a_body_in_the_scene_takes_over_its_entries():
    b = sphere((1, 2, 3), R)
    O.bodies.append(b)
    old = b.state
    b.state = State(pos=(4, 5, 6), mass=1)
    assert tuple(O.bodies.arrays().pos[0]) == (4, 5, 6)
    assert tuple(old.pos) == (1, 2, 3)                 # the old one keeps its values
    old.pos = (0, 0, 0)
    assert tuple(O.bodies[0].state.pos) == (4, 5, 6)
    # None is taken, as in the reference (tests/test_reference_core.py); the next step refuses it, naming the body
    b.state = None
    assert b.state is None
    with pytest.raises(RuntimeError, match="Body #0: has Body::material, but NULL Body::state"):
        O.step()
    assert O.iter == 0
    b.state = State(pos=(7, 8, 9), mass=1)
    assert tuple(O.bodies.arrays().pos[0]) == (7, 8, 9)


def test_mask_reaches_the_column_the_integrator_reads():
    O.bodies.append([sphere((0, 0, 0), R), sphere((1, 0, 0), R)])
    O.bodies[1].mask = 2
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10), mask=1)]
    O.dt = 1e-3
    O.run(3, True)
    assert O.bodies[0].state.pos[2] < 0 and O.bodies[1].state.pos[2] == 0


# ------------------------------------------------------------------ files written before the store

DATA = __import__("os").path.join(__import__("os").path.dirname(__file__), "data")


@pytest.mark.parametrize("name", ["saved-before-store.yade.gz", "saved-before-store.xml"])
def test_a_file_saved_before_the_body_store_loads_and_runs_the_same(name):
    """Written by commit 802e60c (tests/data/make_saved_before_store.py): the scene after 40
    steps, and the state the old build reached 50 steps later."""
    import json, os
    expected = json.load(open(os.path.join(DATA, "saved-before-store.json")))
    O.load(os.path.join(DATA, name))
    assert O.iter == 40 and len(O.bodies) == len(expected["pos"])
    assert O.bodies.arrays().exists.all()
    O.run(50, True)
    assert O.iter == expected["iter"] and O.interactions.countReal() == expected["real"]
    a = O.bodies.arrays()
    assert np.allclose(a.pos, expected["pos"], rtol=1e-12, atol=1e-15)
    assert np.allclose(a.vel, expected["vel"], rtol=1e-10, atol=1e-13)
    assert np.allclose([list(b.state.ori) for b in O.bodies], expected["ori"], rtol=1e-12, atol=1e-15)


# ------------------------------------------------------------------ the interaction columns

def pair(overlap=1e-4):
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((0, 0, 0), R), sphere((2 * R - overlap, 0, 0), R)])
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                           [Law2_ScGeom_FrictPhys_CundallStrack()])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), loop, NewtonIntegrator()]
    O.dt = 1e-7
    O.step()
    return loop


def test_a_phys_assigned_from_python_is_the_one_the_law_uses():
    pair()
    i = O.interactions[0, 1]
    kn = i.phys.kn
    fn = O.forces.f(0).norm()
    i.phys = FrictPhys(kn=2 * kn, ks=i.phys.ks, tangensOfFrictionAngle=i.phys.tangensOfFrictionAngle)
    O.step()
    assert O.interactions[0, 1].phys.kn == 2 * kn
    depth = O.interactions[0, 1].geom.penetrationDepth
    assert O.forces.f(0).norm() == pytest.approx(2 * kn * depth, rel=1e-9)
    assert O.forces.f(0).norm() > 1.9 * fn


def test_new_law_functors_replace_the_ones_chosen_before():
    loop = pair()
    O.step()
    assert O.interactions.countReal() == 1
    O.bodies[1].state.vel = (100, 0, 0)                  # away, fast: the contact ends at the next steps
    loop.lawDispatcher.functors = [Law2_ScGeom_FrictPhys_CundallStrack(neverErase=True)]
    O.run(20, True)
    i = O.interactions[0, 1]
    assert i.isReal and i.geom.penetrationDepth < 0     # kept by the new functor (the old one would erase it)
    assert tuple(i.phys.normalForce) == (0, 0, 0)


def test_every_view_shows_each_body_s_own_entries():
    """Each row of each NumPy view is its body's value (State and O.forces agree), a hole included."""
    lattice(n=3)
    O.bodies.erase(4)
    a = O.bodies.arrays()
    for i in range(len(O.bodies)):
        b = O.bodies[i]
        if b is None:
            assert not a.exists[i]
            continue
        assert a.exists[i]
        assert tuple(a.pos[i]) == tuple(b.state.pos) and tuple(a.vel[i]) == tuple(b.state.vel)
        assert tuple(a.angVel[i]) == tuple(b.state.angVel) and tuple(a.inertia[i]) == tuple(b.state.inertia)
        assert a.mass[i] == b.state.mass
        assert tuple(a.force[i]) == tuple(O.forces.f(i)) and tuple(a.torque[i]) == tuple(O.forces.t(i))
    assert np.abs(a.force).max() > 0 and np.abs(a.torque).max() > 0


# ------------------------------------------------------------------ stale views

def moving_scene():
    """Two spheres far apart, an integrator without damping or gravity."""
    O.bodies.append([sphere((0, 0, 0), R), sphere((1, 0, 0), R)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-3


def assert_fresh_arrays_drive_the_engine(body):
    """A new set of arrays is writable, and a velocity written through it moves the body."""
    a = O.bodies.arrays()
    assert not a.stale and a.vel.flags.writeable and a.pos.flags.writeable
    x0 = a.pos[body].copy()
    a.vel[body] = (2.0, 0, 0)
    O.step()
    assert O.bodies[body].state.pos[0] == pytest.approx(x0[0] + 2.0 * O.dt, rel=1e-12)
    assert a.pos[body][0] == O.bodies[body].state.pos[0]      # (the view shows it)
    a.pos[body] = (x0[0], 3.0, 0)                             # positions too
    O.step()
    assert O.bodies[body].state.pos[1] == 3.0


def assert_stale(a):
    assert a.stale
    for name in ("pos", "vel", "angVel", "ori", "mass", "inertia"):
        arr = getattr(a, name)
        assert not arr.flags.writeable
        with pytest.raises(ValueError, match="read-only"):
            arr[0] = 1
        with pytest.raises(ValueError):
            arr.flags.writeable = True                      # (numpy refuses: the memory's owner is not an array)


def test_a_view_taken_before_an_append_refuses_writes():
    moving_scene()
    a = O.bodies.arrays()
    assert not a.stale
    before = O.bodies[0].state.vel[0]
    O.bodies.append(sphere((0, 1, 0), R))
    assert_stale(a)
    assert O.bodies[0].state.vel[0] == before                 # nothing written
    assert a.pos[1][0] == 1.0                                 # still readable: the columns' values
    assert_fresh_arrays_drive_the_engine(2)


def test_a_view_taken_before_an_erase_refuses_writes():
    moving_scene()
    O.bodies.append(sphere((0, 1, 0), R))
    a = O.bodies.arrays()
    pos = a.pos
    O.bodies.erase(2)
    assert_stale(a)
    assert pos is a.pos and not a.exists[2]
    assert_fresh_arrays_drive_the_engine(1)


def test_a_view_taken_before_a_reset_refuses_writes_and_can_still_be_read():
    moving_scene()
    a = O.bodies.arrays()
    vel = a.vel                                               # held alone, after the BodyArrays is gone
    del a
    O.reset()
    assert not vel.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        vel[0] = (1, 0, 0)
    assert vel.shape == (2, 3) and np.all(vel == 0)           # the old scene's last values
    moving_scene()
    assert_fresh_arrays_drive_the_engine(0)
    b = O.bodies.arrays()
    O.bodies.clear()
    assert_stale(b)


def test_a_slice_of_a_stale_view_refuses_writes_and_steps_go_on():
    """A slice made from a stale view is read-only too; the steps after the change run as usual."""
    moving_scene()
    a = O.bodies.arrays()
    O.bodies.append(sphere((0, 2, 0), R))
    with pytest.raises(ValueError, match="read-only"):
        a.pos[1:][0, 0] = 5
    O.step()
    assert O.bodies[1].state.pos[0] == 1.0


def test_contact_arrays_go_stale_when_a_contact_ends():
    pair()
    O.step()
    c = O.interactions.arrays()
    assert isinstance(c, dict) and not c.stale and len(c["id1"]) == 1
    for arr in c.values():
        assert not arr.flags.writeable
    O.step()                                                  # the same contact: still current
    assert not c.stale and len(O.interactions.arrays()["id1"]) == 1
    O.bodies[1].state.vel = (100, 0, 0)                       # away: the contact ends
    O.run(20, True)
    assert O.interactions.countReal() == 0
    assert c.stale
    with pytest.raises(ValueError, match="read-only"):
        c["normalForce"][0] = (1, 0, 0)
    fresh = O.interactions.arrays()
    assert not fresh.stale and len(fresh["id1"]) == 0


def test_contact_arrays_go_stale_when_a_contact_is_made_erased_or_the_scene_reset():
    loop = pair(overlap=-1e-3)                                # apart: no contact yet
    c = O.interactions.arrays()
    assert len(c["id1"]) == 0
    O.bodies[1].state.pos = (2 * R - 1e-4, 0, 0)              # overlapping: a contact is made
    O.step()
    assert c.stale
    c = O.interactions.arrays()
    assert len(c["id1"]) == 1 and not c.stale
    O.interactions.erase(0, 1)
    assert c.stale
    O.step()
    c = O.interactions.arrays()
    assert len(c["id1"]) == 1 and not c.stale
    fn = c["normalForce"].copy()
    O.reset()
    assert c.stale and np.array_equal(c["normalForce"], fn)   # still readable: the pool is kept
    del loop
