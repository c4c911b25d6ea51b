"""GLViewer: a 3D view as scripts see it (`v = qt.View(); v.viewDir = ...`), with the reference's settings.

The settings live in a Camera (camera.py); a view with a window (glwidget.py) draws from them, and one
without a display keeps them and draws nothing, so that a script sets the same things either way.
"""
import numpy

from yade import math as _math
from yade.qt.camera import Camera, sceneBox


def _vector3(name, value):
    try:
        v = numpy.array([float(x) for x in value])
    except (TypeError, ValueError):
        raise TypeError("GLViewer.%s: expected a Vector3 or a sequence of 3 numbers, got %r" % (name, value)) from None
    if v.shape != (3,):
        raise TypeError("GLViewer.%s: expected a Vector3 or a sequence of 3 numbers, got %r" % (name, value))
    if not numpy.isfinite(v).all():
        raise ValueError("GLViewer.%s must be finite (got %r)" % (name, value))
    return v


class GLViewer:
    """A 3D view (the reference's GLViewer): camera settings, snapshots, centering."""
    _settings = ('axes', 'eyePosition', 'fps', 'grid', 'lookAt', 'ortho', 'scale', 'sceneRadius', 'screenSize',
                 'selection', 'timeDisp', 'upVector', 'viewDir')
    __slots__ = ('_id', '_widget', '_camera', '_flags', '_closeHook')

    def __init__(self, viewId, widget=None, closeHook=None):
        object.__setattr__(self, '_id', viewId)
        object.__setattr__(self, '_widget', widget)
        object.__setattr__(self, '_camera', Camera())
        object.__setattr__(self, '_flags', {'axes': False, 'fps': False, 'grid': (False, False, False), 'scale': True,
                                            'screenSize': (550, 550), 'selection': -1, 'timeDisp': 'rvi'})
        object.__setattr__(self, '_closeHook', closeHook)
        if widget is not None:
            widget.attachViewer(self)

    # --- the settings
    def __getattr__(self, name):
        c = object.__getattribute__(self, '_camera')
        if name == 'eyePosition':
            return _math.Vector3(*c.eye)
        if name == 'viewDir':
            return _math.Vector3(*c.viewDir)
        if name == 'upVector':
            return _math.Vector3(*c.upVector)
        if name == 'lookAt':
            return _math.Vector3(*(c.eye + c.viewDir))
        if name == 'ortho':
            return c.ortho
        if name == 'sceneRadius':
            return c.sceneRadius
        flags = object.__getattribute__(self, '_flags')
        if name == 'screenSize':
            w = object.__getattribute__(self, '_widget')
            return _math.Vector2i(*((w.width(), w.height()) if w is not None else flags['screenSize']))
        if name in flags:
            return flags[name]
        raise AttributeError("GLViewer has no attribute '%s' (its settings: %s)" % (name, ', '.join(GLViewer._settings)))

    def __setattr__(self, name, value):
        c, flags = self._camera, self._flags
        if name not in GLViewer._settings:
            raise AttributeError("GLViewer has no attribute '%s' (its settings: %s)" % (name, ', '.join(GLViewer._settings)))
        if name == 'eyePosition':
            c.eye = _vector3(name, value)
        elif name == 'viewDir':
            v = _vector3(name, value)
            if not numpy.linalg.norm(v) > 0:
                raise ValueError("GLViewer.viewDir must not be zero")
            c.setViewDir(v)
        elif name == 'upVector':
            v = _vector3(name, value)
            if not numpy.linalg.norm(v) > 0:
                raise ValueError("GLViewer.upVector must not be zero")
            c.setUpVector(v)
        elif name == 'lookAt':
            v = _vector3(name, value)
            if not numpy.linalg.norm(v - c.eye) > 0:
                raise ValueError("GLViewer.lookAt must differ from eyePosition")
            c.setViewDir(v - c.eye)
        elif name == 'ortho':
            c.ortho = bool(value)
        elif name == 'sceneRadius':
            r = float(value)
            if not r > 0 or r == float('inf'):
                raise ValueError("GLViewer.sceneRadius must be positive and finite (got %s)" % value)
            c.sceneRadius = r
        elif name == 'grid':
            try:
                g = tuple(bool(x) for x in value)
            except TypeError:
                g = ()
            if len(g) != 3:
                raise TypeError("GLViewer.grid: expected 3 booleans (the planes yz, zx, xy), got %r" % (value,))
            flags['grid'] = g
        elif name == 'screenSize':
            w, h = (int(x) for x in value)
            if w < 1 or h < 1:
                raise ValueError("GLViewer.screenSize must be positive (got %r)" % (value,))
            flags['screenSize'] = (w, h)
            if self._widget is not None:
                self._widget.resize(w, h)
        elif name == 'selection':
            flags['selection'] = int(value)
        elif name == 'timeDisp':
            value = str(value)
            if set(value) - set('rvi'):
                raise ValueError("GLViewer.timeDisp: letters r (real time), v (virtual time) and i (iteration) only, "
                                 "got %r" % value)
            flags['timeDisp'] = value
        else:
            flags[name] = bool(value)
        self._update()

    def __repr__(self):
        return '<GLViewer for view #%d%s>' % (self._id, '' if self._widget is not None else ' (no display)')

    def _update(self):
        if self._widget is not None:
            self._widget.update()

    # --- the methods
    def center(self, median=True, suggestedRadius=-1):
        """Centers the view on the scene (median=True: on the bodies' median position); suggestedRadius > 0
        sets the scene's radius."""
        from yade import _yade
        frame = _yade._displayFrame(contacts=False, pairs=False)
        if frame is None:  # the run's thread waits for the GUI: centered at the next call
            return
        c, r = sceneBox(frame, median=median)
        self._camera.sceneCenter = numpy.asarray(c, dtype=float)
        self._camera.sceneRadius = float(suggestedRadius) if suggestedRadius > 0 else r
        self._camera.showEntireScene()
        self._update()

    def fitAABB(self, mn, mx):
        """Fits the view to the box [mn, mx]."""
        self._camera.fitAABB(_vector3('fitAABB', mn), _vector3('fitAABB', mx))
        self._update()

    def fitSphere(self, center, radius):
        """Fits the view to a sphere."""
        self._camera.fitSphere(_vector3('fitSphere', center), float(radius))
        self._update()

    def showEntireScene(self):
        """Fits the view to the scene's center and radius."""
        self._camera.showEntireScene()
        self._update()

    def saveState(self, stateName='7'):
        """Keeps the camera in a slot (the reference keeps 10, named by a digit)."""
        _states[str(stateName)] = (self._camera.eye.copy(), self._camera.viewDir.copy(), self._camera.upVector.copy(),
                                   self._camera.ortho)

    def loadState(self, stateName='7'):
        """Restores the camera from a slot saved by saveState."""
        if str(stateName) not in _states:
            raise KeyError("GLViewer.loadState: no camera saved as %r" % stateName)
        eye, d, u, o = _states[str(stateName)]
        self._camera.eye, self._camera.viewDir, self._camera.upVector, self._camera.ortho = eye.copy(), d.copy(), u.copy(), o
        self._update()

    def saveSnapshot(self, filename):
        """Saves the view as an image (the format from the file's extension)."""
        if self._widget is None:
            from yade import qt
            qt._headless('saveSnapshot')
            return
        self._widget.saveSnapshot(str(filename))

    def close(self):
        """Closes the view."""
        if self._closeHook is not None:
            self._closeHook(self)
            object.__setattr__(self, '_closeHook', None)
        if self._widget is not None:
            self._widget.close()


_states = {}
