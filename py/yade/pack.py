"""Sphere packings, as in yade.pack: SpherePack (geometry only: centers, radii and clump ids) and its
makeCloud and makeClumpCloud loose random packings; volume predicates (inSphere, inCylinder... and their boolean operations,
yade._packPredicates) and the regular packings that fill them (regularOrtho, regularHexa), and
filterSpherePack; the dense random packings randomDensePack and randomPeriPack (yade._densePack).

    from yade import pack
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, rRelFuzz=.3, seed=1)
    ids = sp.toSimulation(color=(0, 0, 1))   # keywords go to utils.sphere

SpherePack is implemented in C++ (pkg/dem/SpherePack); toSimulation is added here.
"""
import math
import warnings

from ._yade import O, SpherePack, Vector3, Quaternion, Matrix3
from . import utils
from ._packPredicates import *  # noqa: F401,F403
from ._packPredicates import Predicate, __all__ as _predicateNames
from ._densePack import randomDensePack, randomPeriPack  # noqa: E402 (they use filterSpherePack, below)

__all__ = ['SpherePack', 'SpherePackIterator', 'SpherePack_toSimulation', 'regularOrtho', 'regularHexa', 'filterSpherePack',
           'cloudBestFitOBB', 'randomDensePack', 'randomPeriPack'] + _predicateNames


def _periodicCell(sp):
    """Make the scene periodic with the packing's cell, as Yade does."""
    O.periodic = True
    O.cell.setBox(sp.cellSize)


def SpherePack_toSimulation(self, rot=None, **kw):
    """Add the spheres to the simulation as bodies made by utils.sphere(center, radius, **kw), in one
    O.bodies.append call, then (a packing with clump ids, as makeClumpCloud makes) one clump of the
    members of each clump by O.bodies.clump, by increasing clump id; returns the list of the ids of
    the spheres, then of the clumps (the reference's numbering). rot (a Quaternion or a rotation
    Matrix3) turns the packing about the origin first. A periodic packing also sets the periodic cell."""
    if rot is not None and not isinstance(rot, (Quaternion, Matrix3)):
        raise TypeError('SpherePack.toSimulation: rot must be a Quaternion or a Matrix3, got %s' % type(rot).__name__)
    clumps = self.getClumps()[1]
    if clumps and not hasattr(O.bodies, 'clump'):
        raise NotImplementedError('SpherePack.toSimulation: the packing has clumps, and this build has no O.bodies.clump yet')
    if self.isPeriodic:
        _periodicCell(self)
    turn = (lambda c: c) if rot is None else (lambda c: rot * Vector3(c))
    ids = O.bodies.append([utils.sphere(turn(c), r, **kw) for c, r in self])
    return ids + [O.bodies.clump([ids[i] for i in members]) for members in clumps]


SpherePack.toSimulation = SpherePack_toSimulation
SpherePackIterator = type(iter(SpherePack()))  # (what iter(sp) gives: (center, radius) pairs)


def _latticeBox(predicate, radius, gap, who):
    if not isinstance(predicate, Predicate):
        raise TypeError('%s: predicate must be a volume predicate (pack.inSphere(...), ...), got %s' % (who, type(predicate).__name__))
    radius, gap = float(radius), float(gap)
    if not (radius > 0 and math.isfinite(radius)):
        raise ValueError('%s: radius must be positive and finite, got %r' % (who, radius))
    if not (gap > -2 * radius and math.isfinite(gap)):  # (negative: overlapping neighbours, as the reference allows)
        raise ValueError('%s: gap must be finite and above -2*radius (the spacing 2*radius+gap must be positive), got %r' % (who, gap))
    lo, hi = (Vector3(v) for v in predicate.aabb())
    if not all(math.isfinite(x) for x in list(lo) + list(hi)):
        raise ValueError('%s: the predicate has an unbounded box (%s, %s); intersect it with a bounded one (pred & pack.inAlignedBox(...))'
                         % (who, tuple(lo), tuple(hi)))
    return lo, hi, radius, gap


def regularOrtho(predicate, radius, gap, **kw):
    """Spheres of the given radius on a cubic lattice of spacing 2*radius+gap, from the corner of the
    predicate's box, those inside the predicate (at least radius from its boundary); returns the
    list of bodies made by utils.sphere(center, radius, **kw). Along each axis the centres are
    lo+r, lo+r+a... strictly below hi-r (a = 2r+gap), as the reference's: a sphere that would touch
    the box's upper face exactly is not made (box (0,0,0)-(1,1,1), r = 0.1: 64 spheres there and here)."""
    lo, hi, r, gap = _latticeBox(predicate, radius, gap, 'regularOrtho')
    a = 2 * r + gap
    n = [max(0, int(math.ceil(((h - r) - (l + r)) / a))) for l, h in zip(lo, hi)]
    centers = [c for i in range(n[0]) for j in range(n[1]) for k in range(n[2])
               for c in (Vector3(lo[0] + r + i * a, lo[1] + r + j * a, lo[2] + r + k * a),) if predicate(c, r)]
    return [utils.sphere(c, r, **kw) for c in centers]


