"""Convex polyhedra (Polyhedra, PolyhedraMat): making the bodies, random shapes and packings.

Our own code, with the reference's function names and arguments; the shapes themselves come from
Polyhedra.Initialize() (the convex hull of the vertices, written here, no CGAL)."""
import math
import random as _random

from ._yade import Body, Polyhedra, Vector3, O
from ._yade import _polyhedra_utils as _cpp
from . import utils as _utils

SieveSize = _cpp.SieveSize
SizeOfPolyhedra = _cpp.SizeOfPolyhedra

__all__ = ['polyhedra', 'polyhedralBall', 'polyhedraSnubCube', 'polyhedraTruncIcosaHed', 'fillBox', 'randomColor', 'SieveSize',
           'SizeOfPolyhedra']


def randomColor(seed=None):
    """Return random Vector3 with each component in interval 0…1 (uniform distribution)"""
    r = _random.Random(seed) if seed is not None else _random
    return Vector3(r.random(), r.random(), r.random())


def _body(shape, material, mask, fixed, color):
    """a body of this (initialized) shape: at its centroid, turned as its vertices were given, mass from the density"""
    b = Body()
    b.shape = shape
    b.material = _utils._resolveMaterial(material)
    b.state.pos = b.state.refPos = shape.GetCentroid()
    b.state.ori = b.state.refOri = shape.GetOri()
    b.state.mass = b.material.density * shape.GetVolume()
    b.state.inertia = b.material.density * shape.GetInertia()
    b.mask = mask
    if fixed:
        b.dynamic = False
        b.state.blockedDOFs = 'xyzXYZ'
    shape.color = Vector3(color) if color is not None and min(color) >= 0 else randomColor()
    return b


def polyhedra(material, size=Vector3(1, 1, 1), seed=None, v=[], mask=1, fixed=False, color=[-1, -1, -1]):
    """create polyhedra, one can specify vertices directly, or leave it empty for random shape.

    :param Material material: material of new body
    :param Vector3 size: size of new body (see Polyhedra docs)
    :param int seed: seed of the random shape (the same seed gives the same shape)
    :param [Vector3] v: list of body vertices (see Polyhedra docs); at least 4, not coplanar
    """
    shape = Polyhedra()
    if len(v) > 0:
        shape.v = [Vector3(x) for x in v]
    else:
        shape.size = Vector3(size)
        shape.seed = int(seed) if seed is not None else _random.randrange(2 ** 31)
        shape.Initialize()
    return _body(shape, material, mask, fixed, color)


def _fibonacciSphere(n):
    """n points spread evenly on the unit sphere"""
    golden = math.pi * (3 - math.sqrt(5))
    pts = []
    for i in range(n):
        z = 1 - 2 * (i + 0.5) / n
        r = math.sqrt(1 - z * z)
        pts.append(Vector3(r * math.cos(golden * i), r * math.sin(golden * i), z))
    return pts


def polyhedralBall(radius, N, material, center, mask=1):
    """creates polyhedra having N vertices and resembling sphere

    :param float radius: ball radius
    :param int N: number of vertices (at least 4)
    :param Material material: material of new body
    :param Vector3 center: center of the new body
    """
    if int(N) < 4:
        raise ValueError('polyhedralBall needs at least 4 vertices, got N=%r' % N)
    if not radius > 0:
        raise ValueError('polyhedralBall: radius must be positive, got %r' % radius)
    b = polyhedra(material, v=[radius * p for p in _fibonacciSphere(int(N))], mask=mask)
    b.state.pos = b.state.refPos = Vector3(center)
    return b


def _ball(radius, unit, material, centre, mask):
    scale = radius / max(p.norm() for p in unit)
    b = polyhedra(material, v=[scale * p for p in unit], mask=mask)
    b.state.pos = b.state.refPos = Vector3(centre)
    return b


def polyhedraSnubCube(radius, material, centre, mask=1):
    """a snub cube (24 vertices) of circumscribed radius `radius` centered at `centre`"""
    t = 1.8392867552141612  # the tribonacci constant
    pts = []
    for (a, b, c) in [(1, 1 / t, t), (1 / t, t, 1), (t, 1, 1 / t)]:  # even permutations, an even number of minus signs...
        for sx in (1, -1):
            for sy in (1, -1):
                sz = sx * sy  # ...(an odd number for the other chirality)
                pts.append(Vector3(sx * a, sy * b, sz * c))
    for (a, b, c) in [(1, t, 1 / t), (t, 1 / t, 1), (1 / t, 1, t)]:  # odd permutations, an odd number of minus signs
        for sx in (1, -1):
            for sy in (1, -1):
                sz = -sx * sy
                pts.append(Vector3(sx * a, sy * b, sz * c))
    return _ball(radius, pts, material, centre, mask)


def polyhedraTruncIcosaHed(radius, material, centre, mask=1):
    """a truncated icosahedron (60 vertices) of circumscribed radius `radius` centered at `centre`"""
    phi = (1 + math.sqrt(5)) / 2
    base = [(0, 1, 3 * phi), (1, 2 + phi, 2 * phi), (phi, 2, 2 * phi + 1)]
    pts = set()
    for (a, b, c) in base:
        for p in [(a, b, c), (b, c, a), (c, a, b)]:  # cyclic permutations, all signs
            for sx in (1, -1):
                for sy in (1, -1):
                    for sz in (1, -1):
                        pts.add((sx * p[0], sy * p[1], sz * p[2]))
    return _ball(radius, [Vector3(*p) for p in sorted(pts)], material, centre, mask)


def fillBox(mincoord, maxcoord, material, sizemin=[1, 1, 1], sizemax=[1, 1, 1], ratio=[0, 0, 0], seed=None, mask=1):
    """fill box [mincoord, maxcoord] by non-overlaping polyhedrons with random geometry and sizes within the range (uniformly distributed)
    :param Vector3 mincoord: first corner
    :param Vector3 maxcoord: second corner
    :param Vector3 sizemin: minimal size of bodies
    :param Vector3 sizemax: maximal size of bodies
    :param Vector3 ratio: scaling ratio (kept for scripts, not used)
    :param float seed: random seed

    The bodies are appended to O.bodies (nothing is returned); their bounding spheres do not overlap and lie inside the box."""
    lo, hi = Vector3(mincoord), Vector3(maxcoord)
    smin, smax = Vector3(sizemin), Vector3(sizemax)
    if not all(hi[k] > lo[k] and 0 < smin[k] <= smax[k] for k in range(3)):
        raise ValueError('fillBox: needs mincoord < maxcoord and 0 < sizemin <= sizemax in each coordinate')
    rnd = _random.Random(seed)
    placed = []  # (center, radius of the bounding sphere)
    misses = 0
    while misses < 1000:
        size = Vector3(*[smin[k] + rnd.random() * (smax[k] - smin[k]) for k in range(3)])
        b = polyhedra(material, size=size, seed=rnd.randrange(2 ** 31), mask=mask)
        r = max(x.norm() for x in b.shape.v)
        if any(hi[k] - lo[k] < 2 * r for k in range(3)):
            misses += 1
            continue
        c = Vector3(*[lo[k] + r + rnd.random() * (hi[k] - lo[k] - 2 * r) for k in range(3)])
        if any((c - p).norm() < r + q for p, q in placed):
            misses += 1
            continue
        b.state.pos = b.state.refPos = c
        O.bodies.append(b)
        placed.append((c, r))
        misses = 0
    print('generated %d polyhedrons' % len(placed))
