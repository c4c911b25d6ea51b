"""Volume predicates (the manual, 4.1 "Volume representation"): solids that say whether a point is
inside them, at least `pad` away from their boundary (so that a sphere of radius pad centred there
does not stick out), and give their axis-aligned bounding box. The primitives inSphere,
inAlignedBox, inCylinder, inEllipsoid, inHyperboloid, inParallelepiped, notInNotch, inSpace, and
inHalfSpace, inConvexPolyhedron, and the boolean operations on them: A & B (intersection), A | B (union), A - B (difference), A ^ B
(symmetric difference). A Python class deriving from Predicate and defining __call__(pt, pad) and
aabb() takes part in the operations too.

    from yade import pack
    pred = pack.inAlignedBox((-2, -2, -2), (2, 2, 2)) - pack.inCylinder((0, -2, 0), (0, 2, 0), 1)
    pred((0, 0, 1.5), 0.1)   # -> True
    pack.regularHexa(pred, radius=.1, gap=0)

Whether a point is inside is evaluated exactly for every primitive but the hyperboloid and the
ellipsoid with a pad (their pad is applied to the semi-axes, as the reference does), and with
closed boundaries (a point at exactly pad from the boundary is inside).
"""
import math

from ._yade import Vector3

__all__ = ['Predicate', 'PredicateBoolean', 'PredicateUnion', 'PredicateIntersection', 'PredicateDifference',
           'PredicateSymmetricDifference', 'inSphere', 'inAlignedBox', 'inCylinder', 'inEllipsoid', 'inHyperboloid',
           'inParallelepiped', 'notInNotch', 'inSpace', 'inHalfSpace', 'inConvexPolyhedron']

_INF = float('inf')


def _vec(v, what):
    """A Vector3 of finite numbers from v (a sequence of 3), or TypeError/ValueError naming `what`."""
    try:
        x = Vector3(*[float(c) for c in v])
    except (TypeError, ValueError) as e:
        raise TypeError('%s: expected a sequence of 3 numbers, got %r' % (what, v)) from e
    if len(v) != 3:
        raise TypeError('%s: expected a sequence of 3 numbers, got %r' % (what, v))
    if not all(math.isfinite(c) for c in x):
        raise ValueError('%s must be finite, got %s' % (what, tuple(x)))
    return x


def _positive(x, what):
    x = float(x)
    if not x > 0 or not math.isfinite(x):
        raise ValueError('%s must be positive and finite, got %r' % (what, x))
    return x


class Predicate:
    """A solid: pred(pt, pad) says whether pt is inside, at least pad away from the boundary;
    aabb() its axis-aligned bounding box (min, max); dim() and center() the box's size and centre."""

    def __call__(self, pt, pad):
        raise NotImplementedError('%s does not define __call__(pt, pad)' % type(self).__name__)

    def aabb(self):
        raise NotImplementedError('%s does not define aabb()' % type(self).__name__)

    def dim(self):
        lo, hi = self.aabb()
        return Vector3(hi) - Vector3(lo)

    def center(self):
        lo, hi = self.aabb()
        return .5 * (Vector3(lo) + Vector3(hi))

    def __and__(self, other):
        return PredicateIntersection(self, other)

    def __or__(self, other):
        return PredicateUnion(self, other)

    def __sub__(self, other):
        return PredicateDifference(self, other)

    def __xor__(self, other):
        return PredicateSymmetricDifference(self, other)


class PredicateBoolean(Predicate):
    """A boolean operation on two predicates (A and B)."""

    def __init__(self, A, B):
        for p in (A, B):
            if not isinstance(p, Predicate):
                raise TypeError('%s: both operands must be predicates, got %s' % (type(self).__name__, type(p).__name__))
        self.A, self.B = A, B


def _boxUnion(a, b):
    return (Vector3(*[min(x, y) for x, y in zip(a[0], b[0])]), Vector3(*[max(x, y) for x, y in zip(a[1], b[1])]))


class PredicateUnion(PredicateBoolean):
    """A | B: in A or in B."""

    def __call__(self, pt, pad):
        return self.A(pt, pad) or self.B(pt, pad)

    def aabb(self):
        return _boxUnion(self.A.aabb(), self.B.aabb())


class PredicateIntersection(PredicateBoolean):
    """A & B: in A and in B."""

    def __call__(self, pt, pad):
        return self.A(pt, pad) and self.B(pt, pad)

    def aabb(self):
        a, b = self.A.aabb(), self.B.aabb()
        return (Vector3(*[max(x, y) for x, y in zip(a[0], b[0])]), Vector3(*[min(x, y) for x, y in zip(a[1], b[1])]))


