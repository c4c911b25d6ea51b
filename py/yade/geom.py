"""Boundaries made of facets: facetBox and facetCylinder (as in yade.geom)."""
import math

from ._yade import Quaternion, Vector3
from .utils import facet

__all__ = ['facetBox', 'facetCylinder']


def _quad(a, b, c, d, **kw):
    """Two facets covering the quadrilateral a-b-c-d (vertices in order around it)."""
    return [facet((a, b, c), **kw), facet((a, c, d), **kw)]


def facetBox(center, extents, orientation=Quaternion.Identity, wallMask=63, **kw):
    """The faces of a box (half-sizes `extents`) as facets, two per face. wallMask selects faces:
    1 -x, 2 +x, 4 -y, 8 +y, 16 -z, 32 +z (63: all, 31: open top). Extra keywords go to utils.facet.
    A flat box (one extent zero) is one rectangle, two facets whose normal points along + that
    axis, whatever wallMask (as in Yade)."""
    center, extents, q = Vector3(center), Vector3(extents), Quaternion(orientation)
    if not all(e >= 0 and math.isfinite(e) for e in extents):
        raise ValueError('facetBox extents must be non-negative and finite, got %s' % extents)
    flat = [i for i in range(3) if extents[i] == 0]
    if len(flat) > 1:
        raise ValueError('facetBox needs at least 2 non-zero extents, got %s' % extents)

    def corner(sx, sy, sz):
        return center + q * Vector3(sx * extents[0], sy * extents[1], sz * extents[2])

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


def facetCylinder(center, radius, height, orientation=Quaternion.Identity, segmentsNumber=10, wallMask=7, angleRange=None,
                  closeGap=False, radiusTopInner=-1, radiusBottomInner=-1, **kw):
    """A cylinder of facets around the local z axis, `height` long and centered at `center`.
    wallMask: 1 top cap, 2 bottom cap, 4 side. angleRange=(start, end) makes an open sector;
    closeGap closes such a sector with two radial planes; radiusTopInner / radiusBottomInner > 0
    make the caps rings. Extra keywords go to utils.facet."""
    center, q = Vector3(center), Quaternion(orientation)
    if not (radius > 0 and height > 0):
        raise ValueError('facetCylinder needs positive radius and height')
    if segmentsNumber < 3:
        raise ValueError('facetCylinder needs segmentsNumber >= 3')
    a0, a1 = angleRange if angleRange is not None else (0.0, 2 * math.pi)
    angles = [a0 + (a1 - a0) * i / segmentsNumber for i in range(segmentsNumber + 1)]
    if angleRange is None:
        angles[-1] = angles[0]  # close the circle exactly

    def point(r, a, z):
        return center + q * Vector3(r * math.cos(a), r * math.sin(a), z)

    h = height / 2.
    axisTop, axisBottom = center + q * Vector3(0, 0, h), center + q * Vector3(0, 0, -h)
    ret = []
    for i in range(segmentsNumber):  # per segment: top cap, bottom cap, side (the reference's order)
        a, b = angles[i], angles[i + 1]
        for bit, z, inner, axisPoint in ((1, h, radiusTopInner, axisTop), (2, -h, radiusBottomInner, axisBottom)):
            if not wallMask & bit:
                continue
            if inner > 0:  # a ring: two triangles per segment
                ret.append(facet((point(inner, b, z), point(inner, a, z), point(radius, a, z)), **kw))
                ret.append(facet((point(inner, b, z), point(radius, a, z), point(radius, b, z)), **kw))
            elif bit == 1:
                ret.append(facet((axisPoint, point(radius, b, z), point(radius, a, z)), **kw))
            else:
                ret.append(facet((axisPoint, point(radius, a, z), point(radius, b, z)), **kw))
        if wallMask & 4:
            ret += _quad(point(radius, b, h), point(radius, b, -h), point(radius, a, -h), point(radius, a, h), **kw)
    if closeGap and angleRange is not None:  # close the open sector with two radial planes
        ret.append(facet((axisBottom, point(radius, a0, h), point(radius, a0, -h)), **kw))
        ret.append(facet((axisBottom, axisTop, point(radius, a0, h)), **kw))
        ret.append(facet((axisBottom, point(radius, a1, -h), axisTop), **kw))
        ret.append(facet((axisTop, point(radius, a1, -h), point(radius, a1, h)), **kw))
    return ret
