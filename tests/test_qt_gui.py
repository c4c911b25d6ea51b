"""The 3D view, the controller and the inspector with a display (issue 37), under Xvfb: each test runs a script in
its own process (`xvfb-run`), which prints what it measured as JSON; the assertions are on pixels of the
rendered images, on files written, and on what the windows' API did to the scene.

Skipped when xvfb-run, PyQt5 or PyOpenGL is missing (the headless module is tested in test_qt_headless.py)."""
import json
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _missing():
    if not shutil.which("xvfb-run"):
        return "xvfb-run is not installed (apt-get install xvfb)"
    for module in ("PyQt5.QtWidgets", "OpenGL.GL"):
        r = subprocess.run([sys.executable, "-c", "import " + module], capture_output=True)
        if r.returncode != 0:
            return "%s is not installed" % module
    return ""


pytestmark = pytest.mark.skipif(bool(_missing()), reason=_missing() or "ok")

PRELUDE = """\
import json, os, sys
import numpy
from yade import *
from yade import qt
assert qt.noView == '', qt.noView
from PyQt5.QtGui import QImage

def pixel(img, x, y):
    c = img.pixelColor(int(round(x)), int(round(y)))
    return [c.red(), c.green(), c.blue()]

def projected(v, points):
    w = v._widget
    return v._camera.project(numpy.array(points, dtype=float), w.width(), w.height())
"""


def run(tmp_path, body, launcher=False, timeout=240):
    script = tmp_path / "gui_script.py"
    script.write_text(PRELUDE + textwrap.dedent(body))
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "build"), XDG_RUNTIME_DIR=str(tmp_path))
    cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"]
    cmd += [os.path.join(ROOT, "yade"), "-x", str(script)] if launcher else [sys.executable, str(script)]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    lines = [l for l in r.stdout.splitlines() if l.startswith("{")]
    assert lines, r.stdout[-3000:] + r.stderr[-3000:]
    return json.loads(lines[-1])


def close(a, b, tol=40):
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def test_view_draws_spheres_facets_and_the_background_where_the_camera_says(tmp_path):
    out = run(tmp_path, """
        O.bodies.append(utils.sphere((0, 0, 0), 1, color=(1, 0, 0)))
        O.bodies.append(utils.sphere((3, 0, 0), 0.5, color=(0, 1, 0)))
        O.bodies.append(utils.facet([(-2, -2, -1.5), (4, -2, -1.5), (1, 3, -1.5)], color=(0, 0, 1), wire=True))
        v = qt.View()
        v.saveSnapshot('a.png')
        img = QImage('a.png')
        (rx, ry), (gx, gy), (ex, ey) = projected(v, [(0, 0, 0), (3, 0, 0), (1, -2, -1.5)])
        res = dict(size=[img.width(), img.height()], red=pixel(img, rx, ry), green=pixel(img, gx, gy),
                   edge=max((pixel(img, ex, ey + d) for d in (-1, 0, 1)), key=lambda c: c[2]),
                   corner=pixel(img, 3, 3), between=pixel(img, (rx + gx) / 2, ry - 0.3 * img.height()),
                   eye=list(v.eyePosition), sceneRadius=v.sceneRadius)
        qt.Renderer().bgColor = (0, 0, 1)
        qt.Renderer().shape = False
        v.saveSnapshot('b.png')
        img = QImage('b.png')
        res.update(cornerBlue=pixel(img, 3, 3), redHidden=pixel(img, rx, ry))
        print(json.dumps(res))
    """)
    assert out["size"] == [550, 550]  # the reference's default view size
    assert out["red"][0] > 150 and out["red"][1] < 60 and out["red"][2] < 60, out  # the red sphere's centre
    assert out["green"][1] > 150 and out["green"][0] < 60, out
    assert out["edge"][2] > 150 and out["edge"][0] < 60, out  # on the facet's lower edge: its blue wire
    assert close(out["corner"], [51, 51, 51], 3)  # OpenGLRenderer.bgColor (0.2, 0.2, 0.2)
    assert close(out["between"], [51, 51, 51], 3)
    assert close(out["cornerBlue"], [0, 0, 255], 3)
    assert close(out["redHidden"], [0, 0, 255], 3)  # OpenGLRenderer.shape = False: nothing drawn
    # the first view is centred on the scene, seen along -z as the reference's
    assert out["eye"][0] == pytest.approx(1.0) and out["eye"][1] == pytest.approx(0.5) and out["eye"][2] > 5


