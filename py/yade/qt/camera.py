"""The 3D view's camera: where it is, where it looks, and the matrices that follow (NumPy only, no Qt).

Conventions are the reference's (its camera is libQGLViewer's): a vertical field of view of π/4; a view
looks along `viewDir` from `eyePosition` with `upVector` up; `lookAt` is the point one unit ahead;
`showEntireScene()` puts the eye at sceneRadius / sin(fov/2) from the scene's center, which gives a fresh
view of an empty scene (radius 1.5) its eye at z = 3.9197.
"""
import math

import numpy


def _unit(v):
    v = numpy.asarray(v, dtype=float)
    n = numpy.linalg.norm(v)
    if not n > 0 or not math.isfinite(n):
        raise ValueError("a direction must be a non-zero finite vector (got %s)" % list(v))
    return v / n


class Camera:
    fov = math.pi / 4  # vertical field of view

    def __init__(self):
        self.sceneCenter = numpy.zeros(3)
        self.sceneRadius = 1.5
        self.viewDir = numpy.array([0., 0., -1.])
        self.upVector = numpy.array([0., 1., 0.])
        self.ortho = False
        self.eye = numpy.zeros(3)
        self.showEntireScene()

    # --- placing the camera
    def distanceToFit(self, radius):
        return radius / math.sin(self.fov / 2)

    def fitSphere(self, center, radius):
        if not radius > 0:
            raise ValueError("fitSphere: the radius must be positive (got %s)" % radius)
        self.eye = numpy.asarray(center, dtype=float) - self.viewDir * self.distanceToFit(radius)

    def showEntireScene(self):
        self.fitSphere(self.sceneCenter, self.sceneRadius)

    def fitAABB(self, mn, mx):
        mn, mx = numpy.asarray(mn, dtype=float), numpy.asarray(mx, dtype=float)
        self.fitSphere((mn + mx) / 2, max(numpy.linalg.norm(mx - mn) / 2, 1e-12))

    def setViewDir(self, d):
        self.viewDir = _unit(d)
        self.upVector = self._orthogonalUp(self.upVector)

    def setUpVector(self, u):
        self.upVector = self._orthogonalUp(_unit(u))

    def _orthogonalUp(self, up):
        """up made orthogonal to viewDir (another axis when they are parallel)."""
        u = up - numpy.dot(up, self.viewDir) * self.viewDir
        if numpy.linalg.norm(u) < 1e-9:
            for axis in numpy.eye(3):
                u = axis - numpy.dot(axis, self.viewDir) * self.viewDir
                if numpy.linalg.norm(u) > 1e-3:
                    break
        return _unit(u)

    # --- moving it with the mouse
    def orbit(self, dx, dy):
        """Turns the camera about the scene's center: dx, dy in radians (about up, about the right axis)."""
        right = numpy.cross(self.viewDir, self.upVector)
        rel = self.eye - self.sceneCenter
        for axis, angle in ((self.upVector, -dx), (right, -dy)):
            rel, self.viewDir, self.upVector = (_rotate(v, axis, angle) for v in (rel, self.viewDir, self.upVector))
        self.eye = self.sceneCenter + rel
        self.upVector = self._orthogonalUp(self.upVector)

    def zoom(self, factor):
        """Moves the eye toward the scene's center (factor < 1) or away from it."""
        target = self.sceneCenter if numpy.dot(self.sceneCenter - self.eye, self.viewDir) > 0 else self.eye + self.viewDir
        self.eye = target + (self.eye - target) * factor

    def pan(self, dx, dy):
        """Moves the camera sideways by dx, dy (fractions of the view's height)."""
        right = numpy.cross(self.viewDir, self.upVector)
        h = 2 * self.depth() * math.tan(self.fov / 2)
        shift = (-dx * right + dy * self.upVector) * h
        self.eye = self.eye + shift
        self.sceneCenter = self.sceneCenter + shift

    def depth(self):
        """Distance from the eye to the scene's center along the view."""
        return max(abs(float(numpy.dot(self.sceneCenter - self.eye, self.viewDir))), 1e-9)

    # --- matrices (column vectors; numpy arrays, float32 for OpenGL)
    def viewMatrix(self):
        f, u = self.viewDir, self.upVector
        s = numpy.cross(f, u)
        m = numpy.eye(4)
        m[0, :3], m[1, :3], m[2, :3] = s, u, -f
        m[:3, 3] = -m[:3, :3] @ self.eye
        return m

    def nearFar(self):
        d = float(numpy.dot(self.sceneCenter - self.eye, self.viewDir))
        r = self.sceneRadius
        far = max(d + 2 * r, 1e-6)
        near = max(d - 2 * r, far * 1e-4)
        return near, far

    def projectionMatrix(self, aspect):
        near, far = self.nearFar()
        m = numpy.zeros((4, 4))
        if self.ortho:
            h = self.depth() * math.tan(self.fov / 2)
            w = h * aspect
            m[0, 0], m[1, 1], m[2, 2] = 1 / w, 1 / h, -2 / (far - near)
            m[2, 3], m[3, 3] = -(far + near) / (far - near), 1
        else:
            t = 1 / math.tan(self.fov / 2)
            m[0, 0], m[1, 1] = t / aspect, t
            m[2, 2], m[2, 3] = -(far + near) / (far - near), -2 * far * near / (far - near)
            m[3, 2] = -1
        return m

    def project(self, points, width, height):
        """Window coordinates (x right, y down, in pixels) of world points (n×3)."""
        p = numpy.c_[numpy.asarray(points, dtype=float), numpy.ones(len(points))]
        clip = p @ (self.projectionMatrix(width / height) @ self.viewMatrix()).T
        ndc = clip[:, :3] / clip[:, 3:4]
        return numpy.c_[(ndc[:, 0] + 1) / 2 * width, (1 - ndc[:, 1]) / 2 * height]

    def ray(self, x, y, width, height):
        """Origin and unit direction of the ray through window pixel (x, y)."""
        inv = numpy.linalg.inv(self.projectionMatrix(width / height) @ self.viewMatrix())
        ndc = numpy.array([2 * x / width - 1, 1 - 2 * y / height])
        a = inv @ numpy.array([ndc[0], ndc[1], -1, 1])
        b = inv @ numpy.array([ndc[0], ndc[1], 1, 1])
        a, b = a[:3] / a[3], b[:3] / b[3]
        return a, _unit(b - a)


