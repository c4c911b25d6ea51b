"""InteractionLoop.callbacks and SumIntrForcesCb, against the reference's output on the same script."""
import pytest
from yade import *  # noqa: F401,F403
from yade import O
from yade.utils import sphere


def makeScene(callbacks, vel=(0, 3e3, -1e3)):
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 1, fixed=True), sphere((0, 0.3, 1.9), 1)])
    O.bodies[1].state.vel = vel
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()])
    loop.callbacks = callbacks
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), loop, NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-5
    return loop


def test_sum_of_contact_forces_printed_as_the_reference(capfd):
    makeScene([SumIntrForcesCb()])
    O.run(1, True)
    i = O.interactions[0, 1]
    fn, fs = i.phys.normalForce, i.phys.shearForce
    assert fn.norm() == pytest.approx(764615.9383286566, rel=1e-12)  # (the reference's figures on this script)
    assert fs.norm() == pytest.approx(97297.29729729731, rel=1e-12)
    O.step()
    # at the start of each step, the last step's sum of |Fn + Fs| and count (stderr, no newline): the
    # reference prints (0,0)(770782,1) here
    err = capfd.readouterr().err
    assert err == "(0,0)(770782,1)"
    assert (fn + fs).norm() == pytest.approx(770782, abs=0.5)


def test_two_contacts_and_two_callbacks(capfd):
    # the reference: (0,0)(0,0)(1.5e+06,2)(1.5e+06,2) with two callbacks over two contacts of 1e6 and 5e5 N
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 1, fixed=True), sphere((0, 0, 1.9), 1), sphere((0, 2, 0), 1, fixed=True), sphere((0, 2, 1.95), 1)])
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()])
    loop.callbacks = [SumIntrForcesCb(), SumIntrForcesCb()]
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), loop, NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-5
    O.run(2, True)
    assert capfd.readouterr().err == "(0,0)(0,0)(1.5e+06,2)(1.5e+06,2)"


def test_the_abstract_callback_refuses_to_run():
    makeScene([IntrCallback()])
    with pytest.raises(RuntimeError, match="base class"):
        O.run(1, True)


def test_callbacks_are_saved(tmp_path, capfd):
    loop = makeScene([SumIntrForcesCb()])
    assert len(loop.callbacks) == 1 and isinstance(loop.callbacks[0], SumIntrForcesCb)
    assert isinstance(SumIntrForcesCb(), IntrCallback)
    f = str(tmp_path / "s.xml")
    O.save(f)
    O.reset()
    O.load(f)
    loop = [e for e in O.engines if isinstance(e, InteractionLoop)][0]
    assert [type(c).__name__ for c in loop.callbacks] == ["SumIntrForcesCb"]
    O.run(2, True)
    assert capfd.readouterr().err == "(0,0)(770782,1)"


def test_none_in_the_callbacks_is_refused():
    loop = makeScene([])
    with pytest.raises(TypeError, match="IntrCallback"):
        loop.callbacks = [None]
    with pytest.raises(TypeError, match="IntrCallback"):
        loop.callbacks = [ForceResetter()]
    assert loop.callbacks == []