def test_camera_settings_move_what_is_drawn(tmp_path):
    out = run(tmp_path, """
        O.bodies.append(utils.sphere((0, 0, 0), 1, color=(1, 0, 0)))
        v = qt.View()
        v.eyePosition = (0, -10, 0)
        v.viewDir = (0, 1, 0)
        v.upVector = (0, 0, 1)
        v.saveSnapshot('a.png')
        a = QImage('a.png')
        (x, y), = projected(v, [(0, 0, 0)])
        v.eyePosition = (0, -10, 2)  # the camera goes up: the sphere goes down on the image
        v.saveSnapshot('b.png')
        b = QImage('b.png')
        (x2, y2), = projected(v, [(0, 0, 0)])
        v.ortho = True
        v.saveSnapshot('c.png')
        print(json.dumps(dict(center=[x, y], centerA=pixel(a, x, y), after=[x2, y2], centerB=pixel(b, x2, y2),
                              oldSpotB=pixel(b, x, y - 0.2 * b.height()), orthoCenter=pixel(QImage('c.png'), x2, y2),
                              lookAt=list(v.lookAt))))
    """)
    assert out["center"] == pytest.approx([275, 275], abs=1)
    assert out["centerA"][0] > 150
    assert out["after"][1] > out["center"][1] + 50  # lower on the image
    assert out["centerB"][0] > 150
    assert close(out["oldSpotB"], [51, 51, 51], 3)
    assert out["orthoCenter"][0] > 150
    assert out["lookAt"] == pytest.approx([0, -9, 2])  # eyePosition + viewDir, as the reference's


def test_force_chains_bounds_and_periodic_cell(tmp_path):
    out = run(tmp_path, """
        O.periodic = True
        O.cell.setBox(4, 4, 4)
        O.bodies.append([utils.sphere((1.5, 2, 2), 0.52, color=(.5, .5, .5)), utils.sphere((2.5, 2, 2), 0.52, color=(.5, .5, .5))])
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator()]
        O.dt = 1e-6
        O.step()
        v = qt.View()
        r = qt.Renderer()
        r.shape = False
        v.saveSnapshot('none.png')
        r.intrPhys = True
        v.saveSnapshot('chains.png')
        r.intrPhys = False
        r.bound = True
        v.saveSnapshot('bounds.png')
        lo, hi = O.bodies[0].bound.min, O.bodies[0].bound.max  # (on an edge of the box: x = min, z = max)
        (mx, my), (c0x, c0y), (c1x, c1y), (bx, by) = projected(v, [(2, 2, 2), (0, 0, 4), (4, 0, 4), (lo[0], (lo[1] + hi[1]) / 2, hi[2])])
        cellEdge = [(c0x + c1x) / 2, (c0y + c1y) / 2]
        none, chains, bounds = QImage('none.png'), QImage('chains.png'), QImage('bounds.png')
        print(json.dumps(dict(contacts=O.interactions.countReal(), midNone=pixel(none, mx, my), midChains=pixel(chains, mx, my),
                              cell=max((pixel(none, cellEdge[0], cellEdge[1] + d) for d in (-1, 0, 1)), key=sum),
                              bound=max((pixel(bounds, bx + dx, by + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)), key=sum))))
    """)
    assert out["contacts"] == 1
    assert close(out["midNone"], [51, 51, 51], 3)
    assert out["midChains"] != out["midNone"] and max(out["midChains"]) > 100  # the band of the contact's force
    assert out["cell"][0] > 150 and out["cell"][1] > 150 and out["cell"][2] < 60  # OpenGLRenderer.cellColor: yellow
    assert out["bound"][0] > 150 and out["bound"][1] > 150  # the Aabb's edge


