"""yade.qt without a 3D view (issue 37, the headless part): scripts written with a view run unchanged.

The reference's names and defaults below come from running the reference Yade 2023.02a under Xvfb
(`xvfb-run yade -x`): `OpenGLRenderer().dict()`, each Gl1_* class's attributes, `SnapshotEngine().dict()`
and a fresh `qt.View()` of an empty scene."""
import json
import math
import os
import subprocess
import sys
import textwrap
import warnings

import pytest

from yade import *  # noqa: F401,F403
from yade import qt

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

REFERENCE_RENDERER = {
    'dispScale': (1, 1, 1), 'rotScale': 1.0, 'lightPos': (75, 130, 0), 'light2Pos': (-130, 75, 30),
    'lightColor': (0.6, 0.6, 0.6), 'light2Color': (0.5, 0.5, 0.1), 'cellColor': (1, 1, 0), 'bgColor': (0.2, 0.2, 0.2),
    'wire': False, 'light1': True, 'light2': True, 'dof': False, 'id': False, 'bound': False, 'shape': True,
    'intrWire': False, 'intrGeom': False, 'intrPhys': False, 'intrAllWire': False, 'ghosts': True, 'mask': -1,
    'selId': -1, 'extraDrawers': [],
}
REFERENCE_GL1 = {
    'Gl1_Sphere': {'quality': 1.0, 'wire': False, 'stripes': False, 'localSpecView': True, 'glutSlices': 12,
                   'glutStacks': 6, 'circleView': False, 'circleRelThickness': 0.2, 'circleAllowedRotationAxis': 'z'},
    'Gl1_Facet': {'normals': False},
    'Gl1_Wall': {'div': 20},
    'Gl1_Box': {},
    'Gl1_Aabb': {},
    'Gl1_NormPhys': {'maxFn': 0.0, 'signFilter': 0, 'refRadius': math.inf, 'maxRadius': -1.0, 'slices': 6,
                     'stacks': 1, 'maxWeakFn': math.nan, 'weakFilter': 0, 'weakScale': 1.0},
}
REFERENCE_BASES = {'Gl1_Sphere': ['Sphere'], 'Gl1_Facet': ['Facet'], 'Gl1_Wall': ['Wall'], 'Gl1_Box': ['Box'],
                   'Gl1_Aabb': ['Aabb'], 'Gl1_NormPhys': ['NormPhys']}
REFERENCE_SNAPSHOT = {'format': 'PNG', 'fileBase': '', 'counter': 0, 'ignoreErrors': True, 'snapshots': [],
                      'msecSleep': 0, 'deadTimeout': 3.0, 'plot': ''}


def same(a, b):
    if isinstance(b, float) and math.isnan(b):
        return math.isnan(a)
    if isinstance(b, tuple):
        return len(a) == len(b) and all(abs(x - y) < 1e-15 for x, y in zip(a, b))
    return a == b and type(a) is type(b)


def reference_gl1_defaults():
    for cls, attrs in REFERENCE_GL1.items():
        for k, v in attrs.items():
            setattr(globals()[cls], k, v)


@pytest.fixture(autouse=True)
def restore_gl1():
    """Class-wide settings outlive a test (test_persistence's round trip fills them): the reference's defaults
    before and after each test. The defaults themselves are checked in a fresh process."""
    reference_gl1_defaults()
    yield
    reference_gl1_defaults()


def test_renderer_has_the_references_settings_and_is_one_per_session():
    r = OpenGLRenderer()
    d = r.dict()
    assert set(d) == set(REFERENCE_RENDERER)
    for k, v in REFERENCE_RENDERER.items():
        assert same(tuple(d[k]) if isinstance(v, tuple) else d[k], v), k
    assert qt.Renderer() is qt.Renderer()
    qt.Renderer().intrAllWire = True
    O.reset()
    assert qt.Renderer().intrAllWire is True  # the reference keeps it across O.reset() too
    qt.Renderer().intrAllWire = False


def test_renderer_refuses_bad_values_and_keeps_the_old_one():
    r = qt.Renderer()
    with pytest.raises(TypeError, match="bgColor"):
        r.bgColor = "red"
    with pytest.raises(ValueError, match="bgColor"):
        r.bgColor = (float('nan'), 0, 0)
    assert tuple(r.bgColor) == (0.2, 0.2, 0.2)
    with pytest.raises(AttributeError, match="shapes"):
        r.shapes = False
    r.extraDrawers = [GlExtraDrawer()]
    assert len(r.extraDrawers) == 1
    with pytest.raises(TypeError, match="extraDrawers"):
        r.extraDrawers = [Sphere()]
    assert len(r.extraDrawers) == 1
    r.extraDrawers = []


