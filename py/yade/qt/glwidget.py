"""The window of a 3D view: an OpenGL widget that draws the scene (drawing.py) through the view's camera
(camera.py), redraws a few times a second while a simulation runs, and takes the mouse and keys:

- left button: turn about the scene's center; right button or wheel: zoom; middle button: move sideways;
- shift + left click: select the body under the cursor (OpenGLRenderer.selId, GLViewer.selection; the
  inspector follows it);
- c: center the view on the scene; t: perspective / orthographic; h: this help on the terminal.
"""
import time

import numpy
from PyQt5 import QtCore, QtGui, QtWidgets

from yade import _yade
from yade.qt.drawing import SceneDrawer, drawnBy


def surfaceFormat():
    f = QtGui.QSurfaceFormat()
    f.setVersion(3, 3)
    f.setProfile(QtGui.QSurfaceFormat.CoreProfile)
    f.setDepthBufferSize(24)
    return f


class ViewWidget(QtWidgets.QOpenGLWidget):
    refreshMs = 100  # redraw period while the scene changes
    maxIds = 2000  # OpenGLRenderer.id writes the ids of this many bodies at most

    def __init__(self, renderer, title):
        super().__init__()
        self.setFormat(surfaceFormat())
        self.setWindowTitle(title)
        self.renderer = renderer
        self.viewer = None
        self.drawer = None
        self.drawError = 'the 3D view has not been drawn yet'
        self.frame = None        # the last frame drawn (for picking)
        self.frameOverride = None  # a frame to draw instead of the scene's current one (snapshots)
        self.lastMouse = None
        self.started = time.time()
        self.drawTimes = []      # seconds per frame, the last ones
        self.lastIter = None
        self.timer = QtCore.QTimer(self)
        self.timer.timeout.connect(self._tick)
        self.timer.start(self.refreshMs)
        self.resize(550, 550)

    def attachViewer(self, viewer):
        self.viewer = viewer

    # --- drawing
    def initializeGL(self):
        try:
            self.drawer = SceneDrawer()
        except Exception as e:  # e.g. no OpenGL 3.3 (an old driver, X forwarded over ssh): said, not fatal
            self.drawError = 'the 3D view cannot draw: %s' % e
            import warnings
            warnings.warn('yade.qt: ' + self.drawError, RuntimeWarning)

    def paintGL(self):
        if self.drawer is None:
            painter = QtGui.QPainter(self)
            painter.fillRect(self.rect(), QtGui.QColor(51, 51, 51))
            painter.setPen(QtGui.QColor(255, 255, 255))
            painter.drawText(self.rect(), QtCore.Qt.AlignCenter | QtCore.Qt.TextWordWrap, self.drawError)
            painter.end()
            return
        t0 = time.perf_counter()
        r = self.renderer  # (contacts gathered only when drawn: the run pauses for less)
        frame = self.frameOverride if self.frameOverride is not None else _yade._displayFrame(contacts=r.intrPhys, pairs=r.intrAllWire)
        if frame is None:  # the run's thread waits for the GUI (a PyRunner's makeVideo): the last frame again
            frame = self.frame
            if frame is None:
                return
        self.frame = frame
        ratio = self.devicePixelRatioF()
        w, h = int(self.width() * ratio), int(self.height() * ratio)
        selection = self.viewer.selection if self.viewer is not None else -1
        v = self.viewer
        self.drawer.draw(frame, v._camera, w, h, self.renderer, selection, axes=v.axes, grid=v.grid)
        self._overlay(frame)
        self.drawTimes = (self.drawTimes + [time.perf_counter() - t0])[-20:]

    def _overlay(self, frame):
        """The time display (GLViewer.timeDisp: r real time, v virtual time, i iteration), the fps, the ids."""
        if self.viewer is None:
            return
        lines = []
        td = self.viewer.timeDisp
        if 'i' in td:
            lines.append('#%d' % frame['iter'])
        if 'v' in td:
            lines.append('t = %.6g s' % frame['time'])
        if 'r' in td:
            s = int(time.time() - self.started)
            lines.append('clock %02d:%02d' % (s // 60, s % 60))
        if self.viewer.fps and self.drawTimes:
            lines.append('%.1f fps' % (1 / max(numpy.mean(self.drawTimes), 1e-6)))
        painter = QtGui.QPainter(self)
        if self.renderer.id:  # the bodies' ids at their centres (the first maxIds)
            shown = numpy.nonzero(frame['drawer'] >= 0)[0][:self.maxIds]
            if len(shown):
                xy = self.viewer._camera.project(frame['pos'][shown], self.width(), self.height())
                painter.setPen(QtGui.QColor(255, 255, 255))
                for i, (x, y) in zip(shown, xy):
                    painter.drawText(int(x), int(y), str(i))
        painter.setPen(QtGui.QColor(0, 200, 200))
        y = self.height() - 8 - 14 * (len(lines) - 1)
        for line in lines:
            painter.drawText(10, y, line)
            y += 14
        painter.end()

    def _tick(self):
        """Redraws when the scene moved on (or always, cheaply enough, when the iteration is unknown)."""
        it = (_yade.O.iter, _yade.O.time)
        if it != self.lastIter or _yade.O.running:
            self.lastIter = it
            self.update()

    def renderFrame(self, frame=None):
        """The view as an image (QImage), of `frame` (a _displayFrame) or of the scene now."""
        self.frameOverride = frame
        try:
            return self.grabFramebuffer()
        finally:
            self.frameOverride = None

    def saveSnapshot(self, filename, frame=None):
        img = self.renderFrame(frame)
        if not img.save(filename):
            raise OSError("GLViewer.saveSnapshot: could not write %s" % filename)

    # --- mouse and keys
    def mousePressEvent(self, e):
        self.lastMouse = e.pos()
        if e.button() == QtCore.Qt.LeftButton and e.modifiers() & QtCore.Qt.ShiftModifier:
            self.select(e.pos().x(), e.pos().y())

    def mouseMoveEvent(self, e):
        if self.lastMouse is None or self.viewer is None:
            return
        dx, dy = e.pos().x() - self.lastMouse.x(), e.pos().y() - self.lastMouse.y()
        self.lastMouse = e.pos()
        cam = self.viewer._camera
        if e.buttons() & QtCore.Qt.LeftButton:
            cam.orbit(dx * 0.01, dy * 0.01)
        elif e.buttons() & QtCore.Qt.RightButton:
            cam.zoom(1.0 + dy * 0.005)
        elif e.buttons() & QtCore.Qt.MiddleButton:
            cam.pan(dx / max(self.height(), 1), dy / max(self.height(), 1))
        self.update()

    def wheelEvent(self, e):
        if self.viewer is not None:
            self.viewer._camera.zoom(0.9 ** (e.angleDelta().y() / 120))
            self.update()

    def keyPressEvent(self, e):
        if self.viewer is None:
            return
        if e.key() == QtCore.Qt.Key_C:
            self.viewer.center()
        elif e.key() == QtCore.Qt.Key_T:
            self.viewer.ortho = not self.viewer.ortho
        elif e.key() == QtCore.Qt.Key_H:
            print(__doc__)
        self.update()

    def select(self, x, y):
        """Selects the sphere under window pixel (x, y) (the nearest along the ray), or none."""
        f = self.frame
        if f is None or self.viewer is None:
            return -1
        origin, d = self.viewer._camera.ray(x, y, self.width(), self.height())
        sph = numpy.nonzero(drawnBy(f, 'Gl1_Sphere'))[0]
        best = -1
        if len(sph):
            oc = origin - f['pos'][sph]
            b = oc @ d
            c = (oc * oc).sum(axis=1) - f['size'][sph, 0] ** 2
            disc = b * b - c
            hit = disc >= 0
            if hit.any():
                t = -b[hit] - numpy.sqrt(disc[hit])
                front = t > 0
                if front.any():
                    best = int(sph[hit][front][numpy.argmin(t[front])])
        self.viewer.selection = best
        self.renderer.selId = best
        from yade import qt
        qt._selectionChanged(best)
        return best

    def closeEvent(self, e):
        if self.viewer is not None and self.viewer._closeHook is not None:
            self.viewer._closeHook(self.viewer)
            object.__setattr__(self.viewer, '_closeHook', None)
        self.timer.stop()
        super().closeEvent(e)