def test_snapshot_engine_writes_numbered_frames_of_a_script_run_with_x(tmp_path):
    """The reference times out here (its view waits for the script, which waits for the run) and writes nothing."""
    out = run(tmp_path, """
        O.bodies.append([utils.sphere((0, 0, 3), 0.5, color=(1, 0, 0)), utils.wall(0, axis=2)])
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                     InteractionLoop([Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     NewtonIntegrator(gravity=(0, 0, -9.81), damping=0),
                     qt.SnapshotEngine(fileBase='frames/f-', iterPeriod=500, label='snap')]
        O.dt = 1e-4
        os.makedirs('frames')
        v = qt.View()
        v.eyePosition = (0, -12, 2); v.viewDir = (0, 1, 0); v.upVector = (0, 0, 1)
        O.run(5000, True)  # 0.5 s: the sphere falls 1.2 m
        first, last = QImage(snap.snapshots[0]), QImage(snap.snapshots[-1])
        (x, y), (x1, y1) = projected(v, [(0, 0, 3), O.bodies[0].state.pos])
        print(json.dumps(dict(files=sorted(os.listdir('frames')), snapshots=snap.snapshots, counter=snap.counter,
                              size=[last.width(), last.height()], startFirst=pixel(first, x, y), startLast=pixel(last, x, y),
                              nowLast=pixel(last, x1, y1), z=O.bodies[0].state.pos[2])))
    """, launcher=True)
    # 9 frames in 5 000 steps every 500, as the reference's PeriodicEngine counts them (3 in 20 steps every 5)
    assert out["files"] == ["f-%05d.png" % i for i in range(9)]
    assert out["snapshots"] == ["frames/f-%05d.png" % i for i in range(9)] and out["counter"] == 9
    assert out["size"] == [550, 550]
    assert out["z"] == pytest.approx(3 - 9.81 * 0.5 ** 2 / 2, abs=1e-3)
    assert out["startFirst"][0] > 150  # the sphere where it started, in the first frame
    assert close(out["startLast"], [51, 51, 51], 3)  # gone from there in the last (taken at step 4 500)
    assert out["nowLast"][0] > 150  # and near where it is now


@pytest.mark.skipif(not shutil.which("ffmpeg"), reason="ffmpeg is not installed")
def test_make_video_from_snapshot_engine_frames(tmp_path):
    out = run(tmp_path, """
        import subprocess
        O.bodies.append(utils.sphere((0, 0, 0), 0.5, color=(1, 0, 0)))
        O.engines = [NewtonIntegrator(gravity=(0, 0, -9.81), damping=0), qt.SnapshotEngine(fileBase='frames/f-', iterPeriod=20, label='snap')]
        O.dt = 1e-3
        os.makedirs('frames')
        v = qt.View()
        O.run(201, True)
        a = makeVideo(snap.snapshots, 'movie.avi', fps=10)
        b = makeVideo('frames/f-%05d.png', 'movie.avi', fps=10)  # renamed: movie-1.avi
        c = makeVideo('frames/f-*.png', 'movie.avi', fps=10, renameNotOverwrite=False)
        probe = subprocess.run(['ffprobe', '-v', 'error', '-count_frames', '-select_streams', 'v:0', '-show_entries',
                                'stream=nb_read_frames,width,height,codec_name', '-of', 'json', 'movie.avi'],
                               capture_output=True, text=True).stdout
        errors = []
        for bad in ('nothing-*.png', ['frames/f-00000.png', 'frames/missing.png']):
            try:
                makeVideo(bad, 'x.avi')
            except ValueError as e:
                errors.append(str(e))
        print(json.dumps(dict(frames=len(snap.snapshots), names=[a, b, c], probe=json.loads(probe)['streams'][0], errors=errors)))
    """, launcher=True)
    assert out["frames"] == 10
    assert out["names"] == ["movie.avi", "movie-1.avi", "movie.avi"]
    p = out["probe"]
    assert p["codec_name"] == "mpeg4" and int(p["nb_read_frames"]) == 10 and (p["width"], p["height"]) == (550, 550)
    assert "no frames match" in out["errors"][0] and "do not exist" in out["errors"][1]