def test_drawing_functors_have_the_references_settings():
    """Checked in a fresh process: class-wide values set by other tests outlive them."""
    script = textwrap.dedent("""\
        import json, math, yade
        out = {}
        for name in %r:
            c = getattr(yade, name)
            d = c().dict()
            d.pop('label')
            out[name] = {'dict': {k: (repr(v) if isinstance(v, float) and not math.isfinite(v) else v) for k, v in d.items()},
                         'class': {k: repr(getattr(c, k)) for k in d}, 'bases': c().bases}
        print(json.dumps(out))
    """ % sorted(REFERENCE_GL1))
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build")))
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout)
    for cls, ref in REFERENCE_GL1.items():
        d = got[cls]['dict']
        assert set(d) == set(ref), cls
        for k, v in ref.items():
            value = float(d[k]) if isinstance(d[k], str) and d[k] in ('inf', 'nan') else d[k]
            assert same(value, v), (cls, k, d[k])
            assert got[cls]['class'][k] == repr(v), (cls, k)  # read from the class as well
        assert got[cls]['bases'] == REFERENCE_BASES[cls]


def test_drawing_settings_are_one_value_for_the_class():
    a, b = Gl1_Sphere(), Gl1_Sphere()
    Gl1_Sphere.stripes = True  # the reference's examples set them this way (14 of them: stripes)
    assert a.stripes is True and b.stripes is True and Gl1_Sphere().stripes is True
    a.quality = 3  # through an instance: the class changes too, as in the reference
    assert Gl1_Sphere.quality == 3.0 and b.quality == 3.0
    Gl1_Wall(div=7)  # a keyword of the constructor sets the class's value
    assert Gl1_Wall.div == 7
    assert Gl1_Facet.normals is False  # other classes are untouched
    assert isinstance(Gl1_Sphere.__dict__['quality'].__doc__, str) and "one value for the class" in Gl1_Sphere.__dict__['quality'].__doc__


def test_drawing_settings_refuse_bad_values_and_keep_the_old_one():
    with pytest.raises(TypeError, match="Gl1_Sphere.quality"):
        Gl1_Sphere.quality = "high"
    with pytest.raises(ValueError, match="Gl1_Sphere.quality"):
        Gl1_Sphere.quality = -1
    with pytest.raises(ValueError, match="Gl1_Wall.div"):
        Gl1_Wall().div = 0
    assert Gl1_Sphere.quality == 1.0 and Gl1_Wall.div == 20
    assert isinstance(Gl1_Sphere.__dict__['quality'], property)  # still the attribute, not replaced by a value


def test_the_view_keeps_camera_settings_and_refuses_bad_ones():
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        v = qt.View()
        qt.View().close()
    assert all(issubclass(x.category, UserWarning) for x in w)
    assert v in qt.views()
    # the reference's defaults for a fresh view
    assert tuple(v.viewDir) == (0, 0, -1) and tuple(v.upVector) == (0, 1, 0) and v.ortho is False
    assert tuple(v.screenSize) == (550, 550) and v.sceneRadius == 1.5 and v.timeDisp == 'rvi' and v.selection == -1
    v.eyePosition = (1, 2, 3)
    v.viewDir = Vector3(0, 1, 0)
    v.grid = (False, True, False)
    v.ortho = True
    assert v.eyePosition == Vector3(1, 2, 3) and v.viewDir == Vector3(0, 1, 0)
    assert v.grid == (False, True, False) and v.ortho is True
    with pytest.raises(AttributeError, match="eyePos.*eyePosition"):
        v.eyePos = (0, 0, 0)
    with pytest.raises(TypeError, match="viewDir"):
        v.viewDir = (0, 1)
    with pytest.raises(ValueError, match="sceneRadius"):
        v.sceneRadius = 0
    with pytest.raises(ValueError, match="timeDisp"):
        v.timeDisp = 'x'
    assert v.viewDir == Vector3(0, 1, 0) and v.sceneRadius == 1.5
    v.center()
    v.fitAABB((0, 0, 0), (1, 1, 1))
    v.showEntireScene()
    v.close()
    assert v not in qt.views()


