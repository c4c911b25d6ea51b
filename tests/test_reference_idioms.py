"""Idioms of scripts written for the reference, each checked against what the reference printed on the
same script (Yade 2023.02a, `yade -n -x`): attributes of bodies and interactions, engine labels, tags,
utils.kineticEnergy(findMaxId=True)."""
import pytest
from yade import *  # noqa: F401,F403
from yade import O
from yade import utils


def scene():
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), 0.5), utils.sphere((0, 0, 0.98), 0.5)])
    O.bodies.append(utils.facet([(-2, -2, -0.45), (2, -2, -0.45), (0, 2, -0.45)]))
    O.bodies.append(utils.box((5, 5, 5), (1, 2, 3)))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-5
    O.run(3, True)


def test_bodies_know_when_they_were_born_and_are_no_clumps():
    scene()
    for b in O.bodies:  # appended before the first step: 0, 0.0 there
        assert (b.iterBorn, b.timeBorn) == (0, 0.0)
        assert not b.isClump and not b.isClumpMember and b.isStandalone and b.groupMask == b.mask == 1
    n = utils.sphere((3, 3, 3), 0.1)
    assert (n.iterBorn, n.timeBorn) == (-1, -1.0)
    O.bodies.append(n)
    assert n.iterBorn == 3 and n.timeBorn == pytest.approx(3e-5, rel=1e-12)  # (3.0000000000000004e-05 there)
    n.groupMask = 5
    assert n.mask == 5
    assert (Body().iterBorn, Body().timeBorn) == (-1, -1.0)


def test_interactions_are_active_and_erase_takes_the_clump_flag():
    scene()
    assert sorted((min(i.id1, i.id2), max(i.id1, i.id2)) for i in O.interactions) == [(0, 1), (0, 2)]
    assert all(i.isActive for i in O.interactions)
    assert O.bodies.erase(3, True) is True
    assert O.bodies.erase(1, eraseClumpMembers=True) is True
    assert O.bodies.erase(1) is False  # (already erased)


def test_a_label_given_twice_names_the_first_engine():
    O.reset()
    O.engines = [PyRunner(command='a=1', label='dup', iterPeriod=3), PyRunner(command='a=2', label='dup', iterPeriod=7)]
    import builtins
    assert (builtins.dup.command, builtins.dup.iterPeriod) == ('a=1', 3)


def test_kinetic_energy_with_the_id_of_the_largest():
    scene()
    O.bodies.erase(3)
    O.bodies.erase(1)
    e, i = utils.kineticEnergy(findMaxId=True)
    assert e == pytest.approx(0.028617561925785486, rel=1e-12) and i == 0  # (the reference's)
    assert utils.kineticEnergy() == e


def test_author_tag():
    import getpass
    import socket
    author = O.tags['author']
    assert '~' not in getpass.getuser() and author.endswith('(%s@%s)' % (getpass.getuser(), socket.gethostname())) and ' ' not in author


def test_regular_ortho_counts_equal_the_references():
    from yade import pack
    box = pack.inAlignedBox((-1, -2, -3), (1, 2, 3)) - pack.inCylinder((0, 0, -3), (0, 0, 3), 0.2)
    cases = [(pack.inAlignedBox((0, 0, 0), (1, 1, 1)), 0.1, 0, 64), (pack.inAlignedBox((0, 0, 0), (1.05, 1, 1)), 0.1, 0, 80),
             (pack.inCylinder((0, 0, 0), (0, 0, 1), 0.5), 0.1, 0, 44), (pack.inSphere((0, 0, 0), 0.5), 0.1, 0, 30),
             (pack.inAlignedBox((0, 0, 0), (1, 1, 1)), 0.1, 0.01, 64), (box, 0.2, 0, 476), (box, 0.15, 0, 1425), (box, 0.25, 0, 187),
             (pack.inSphere((1, 2, 3), 1.3), 0.07, 0.003, 2650)]
    for predicate, r, gap, n in cases:
        assert len(pack.regularOrtho(predicate, radius=r, gap=gap)) == n
    xs = sorted({round(b.state.pos[0], 12) for b in pack.regularOrtho(pack.inAlignedBox((0, 0, 0), (1, 1, 1)), radius=0.1, gap=0)})
    assert xs == [0.1, 0.3, 0.5, 0.7]


def test_a_relative_verlet_distance_reads_as_the_distance_after_the_first_step():
    # the reference on this script: -0.5, then 0.15 (0.5 x the smallest radius), 0.15, and -0.2 kept
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), 0.5), utils.sphere((0, 0, 3), 0.3)])
    c = InsertionSortCollider([Bo1_Sphere_Aabb()])
    assert c.verletDist == -0.5
    O.engines = [ForceResetter(), c, NewtonIntegrator()]
    O.dt = 1e-4
    O.step()
    assert c.verletDist == pytest.approx(0.15, rel=1e-15)
    O.bodies.append(utils.sphere((5, 5, 5), 0.1))
    O.step()
    assert c.verletDist == pytest.approx(0.15, rel=1e-15)
    c.verletDist = -0.2
    O.step()
    assert c.verletDist == -0.2
