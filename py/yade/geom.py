"""Boundaries made of facets, as in yade.geom: facetBox, facetParallelepiped, facetCylinder, facetCone,
facetBunker, facetPolygon, facetHelix, facetSphere.

Each returns a list of utils.facet bodies (extra keywords -- material, color, wire, fixed, mask... -- go to
utils.facet). The facets, their order and the order of their vertices (so the direction of their normals) are
those of the reference Yade 2023.02a (tests/test_geom_facets.py compares world-space vertices to 1e-12 with
dumps of the reference, tests/data/geom_facets/). Where the reference accepts arguments that make degenerate
facets (coincident or collinear vertices, which its Facet then reports as a FATAL ERROR) or crashes, these raise
GeomArgumentError, a ValueError that is also a RuntimeError (the reference raises RuntimeError for the arguments
it refuses itself); each such difference is commented where it is checked."""
import math
import operator

from ._yade import Quaternion, Vector3
from .utils import facet

__all__ = ['facetBox', 'facetCylinder', 'facetCone', 'facetBunker', 'facetPolygon', 'facetHelix', 'facetSphere',
           'facetParallelepiped']


class GeomArgumentError(ValueError, RuntimeError):
    """Bad arguments of a geom function (a ValueError; also a RuntimeError, which the reference raises)."""


def _require(ok, message):
    if not ok:
        raise GeomArgumentError(message)


def _number(name, x, fn):
    try:
        x = float(x)
    except (TypeError, ValueError):
        raise TypeError('%s: %s must be a number, got %r' % (fn, name, x)) from None
    _require(math.isfinite(x), '%s: %s must be finite, got %r' % (fn, name, x))
    return x


def _segments(n, fn, least=3):
    n = operator.index(n)  # (a float raises TypeError, as range() does in the reference)
    _require(n >= least, '%s: segmentsNumber must be at least %d, got %d' % (fn, least, n))
    return n


def _quad(a, b, c, d, **kw):
    """Two facets covering the quadrilateral a-b-c-d (vertices in order around it)."""
    return [facet((a, b, c), **kw), facet((a, c, d), **kw)]


# ---------------------------------------------------------------------------------------------- boxes

def _boxFacets(corner, dims, wallMask, fn, kw):
    """The faces of a (possibly sheared) box, two facets per face; corner(sx, sy, sz) with s = -1 or +1 gives
    a corner, dims the three sizes (a zero one makes the box flat: one rectangle whose normal points along +
    that axis, whatever wallMask, as in the reference). wallMask: 1 -x, 2 +x, 4 -y, 8 +y, 16 -z, 32 +z."""
    flat = [i for i in range(3) if dims[i] == 0]
    _require(len(flat) <= 1, '%s needs at least 2 non-zero extents, got %s' % (fn, tuple(dims)))
    if flat:  # (the corners in the order that makes the normal point along + the flat axis)
        rectangle = {0: [(0, -1, -1), (0, 1, -1), (0, 1, 1), (0, -1, 1)],
                     1: [(-1, 0, -1), (-1, 0, 1), (1, 0, 1), (1, 0, -1)],
                     2: [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]}[flat[0]]
        return _quad(*[corner(*c) for c in rectangle], **kw)
    faces = [  # (mask bit, four corners in order)
        (1, [(-1, -1, -1), (-1, 1, -1), (-1, 1, 1), (-1, -1, 1)]),
        (2, [(1, -1, -1), (1, -1, 1), (1, 1, 1), (1, 1, -1)]),
        (4, [(-1, -1, -1), (-1, -1, 1), (1, -1, 1), (1, -1, -1)]),
        (8, [(-1, 1, -1), (1, 1, -1), (1, 1, 1), (-1, 1, 1)]),
        (16, [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1)]),
        (32, [(-1, -1, 1), (-1, 1, 1), (1, 1, 1), (1, -1, 1)]),
    ]
    ret = []
    for bit, corners in faces:
        if wallMask & bit:
            ret += _quad(*[corner(*c) for c in corners], **kw)
    return ret