def test_inspector_shows_and_edits_attributes_and_refuses_bad_values(tmp_path):
    out = run(tmp_path, """
        O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((3, 0, 0), 1)])
        O.engines = [NewtonIntegrator(damping=0.2, label='newton')]
        ins = qt.Inspector()
        res = {}
        ins.select(O.engines[0])
        res['damping'] = ins.value('damping')
        res['setDamping'] = ins.setAttribute('damping', '0.35')
        res['damping2'] = newton.damping
        res['badDamping'] = ins.setAttribute('damping', '"much"')
        res['damping3'] = newton.damping
        ins.select(O.bodies[1].shape)
        res['setRadius'] = ins.setAttribute('radius', '0.25')
        res['radius'] = O.bodies[1].shape.radius
        res['badRadius'] = ins.setAttribute('radius', 'float("nan")')
        res['radius2'] = O.bodies[1].shape.radius
        res['color'] = ins.setAttribute('color', 'Vector3(1, 0, 0)') is None and list(O.bodies[1].shape.color)
        v = qt.View()
        (x, y), = projected(v, [(3, 0, 0)])
        v._widget.renderFrame()
        res['picked'] = v._widget.select(x, y)
        res['selection'] = v.selection
        res['selId'] = qt.Renderer().selId
        res['inspected'] = [ins.value('id'), ins.value('shape')]
        ins.rebuild()
        res['tree'] = [ins.tree.topLevelItem(i).text(0) for i in range(ins.tree.topLevelItemCount())]
        print(json.dumps(res))
    """)
    assert out["damping"] == "0.2" and out["setDamping"] is None and out["damping2"] == 0.35
    assert out["badDamping"].startswith("TypeError") and out["damping3"] == 0.35
    assert out["setRadius"] is None and out["radius"] == 0.25
    assert out["badRadius"].startswith("ValueError") and out["radius2"] == 0.25
    assert out["color"] == [1, 0, 0]
    assert out["picked"] == 1 and out["selection"] == 1 and out["selId"] == 1
    assert out["inspected"] == ["1", "[Sphere]"]  # the inspector follows the view's selection: body 1
    assert out["tree"] == ["Engines", "Bodies (2)", "Interactions (0)"]


def test_controller_runs_steps_sets_dt_and_runs_commands(tmp_path):
    out = run(tmp_path, """
        O.bodies.append(utils.sphere((0, 0, 0), 1))
        O.engines = [NewtonIntegrator(gravity=(0, 0, -10))]
        O.dt = 1e-3
        c = qt.Controller()
        res = {}
        c.step(); c.step()
        res['iter'] = O.iter
        c.dtEdit.setText('2e-4'); c.applyDt()
        res['dt'] = O.dt
        c.dtEdit.setText('fast'); c.applyDt()
        res['dtBad'] = [O.dt, c.message.text(), c.dtEdit.text()]
        c.dtEdit.setText('-1'); c.applyDt()
        res['dtNegative'] = [O.dt, c.message.text()]
        res['command'] = c.runCommand('O.iter + 40')
        res['commandError'] = c.runCommand('O.bodies[7]')
        c.switches['bound'].setChecked(True)
        res['bound'] = qt.Renderer().bound
        c.runOrPause()
        import time; time.sleep(0.2)
        running = O.running
        c.runOrPause()
        res['ran'] = [running, O.running, O.iter > 2]
        c.refresh()
        res['labels'] = [c.iterLabel.text(), c.dtState.text(), c.runButton.text()]
        print(json.dumps(res))
    """)
    assert out["iter"] == 2
    assert out["dt"] == 2e-4
    assert out["dtBad"][0] == 2e-4 and out["dtBad"][1].startswith("ValueError") and out["dtBad"][2] == "0.0002"
    assert out["dtNegative"][0] == 2e-4 and out["dtNegative"][1] != ""
    assert out["command"] == "42"
    assert out["commandError"].startswith("IndexError")
    assert out["bound"] is True
    assert out["ran"] == [True, False, True]
    assert out["labels"][0].startswith("#") and out["labels"][1] == "(fixed)" and out["labels"][2] == "Run"