class PredicateDifference(PredicateBoolean):
    """A - B: in A and at least pad outside B."""

    def __call__(self, pt, pad):
        return self.A(pt, pad) and not self.B(pt, -pad)

    def aabb(self):
        return self.A.aabb()


class PredicateSymmetricDifference(PredicateBoolean):
    """A ^ B: in exactly one of A and B (at least pad outside the other)."""

    def __call__(self, pt, pad):
        return (self.A(pt, pad) and not self.B(pt, -pad)) or (self.B(pt, pad) and not self.A(pt, -pad))

    def aabb(self):
        return _boxUnion(self.A.aabb(), self.B.aabb())


class inSphere(Predicate):
    """Sphere predicate: inSphere(center, radius)."""

    def __init__(self, center, radius):
        self._c = _vec(center, 'inSphere: center')
        self._r = _positive(radius, 'inSphere: radius')

    def __call__(self, pt, pad):
        return (Vector3(pt) - self._c).norm() <= self._r - pad

    def aabb(self):
        r = Vector3(self._r, self._r, self._r)
        return (self._c - r, self._c + r)


class inAlignedBox(Predicate):
    """Axis-aligned box predicate: inAlignedBox(minAABB, maxAABB)."""

    def __init__(self, minAABB, maxAABB):
        self._lo, self._hi = _vec(minAABB, 'inAlignedBox: minAABB'), _vec(maxAABB, 'inAlignedBox: maxAABB')
        if not all(l < h for l, h in zip(self._lo, self._hi)):
            raise ValueError('inAlignedBox: minAABB %s must be below maxAABB %s in every axis' % (tuple(self._lo), tuple(self._hi)))

    def __call__(self, pt, pad):
        p = Vector3(pt)
        return all(l + pad <= x <= h - pad for l, x, h in zip(self._lo, p, self._hi))

    def aabb(self):
        return (Vector3(self._lo), Vector3(self._hi))


class inParallelepiped(Predicate):
    """Parallelepiped predicate: inParallelepiped(o, a, b, c), o a corner and a, b, c the three
    corners next to it."""

    def __init__(self, o, a, b, c):
        self._o = _vec(o, 'inParallelepiped: o')
        corners = [_vec(v, 'inParallelepiped: ' + n) for v, n in ((a, 'a'), (b, 'b'), (c, 'c'))]
        self._e = [v - self._o for v in corners]
        e = self._e
        volume = e[0].dot(e[1].cross(e[2]))
        if not abs(volume) > 0:
            raise ValueError('inParallelepiped: o, a, b, c are coplanar (a degenerate parallelepiped)')
        # each pair of faces: its unit normal (pointing inside from the face through o) and the thickness
        self._faces = []
        for i in range(3):
            n = e[(i + 1) % 3].cross(e[(i + 2) % 3])
            n = n / n.norm()
            if n.dot(e[i]) < 0:
                n = -n
            self._faces.append((n, n.dot(e[i])))

    def __call__(self, pt, pad):
        d = Vector3(pt) - self._o
        return all(pad <= n.dot(d) <= h - pad for n, h in self._faces)

    def aabb(self):
        e = self._e
        pts = [self._o + i * e[0] + j * e[1] + k * e[2] for i in (0, 1) for j in (0, 1) for k in (0, 1)]
        return (Vector3(*[min(p[a] for p in pts) for a in range(3)]), Vector3(*[max(p[a] for p in pts) for a in range(3)]))


def _discReach(axis, r):
    """How far a disc of radius r normal to the unit vector axis reaches along each coordinate axis."""
    n = axis
    return Vector3(r * math.sqrt(n[1] ** 2 + n[2] ** 2), r * math.sqrt(n[0] ** 2 + n[2] ** 2), r * math.sqrt(n[0] ** 2 + n[1] ** 2))


