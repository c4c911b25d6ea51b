"""How O.interactions stores pairs (doc/storage.md): a potential pair (bounds overlap, no contact)
is an entry of the container's columns, with an Interaction object only once Python or a functor
asks for one; what Python sees is the same as if every pair had its object."""
import pytest

from yade import *  # noqa: F401,F403
from yade import O
from yade.utils import sphere


@pytest.fixture(autouse=True)
def fresh_scene():
    O.pause()
    O.reset()
    yield
    O.pause()


def engines():
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                            [Law2_ScGeom_FrictPhys_CundallStrack()]),
            NewtonIntegrator(gravity=(0, 0, 0), damping=0)]


def three_spheres():
    """#0 and #1 touch (a contact); #1 and #2 have overlapping bounds, 0.1 mm apart (a potential
    pair); #0 and #2 are far apart."""
    O.bodies.append([sphere((0, 0, 0), 1e-3), sphere((1.99e-3, 0, 0), 1e-3), sphere((4.09e-3, 0, 0), 1e-3)])
    for b in O.bodies:
        b.state.blockedDOFs = 'xyzXY'  # moved only by the velocities the tests give them (still dynamic)
    O.engines = engines()
    O.dt = 1e-6
    O.step()


def test_potential_pair_is_counted_and_found_without_being_real():
    three_spheres()
    assert len(O.interactions) == 2
    assert O.interactions.countReal() == 1
    assert O.interactions.has(1, 2) and not O.interactions.has(1, 2, onlyReal=True)
    assert O.interactions.has(2, 1)
    assert not O.interactions.has(0, 2)
    assert [(i.id1, i.id2) for i in O.interactions] == [(0, 1)]


def test_potential_pair_object_is_made_on_request_and_kept():
    three_spheres()
    i = O.interactions[2, 1]
    assert (min(i.id1, i.id2), max(i.id1, i.id2)) == (1, 2)
    assert not i.isReal and i.geom is None and i.phys is None and i.iterMadeReal == -1
    assert O.interactions[1, 2] is i  # the same object from then on
    assert sorted((min(x.id1, x.id2), max(x.id1, x.id2)) for x in O.interactions.all()) == [(0, 1), (1, 2)]
    O.step()
    assert O.interactions[1, 2] is i and not i.isReal


def test_a_held_potential_pair_becomes_the_contact():
    three_spheres()
    held = O.interactions[1, 2]
    O.bodies[2].state.vel = (-1, 0, 0)  # closes the 0.1 mm gap in 100 steps
    O.run(200, True)
    assert O.interactions[1, 2] is held and held.isReal
    assert held.phys.normalForce.norm() > 0


def test_ended_contact_held_by_python_is_reset_and_a_new_one_made_later():
    three_spheres()
    contact = O.interactions[0, 1]
    assert contact.isReal
    O.bodies[1].state.vel = (1, 0, 0)  # separates #0 and #1 (and closes on #2)
    O.run(100, True)
    assert not contact.isReal and contact.geom is None and contact.phys is None and contact.iterMadeReal == -1
    if O.interactions.has(0, 1):
        assert O.interactions[0, 1] is contact
    O.bodies[1].state.vel = (-1, 0, 0)
    O.run(200, True)
    assert O.interactions[0, 1].isReal


def test_contact_that_ends_and_starts_again_gives_the_same_forces_as_a_fresh_one():
    # an ended contact's object is dropped when nobody holds it; the next contact starts from
    # zero shear, as a new one
    three_spheres()
    O.bodies[1].state.vel = (1, 0, 0)
    O.run(150, True)
    assert not O.interactions.has(0, 1, onlyReal=True)
    O.bodies[1].state.vel = (-1, 0, 0)
    O.run(250, True)
    i = O.interactions[0, 1]
    assert i.isReal and i.phys.shearForce.norm() == 0
    assert i.iterMadeReal > 150


