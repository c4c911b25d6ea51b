"""Measuring and transforming groups of spheres and facets (the reference's yade.bodiesHandling):
the box a group occupies, its volume and mass; copies of spheres; a group shifted, scaled and turned
about its center.

Bodies are given as a list of ids or of Body objects; an empty list means every body whose mask
shares a bit with `mask`. Bodies of another shape in the list are left out."""
import math

from yade import O, Facet, Quaternion, Sphere, Vector3, utils

__all__ = ['spheresPackDimensions', 'facetsDimensions', 'sphereDuplicate', 'spheresModify']


def _bodies(items, mask, shape, who):
    """The bodies of class `shape` among items (ids or bodies), or in O.bodies when items is empty;
    mask filters both (-1: any)."""
    if not items:
        if mask == -1:
            raise ValueError('%s: give a list of body ids (or bodies), or a mask selecting bodies of O.bodies' % who)
        items = [b for b in O.bodies]
    out = []
    for item in items:
        b = O.bodies[item] if isinstance(item, int) else item
        if b is not None and isinstance(b.shape, shape) and (mask == -1 or (b.mask & mask) != 0):
            out.append(b)
    return out


def _extent(points):
    """min, max and the ids reaching them along each axis, over (id, low corner, high corner) triples (the
    first one reaching an extreme keeps it); all zero for none."""
    lo, hi = Vector3(0, 0, 0), Vector3(0, 0, 0)
    loId, hiId = Vector3(0, 0, 0), Vector3(0, 0, 0)
    for n, (bid, a, b) in enumerate(points):
        for i in range(3):
            if n == 0 or a[i] < lo[i]:
                lo[i], loId[i] = a[i], bid
            if n == 0 or b[i] > hi[i]:
                hi[i], hiId[i] = b[i], bid
    return dict(min=lo, max=hi, minId=loId, maxId=hiId, center=(lo + hi) / 2, extends=hi - lo)


def spheresPackDimensions(idSpheres=[], mask=-1):
    """The box holding the spheres (`min`, `max`, the ids reaching them per axis `minId`, `maxId`, `center`,
    `extends` = max - min), their total `volume` and `mass`, and their `number` (all zero for none)."""
    spheres = _bodies(idSpheres, mask, Sphere, 'spheresPackDimensions')
    d = _extent([(b.id, b.state.pos - Vector3(1, 1, 1) * b.shape.radius, b.state.pos + Vector3(1, 1, 1) * b.shape.radius)
                 for b in spheres])
    d.update(volume=sum(4. / 3. * math.pi * b.shape.radius ** 3 for b in spheres), mass=sum(b.state.mass for b in spheres),
             number=len(spheres))
    return d


def facetsDimensions(idFacets=[], mask=-1):
    """The box holding the facets' vertices (keys as spheresPackDimensions, without volume and mass)."""
    facets = _bodies(idFacets, mask, Facet, 'facetsDimensions')
    corners = []
    for b in facets:
        for v in b.shape.vertices:
            p = b.state.pos + b.state.ori * v
            corners.append((b.id, p, p))
    d = _extent(corners)
    d.update(number=len(facets))
    return d


def sphereDuplicate(idSphere):
    """A new sphere (not in O.bodies) at the position of sphere `idSphere`, of its radius, material, color
    and mask, at rest and free."""
    b = O.bodies[idSphere]
    if b is None or not isinstance(b.shape, Sphere):
        raise ValueError('sphereDuplicate: body #%d is not a sphere' % idSphere)
    return utils.sphere(b.state.pos, b.shape.radius, material=b.material, color=b.shape.color, mask=b.mask)


def spheresModify(idSpheres=[], mask=-1, shift=Vector3(0, 0, 0), scale=1.0, orientation=Quaternion.Identity, copy=False):
    """Turns the spheres by `orientation` and scales their positions and radii by `scale` about the center of
    their box (spheresPackDimensions), then shifts them by `shift`; masses scale by scale³ and inertias by
    scale⁵, velocities and orientations stay. With copy=True the spheres are left as they are and modified
    copies (sphereDuplicate, not in O.bodies) are returned; otherwise True."""
    if not (isinstance(scale, (int, float)) and math.isfinite(scale) and scale > 0):
        raise ValueError('spheresModify: scale must be positive and finite, got %r' % (scale,))
    spheres = _bodies(idSpheres, mask, Sphere, 'spheresModify')
    center = spheresPackDimensions(spheres)['center'] if spheres else Vector3(0, 0, 0)
    if copy:
        spheres = [sphereDuplicate(b.id) for b in spheres]
    shift = Vector3(*shift)
    for b in spheres:
        b.state.pos = center + orientation * (b.state.pos - center) * scale + shift
        b.shape.radius *= scale
        b.state.mass *= scale ** 3
        b.state.inertia *= scale ** 5
    return spheres if copy else True