def facetBox(center, extents, orientation=Quaternion.Identity, wallMask=63, **kw):
    """The faces of a box (half-sizes `extents`) as facets, two per face. wallMask selects faces:
    1 -x, 2 +x, 4 -y, 8 +y, 16 -z, 32 +z (63: all, 31: open top). Extra keywords go to utils.facet.
    A flat box (one extent zero) is one rectangle, two facets whose normal points along + that
    axis, whatever wallMask (as in Yade)."""
    center, extents, q = Vector3(center), Vector3(extents), Quaternion(orientation)
    # (the reference accepts negative extents, which turn the normals inward)
    if not all(e >= 0 and math.isfinite(e) for e in extents):
        raise GeomArgumentError('facetBox extents must be non-negative and finite, got %s' % extents)

    def corner(sx, sy, sz):
        return center + q * Vector3(sx * extents[0], sy * extents[1], sz * extents[2])

    return _boxFacets(corner, extents, wallMask, 'facetBox', kw)


def facetParallelepiped(center, extents, height, orientation=Quaternion.Identity, wallMask=63, **kw):
    """A parallelepiped of facets, two per face (wallMask as facetBox's: 1 -x, 2 +x, 4 -y, 8 +y, 16 -z, 32 +z).
    Its bottom face (local z = -height) is the rectangle of half-sizes extents[0], extents[1] about `center`;
    the top face (z = +height) is the same rectangle moved along +x by sqrt(extents[2]² - height²) (the
    reference's geometry: height = extents[2] gives a box of half-sizes (extents[0], extents[1], height)).
    height = 0 (or extents[0] or [1] = 0) gives one flat rectangle, as facetBox does. Extra keywords go to
    utils.facet."""
    center, extents, q = Vector3(center), Vector3(extents), Quaternion(orientation)
    height = _number('height', height, 'facetParallelepiped')
    # (negative extents are refused as in facetBox; the reference accepts them)
    _require(all(e >= 0 and math.isfinite(e) for e in extents),
             'facetParallelepiped extents must be non-negative and finite, got %s' % extents)
    _require(height >= 0, 'facetParallelepiped: height must be non-negative, got %r' % height)
    _require(height <= extents[2], 'facetParallelepiped: height (%r) must not exceed extents[2] (%r)' % (height, extents[2]))
    shift = math.sqrt(extents[2] ** 2 - height ** 2)

    def corner(sx, sy, sz):
        return center + q * Vector3(sx * extents[0] + (shift if sz > 0 else 0.), sy * extents[1], sz * height)

    return _boxFacets(corner, (extents[0], extents[1], height), wallMask, 'facetParallelepiped', kw)


# ------------------------------------------------------------------------------------ cylinders, cones

def _angleRange(angleRange, fn, allowReversed=False, limit=True):
    """(a0, a1, full) of angleRange (None: the full circle (0, 2π)); full: the range is a whole turn."""
    if angleRange is None:
        return 0., 2 * math.pi, True
    try:
        a0, a1 = angleRange
    except (TypeError, ValueError):
        raise TypeError('%s: angleRange must be None or (start, end), got %r' % (fn, angleRange)) from None
    a0, a1 = _number('angleRange[0]', a0, fn), _number('angleRange[1]', a1, fn)
    if not allowReversed:
        _require(a1 >= a0, '%s: angleRange[1] must not be smaller than angleRange[0], got %r' % (fn, (a0, a1)))
    # an empty range makes only degenerate facets (the reference makes them)
    _require(a1 != a0, '%s: angleRange is empty, got %r' % (fn, (a0, a1)))
    if limit:
        _require(abs(a1 - a0) <= 2 * math.pi, '%s: |angleRange| must not be larger than 2π, got %r' % (fn, (a0, a1)))
    return a0, a1, abs(a1 - a0) == 2 * math.pi


def _anglesOf(a0, a1, full, n):
    angles = [a0 + (a1 - a0) * i / n for i in range(n + 1)]
    if full:
        angles[-1] = angles[0]  # close the circle exactly (the reference ends one rounding away from the start)
    return angles