def regularHexa(predicate, radius, gap, **kw):
    """Spheres of the given radius in hexagonal close packing (spacing 2*radius+gap between
    neighbours; layers along z, rows along y), those inside the predicate (at least radius from
    its boundary); returns the list of bodies made by utils.sphere(center, radius, **kw)."""
    lo, hi, r, gap = _latticeBox(predicate, radius, gap, 'regularHexa')
    a = 2 * r + gap
    dy, dz = a * math.sqrt(3) / 2, a * math.sqrt(2 / 3.)  # between rows, between layers
    n = [int(math.ceil((hi[0] - lo[0]) / a)) + 2, int(math.ceil((hi[1] - lo[1]) / dy)) + 2, int(math.ceil((hi[2] - lo[2]) / dz)) + 2]
    centers = []
    for i in range(n[0]):
        for j in range(n[1]):
            for k in range(n[2]):
                # rows alternate by half a spacing along x; odd layers sit over the holes of even ones
                c = Vector3(lo[0] + (i + .5 * ((j + k) % 2)) * a, lo[1] + (j + (k % 2) / 3.) * dy, lo[2] + k * dz)
                if predicate(c, r):
                    centers.append(c)
    return [utils.sphere(c, r, **kw) for c in centers]


def filterSpherePack(predicate, spherePack, returnSpherePack=None, **kw):
    """The spheres of spherePack inside the predicate (each at least its radius from the boundary),
    the packing first moved so that its centre is the predicate's: a new SpherePack with
    returnSpherePack=True, else a list of bodies made by utils.sphere(center, radius, **kw)
    (without returnSpherePack, with the reference's FutureWarning). spherePack is not changed."""
    if not isinstance(predicate, Predicate):
        raise TypeError('filterSpherePack: predicate must be a volume predicate, got %s' % type(predicate).__name__)
    if not isinstance(spherePack, SpherePack):
        raise TypeError('filterSpherePack: spherePack must be a SpherePack, got %s' % type(spherePack).__name__)
    if returnSpherePack is None:
        warnings.warn('filterSpherePack: specify returnSpherePack=True to get a SpherePack (add it with its toSimulation()), '
                      'or False to get a list of bodies', FutureWarning, stacklevel=2)
    dimP, dimS = Vector3(predicate.dim()), Vector3(spherePack.dim())
    if any(s < p for s, p in zip(dimS, dimP)):
        warnings.warn("Packing's dimension (%s) doesn't fully contain dimension of the predicate (%s)." % (tuple(dimS), tuple(dimP)))
    shift = Vector3(predicate.center()) - Vector3(spherePack.center())
    kept = [(c, r) for c, r in ((Vector3(c) + shift, r) for c, r in spherePack) if predicate(c, r)]
    if returnSpherePack:
        out = SpherePack()
        out.fromList(kept)
        return out
    return [utils.sphere(c, r, **kw) for c, r in kept]


def cloudBestFitOBB(points):
    """The oriented bounding box of least volume of the points (a sequence of 3-vectors), found by a
    search over orientations (a coarse grid of rotations and the principal axes, then refined):
    returns (center, halfSize, orientation), the points p lying within
    orientation.conjugate() * (p - center) in [-halfSize, halfSize]."""
    import numpy
    try:
        P = numpy.array([[float(x) for x in p] for p in points], dtype=float)
    except (TypeError, ValueError) as e:
        raise TypeError('cloudBestFitOBB: expected a sequence of 3-vectors') from e
    if P.ndim != 2 or P.shape[1] != 3 or len(P) < 1:
        raise TypeError('cloudBestFitOBB: expected a non-empty sequence of 3-vectors')
    if not numpy.isfinite(P).all():
        raise ValueError('cloudBestFitOBB: the points must be finite')

    def volume(R):  # (the box's axes are the columns of R)
        Q = P @ R
        return numpy.prod(Q.max(0) - Q.min(0))

    def rotation(axis, angle):
        axis = numpy.asarray(axis, float) / numpy.linalg.norm(axis)
        K = numpy.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
        return numpy.eye(3) + numpy.sin(angle) * K + (1 - numpy.cos(angle)) * K @ K

    candidates = [numpy.eye(3)]
    if len(P) > 3:
        _, vecs = numpy.linalg.eigh(numpy.cov(P.T))
        candidates.append(vecs * numpy.sign(numpy.linalg.det(vecs)))
    grid = numpy.radians(numpy.arange(0, 90, 15))
    for a in grid:
        for b in grid:
            for c in grid:
                candidates.append(rotation((0, 0, 1), a) @ rotation((0, 1, 0), b) @ rotation((1, 0, 0), c))
    best = sorted(candidates, key=volume)[:4]
    results = []
    for R in best:  # pattern search over small turns about the box's own axes
        v, step = volume(R), .2
        while step > 1e-9:
            improved = False
            for i in range(3):
                for sgn in (1, -1):
                    T = R @ rotation(numpy.eye(3)[i], sgn * step)
                    w = volume(T)
                    if w < v * (1 - 1e-15):
                        R, v, improved = T, w, True
            if not improved:
                step *= .5
        results.append((v, R))
    v, R = min(results, key=lambda x: x[0])
    Q = P @ R
    lo, hi = Q.min(0), Q.max(0)
    center = R @ ((lo + hi) / 2)
    orientation = Quaternion(Matrix3(*R.flatten()))
    orientation.normalize()
    return (Vector3(*center), Vector3(*((hi - lo) / 2)), orientation)
