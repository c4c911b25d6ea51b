"""The reference's Qt GUI module: ``qt.View()``, ``qt.Controller()``, ``qt.Inspector()``, ``qt.Renderer()``,
``qt.SnapshotEngine``, ``qt.views()``.

This build has no 3D view yet (gui/README.md). So that scripts written with a view run unchanged where there
is none anyway (``-n``, a batch job, a cluster node), importing this module succeeds, unlike the reference's,
which raises ImportError without a display:

- ``View()`` warns once and gives a view object that takes the camera settings scripts make (``eyePosition``,
  ``viewDir``, ``upVector``, ``ortho``, ``grid``...) and draws nothing; ``Controller()`` and ``Inspector()`` warn
  once and return None, as the reference's Controller() does;
- the renderer's settings can be set: ``Renderer()`` is the one OpenGLRenderer of the session, and the drawing
  functors' settings are class attributes (``Gl1_Sphere.stripes = True``);
- ``SnapshotEngine`` warns once at its first run and saves nothing.
"""
import warnings

from yade.wrapper import *  # noqa: F401,F403  (the reference's qt namespace holds the wrapper's classes too)
from yade.wrapper import OpenGLRenderer, SnapshotEngine  # noqa: F401
from yade import math as _math

_warned = set()


def _headless(what):
    """Warns once per name that there is no 3D view."""
    if what in _warned:
        return
    _warned.add(what)
    warnings.warn("yade.qt.%s: this build has no 3D view yet (see gui/README.md); the script goes on without it"
                  % what, UserWarning, stacklevel=3)


_renderer = None


def Renderer():
    """The session's OpenGLRenderer: the 3D view's settings (shape, bound, intrPhys, bgColor...). They can be set
    without a display and last across O.reset(), as in the reference."""
    global _renderer
    if _renderer is None:
        _renderer = OpenGLRenderer()
    return _renderer


class GLViewer:
    """A 3D view (the reference's GLViewer). Without a view to show, it keeps the camera settings a script gives
    (checked as the reference's are) and draws nothing."""
    _vectors = {'eyePosition': 3, 'lookAt': 3, 'upVector': 3, 'viewDir': 3}
    __slots__ = ('_id', '_closed', 'axes', 'eyePosition', 'fps', 'grid', 'lookAt', 'ortho', 'scale',
                 'sceneRadius', 'screenSize', 'selection', 'timeDisp', 'upVector', 'viewDir')

    def __init__(self, viewId):
        object.__setattr__(self, '_id', viewId)
        object.__setattr__(self, '_closed', False)
        # the reference's defaults for an empty scene
        for name, value in (('axes', False), ('eyePosition', _math.Vector3(0, 0, 3.9196888946291293)), ('fps', False),
                            ('grid', (False, False, False)), ('lookAt', _math.Vector3(0, 0, 2.9196888946291293)),
                            ('ortho', False), ('scale', True), ('sceneRadius', 1.5),
                            ('screenSize', _math.Vector2i(550, 550)), ('selection', -1), ('timeDisp', 'rvi'),
                            ('upVector', _math.Vector3(0, 1, 0)), ('viewDir', _math.Vector3(0, 0, -1))):
            object.__setattr__(self, name, value)

    def __setattr__(self, name, value):
        if name.startswith('_') or name not in GLViewer.__slots__:
            raise AttributeError("GLViewer has no attribute '%s' (its settings: %s)"
                                 % (name, ', '.join(n for n in GLViewer.__slots__ if not n.startswith('_'))))
        if name in GLViewer._vectors:
            try:
                value = _math.Vector3(*value)
            except TypeError:
                raise TypeError("GLViewer.%s: expected a Vector3 or a sequence of 3 numbers, got %r" % (name, value)) from None
        elif name == 'grid':
            if len(value) != 3:
                raise TypeError("GLViewer.grid: expected 3 booleans (the planes yz, zx, xy), got %r" % (value,))
            value = tuple(bool(x) for x in value)
        elif name == 'screenSize':
            value = _math.Vector2i(*value)
        elif name == 'sceneRadius':
            value = float(value)
            if not value > 0:
                raise ValueError("GLViewer.sceneRadius must be positive (got %s)" % value)
        elif name == 'selection':
            value = int(value)
        elif name == 'timeDisp':
            value = str(value)
            if set(value) - set('rvi'):
                raise ValueError("GLViewer.timeDisp: letters r (real time), v (virtual time) and i (iteration) only, got %r"
                                 % value)
        else:
            value = bool(value)
        object.__setattr__(self, name, value)

    def __repr__(self):
        return '<GLViewer for view #%d (no display)>' % self._id

    def center(self, median=True, suggestedRadius=-1):
        """Centers the view on the scene (nothing to do without a display)."""

    def fitAABB(self, mn, mx):
        """Fits the view to a box (nothing to do without a display)."""

    def fitSphere(self, center, radius):
        """Fits the view to a sphere (nothing to do without a display)."""

    def showEntireScene(self):
        """Fits the view to the scene (nothing to do without a display)."""

    def saveState(self, stateName='7'):
        """Keeps the camera in a slot (nothing to do without a display)."""

    def loadState(self, stateName='7'):
        """Restores the camera from a slot (nothing to do without a display)."""

    def saveSnapshot(self, filename):
        """Would save the view as an image; without a display it warns once and saves nothing."""
        _headless('saveSnapshot')

    def close(self):
        """Closes the view."""
        if not self._closed:
            object.__setattr__(self, '_closed', True)
            _views.remove(self)


_views = []
_nextViewId = [0]


def View():
    """Opens a 3D view and returns it (the reference's qt.View()). Without a display: warns once and returns a
    view that keeps its camera settings and draws nothing."""
    _headless('View()')
    v = GLViewer(_nextViewId[0])
    _nextViewId[0] += 1
    _views.append(v)
    return v


def views():
    """The open 3D views."""
    return list(_views)


def center(median=True, suggestedRadius=-1):
    """Centers every view on the scene."""
    for v in _views:
        v.center(median, suggestedRadius)


def Controller():
    """Opens the controller window (run, pause, step, dt, display settings). Without a display: warns once and
    returns None (the reference's Controller() returns None too)."""
    _headless('Controller()')
    return None


def Inspector():
    """Opens the inspector (engines, bodies, interactions, cell). Without a display: warns once and returns None."""
    _headless('Inspector()')
    return None