def test_view_controller_inspector_warn_once_and_do_nothing():
    script = textwrap.dedent("""\
        import warnings
        warnings.simplefilter('default')
        from yade import qt
        for i in range(3):
            v = qt.View()
            print('controller', qt.Controller(), 'inspector', qt.Inspector())
        print('views', len(qt.views()))
    """)
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                       env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build")))
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("controller None inspector None") == 3 and "views 3" in r.stdout
    for what in ("View()", "Controller()", "Inspector()"):
        assert r.stderr.count("yade.qt.%s: there is no display" % what) == 1, r.stderr


def test_snapshot_engine_has_the_references_settings_warns_once_and_saves_nothing(tmp_path):
    s = qt.SnapshotEngine(fileBase=str(tmp_path / 'frame-'), iterPeriod=2)
    assert qt.SnapshotEngine is SnapshotEngine
    d = SnapshotEngine().dict()
    for k, v in REFERENCE_SNAPSHOT.items():
        assert same(d[k], v), k
    script = textwrap.dedent("""\
        import os, sys
        from yade import *
        from yade import qt
        O.bodies.append(utils.sphere((0, 0, 0), 1))
        O.engines = [qt.SnapshotEngine(fileBase=sys.argv[1], iterPeriod=2, label='snap'), NewtonIntegrator()]
        O.dt = 1e-3
        O.run(10, True)
        O.run(10, True)
        print('iter', O.iter, 'counter', snap.counter, 'snapshots', snap.snapshots, 'files', os.listdir(os.path.dirname(sys.argv[1])))
        snap.ignoreErrors = False
        try:
            O.run(2, True)
        except RuntimeError as e:
            print('refused', 'ignoreErrors' in str(e), O.iter)
    """)
    r = subprocess.run([sys.executable, "-c", script, str(tmp_path / 'frame-')], capture_output=True, text=True,
                       timeout=120, env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build")))
    assert r.returncode == 0, r.stderr
    assert "iter 20 counter 0 snapshots [] files []" in r.stdout
    assert r.stderr.count("SnapshotEngine: there is no 3D view") == 1, r.stderr
    assert "refused True" in r.stdout
    assert s.counter == 0


def test_snapshot_engine_and_settings_save_and_load(tmp_path):
    O.reset()
    O.engines = [SnapshotEngine(fileBase='f-', iterPeriod=5, counter=3, format='JPEG', label='snap')]
    f = str(tmp_path / 's.yade')
    O.save(f)
    O.reset()
    O.load(f)
    e = O.engines[0]
    assert (e.fileBase, e.iterPeriod, e.counter, e.format, e.label) == ('f-', 5, 3, 'JPEG', 'snap')
    O.reset()


def test_a_script_in_the_references_gui_style_runs_headless(tmp_path):
    """The lines the reference's examples use most (qt.View 161 times, qt.Controller 66, qt.Renderer 58,
    v.viewDir/eyePosition/upVector/ortho, Gl1_Sphere.stripes 14) in one script, run with -n -x."""
    script = tmp_path / "gui.py"
    script.write_text(textwrap.dedent("""\
        from yade import qt
        O.bodies.append([sphere((0, 0, i), 0.5) for i in range(3)])
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     NewtonIntegrator(gravity=(0, 0, -9.81)),
                     qt.SnapshotEngine(fileBase='/nonexistent/frame-', iterPeriod=10)]
        O.dt = 1e-4
        Gl1_Sphere.stripes = True
        rr = qt.Renderer()
        rr.shape = True
        rr.intrPhys = True
        Gl1_NormPhys.maxRadius = 0.1
        qt.Controller()
        v = qt.View()
        v.eyePosition = Vector3(0, -10, 1); v.upVector = (0, 0, 1); v.viewDir = (0, 1, 0); v.ortho = True
        v.grid = (False, True, False)
        O.run(50, True)
        print('done', O.iter, Gl1_Sphere.stripes, v.ortho)
    """))
    r = subprocess.run([os.path.join(ROOT, "yade"), "-n", "-x", str(script)], capture_output=True, text=True,
                       timeout=120, cwd=str(tmp_path))
    assert r.returncode == 0, r.stderr
    assert "done 50 True True" in r.stdout


def test_display_frame_gathers_what_the_view_draws():
    """_displayFrame (C++, one pass per frame) against the scene, number by number: it needs no display."""
    import numpy
    from yade import _yade
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 0.5, color=(1, 0, 0)))
    O.bodies.append(utils.sphere((0.9, 0, 0), 0.5, color=(0, 1, 0), wire=True))
    f = utils.facet([(0, 0, -1), (1, 0, -1), (0, 1, -1)], color=(0, 0, 1))
    O.bodies.append(f)
    O.bodies.append(utils.wall(-2, axis=2, sense=1))
    O.bodies.append(utils.box((5, 0, 0), (1, 2, 3), orientation=Quaternion((0, 0, 1), 0.5)))
    O.bodies.append(utils.sphere((9, 9, 9), 1, mask=2))
    O.bodies.erase(5)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb(), Bo1_Box_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                 [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator()]
    O.dt = 1e-6
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # (no Ig2 functor for the box's pairs)
        O.step()
    d = _yade._displayFrame()
    names = list(d['drawers'])
    assert {'Gl1_Sphere', 'Gl1_Facet', 'Gl1_Wall', 'Gl1_Box'} <= set(names)
    assert [names[k] if k >= 0 else k for k in d['drawer']] == ['Gl1_Sphere', 'Gl1_Sphere', 'Gl1_Facet', 'Gl1_Wall', 'Gl1_Box', -1]
    assert d['undrawn'] == set()
    assert numpy.allclose(d['pos'][:5], [b.state.pos for b in O.bodies][:5])
    assert numpy.allclose(d['size'][0], [0.5, 0, 0]) and numpy.allclose(d['size'][3], [2, 1, 0])  # wall: axis, sense
    assert numpy.allclose(d['size'][4], [1, 2, 3])
    assert numpy.allclose(d['rot'][4], O.bodies[4].state.ori.toRotationMatrix())
    assert numpy.allclose(d['color'][:3], [(1, 0, 0), (0, 1, 0), (0, 0, 1)])
    assert list(d['wire'][:2]) == [False, True]
    assert d['mask'][5] == 0 and d['mask'][0] == 1
    assert list(d['triangleBody']) == [2]
    world = [f.state.pos + f.state.ori * v for v in f.shape.vertices]
    assert numpy.allclose(d['triangleCorners'][0], world) and numpy.allclose(d['triangleCorners'][0], [(0, 0, -1), (1, 0, -1), (0, 1, -1)])
    assert numpy.allclose(d['boundMin'][0], O.bodies[0].bound.min) and numpy.isnan(d['boundMin'][5]).all()
    i = O.interactions[0, 1]
    assert [sorted(p) for p in d['contactIds'].tolist()] == [[0, 1]]
    fn = i.phys.normalForce.dot(i.geom.normal)
    assert fn > 0 and d['contactFn'][0] == pytest.approx(fn, rel=1e-12)  # positive in compression
    assert sorted(map(sorted, d['pairIds'].tolist())) == sorted(sorted((i.id1, i.id2)) for i in O.interactions.all())
    assert d['cellHSize'] is None and d['iter'] == 1 and d['time'] == pytest.approx(1e-6)
    O.periodic = True
    O.cell.setBox(10, 11, 12)
    assert numpy.allclose(_yade._displayFrame()['cellHSize'], numpy.diag([10, 11, 12]))
    # a shape class no drawing functor draws is named; a clump is drawn as its members
    O.reset()
    O.bodies.append(Body(shape=Shape(), state=State()))
    cid, ids = O.bodies.appendClumped([utils.sphere((0, 0, 0), 1), utils.sphere((1, 0, 0), 1)])
    d = _yade._displayFrame()
    assert d['undrawn'] == {'Shape'} and d['drawer'][0] == -1 and d['drawer'][cid] == -2
    assert all(d['drawers'][d['drawer'][i]] == 'Gl1_Sphere' for i in ids)
    O.reset()


def test_a_script_pause_while_the_view_holds_the_run_stops_it():
    """A frame holds the run between two steps and resumes it after; an O.pause() the script made meanwhile
    (a PyRunner, here one that takes 0.2 s, during which the frame waits) wins: the run stays stopped."""
    from yade import _yade
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), 0.5))
    O.engines = [PyRunner(command='import time; from yade import O; time.sleep(.2); O.pause()', iterPeriod=50)]
    O.dt = 1e-3
    O.run()
    import time
    end = time.monotonic() + 30
    frames = 0
    while O.running and time.monotonic() < end:  # (without the fix the view resumed the run: it never stopped)
        _yade._displayFrame(pauseRun=True)
        frames += 1
    running = O.running
    O.pause()
    assert not running and O.iter == 51 and frames > 0
