"""The reference's Qt GUI module: ``qt.View()``, ``qt.Controller()``, ``qt.Inspector()``, ``qt.Renderer()``,
``qt.SnapshotEngine``, ``qt.views()`` (doc/gui.md).

With a display (``DISPLAY`` set, no ``-n``), PyQt5 and PyOpenGL, these open windows: the 3D view
(glwidget.py, drawing.py), the controller (controller.py) and the inspector (inspector.py). Without them
importing this module still succeeds, unlike the reference's, so that scripts written with a view run
unchanged in batch jobs and on cluster nodes:

- ``View()`` warns once and gives a view object that takes the camera settings scripts make (``eyePosition``,
  ``viewDir``, ``upVector``, ``ortho``, ``grid``...) and draws nothing; ``Controller()`` and ``Inspector()`` warn
  once and return None, as the reference's Controller() does;
- the renderer's settings can be set: ``Renderer()`` is the one OpenGLRenderer of the session, and the drawing
  functors' settings are class attributes (``Gl1_Sphere.stripes = True``);
- ``SnapshotEngine`` warns once at its first run and saves nothing.

``noView`` says why there are no windows ('' when there are).
"""
import os
import queue
import threading
import warnings

from yade.wrapper import *  # noqa: F401,F403  (the reference's qt namespace holds the wrapper's classes too)
from yade.wrapper import OpenGLRenderer, SnapshotEngine  # noqa: F401
from yade.qt.viewer import GLViewer


def _whyNoView():
    if not os.environ.get('DISPLAY') and not os.environ.get('WAYLAND_DISPLAY'):
        return 'there is no display (DISPLAY is not set, or the launcher was given -n)'
    try:
        import PyQt5.QtWidgets  # noqa: F401
        import OpenGL.GL  # noqa: F401
    except ImportError as e:
        return 'PyQt5 or PyOpenGL is missing (%s; apt-get install python3-pyqt5 python3-opengl)' % e
    return ''


noView = _whyNoView()
_warned = set()


def _headless(what):
    """Warns once per name that there is no 3D view."""
    if what in _warned:
        return
    _warned.add(what)
    warnings.warn("yade.qt.%s: %s, so there is no 3D view; the script goes on without it" % (what, noView or 'no view'),
                  UserWarning, stacklevel=3)


_renderer = None


def Renderer():
    """The session's OpenGLRenderer: the 3D view's settings (shape, bound, intrPhys, bgColor...). They can be set
    without a display and last across O.reset(), as in the reference."""
    global _renderer
    if _renderer is None:
        _renderer = OpenGLRenderer()
    return _renderer


_views = []
_nextViewId = [0]


def _forget(view):
    if view in _views:
        _views.remove(view)


_app = None


def _application():
    global _app
    from PyQt5 import QtWidgets
    from yade.qt.glwidget import surfaceFormat
    from PyQt5 import QtGui
    app = QtWidgets.QApplication.instance()
    if app is None:
        QtGui.QSurfaceFormat.setDefaultFormat(surfaceFormat())
        app = _app = QtWidgets.QApplication(['yade'])  # (kept: Qt needs it as long as there are windows)
        app.setQuitOnLastWindowClosed(False)
        try:  # at the IPython prompt, Qt's events are handled while it waits for input
            ip = get_ipython()  # noqa: F821  (defined by IPython)
            ip.enable_gui('qt5')
        except Exception:
            pass
    return app


def View():
    """Opens a 3D view and returns it (a GLViewer). Without a display: warns once and returns a view that keeps
    its camera settings and draws nothing."""
    if noView:
        _headless('View()')
        v = GLViewer(_nextViewId[0], closeHook=_forget)
    else:
        _application()
        from yade.qt.glwidget import ViewWidget
        w = ViewWidget(Renderer(), 'Yade 3D view #%d' % _nextViewId[0])
        v = GLViewer(_nextViewId[0], widget=w, closeHook=_forget)
        w.show()
        if not _views:  # the first view looks at the whole scene
            v.center()
    _nextViewId[0] += 1
    _views.append(v)
    _processEvents()
    return v


def views():
    """The open 3D views."""
    return list(_views)


def center(median=True, suggestedRadius=-1):
    """Centers every view on the scene."""
    for v in _views:
        v.center(median, suggestedRadius)


