"""Contacts stored in ContactPools (doc/storage.md): one compact array of records per kind of
contact, the Interaction objects Python holds and their geom and phys as views of the records,
and O.interactions.arrays() as NumPy views of them."""
import numpy as np
import pytest

from yade import *
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")

R = 0.01


def row(n=8, gap=0.99):
    """n spheres in a row along x, each overlapping the next (contacts 0-1, 1-2, ...), x blocked so
    that only the velocities the tests give move them."""
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    for i in range(n):
        O.bodies.append(sphere((2 * R * gap * i, 0, 0), R))
    for b in O.bodies:
        b.state.blockedDOFs = 'xyzXY'  # (still dynamic: static bodies do not collide)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.step()
    assert O.interactions.countReal() == n - 1


def contacts():
    return {(min(i.id1, i.id2), max(i.id1, i.id2)): i for i in O.interactions}


def test_held_geometry_and_physics_follow_their_contact_when_others_end_and_records_move():
    """Ending the first contacts moves the last records into their rows: what Python holds of the
    others still shows its own contact, the same values as asked for anew."""
    row(8)
    held = {p: (i.geom, i.phys) for p, i in contacts().items()}
    for b in O.bodies:
        if b.id <= 2:
            b.state.vel = (-2, 0, 0)  # #0, #1, #2 leave to the left, apart: contacts 0-1, 1-2, 2-3 end
    O.bodies[1].state.vel = (-4, 0, 0)
    O.bodies[0].state.vel = (-6, 0, 0)
    O.run(200, True)
    now = contacts()
    assert sorted(now) == [(3, 4), (4, 5), (5, 6), (6, 7)]
    O.bodies[5].state.vel = (1e-3, 0, 0)  # the overlaps change: values the views must follow
    O.run(5, True)
    for p, i in contacts().items():
        g, ph = held[p]
        assert i.geom is g and i.phys is ph
        assert g.penetrationDepth == i.geom.penetrationDepth and g.penetrationDepth > 0
        assert tuple(ph.normalForce) == tuple(i.phys.normalForce) and tuple(g.normal) == tuple(i.geom.normal)
        assert ph.normalForce.norm() == pytest.approx(ph.kn * g.penetrationDepth, rel=1e-12)


def test_geometry_held_past_the_end_of_its_contact_keeps_its_last_values():
    row(2)
    i = O.interactions[0, 1]
    g, ph = i.geom, i.phys
    O.bodies[1].state.vel = (1, 0, 0)
    O.run(2, True)
    depth, force = g.penetrationDepth, tuple(ph.normalForce)
    O.run(300, True)  # apart
    assert not i.isReal and i.geom is None
    # the values of its last step: the overlap gone (1 µm per step), the stiffness kept
    assert -1e-6 <= g.penetrationDepth <= 0 and g.penetrationDepth < depth and ph.kn > 0 and np.linalg.norm(force) > 0
    g.penetrationDepth = 1.0  # its own value now, no longer a contact's
    assert g.penetrationDepth == 1.0


def test_contact_arrays_are_views_that_follow_the_steps():
    row(8)
    c = O.interactions.arrays()
    assert not c["normalForce"].flags.writeable
    assert len(c["id1"]) == 7
    O.bodies[4].state.vel = (1e-2, 0, 0)  # closes on #5, opens on #3: forces change, no contact ends
    O.run(3, True)
    assert O.interactions.countReal() == 7
    loop = {(i.id1, i.id2): (np.array(i.phys.normalForce), i.geom.penetrationDepth) for i in O.interactions}
    for r in range(7):
        f, d = loop[(int(c["id1"][r]), int(c["id2"][r]))]
        assert np.array_equal(c["normalForce"][r], f) and c["penetrationDepth"][r] == d
    k = O.interactions[4, 5].phys.kn
    r45 = [r for r in range(7) if {int(c["id1"][r]), int(c["id2"][r])} == {4, 5}][0]
    assert c["penetrationDepth"][r45] > 0.01 * R * 1.5
    assert np.linalg.norm(c["normalForce"][r45]) == pytest.approx(k * c["penetrationDepth"][r45], rel=1e-12)


