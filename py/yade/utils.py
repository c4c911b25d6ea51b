"""Helpers to build scenes, as in yade.utils: sphere(), default material, ..."""
import math
import random

from ._yade import O, Body, Sphere, Facet, Wall, Box, Aabb, State, FrictMat, Material, Vector3, Quaternion
from ._yade import PWaveTimeStep, unbalancedForce, kineticEnergy, getSpheresVolume

__all__ = ['sphere', 'facet', 'wall', 'box', 'aabbWalls', 'aabbWall', 'defaultMaterial', 'randomColor', 'PWaveTimeStep',
           'unbalancedForce', 'kineticEnergy', 'getSpheresVolume', 'aabbExtrema', 'avgNumInteractions', 'porosity',
           'typedEngine']


def typedEngine(name):
    """The first engine of class `name` in O.engines (IndexError naming it if there is none, as in Yade)."""
    for e in O.engines:
        if type(e).__name__ == name:
            return e
    raise IndexError("no engine of class %s in O.engines" % name)


def defaultMaterial():
    """The material used when none is given: FrictMat(density=1e3, young=1e7, poisson=.3, frictionAngle=.5)."""
    return FrictMat(density=1e3, young=1e7, poisson=.3, frictionAngle=.5, label='defaultMat')


def randomColor():
    """A random RGB color."""
    return Vector3(random.random(), random.random(), random.random())


def _resolveMaterial(material):
    """Material by id, label, instance or callable; -1 is the last defined one (the default if none)."""
    if isinstance(material, Material):
        return material
    if isinstance(material, bool):
        raise TypeError('material must be an id, a label, a Material or a callable, not bool')
    if isinstance(material, int):
        if material == -1:
            if len(O.materials) == 0:
                O.materials.append(defaultMaterial())
            return O.materials[-1]
        if material < 0 or material >= len(O.materials):
            raise IndexError('material id %d out of range (len(O.materials)=%d)' % (material, len(O.materials)))
        return O.materials[material]
    if isinstance(material, str):
        return O.materials[material]
    if callable(material):
        return _resolveMaterial(material())
    raise TypeError('material must be an id, a label, a Material or a callable, not %s' % type(material).__name__)


def _finiteVector(name, v):
    try:
        v = Vector3(v)
    except Exception as e:
        raise TypeError('%s must be a sequence of 3 numbers (%s)' % (name, e))
    if not all(math.isfinite(x) for x in v):
        raise ValueError('%s must be finite, got %s' % (name, v))
    return v


def _commonBodySetup(b, shape, center, material, fixed, mask, volume=None, inertia=None, noBound=False):
    """Shape, material, position, mass and inertia (inertia: per unit mass), dynamic flag, mask, bound."""
    b.shape = shape
    b.material = _resolveMaterial(material)
    b.state.pos = b.state.refPos = center
    if volume is not None:
        b.state.mass = volume * b.material.density
        b.state.inertia = Vector3(inertia) * b.state.mass
    b.dynamic = not fixed
    b.mask = mask
    if not noBound:
        b.bound = Aabb(color=(0, 1, 0))
    return b


def sphere(center, radius, dynamic=None, fixed=False, wire=False, color=None, highlight=False, material=-1, mask=1):
    """A spherical body of the given center and radius; mass and inertia come from the material's density.

    fixed=True makes it non-dynamic (dynamic=False is the old spelling of the same); material is an id
    in O.materials, a label, a Material or a callable returning one (-1: the last defined material,
    or a default FrictMat if there is none)."""
    center = _finiteVector('center', center)
    if isinstance(radius, bool) or not isinstance(radius, (int, float)):
        raise TypeError('radius must be a number, not %s' % type(radius).__name__)
    if not (math.isfinite(radius) and radius > 0):
        raise ValueError('radius must be positive and finite, got %r' % radius)
    if dynamic is not None:
        fixed = not dynamic
    shape = Sphere(radius=radius, color=color if color is not None else randomColor(), wire=wire, highlight=highlight)
    volume = 4. / 3. * math.pi * radius ** 3
    return _commonBodySetup(Body(), shape, center, material, fixed, mask, volume, Vector3(1, 1, 1) * (2. / 5. * radius ** 2))


def _inscribedCircleCenter(v0, v1, v2):
    """Center of the circle inscribed in a triangle: vertices weighted by the opposite edge lengths."""
    a, b, c = (v1 - v2).norm(), (v2 - v0).norm(), (v0 - v1).norm()
    return (v0 * a + v1 * b + v2 * c) / (a + b + c)


def facet(vertices, dynamic=None, fixed=True, wire=True, color=None, highlight=False, noBound=False, material=-1, mask=1):
    """A triangular Facet body; its position is the center of the inscribed circle and the
    vertices are stored relative to it. Facets are fixed (non-dynamic) by default."""
    if len(vertices) != 3:
        raise ValueError('facet needs exactly 3 vertices, got %d' % len(vertices))
    vs = [_finiteVector('vertices[%d]' % i, v) for i, v in enumerate(vertices)]
    if dynamic is not None:
        fixed = not dynamic
    center = _inscribedCircleCenter(*vs)
    shape = Facet(vertices=[v - center for v in vs], color=color if color is not None else randomColor(), wire=wire, highlight=highlight)
    return _commonBodySetup(Body(), shape, center, material, fixed, mask, noBound=noBound)