def test_live_plot_follows_a_run_while_the_script_waits(tmp_path):
    out = run(tmp_path, """
        import time
        from yade import plot
        O.bodies.append(utils.sphere((0, 0, 0), 1))
        O.engines = [NewtonIntegrator(gravity=(0, 0, -10)), PyRunner(command='plot.addData(i=O.iter, z=O.bodies[0].state.pos[2])', iterPeriod=1)]
        O.dt = 1e-3
        plot.plots = {'i': ('z',)}
        plot.liveInterval = 0.05
        O.run(5, True)
        plot.plot()
        fig = plot._liveFigures[0]
        before = len(fig._yadeLines[0][0].get_xdata())
        O.engines = O.engines + [PyRunner(command='time.sleep(0.002)', iterPeriod=1)]
        t0 = time.time()
        O.run(300, True)  # about a second, the main thread waiting in C++
        lines = fig._yadeLines[0][0]
        print(json.dumps(dict(before=before, after=len(lines.get_xdata()), records=len(plot.data['i']),
                              wall=time.time() - t0, backend=__import__('matplotlib').get_backend())))
    """, launcher=True)
    assert "qt" in out["backend"].lower()
    assert out["before"] < 10 and out["records"] > 300
    assert out["after"] > 100  # the figure was redrawn during the run, not only before it (a few points then)


def test_launcher_prompt_opens_the_controller_and_f11_f12_keys_open_windows(tmp_path):
    """./yade without -x: the prompt with the controller open (the manual: started automatically), F11 a view."""
    import pty
    import select
    import time
    pid, fd = pty.fork()
    if pid == 0:
        os.environ["XDG_RUNTIME_DIR"] = str(tmp_path)
        os.execvp("xvfb-run", ["xvfb-run", "-a", os.path.join(ROOT, "yade")])
    out = b""

    def readUntil(token, limit=60):
        nonlocal out
        end = time.time() + limit
        while time.time() < end and token not in out:
            r, _, _ = select.select([fd], [], [], 0.1)
            if r:
                try:
                    out += os.read(fd, 65536)
                except OSError:
                    return
    try:
        readUntil(b"Yade [")  # (the prompt; its number comes in another color)
        os.write(fd, b"\x1b[23~")  # F11
        time.sleep(1)
        os.write(fd, b"import yade.qt; print('WINDOWS', len(yade.qt.views()), yade.qt._controller is not None, 'END')\r")
        readUntil(b"WINDOWS 1 True END", 30)
        os.write(fd, b"exit()\r")
    finally:
        # the whole group (pty.fork made the child a session leader): xvfb-run's Xvfb too, which killing
        # xvfb-run alone left running
        try:
            os.killpg(pid, 9)
        except OSError:
            pass
        os.waitpid(pid, 0)
    assert b"WINDOWS 1 True END" in out, out.decode(errors="replace")[-2000:]


def test_view_follows_a_background_run(tmp_path):
    """O.run() in the background while the view draws: each frame pauses the loop at the end of a step to take
    its arrays (never in the middle of one), and the run goes on."""
    out = run(tmp_path, """
        import time
        O.bodies.append([utils.sphere((i, 0, 0), 0.45) for i in range(200)])
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     NewtonIntegrator(gravity=(0, 0, -1), damping=0)]
        O.dt = 1e-4
        v = qt.View()
        O.run()
        iters = []
        t0 = time.time()
        while time.time() - t0 < 1.5:
            v._widget.renderFrame()
            iters.append(int(v._widget.frame['iter']))
            qt._processEvents()
        running = O.running
        O.pause()
        z = O.bodies[0].state.pos[2]
        print(json.dumps(dict(iters=iters, running=running, iter=O.iter, z=z, t=O.time)))
    """)
    iters = out["iters"]
    assert out["running"] and len(iters) >= 5
    assert iters == sorted(iters) and iters[-1] > iters[0]  # frames of later and later steps
    n = out["iter"]
    assert out["z"] == pytest.approx(-1e-8 * n * (n + 1) / 2, rel=1e-9)  # the leapfrog's free fall: every step whole