class inCylinder(Predicate):
    """Cylinder predicate: inCylinder(centerBottom, centerTop, radius)."""

    def __init__(self, centerBottom, centerTop, radius):
        self._c1, self._c2 = _vec(centerBottom, 'inCylinder: centerBottom'), _vec(centerTop, 'inCylinder: centerTop')
        self._r = _positive(radius, 'inCylinder: radius')
        axis = self._c2 - self._c1
        self._len = axis.norm()
        if not self._len > 0:
            raise ValueError('inCylinder: centerBottom and centerTop are the same point')
        self._axis = axis / self._len

    def __call__(self, pt, pad):
        d = Vector3(pt) - self._c1
        t = d.dot(self._axis)
        if not (pad <= t <= self._len - pad):
            return False
        return (d - t * self._axis).norm() <= self._r - pad

    def aabb(self):
        ext = _discReach(self._axis, self._r)
        lo = Vector3(*[min(a, b) for a, b in zip(self._c1, self._c2)])
        hi = Vector3(*[max(a, b) for a, b in zip(self._c1, self._c2)])
        return (lo - ext, hi + ext)


class inEllipsoid(Predicate):
    """Axis-aligned ellipsoid predicate: inEllipsoid(centerPoint, abc), abc its semi-axes. With a
    pad, the point must be in the ellipsoid of semi-axes abc - pad (close to the boundary, not exact
    where the semi-axes differ much)."""

    def __init__(self, centerPoint, abc):
        self._c = _vec(centerPoint, 'inEllipsoid: centerPoint')
        self._abc = _vec(abc, 'inEllipsoid: abc')
        if not all(x > 0 for x in self._abc):
            raise ValueError('inEllipsoid: the semi-axes abc must be positive, got %s' % (tuple(self._abc),))

    def __call__(self, pt, pad):
        d = Vector3(pt) - self._c
        axes = [x - pad for x in self._abc]
        if not all(x > 0 for x in axes):
            return False
        return sum((di / ai) ** 2 for di, ai in zip(d, axes)) <= 1

    def aabb(self):
        return (self._c - self._abc, self._c + self._abc)


class inHyperboloid(Predicate):
    """Hyperboloid (dogbone) predicate: inHyperboloid(centerBottom, centerTop, radius, skirt), radius
    at both ends and skirt (smaller) at the middle, r(z)² = skirt²·(1 + z²/c²) along the axis. With
    a pad the point must be at least pad inside both ends and within r(z) - pad of the axis."""

    def __init__(self, centerBottom, centerTop, radius, skirt):
        self._c1, self._c2 = _vec(centerBottom, 'inHyperboloid: centerBottom'), _vec(centerTop, 'inHyperboloid: centerTop')
        self._r = _positive(radius, 'inHyperboloid: radius')
        self._skirt = _positive(skirt, 'inHyperboloid: skirt')
        if not self._skirt < self._r:
            raise ValueError('inHyperboloid: skirt (%g) must be smaller than radius (%g)' % (self._skirt, self._r))
        axis = self._c2 - self._c1
        self._len = axis.norm()
        if not self._len > 0:
            raise ValueError('inHyperboloid: centerBottom and centerTop are the same point')
        self._axis = axis / self._len
        self._cc = (.5 * self._len) ** 2 / ((self._r / self._skirt) ** 2 - 1)  # c²

    def __call__(self, pt, pad):
        d = Vector3(pt) - self._c1
        t = d.dot(self._axis)
        if not (pad <= t <= self._len - pad):
            return False
        z = t - .5 * self._len
        rz = self._skirt * math.sqrt(1 + z * z / self._cc)
        return (d - t * self._axis).norm() <= rz - pad

    def aabb(self):
        ext = _discReach(self._axis, self._r)
        lo = Vector3(*[min(a, b) for a, b in zip(self._c1, self._c2)])
        hi = Vector3(*[max(a, b) for a, b in zip(self._c1, self._c2)])
        return (lo - ext, hi + ext)


class notInNotch(Predicate):
    """Outside an infinite notch: notInNotch(centerPoint, edge, normal, aperture). The notch is the
    slab of thickness aperture around the plane through centerPoint with the given normal, on the
    side of its edge (a line through centerPoint along edge) that edge × normal points to. Its
    bounding box is infinite."""

    def __init__(self, centerPoint, edge, normal, aperture):
        self._c = _vec(centerPoint, 'notInNotch: centerPoint')
        e, n = _vec(edge, 'notInNotch: edge'), _vec(normal, 'notInNotch: normal')
        if not (e.norm() > 0 and n.norm() > 0):
            raise ValueError('notInNotch: edge and normal must not be zero')
        self._e, self._n = e / e.norm(), n / n.norm()
        self._inside = self._e.cross(self._n)
        if not self._inside.norm() > 0:
            raise ValueError('notInNotch: edge and normal must not be parallel')
        self._inside = self._inside / self._inside.norm()
        self._half = .5 * _positive(aperture, 'notInNotch: aperture')

    def __call__(self, pt, pad):
        d = Vector3(pt) - self._c
        inNotch = d.dot(self._inside) >= -pad and abs(d.dot(self._n)) <= self._half + pad
        return not inNotch

    def aabb(self):
        return (Vector3(-_INF, -_INF, -_INF), Vector3(_INF, _INF, _INF))