def test_erase_makes_a_real_interaction_potential_as_the_reference():
    # The reference's O.interactions.erase: a real interaction becomes a potential pair (geom and phys
    # None), computed again at the next step; a potential pair, or no pair at all, is left as it is.
    three_spheres()
    held = O.interactions[0, 1]
    O.interactions.erase(2, 1)  # potential: stays
    O.interactions.erase(0, 2)  # no such pair: nothing happens (no error, as there)
    assert len(O.interactions) == 2 and O.interactions.countReal() == 1
    O.interactions.erase(1, 0)
    assert len(O.interactions) == 2 and O.interactions.countReal() == 0
    assert O.interactions.has(0, 1) and not O.interactions.has(0, 1, onlyReal=True)
    i = O.interactions[0, 1]
    assert not i.isReal and i.geom is None and i.phys is None
    assert not held.isReal and held.geom is None
    O.interactions.erase(0, 1)  # (again: a potential pair now, left as it is)
    O.step()  # the bodies still touch: real again
    assert O.interactions[0, 1].isReal and held.isReal and O.interactions.countReal() == 1


def test_a_contact_erased_between_steps_pushes_again_with_the_references_figures():
    # The reference (same script): 0.989370288900787 after 105 steps; with the pair dropped for good the
    # sphere sank into the fixed one (0.98043).
    O.bodies.append([sphere((0, 0, 0), 0.5, fixed=True), sphere((0, 0, 0.98), 0.5), sphere((0, 0, 3), 0.5), sphere((0, 0, 3.9), 0.5)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -10), damping=0)]
    O.dt = 1e-4
    O.run(5, True)
    O.interactions.erase(0, 1)
    O.interactions.erase(2, 3)
    assert (O.interactions.countReal(), len(O.interactions)) == (0, 2)
    O.step()
    assert (O.interactions.countReal(), len(O.interactions)) == (2, 2)
    assert O.bodies[1].state.pos[2] == pytest.approx(0.980037994949027, rel=1e-13)
    O.run(100, True)
    assert O.bodies[1].state.pos[2] == pytest.approx(0.989370288900787, rel=1e-13)


def test_erasing_a_body_drops_its_pairs_and_keeps_the_others_findable():
    O.bodies.append([sphere((x * 1.99e-3, 0, 0), 1e-3) for x in range(6)])
    O.engines = engines()
    O.dt = 1e-6
    O.step()
    assert O.interactions.countReal() == 5
    O.bodies.erase(2)
    assert O.interactions.countReal() == 3
    for a, b in [(0, 1), (3, 4), (4, 5)]:
        assert O.interactions[b, a].isReal
    assert not O.interactions.has(1, 2) and not O.interactions.has(2, 3)


def test_save_and_load_keep_potential_pairs(tmp_path):
    three_spheres()
    f = str(tmp_path / 'scene.yade.gz')
    O.save(f)
    O.reset()
    O.load(f)
    assert len(O.interactions) == 2 and O.interactions.countReal() == 1
    assert O.interactions.has(1, 2) and not O.interactions[1, 2].isReal


def test_iteration_skips_what_was_erased_meanwhile():
    O.bodies.append([sphere((x * 1.99e-3, 0, 0), 1e-3) for x in range(4)])
    O.engines = engines()
    O.dt = 1e-6
    O.step()
    it = iter(O.interactions)
    first = next(it)
    O.interactions.erase(2, 3)  # (no longer real: potential)
    rest = list(it)
    assert [(i.id1, i.id2) for i in [first] + rest] == [(0, 1), (1, 2)]
    it = iter(O.interactions)
    O.interactions.clear()
    assert list(it) == []


def test_a_held_interaction_that_was_erased_raises_instead_of_showing_stale_data():
    three_spheres()
    potential, contact = O.interactions[1, 2], O.interactions[0, 1]
    O.bodies.erase(2)  # (its pairs go)
    for attr in ('isReal', 'geom', 'phys', 'id1', 'iterMadeReal'):
        with pytest.raises(ReferenceError, match='erased'):
            getattr(potential, attr)
    with pytest.raises(ReferenceError):
        potential.phys = None
    assert contact.isReal  # the one that moved into the hole is still alive
    O.bodies.erase(0)
    with pytest.raises(ReferenceError, match=r'##0\+1'):
        contact.phys