_controller = None
_inspector = None


def Controller():
    """Opens the controller (run, pause, step, iteration and times, dt, save and load, the display's switches, a
    Python command). Without a display: warns once and returns None, as the reference's does."""
    global _controller
    if noView:
        _headless('Controller()')
        return None
    _application()
    from yade.qt.controller import ControllerWindow
    if _controller is None:
        _controller = ControllerWindow(Renderer(), View)
    _controller.show()
    _controller.raise_()
    _processEvents()
    return _controller


def Inspector():
    """Opens the inspector: engines, bodies, interactions and the cell, every attribute shown and editable.
    Without a display: warns once and returns None."""
    global _inspector
    if noView:
        _headless('Inspector()')
        return None
    _application()
    from yade.qt.inspector import InspectorWindow
    if _inspector is None:
        _inspector = InspectorWindow()
    _inspector.show()
    _processEvents()
    return _inspector


def _selectionChanged(bodyId):
    """A view selected a body: the inspector shows it."""
    if _inspector is not None and bodyId >= 0:
        _inspector.showBody(bodyId)


# ---------------------------------------------------------------- snapshots and the GUI's turn
# A SnapshotEngine runs in the simulation's thread, which must not draw: it takes the frame's data there
# (the loop is between two engines, so nothing moves meanwhile) and leaves it here; the main thread draws
# and saves it at its next turn: at once when the engine runs in the main thread (O.step()), else while
# O.run(n, True) or O.wait() waits, at the IPython prompt, or at the end of the script.
_pending = queue.Queue()


def _processEvents():
    if noView:
        return
    from PyQt5 import QtWidgets
    app = QtWidgets.QApplication.instance()
    if app is not None:
        app.processEvents()
    _saveSnapshots()


def _saveSnapshots():
    while True:
        try:
            file, frame = _pending.get_nowait()
        except queue.Empty:
            return
        try:
            v = next((v for v in _views if v._widget is not None), None)
            if v is None:
                warnings.warn("SnapshotEngine: the 3D view was closed before %s could be saved" % file, RuntimeWarning)
                continue
            try:
                v._widget.saveSnapshot(file, frame)
            except OSError as e:
                warnings.warn("SnapshotEngine: %s" % e, RuntimeWarning)
        finally:
            _pending.task_done()


def _waitForSnapshots(timeout=30.):
    """Until the snapshots taken so far are saved (utils.makeVideo, before it reads them): saved here in the
    main thread; from the simulation's thread (a PyRunner), waits for the main thread to save them (it does
    while O.run(n, True) or O.wait() waits, or at the prompt), at most `timeout` seconds."""
    if noView:
        return
    if threading.current_thread() is threading.main_thread():
        _saveSnapshots()
        return
    import time
    from yade import _yade
    end = time.monotonic() + timeout
    _yade._loopWaitsForGui(True)  # (the view's frames do not wait for this step to end meanwhile)
    try:
        while _pending.unfinished_tasks and time.monotonic() < end:
            time.sleep(.02)
    finally:
        _yade._loopWaitsForGui(False)


def _takeSnapshot(file, format, timeout):
    """Called by SnapshotEngine (from C++): '' when the frame is taken, else why not; None: no view at all."""
    if noView:
        return None
    if not any(v._widget is not None for v in _views):
        return 'no 3D view is open (open one with qt.View())'
    from yade import _yade
    r = Renderer()
    _pending.put((file, _yade._displayFrame(pauseRun=False, contacts=r.intrPhys, pairs=r.intrAllWire)))
    if threading.current_thread() is threading.main_thread():
        _saveSnapshots()
    return ''


def _whileWaiting():
    """The GUI's turn while O.run(n, True) or O.wait() waits (called from C++): draws the windows, saves the
    snapshots asked for, updates live plots (yade.plot). False when there is nothing to do any more."""
    import sys
    plot = sys.modules.get('yade.plot')
    plots = plot._pumpLive() if plot is not None else False
    if noView:
        return plots
    from PyQt5 import QtWidgets
    if QtWidgets.QApplication.instance() is None:
        return plots
    _processEvents()
    return True


def _flushAtExit():
    if not noView and not _pending.empty():
        _saveSnapshots()


import atexit  # noqa: E402
atexit.register(_flushAtExit)