def test_stripes_axes_grid_and_ids(tmp_path):
    out = run(tmp_path, """
        O.bodies.append(utils.sphere((0, 0, 0), 1, color=(1, 0, 0)))
        v = qt.View()
        v.eyePosition = (0, 0, 10)
        def reds(img):  # the red channel over a ring of points inside the sphere's disk
            (cx, cy), (ex, ey) = projected(v, [(0, 0, 0), (0.6, 0, 0)])
            r = ex - cx
            import math
            return [pixel(img, cx + r * math.cos(a / 24 * 2 * math.pi), cy + r * math.sin(a / 24 * 2 * math.pi))[0] for a in range(24)]
        v.saveSnapshot('plain.png')
        Gl1_Sphere.stripes = True
        v.saveSnapshot('stripes.png')
        Gl1_Sphere.stripes = False
        v.axes = True
        v.grid = (False, False, True)
        v.saveSnapshot('axes.png')
        (ax, ay), = projected(v, [(0.8 * v.sceneRadius, 0, 0)])
        (gx, gy), = projected(v, [(-v.sceneRadius, 0.5 * v.sceneRadius, 0)])
        v.axes, v.grid = False, (False, False, False)
        qt.Renderer().id = True
        v.saveSnapshot('ids.png')
        (cx, cy), = projected(v, [(0, 0, 0)])
        ids = QImage('ids.png'); plain = QImage('plain.png')
        idPixels = sum(pixel(ids, cx + dx, cy + dy) != pixel(plain, cx + dx, cy + dy) for dx in range(-6, 7) for dy in range(-12, 3))
        print(json.dumps(dict(plain=reds(QImage('plain.png')), stripes=reds(QImage('stripes.png')),
                              axis=max((pixel(QImage('axes.png'), ax, ay + d) for d in (-1, 0, 1)), key=lambda c: c[0]),
                              grid=max((pixel(QImage('axes.png'), gx + d, gy) for d in (-1, 0, 1)), key=sum), idPixels=idPixels)))
    """)
    plain, stripes = out["plain"], out["stripes"]
    # sectors alternate round the ring: some as without stripes, some darker
    assert sum(s < 0.8 * p for s, p in zip(stripes, plain)) >= 6
    assert sum(abs(s - p) <= 0.1 * p for s, p in zip(stripes, plain)) >= 6
    assert out["axis"][0] > 200 and out["axis"][1] < 60  # the x axis, red
    assert out["grid"][0] == out["grid"][1] == out["grid"][2] and out["grid"][0] > 100  # a grey grid line
    assert out["idPixels"] > 5  # "0" written at the sphere's centre


def test_a_shape_no_drawing_functor_draws_is_named_once(tmp_path):
    out = run(tmp_path, """
        import warnings
        O.bodies.append([Body(shape=Shape(), state=State()), utils.sphere((0, 0, 0), 1, color=(1, 0, 0))])
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter('always')
            v = qt.View()
            v.saveSnapshot('a.png')
            v.saveSnapshot('b.png')
        (x, y), = projected(v, [(0, 0, 0)])
        print(json.dumps(dict(messages=[str(m.message) for m in w], red=pixel(QImage('b.png'), x, y))))
    """)
    assert out["messages"] == ["yade.qt: no drawing functor draws Shape bodies (a Gl1_Shape class); they are not drawn"]
    assert out["red"][0] > 150  # the others are drawn


def test_tutorial_05_makes_its_video_from_the_snapshots(tmp_path):
    """examples/tutorial/05-3d-postprocessing.py as the manual gives it, with its 3D view: the SnapshotEngine's
    100 frames (the last taken in the step finish() runs in) become 3d.mpeg, and the run stops at 20 000."""
    script = os.path.join(ROOT, "examples", "tutorial", "05-3d-postprocessing.py")
    out = run(tmp_path, """
        exec(open(%r).read())
        O.run(); O.wait()
        print(json.dumps(dict(iter=O.iter, frames=len(snapshot.snapshots), video=os.path.getsize('3d.mpeg'))))
    """ % script, launcher=True)
    assert out["iter"] == 20001 and out["frames"] == 100 and out["video"] > 10000