def test_held_interactions_raise_after_clear_and_reset():
    three_spheres()
    i = O.interactions[0, 1]
    O.interactions.clear()
    with pytest.raises(ReferenceError):
        i.isReal
    O.reset()
    three_spheres()
    j = O.interactions[0, 1]
    O.reset()
    with pytest.raises(ReferenceError):
        j.geom


def test_collider_dropping_a_held_potential_pair_makes_it_raise():
    three_spheres()
    held = O.interactions[1, 2]
    O.bodies[2].state.vel = (10, 0, 0)  # away from #1: the bounds separate, the collider drops the pair
    O.run(300, True)
    assert not O.interactions.has(1, 2)
    with pytest.raises(ReferenceError):
        held.isReal


def test_contacts_keep_their_geometry_and_physics_after_iteration_drops_its_objects():
    """A contact has no Interaction object unless Python asks (its geometry and physics belong to
    O.interactions); iterating makes one object at a time and drops it when the iteration moves on:
    the geometry and physics seen later are the same objects, updated by the steps since."""
    three_spheres()
    geoms = [i.geom for i in O.interactions]
    physs = [i.phys for i in O.interactions]
    assert len(geoms) == 1
    depth0 = geoms[0].penetrationDepth
    O.bodies[1].state.vel = (-1e-3, 0, 0)  # pushes into #0: the overlap grows
    O.run(10, True)
    i = O.interactions[0, 1]
    assert i.geom is geoms[0] and i.phys is physs[0]
    # (the geometry of step n sees the positions of step n - 1: 9 moves of 1 nm)
    assert geoms[0].penetrationDepth == pytest.approx(depth0 + 9 * 1e-6 * 1e-3, rel=1e-9)
    assert physs[0].normalForce.norm() == pytest.approx(physs[0].kn * geoms[0].penetrationDepth, rel=1e-9)


def test_physics_replaced_while_iterating_is_what_the_next_step_uses():
    three_spheres()
    kn0 = O.interactions[0, 1].phys.kn
    for i in O.interactions:  # (each object is dropped after the loop body, its new phys kept)
        i.phys = FrictPhys(kn=2 * kn0, ks=i.phys.ks, tangensOfFrictionAngle=i.phys.tangensOfFrictionAngle)
    O.step()
    i = O.interactions[0, 1]
    assert i.phys.kn == 2 * kn0
    assert i.phys.normalForce.norm() == pytest.approx(2 * kn0 * i.geom.penetrationDepth, rel=1e-9)


def test_withBodyAll_includes_potential_pairs_and_nth_walks_the_container():
    three_spheres()
    assert sorted((min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions.withBody(1)) == [(0, 1)]
    assert sorted((min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions.withBodyAll(1)) == [(0, 1), (1, 2)]
    pairs = sorted((min(O.interactions.nth(k).id1, O.interactions.nth(k).id2),
                    max(O.interactions.nth(k).id1, O.interactions.nth(k).id2)) for k in range(len(O.interactions)))
    assert pairs == [(0, 1), (1, 2)]
    assert O.interactions.nth(-1) is O.interactions.nth(len(O.interactions) - 1)
    with pytest.raises(IndexError):
        O.interactions.nth(2)


def test_resetTime_zeroes_the_clocks_and_nothing_else():
    three_spheres()
    O.bodies[2].state.vel = (-1, 0, 0)
    O.run(20, True)
    f = O.forces.f(1)
    O.resetTime()
    assert O.iter == 0 and O.time == 0 and O.realtime < 60
    assert O.forces.f(1) == f and O.interactions.countReal() == 1
    O.run(150, True)  # (#2 reaches #1 as without the reset)
    assert O.iter == 150 and O.time == pytest.approx(150 * O.dt, rel=1e-12)
    assert O.interactions.has(1, 2, onlyReal=True)