def _cylinderCone(center, radiusTop, radiusBottom, height, orientation, segmentsNumber, wallMask, angleRange, closeGap,
                  radiusTopInner, radiusBottomInner, kw, fn):
    """The facets of a cone frustum around the local z axis, centered at `center` (the reference's
    facetCylinderConeGenerator): per segment the top cap (wallMask 1; a ring if radiusTopInner > 0), the bottom
    cap (2; a ring if radiusBottomInner > 0) and the side (4); then, with closeGap and a partial angleRange, the
    facets closing the gap (radial planes through the axis for a range below π, the chord plane otherwise, with
    the caps' triangles for a range above π)."""
    center, q = Vector3(center), Quaternion(orientation)
    n = _segments(segmentsNumber, fn)
    rT, rB = _number('radiusTop', radiusTop, fn), _number('radiusBottom', radiusBottom, fn)
    height = _number('height', height, fn)
    rTi, rBi = _number('radiusTopInner', radiusTopInner, fn), _number('radiusBottomInner', radiusBottomInner, fn)
    # (the reference accepts negative radii: the points go to the opposite side of the axis)
    _require(rT >= 0 and rB >= 0, '%s: radii must be non-negative, got %r, %r' % (fn, rT, rB))
    _require(rT > 0 or rB > 0, '%s: radiusTop or radiusBottom must be positive' % fn)
    _require(height >= 0, '%s: height must be non-negative, got %r' % (fn, height))
    # (the reference accepts these and makes facets of coincident vertices)
    _require(height > 0 or rT != rB or not wallMask & 4, '%s: a side of zero height with equal radii is degenerate' % fn)
    _require(rTi < rT or rTi <= 0, '%s: radiusTopInner (%r) must be smaller than the top radius (%r)' % (fn, rTi, rT))
    _require(rBi < rB or rBi <= 0, '%s: radiusBottomInner (%r) must be smaller than the bottom radius (%r)'
             % (fn, rBi, rB))
    a0, a1, full = _angleRange(angleRange, fn)
    angles = _anglesOf(a0, a1, full, n)
    h = height / 2.

    def P(r, a, z):
        return center + q * Vector3(r * math.cos(a), r * math.sin(a), z)

    ct, cb = center + q * Vector3(0, 0, h), center + q * Vector3(0, 0, -h)
    tris = []
    for i in range(n):
        a, b = angles[i], angles[i + 1]
        if wallMask & 1 and rT > 0:
            if rTi > 0:
                tris += [(P(rT, a, h), P(rTi, b, h), P(rTi, a, h)), (P(rT, a, h), P(rT, b, h), P(rTi, b, h))]
            else:
                tris.append((ct, P(rT, b, h), P(rT, a, h)))
        if wallMask & 2 and rB > 0:  # (a ring's normal points to +z, as the top ring's: the reference's order)
            if rBi > 0:
                tris += [(P(rB, a, -h), P(rBi, b, -h), P(rBi, a, -h)), (P(rB, a, -h), P(rB, b, -h), P(rBi, b, -h))]
            else:
                tris.append((cb, P(rB, a, -h), P(rB, b, -h)))
        if wallMask & 4:
            if rT == 0:
                tris.append((ct, P(rB, b, -h), P(rB, a, -h)))
            elif rB == 0:
                tris.append((cb, P(rT, a, h), P(rT, b, h)))
            else:
                tris += [(P(rT, b, h), P(rB, b, -h), P(rB, a, -h)), (P(rB, a, -h), P(rT, a, h), P(rT, b, h))]
    # A whole turn has no gap: the reference closes it anyway with facets of (nearly) coincident vertices.
    T0, T1, B0, B1 = P(rT, a0, h), P(rT, a1, h), P(rB, a0, -h), P(rB, a1, -h)
    if closeGap and not full and a1 - a0 > math.pi:  # the caps' triangles up to the chord (whether or not a side)
        if wallMask & 1 and rT > 0:
            tris.append((T0, T1, ct))
        if wallMask & 2 and rB > 0:
            tris.append((cb, B1, B0))
    if closeGap and not full and wallMask & 4:
        if a1 - a0 >= math.pi:  # the chord plane
            if rT == 0:
                tris.append((ct, B0, B1))
            elif rB == 0:
                tris.append((T1, T0, cb))
            else:
                tris += [(B0, B1, T0), (B1, T1, T0)]
        else:  # two radial planes
            if rT == 0:
                tris += [(ct, B0, cb), (ct, cb, B1)]
            elif rB == 0:
                tris += [(ct, T0, cb), (T1, ct, cb)]
            else:
                tris += [(B0, cb, T0), (cb, ct, T0), (cb, B1, ct), (B1, T1, ct)]
    return [facet(t, **kw) for t in tris]