class inSpace(Predicate):
    """The whole space: every point is inside; the bounding box is infinite."""

    def __call__(self, pt, pad):
        return True

    def aabb(self):
        return (Vector3(-_INF, -_INF, -_INF), Vector3(_INF, _INF, _INF))


class inHalfSpace(Predicate):
    """Half-space predicate: inHalfSpace(center, dir), the points on the side of the plane through
    center that dir points to. Its bounding box is infinite, except on the bounded side when dir is
    along a coordinate axis."""

    def __init__(self, center, dir):
        self._c = _vec(center, 'inHalfSpace: center')
        d = _vec(dir, 'inHalfSpace: dir')
        if not d.norm() > 0:
            raise ValueError('inHalfSpace: dir must not be zero')
        self._n = d / d.norm()

    def __call__(self, pt, pad):
        return (Vector3(pt) - self._c).dot(self._n) >= pad

    def aabb(self):
        lo, hi = [-_INF] * 3, [_INF] * 3
        axes = [i for i in range(3) if self._n[i] != 0]
        if len(axes) == 1:
            i = axes[0]
            (lo if self._n[i] > 0 else hi)[i] = self._c[i]
        return (Vector3(*lo), Vector3(*hi))


class inConvexPolyhedron(Predicate):
    """Convex polyhedron predicate: inConvexPolyhedron([(point, normal), ...]), the intersection of the
    half-spaces each on the side of the plane through point that normal points to. Its bounding box
    is that of its vertices (the polyhedron must be bounded)."""

    def __init__(self, planes):
        try:
            pairs = [(p, n) for p, n in planes]
        except (TypeError, ValueError) as e:
            raise TypeError('inConvexPolyhedron: expected a list of (point, normal) pairs, got %r' % (planes,)) from e
        if len(pairs) < 4:
            raise ValueError('inConvexPolyhedron: a bounded polyhedron needs at least 4 planes, got %d' % len(pairs))
        self._planes = []
        for i, (p, n) in enumerate(pairs):
            p, n = _vec(p, 'inConvexPolyhedron: point %d' % i), _vec(n, 'inConvexPolyhedron: normal %d' % i)
            if not n.norm() > 0:
                raise ValueError('inConvexPolyhedron: normal %d is zero' % i)
            self._planes.append((p, n / n.norm()))
        self._box = self._vertexBox()

    def __call__(self, pt, pad):
        x = Vector3(pt)
        return all((x - p).dot(n) >= pad for p, n in self._planes)

    def _vertexBox(self):
        # the vertices: the points where three planes meet that are in every half-space
        import itertools
        import numpy
        tol = 1e-9 * (1 + max(p.norm() for p, _ in self._planes))
        verts = []
        for a, b, c in itertools.combinations(self._planes, 3):
            A = numpy.array([list(a[1]), list(b[1]), list(c[1])])
            if abs(numpy.linalg.det(A)) < 1e-12:
                continue
            x = numpy.linalg.solve(A, [a[1].dot(a[0]), b[1].dot(b[0]), c[1].dot(c[0])])
            v = Vector3(*x)
            if all((v - p).dot(n) >= -tol for p, n in self._planes):
                verts.append(v)
        if not verts:
            raise ValueError('inConvexPolyhedron: the half-spaces have no common vertex (empty or unbounded)')
        # unbounded when some direction d leaves no half-space (n·d >= 0 for all n): the edges of that
        # cone of directions are crosses of two normals
        normals = [n for _, n in self._planes]
        for a, b in itertools.combinations(normals, 2):
            d = a.cross(b)
            if d.norm() < 1e-12:
                continue
            for e in (d, -d):
                if all(n.dot(e) >= -1e-12 * e.norm() for n in normals):
                    raise ValueError('inConvexPolyhedron: the half-spaces leave the polyhedron unbounded along %s' % (tuple(e / e.norm()),))
        lo = Vector3(*[min(v[i] for v in verts) for i in range(3)])
        hi = Vector3(*[max(v[i] for v in verts) for i in range(3)])
        return (lo, hi)

    def aabb(self):
        return (Vector3(self._box[0]), Vector3(self._box[1]))
