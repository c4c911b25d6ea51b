"""ParallelEngine (the reference's groups of engines, ParallelEngine([e1, [e2, e3]])): its special
constructor and slaves as the reference shows them, the groups run in order here (a scene run
through one gives the bits of the same engines listed in O.engines), labels, dead, errors naming
the slave that threw, bad input refused, save and load."""
import pytest

from yade import (O, ParallelEngine, ForceResetter, NewtonIntegrator, InsertionSortCollider, InteractionLoop, PyRunner,
                  Bo1_Sphere_Aabb, Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                  Vector3)
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def test_special_constructor_and_slaves_as_the_reference():
    # (the reference's tests/wrapper.py testParallelEngineCtor, and what it prints for the same calls)
    c, r, n = InsertionSortCollider(), PyRunner(command='pass'), NewtonIntegrator()
    pe = ParallelEngine([c, [r, n]])
    assert pe.slaves[0] is c and isinstance(pe.slaves[1], list) and pe.slaves[1][0] is r and pe.slaves[1][1] is n
    assert ParallelEngine().slaves == [] and ParallelEngine([[]]).slaves == [[]]
    pe.slaves = [(n, r)]  # (a tuple is a group too)
    assert len(pe.slaves) == 1 and pe.slaves[0] == [n, r]
    pe.slaves = []
    assert pe.slaves == []


def test_bad_slaves_are_refused_and_leave_the_engine_as_it_was():
    f = ForceResetter()
    pe = ParallelEngine([f])
    for bad in ([1], [[f, 3]], [None], 5, "ForceResetter"):
        with pytest.raises(TypeError, match="ParallelEngine"):
            pe.slaves = bad
        assert pe.slaves == [f]
    with pytest.raises(TypeError, match="one positional argument"):
        ParallelEngine([f], [f])


def test_a_parallel_engine_cannot_hold_itself_at_any_depth():
    pe1 = ParallelEngine([ForceResetter()])
    with pytest.raises(ValueError, match="its own slave"):
        pe1.slaves = [pe1]
    pe2 = ParallelEngine([[ForceResetter(), pe1]], label='outer')
    pe3 = ParallelEngine([pe2])
    for bad in ([pe2], [[ForceResetter(), pe3]]):  # pe1 in pe2 in pe1; pe1 in pe2 in pe3 in pe1
        with pytest.raises(ValueError, match="its own slave"):
            pe1.slaves = bad
        assert len(pe1.slaves) == 1 and type(pe1.slaves[0]) is ForceResetter
    # nested without a cycle runs, each engine once a step
    r = PyRunner(command='pass', iterPeriod=1)
    O.engines = [ParallelEngine([ParallelEngine([[ParallelEngine([r])]])])]
    O.run(3, True)
    assert r.nDone == 3


def falling_pair_engines(grouped):
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 0.5, fixed=True), sphere((0, 0, 1.02), 0.5)])
    engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
               InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
               NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.2)]
    O.engines = [ParallelEngine([engines[0], engines[1:3]]), engines[3]] if grouped else engines
    O.dt = 1e-4
    O.run(20000, True)
    return O.bodies[1].state.pos, O.bodies[1].state.vel, O.interactions[0, 1].phys.normalForce


def test_groups_run_in_order_and_give_the_bits_of_the_plain_list():
    plain = falling_pair_engines(False)
    grouped = falling_pair_engines(True)
    assert plain == grouped
    pos, vel, fn = grouped
    # at rest on the fixed sphere (damped motion): the contact force carries the weight
    weight = O.bodies[1].state.mass * 9.81
    assert abs(fn[2] - weight) < 1e-3 * weight
    assert pos[2] < 1.0 and abs(vel[2]) < 1e-3


def test_labels_dead_and_timing_of_slaves():
    O.engines = [ParallelEngine([PyRunner(command='from yade import O; O.tags["a"] = str(O.iter)', iterPeriod=1, label='inGroup'),
                                 [ForceResetter(), PyRunner(command='from yade import O; O.tags["b"] = str(O.iter)', iterPeriod=1)]], label='group')]
    import builtins
    assert builtins.inGroup is O.engines[0].slaves[0] and builtins.group is O.engines[0]
    O.timingEnabled = True
    O.run(3, True)
    assert O.tags["a"] == "2" and O.tags["b"] == "2"
    # (a PyRunner runs from iteration 1 on: its first call only starts its period)
    assert O.engines[0].slaves[0].execCount == 2 and O.engines[0].slaves[1][0].execCount == 3 and O.engines[0].execCount == 3
    O.engines[0].slaves[0].dead = True
    O.run(2, True)
    assert O.tags["a"] == "2" and O.tags["b"] == "4"
    O.engines[0].dead = True
    O.run(1, True)
    assert O.tags["b"] == "4"


def test_an_error_names_the_slave_that_threw():
    O.engines = [ParallelEngine([ForceResetter(), [PyRunner(command='1/0', iterPeriod=1, initRun=True, label='bad')]])]
    with pytest.raises(ZeroDivisionError) as e:
        O.run(1, True)
    assert "in PyRunner labeled 'bad' at iteration 0" in " ".join(getattr(e.value, "__notes__", []))
    assert O.iter == 0


def test_saved_and_loaded_with_its_groups(tmp_path):
    O.engines = [ParallelEngine([ForceResetter(), [PyRunner(command='pass', label='r1'), NewtonIntegrator(damping=0.3)]])]
    path = str(tmp_path / "pe.yade")
    O.save(path)
    O.reset()
    O.load(path)
    pe = O.engines[0]
    assert type(pe) is ParallelEngine and type(pe.slaves[0]) is ForceResetter
    assert [type(e).__name__ for e in pe.slaves[1]] == ["PyRunner", "NewtonIntegrator"]
    assert pe.slaves[1][0].label == "r1" and pe.slaves[1][1].damping == 0.3
    assert "members" not in pe.dict() and "groupSizes" not in pe.dict()