def facetCylinder(center, radius, height, orientation=Quaternion.Identity, segmentsNumber=10, wallMask=7, angleRange=None,
                  closeGap=False, radiusTopInner=-1, radiusBottomInner=-1, **kw):
    """A cylinder of facets around the local z axis, `height` long and centered at `center`.
    wallMask: 1 top cap, 2 bottom cap, 4 side. angleRange=(start, end) makes an open sector;
    closeGap closes such a sector (two radial planes below π, the chord plane above); radiusTopInner /
    radiusBottomInner > 0 make the caps rings. Extra keywords go to utils.facet."""
    radius, height = _number('radius', radius, 'facetCylinder'), _number('height', height, 'facetCylinder')
    _require(radius > 0, 'facetCylinder: radius must be positive, got %r' % radius)
    # (the reference accepts a zero height and makes facets of coincident vertices)
    _require(height > 0, 'facetCylinder: height must be positive, got %r' % height)
    return _cylinderCone(center, radius, radius, height, orientation, segmentsNumber, wallMask, angleRange, closeGap,
                         radiusTopInner, radiusBottomInner, kw, 'facetCylinder')


def facetCone(center, radiusTop, radiusBottom, height, orientation=Quaternion.Identity, segmentsNumber=10, wallMask=7,
              angleRange=None, closeGap=False, radiusTopInner=-1, radiusBottomInner=-1, **kw):
    """A cone frustum of facets around the local z axis, `height` long and centered at `center`: radiusTop at
    z = +height/2, radiusBottom at -height/2 (one of them may be 0: a pointed cone; a zero height is a flat
    ring). wallMask, angleRange, closeGap, radiusTopInner, radiusBottomInner as facetCylinder's. Extra keywords
    go to utils.facet."""
    return _cylinderCone(center, radiusTop, radiusBottom, height, orientation, segmentsNumber, wallMask, angleRange,
                         closeGap, radiusTopInner, radiusBottomInner, kw, 'facetCone')


