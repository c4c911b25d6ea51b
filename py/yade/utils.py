"""Helpers to build scenes, as in yade.utils: sphere(), default material, ..."""
import math
import random

from ._yade import O, Body, Sphere, Aabb, State, FrictMat, Material, Vector3, PWaveTimeStep

__all__ = ['sphere', 'defaultMaterial', 'randomColor', 'PWaveTimeStep']


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


def _commonBodySetup(b, shape, center, material, fixed, mask, volume=None, inertiaFactor=None):
    b.shape = shape
    b.material = _resolveMaterial(material)
    b.state.pos = b.state.refPos = center
    if volume is not None:
        b.state.mass = volume * b.material.density
        b.state.inertia = Vector3(1, 1, 1) * (inertiaFactor * b.state.mass)
    b.dynamic = not fixed
    b.mask = mask
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
    return _commonBodySetup(Body(), shape, center, material, fixed, mask, volume, 2. / 5. * radius ** 2)
