"""ForceRecorder and TorqueRecorder (Recorder: a periodic engine writing lines to a file): the
reference's lines on the same scene, the physics of the moment about an axis, addIterNum and
truncate, clear errors."""
import math

import pytest

from yade import (O, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator, Bo1_Sphere_Aabb, Ig2_Sphere_Sphere_ScGeom,
                  Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, ForceRecorder, TorqueRecorder, Recorder,
                  ForceEngine, TorqueEngine, Vector3)
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def test_defaults_as_the_reference():
    r, f, t = Recorder(), ForceRecorder(), TorqueRecorder()
    assert (r.file, r.truncate, r.addIterNum, r.initRun) == ('', False, False, False)
    assert (f.ids, f.totalForce, f.initRun) == ([], Vector3(0, 0, 0), True)
    assert (t.rotationAxis, t.zeroPoint, t.totalTorque, t.initRun) == (Vector3(1, 0, 0), Vector3(0, 0, 0), 0.0, True)


def resting_pair(tmp_path, recorders):
    O.bodies.append([sphere((0, 0, 0), .5, fixed=True), sphere((0, 0, .95), .5), sphere((0, 1, .95), .5)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81))] + recorders
    O.dt = 1e-4
    O.bodies[1].state.angVel = (1, 0, 0)
    O.run(7, True)


def test_force_lines_as_the_reference(tmp_path):
    both, one = str(tmp_path / 'f.txt'), str(tmp_path / 'f2.txt')
    resting_pair(tmp_path, [ForceRecorder(ids=[0, 1], file=both, iterPeriod=2),
                            ForceRecorder(ids=[1], file=one, iterPeriod=1, addIterNum=True, truncate=True)])
    # the reference's files for the same script (the pair's forces cancel; body 1's, one file per run)
    assert open(both).read() == "0 0 0 0 0\n2 0 0 0 0\n4 0 0 0 0\n6 0 0 0 0\n"
    assert open(one + '-0').read() == "0 0 -75 250000 250000\n"
    assert open(one + '-6').read() == "6 0 -524.573 249607 249608\n"
    assert len(list(tmp_path.glob('f2.txt-*'))) == 7
    assert O.engines[-1].totalForce == O.forces.f(1)


def test_torque_is_the_moment_about_the_axis(tmp_path):
    path = str(tmp_path / 't.txt')
    resting_pair(tmp_path, [TorqueRecorder(ids=[1], rotationAxis=(1, 0, 0), file=path, iterPeriod=3)])
    b = O.bodies[1]
    expected = O.forces.t(1)[0] + (b.state.pos.cross(O.forces.f(1)))[0]
    assert O.engines[-1].totalTorque == pytest.approx(expected, rel=1e-12)
    assert [l.split()[0] for l in open(path)] == ['0', '3', '6']
    # (the reference writes -747.56 at step 6: it adds force x arm, the moment with the opposite sign,
    # to the torque; doc/compatibility.md)
    assert float(open(path).read().split()[-1]) == pytest.approx(expected, rel=1e-5)


@pytest.mark.parametrize("pos,force,moment,axis,zero,expected", [
    ((1, 0, 0), (0, 1, 0), (0, 0, .25), (0, 0, 2), (0, 0, 0), 1.25),  # a force +y at +x turns about +z; the axis normalised
    ((0, 0, 1), (0, 1, 0), (0, 0, 0), (1, 0, 0), (0, 0, 0), -1.0),
    ((0, 0, 1), (0, 1, 0), (0, 0, 0), (-1, 0, 0), (0, 0, 0), 1.0),
    ((2, 3, 4), (1, -2, .5), (0, 0, 0), (1, 2, 3), (.5, .1, -.3), -.55 / math.sqrt(14)),
])
def test_torque_about_an_axis_analytic(tmp_path, pos, force, moment, axis, zero, expected):
    O.bodies.append(sphere(pos, .1))
    rec = TorqueRecorder(ids=[0], rotationAxis=axis, zeroPoint=zero, file=str(tmp_path / 'tq.txt'))
    O.engines = [ForceResetter(), ForceEngine(ids=[0], force=force), TorqueEngine(ids=[0], moment=moment), rec, NewtonIntegrator()]
    O.dt = 1e-6
    O.run(1, True)
    assert rec.totalTorque == pytest.approx(expected, abs=1e-12)


def test_appends_unless_truncate(tmp_path):
    path = tmp_path / 'f.txt'
    path.write_text("old\n")
    O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [ForceResetter(), ForceEngine(ids=[0], force=(1, 2, 2)), ForceRecorder(ids=[0], file=str(path), iterPeriod=1)]
    O.dt = 1e-6
    O.run(2, True)
    assert path.read_text() == "old\n0 1 2 2 3\n1 1 2 2 3\n"
    O.engines[-1].truncate, O.engines[-1].file = True, str(tmp_path / 'g.txt')
    (tmp_path / 'g.txt').write_text("old\n")
    O.run(1, True)
    assert (tmp_path / 'g.txt').read_text() == "2 1 2 2 3\n"


def test_clear_errors(tmp_path):
    O.bodies.append(sphere((0, 0, 0), .1))
    for rec, match in [(ForceRecorder(ids=[0]), "file is empty"), (ForceRecorder(ids=[5], file=str(tmp_path / 'x')), "ids contains 5"),
                       (ForceRecorder(ids=[0], file=str(tmp_path / 'no' / 'such' / 'dir')), "cannot open"),
                       (TorqueRecorder(ids=[0], rotationAxis=(0, 0, 0), file=str(tmp_path / 'y')), "rotationAxis must not be zero")]:
        O.engines = [ForceResetter(), rec]
        with pytest.raises(Exception, match=match):
            O.run(1, True)
        assert O.iter == 0
    with pytest.raises(Exception):
        ForceRecorder().totalForce = (1, 2, 3)  # (a result, not a setting)