def facetBunker(center, dBunker, dOutput, hBunker, hOutput, hPipe=0.0, orientation=Quaternion.Identity, segmentsNumber=10,
                wallMask=4, angleRange=None, closeGap=False, **kw):
    """A bunker of facets along the local z axis, from `center` upward: a pipe (diameter dOutput, height hPipe;
    none if hPipe = 0), a cone widening from dOutput to dBunker over hOutput, and a cylinder (diameter dBunker,
    height hBunker; none if hBunker = 0). wallMask: 1 the top cap, 2 the bottom cap, 4 the sides (4 by default:
    open at both ends). angleRange and closeGap as facetCylinder's, for each part. radiusTopInner /
    radiusBottomInner (keywords the reference's facet generator takes here too) make the caps rings. Extra
    keywords go to utils.facet."""
    fn = 'facetBunker'
    center, q = Vector3(center), Quaternion(orientation)
    dBunker, dOutput = _number('dBunker', dBunker, fn), _number('dOutput', dOutput, fn)
    hBunker, hOutput, hPipe = _number('hBunker', hBunker, fn), _number('hOutput', hOutput, fn), _number('hPipe', hPipe, fn)
    _require(dBunker > 0, '%s: dBunker must be positive, got %r' % (fn, dBunker))
    _require(dOutput > 0, '%s: dOutput must be positive, got %r' % (fn, dOutput))
    _require(hBunker >= 0, '%s: hBunker must be non-negative, got %r' % (fn, hBunker))
    _require(hOutput > 0, '%s: hOutput must be positive, got %r' % (fn, hOutput))
    _require(hPipe >= 0, '%s: hPipe must be non-negative, got %r' % (fn, hPipe))
    # (the reference passes both inner radii to every part, so that each must fit the pipe, and makes the flat
    # bottom lid's ring from radiusTopInner; here each is checked and used only where its cap is)
    rTi, rBi = kw.pop('radiusTopInner', -1), kw.pop('radiusBottomInner', -1)
    rB, rO = dBunker / 2., dOutput / 2.
    at = lambda z: center + q * Vector3(0, 0, z)  # noqa: E731
    ret = []

    def part(z, top, bottom, height, mask, topInner=-1, bottomInner=-1):
        return _cylinderCone(at(z), top, bottom, height, q, segmentsNumber, mask, angleRange, closeGap, topInner,
                             bottomInner, kw, fn)

    if hPipe > 0:
        ret += part(hPipe / 2., rO, rO, hPipe, wallMask & 6, bottomInner=rBi)
    elif wallMask & 2:  # a flat lid at the cone's bottom: a top cap (normal -z, outward), as in the reference
        ret += part(0., rO, rO, 0., 1, topInner=rBi)
    ret += part(hPipe + hOutput / 2., rB, rO, hOutput, wallMask & 4)
    if hBunker > 0:
        ret += part(hPipe + hOutput + hBunker / 2., rB, rB, hBunker, wallMask & 5, topInner=rTi)
    elif wallMask & 1:  # a flat lid at the cone's top (normal -z, inward as the cylinder's top cap); the
        ret += part(hPipe + hOutput, rB, rB, 0., 1, topInner=rTi)  # reference makes none
    return ret


# ------------------------------------------------------------------------------------ polygons, helices

def _polygonHelix(center, radiusOuter, pitch, orientation, segmentsNumber, angleRange, radiusInner, kw, fn, helix):
    """A flat polygon (pitch 0), a sector of one or a ring (radiusInner > 0), or the same wound as a helix
    rising `pitch` per turn along the local z axis (the reference's facetPolygonHelixGenerator)."""
    center, q = Vector3(center), Quaternion(orientation)
    n = _segments(segmentsNumber, fn)
    rO, rI = _number('radiusOuter', radiusOuter, fn), _number('radiusInner', radiusInner, fn)
    _require(rO > 0, '%s: radiusOuter must be positive, got %r' % (fn, rO))
    _require(rI >= 0, '%s: radiusInner must be non-negative, got %r' % (fn, rI))
    # (the reference accepts radiusInner >= radiusOuter: degenerate facets if equal, the normals reversed if larger)
    _require(rI < rO, '%s: radiusInner (%r) must be smaller than radiusOuter (%r)' % (fn, rI, rO))
    if helix:
        pitch = _number('pitch', pitch, fn)
        _require(pitch > 0, '%s: pitch must be positive, got %r' % (fn, pitch))
    # a reversed range is accepted (the reference's: the other sense of turning); a helix may turn several times
    a0, a1, full = _angleRange(angleRange, fn, allowReversed=True, limit=not helix)
    angles = _anglesOf(a0, a1, full and not helix, n)
    zs = [pitch * abs(a1 - a0) / (2 * math.pi) * i / n for i in range(n + 1)] if helix else [0.] * (n + 1)

    def P(r, a, z):
        return center + q * Vector3(r * math.cos(a), r * math.sin(a), z)

    tris = []
    for i in range(n):
        a, b, za, zb = angles[i], angles[i + 1], zs[i], zs[i + 1]
        if rI > 0:
            tris += [(P(rI, a, za), P(rO, a, za), P(rO, b, zb)), (P(rI, b, zb), P(rI, a, za), P(rO, b, zb))]
        else:
            tris.append((center + q * Vector3(0, 0, zb), P(rO, b, zb), P(rO, a, za)))
    return [facet(t, **kw) for t in tris]