def wall(position, axis, sense=0, color=None, material=-1, mask=1):
    """An infinite axis-aligned Wall through `position` (a point, or the coordinate along `axis`),
    normal to axis 0, 1 or 2 (or 'x', 'y', 'z'); sense -1/+1 makes only one side interact."""
    if isinstance(axis, str):
        if axis not in ('x', 'y', 'z'):
            raise ValueError("axis must be 0, 1, 2 or 'x', 'y', 'z', got %r" % axis)
        axis = 'xyz'.index(axis)
    if isinstance(position, (int, float)) and not isinstance(position, bool):
        p = Vector3(0, 0, 0)
        p[axis] = position
        position = p
    shape = Wall(axis=axis, sense=sense, color=color if color is not None else randomColor())
    return _commonBodySetup(Body(), shape, _finiteVector('position', position), material, True, mask)


def box(center, extents, orientation=Quaternion.Identity, dynamic=None, fixed=False, wire=False, color=None, highlight=False,
        material=-1, mask=1):
    """A Box body of half-sizes `extents`; mass and inertia of a solid cuboid from the material density."""
    extents = _finiteVector('extents', extents)
    if not all(e > 0 for e in extents):
        raise ValueError('box extents must be positive, got %s' % extents)
    if dynamic is not None:
        fixed = not dynamic
    shape = Box(extents=extents, color=color if color is not None else randomColor(), wire=wire, highlight=highlight)
    x, y, z = 2 * extents[0], 2 * extents[1], 2 * extents[2]
    b = _commonBodySetup(Body(), shape, _finiteVector('center', center), material, fixed, mask, x * y * z,
                         Vector3(y * y + z * z, x * x + z * z, x * x + y * y) / 12.)
    b.state.ori = orientation
    return b


def aabbExtrema(cutoff=0.0, centers=False):
    """Corners (min, max) of the box holding all spheres (their centers if centers=True),
    with the fraction `cutoff` of its size removed (half on each side)."""
    from ._yade import aabbExtremaOfSpheres
    lo, hi = aabbExtremaOfSpheres(centers)
    d = (hi - lo) * (cutoff / 2.)
    return (lo + d, hi - d)


def aabbWalls(extrema=None, thickness=0, oversizeFactor=1.5, **kw):
    """Six boxes (the faces of an axis-aligned box) enclosing `extrema` = (min, max), by default
    the spheres' aabbExtrema(); each face is `thickness` thick and oversizeFactor times larger than
    the box. Extra keywords go to box()."""
    if extrema is None:
        extrema = aabbExtrema()
    lo, hi = Vector3(extrema[0]), Vector3(extrema[1])
    center, half = (lo + hi) / 2, (hi - lo) / 2
    walls = []
    for axis in range(3):
        for side in (-1, 1):
            c = Vector3(center)
            c[axis] = (hi[axis] + thickness / 2) if side > 0 else (lo[axis] - thickness / 2)
            ext = half * oversizeFactor
            ext[axis] = thickness / 2
            walls.append(box(c, ext, fixed=True, **kw) if thickness > 0 else box(c, _flat(ext), fixed=True, **kw))
    return walls


def _flat(ext):
    """A box with zero thickness cannot exist: give it a tiny thickness relative to its size."""
    e = Vector3(ext)
    m = max(e)
    return Vector3([x if x > 0 else 1e-9 * m for x in e])


aabbWall = aabbWalls  # the name used in the manual's tutorial text


def avgNumInteractions(cutoff=0.0, skipFree=False, considerClumps=False):
    """Coordination number Z = 2C/N. Without cutoff and skipFree: 2·(real interactions)/(bodies).
    Otherwise over the bodies whose position lies in aabbExtrema(cutoff); with skipFree, bodies with
    0 or 1 contacts are left out: Z = (2C - N1)/(N - N0 - N1)."""
    if cutoff == 0 and not skipFree:
        n = sum(1 for b in O.bodies)
        return 2.0 * O.interactions.countReal() / n if n else float('nan')
    from ._yade import coordinations
    counts = coordinations(*aabbExtrema(cutoff, centers=False))
    if not counts:
        return float('nan')
    if not skipFree:
        return sum(counts) / float(len(counts))
    n0, n1 = counts.count(0), counts.count(1)
    rest = len(counts) - n0 - n1
    return (sum(counts) - n1) / float(rest) if rest > 0 else float('nan')


def porosity(volume=-1):
    """Volume of voids over the total volume; volume<=0: the box around all spheres (aabbExtrema)."""
    if volume <= 0:
        lo, hi = aabbExtrema()
        d = hi - lo
        volume = d[0] * d[1] * d[2]
    return (volume - getSpheresVolume()) / volume

from .params import readParamsFromTable, waitIfBatch  # noqa: E402
__all__ += ['readParamsFromTable', 'waitIfBatch']