def _rotate(v, axis, angle):
    """v rotated by angle about the unit axis (Rodrigues)."""
    c, s = math.cos(angle), math.sin(angle)
    return v * c + numpy.cross(axis, v) * s + axis * numpy.dot(axis, v) * (1 - c)


def sceneBox(frame, median=False):
    """Center and radius of what the frame holds (walls, which are infinite, left out); median=True centers
    on the bodies' median position, as the reference's center(median=True) does, so that a few bodies far
    away do not shrink the rest."""
    from yade.qt.drawing import drawnBy
    pos, size = frame['pos'], frame['size']
    pts = []
    sph = drawnBy(frame, 'Gl1_Sphere')
    if sph.any():
        r = size[sph, 0:1]
        pts += [pos[sph] - r, pos[sph] + r]
    box = drawnBy(frame, 'Gl1_Box')
    if box.any():
        e = numpy.linalg.norm(size[box], axis=1)[:, None]
        pts += [pos[box] - e, pos[box] + e]
    if len(frame['triangleCorners']):
        pts.append(frame['triangleCorners'].reshape(-1, 3))
    if frame.get('cellHSize') is not None:
        H = numpy.asarray(frame['cellHSize'])
        pts.append(numpy.array([[0, 0, 0], H[:, 0] + H[:, 1] + H[:, 2]]))
    if not pts:
        return numpy.zeros(3), 1.5
    allPts = numpy.concatenate(pts)
    allPts = allPts[numpy.isfinite(allPts).all(axis=1)]
    if not len(allPts):
        return numpy.zeros(3), 1.5
    lo, hi = allPts.min(axis=0), allPts.max(axis=0)
    if median and sph.sum() > 10:
        c = numpy.median(pos[sph], axis=0)
        dist = numpy.linalg.norm(pos[sph] - c, axis=1) + size[sph, 0]
        r = min(dist.max(), 2 * numpy.percentile(dist, 90))  # (a few far away are left out of the view)
        return c, max(float(r), 1e-9)
    return (lo + hi) / 2, max(float(numpy.linalg.norm(hi - lo) / 2), 1e-9)