def facetPolygon(center, radiusOuter, orientation=Quaternion.Identity, segmentsNumber=10, angleRange=None, radiusInner=0,
                 **kw):
    """A flat regular polygon of facets in the local xy plane about `center` (a fan of segmentsNumber
    triangles), a sector of it (angleRange), or a ring (radiusInner > 0). angleRange=None is the whole turn (the
    reference fails on its own default). Extra keywords go to utils.facet."""
    return _polygonHelix(center, radiusOuter, 0., orientation, segmentsNumber, angleRange, radiusInner, kw,
                         'facetPolygon', False)


def facetHelix(center, radiusOuter, pitch, orientation=Quaternion.Identity, segmentsNumber=10, angleRange=None,
               radiusInner=0, **kw):
    """A helical surface of facets around the local z axis, starting at `center` (z = 0) and rising `pitch`
    per turn over angleRange (default one turn; several turns allowed; a reversed range winds the other way),
    segmentsNumber triangles (or pairs of triangles with radiusInner > 0). Extra keywords go to utils.facet."""
    return _polygonHelix(center, radiusOuter, pitch, orientation, segmentsNumber, angleRange, radiusInner, kw,
                         'facetHelix', True)


# ---------------------------------------------------------------------------------------------- sphere

def facetSphere(center, radius, thetaResolution=8, phiResolution=8, returnElementMap=False, **kw):
    """A closed sphere of facets: the two poles (±z) and phiResolution - 2 rings of thetaResolution points
    (as ParaView's sphere glyph); 2·thetaResolution·(phiResolution - 2) facets, in the reference's order and with
    its vertex order, so that their normals do not all point the same way: the last facet of each polar fan and,
    in each band between two rings, all but the last of its first thetaResolution facets point inward, the
    others outward, as there.
    returnElementMap=True returns (facets, nodes, elements): the points (Vector3) and the facets as triples of
    their indices. Extra keywords go to utils.facet."""
    fn = 'facetSphere'
    center = Vector3(center)
    radius = _number('radius', radius, fn)
    _require(radius > 0, '%s: radius must be positive, got %r' % (fn, radius))
    nt, nph = operator.index(thetaResolution), operator.index(phiResolution)
    _require(nt >= 3, '%s: thetaResolution must be at least 3, got %d' % (fn, nt))
    _require(nph >= 3, '%s: phiResolution must be at least 3, got %d' % (fn, nph))
    nodes = [center + Vector3(0, 0, radius)]
    for i in range(1, nph - 1):
        phi = math.pi * i / (nph - 1)
        for j in range(nt):
            theta = 2 * math.pi * j / nt
            nodes.append(center + Vector3(radius * math.sin(phi) * math.cos(theta), radius * math.sin(phi) * math.sin(theta),
                                          radius * math.cos(phi)))
    nodes.append(center + Vector3(0, 0, -radius))
    south = len(nodes) - 1

    def ring(k):  # the node indices of ring k (0: the one next to the north pole)
        return [1 + k * nt + j for j in range(nt)]

    elements = []
    r = ring(0)
    elements += [(0, r[j], r[j + 1]) for j in range(nt - 1)] + [(0, r[0], r[nt - 1])]
    for k in range(nph - 3):
        u, d = ring(k), ring(k + 1)
        elements += [(u[j], u[j + 1], d[j]) for j in range(nt - 1)] + [(u[0], u[nt - 1], d[nt - 1])]
        elements += [(d[j], d[j + 1], u[j + 1]) for j in range(nt - 1)] + [(d[nt - 1], d[0], u[0])]
    r = ring(nph - 3)
    elements += [(south, r[j], r[j - 1]) for j in range(nt - 1, 0, -1)] + [(south, r[nt - 1], r[0])]
    facets = [facet([nodes[i] for i in e], **kw) for e in elements]
    if returnElementMap:
        return facets, nodes, elements
    return facets