def test_contact_arrays_stay_readable_after_reset():
    row(4)
    c = O.interactions.arrays()
    before = c["penetrationDepth"].copy()
    O.reset()
    assert np.array_equal(c["penetrationDepth"], before)  # (its memory is kept by the view)
    assert len(O.interactions.arrays()["id1"]) == 0


def test_geometry_assigned_from_python_becomes_the_contacts_view():
    row(2)
    i = O.interactions[0, 1]
    old = i.geom
    new = ScGeom(penetrationDepth=old.penetrationDepth, normal=old.normal, contactPoint=old.contactPoint,
                 refR1=old.refR1, refR2=old.refR2)
    i.geom = new
    O.bodies[1].state.vel = (-1e-3, 0, 0)  # the overlap grows
    O.run(3, True)
    assert O.interactions[0, 1].geom is new
    assert new.penetrationDepth > old.penetrationDepth  # a view of the contact, updated by the steps
    assert np.allclose(O.interactions.arrays()["penetrationDepth"], [new.penetrationDepth], rtol=0, atol=0)


def test_erase_and_save_load_of_pooled_contacts(tmp_path):
    row(6)
    g = O.interactions[2, 3].geom
    O.interactions.erase(2, 3)
    assert O.interactions.countReal() == 4 and g.penetrationDepth > 0
    a = O.interactions.arrays()
    assert sorted(zip(a["id1"], a["id2"])) == [(0, 1), (1, 2), (3, 4), (4, 5)]
    f = str(tmp_path / "s.yade.gz")
    O.save(f)
    depths = {p: i.geom.penetrationDepth for p, i in contacts().items()}
    O.load(f)
    assert {p: i.geom.penetrationDepth for p, i in contacts().items()} == depths
    O.step()
    assert O.interactions.countReal() >= 4


def test_vectors_of_a_contacts_views_are_copies_that_outlive_the_records():
    """(minieigen views into a record would show another contact once it moves, and freed memory
    once the pools are gone)"""
    row(3)
    g = O.interactions[0, 1].geom
    n = g.normal
    n[0] = 5  # a copy: the contact is unchanged
    assert g.normal[0] != 5
    O.reset()
    assert n[0] == 5 and abs(g.normal.norm() - 1) < 1e-12  # (detached: its last values)


def test_large_pools_are_put_back_in_the_loops_order_after_contacts_end():
    """Contacts that end leave their rows to the last records; in pools larger than the caches (over
    8 MB) the loop then read those records at random. Once one record in 16 is out of place the
    pools are put back in the order the loop visits them: each thread's list by the smaller id."""
    n = 24  # a cubic lattice, each sphere overlapping its six neighbours: 3·24²·23 = 39 744 contacts of 272+ bytes
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append([sphere((2 * R * 0.99 * i, 2 * R * 0.99 * j, 2 * R * 0.99 * k), R)
                     for i in range(n) for j in range(n) for k in range(n)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(damping=0)]
    O.dt = 1e-9
    O.run(2, True)  # (the records made in the first step are put in order at the start of the second)
    real = 3 * n * n * (n - 1)
    assert O.interactions.countReal() == real

    def rows_in_order():
        c = O.interactions.arrays()
        low = np.minimum(c["id1"], c["id2"])
        return len(low) == O.interactions.countReal() and int(np.sum(np.diff(low) < 0)) <= O.numThreads - 1  # (one sorted run per thread)

    assert rows_in_order()
    # every 12th contact erased (1/12 > 1/16 of the rows): the last records move into their rows
    pairs = sorted((min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions)
    for a, b in pairs[::12]:
        O.interactions.erase(a, b)
    assert not rows_in_order()
    assert O.interactions.countReal() == real - len(pairs[::12])  # (erased: potential pairs, records gone)
    O.step()  # (the bodies still touch: those contacts are made again, at the end of the pool)
    assert O.interactions.countReal() == real
    O.step()  # (put in order again at the start of the step)
    assert rows_in_order()
