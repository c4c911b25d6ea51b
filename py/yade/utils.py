"""Helpers to build scenes, as in yade.utils: sphere(), default material, ..."""
import math
import numbers
import random

from ._yade import O, Body, Sphere, Facet, Wall, Box, Aabb, State, FrictMat, Material, Vector3, Quaternion
from ._yade import PWaveTimeStep, unbalancedForce, kineticEnergy, getSpheresVolume, getSpheresMass, Matrix3
from ._yade import createInteraction  # noqa: F401 (a utils function written in C++)
from ._video import makeVideo, encodeVideoFromFrames  # noqa: F401

__all__ = ['sphere', 'facet', 'wall', 'box', 'aabbWalls', 'aabbWall', 'defaultMaterial', 'randomColor', 'PWaveTimeStep',
           'unbalancedForce', 'kineticEnergy', 'getSpheresVolume', 'aabbExtrema', 'avgNumInteractions', 'porosity',
           'typedEngine', 'getSpheresMass', 'aabbDim', 'inscribedCircleCenter', 'ptInAABB', 'sumForces', 'sumTorques', 'forcesOnPlane',
           'forcesOnCoordPlane', 'getStress', 'bodyStressTensors', 'normalShearStressTensors', 'fabricTensor', 'momentum',
           'angularMomentum', 'maxOverlapRatio', 'numIntrsOfEachBody', 'intrsOfEachBody', 'getBodyIdsContacts', 'psd', 'setRefSe3',
           'shiftBodies', 'calm', 'randomizeColors', 'highlightNone', 'wireAll', 'wireNone', 'wireNoSpheres', 'setBodyPosition',
           'setBodyVelocity', 'setBodyAngularVelocity', 'setBodyOrientation', 'setBodyColor', 'runningInBatch', 'replaceCollider',
           'facetBox', 'facetCylinder', 'makeVideo', 'encodeVideoFromFrames', 'aabbExtrema2d']


def typedEngine(name):
    """The first engine of class `name` in O.engines (IndexError naming it if there is none, as in Yade)."""
    for e in O.engines:
        if type(e).__name__ == name:
            return e
    raise IndexError("no engine of class %s in O.engines" % name)


def _movedToGeom(name):
    def alias(*args, **kw):
        import warnings
        warnings.warn('Function utils.%s is deprecated, use geom.%s instead.' % (name, name), stacklevel=2)
        from . import geom
        return getattr(geom, name)(*args, **kw)
    alias.__name__ = alias.__qualname__ = name
    alias.__doc__ = 'Deprecated (as in the reference): geom.%s, with a warning.' % name
    return alias


facetBox, facetCylinder = _movedToGeom('facetBox'), _movedToGeom('facetCylinder')


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
    b.state = b.material.newAssocState()  # (the material's State class: CpmMat's bodies get a CpmState)
    b.state.pos = b.state.refPos = center
    if volume is not None:
        b.state.mass = volume * b.material.density
        b.state.inertia = Vector3(inertia) * b.state.mass
    b.dynamic = not fixed
    b.mask = mask
    # no bound yet: the collider's Bo1 functor makes it at its first pass, as in the reference, where a new
    # body's bound is None until then; noBound=True keeps the body out of the collider (bounded False), as there
    b.bounded = not noBound
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
    """Center of the circle inscribed in a triangle: the vertices weighted by the opposite edge lengths, written
    as v0 + ((v2-v0)·|v1-v0| + (v1-v0)·|v2-v0|) / perimeter. (Computed in this order, the center and so the facets'
    positions and vertices have the reference's bits: 300 random triangles checked, tests/test_utils_functions.py;
    one ulp off before, which made a 1 000-sphere drum of STL facets drift away from the reference's run.)"""
    def norm(v):  # (summed as the reference's Eigen build does)
        return math.sqrt(v[0] * v[0] + (v[1] * v[1] + v[2] * v[2]))
    e1, e2 = v1 - v0, v2 - v0
    n1, n2 = norm(e1), norm(e2)
    return v0 + (e2 * n1 + e1 * n2) / (n1 + norm(v2 - v1) + norm(v0 - v2))


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
    """A Box body of half-sizes `extents`; mass and inertia of a solid cuboid from the material density. A zero
    extent (a plate, as the reference's scripts use for 2D set-ups) is accepted; its mass is then 0 (fixed=True)."""
    extents = _finiteVector('extents', extents)
    if not all(e >= 0 for e in extents):
        raise ValueError('box extents must be non-negative, got %s' % extents)
    if dynamic is not None:
        fixed = not dynamic
    shape = Box(extents=extents, color=color if color is not None else randomColor(), wire=wire, highlight=highlight)
    x, y, z = 2 * extents[0], 2 * extents[1], 2 * extents[2]
    b = _commonBodySetup(Body(), shape, _finiteVector('center', center), material, fixed, mask, x * y * z, (1, 1, 1))
    # m/12·(y² + z², ...), in the reference's order of operations (its bits)
    b.state.inertia = Vector3(y * y + z * z, x * x + z * z, x * x + y * y) * (b.state.mass / 12.)
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
    """Volume of voids over the total volume; volume<=0: the box around all spheres (aabbExtrema). In a
    periodic scene the volume is the cell's, whatever is given (as in the reference)."""
    if O.periodic:
        volume = O.cell.volume
    elif volume <= 0:
        lo, hi = aabbExtrema()
        d = hi - lo
        volume = d[0] * d[1] * d[2]
    return (volume - getSpheresVolume()) / volume

def voxelPorosity(resolution=200, start=Vector3.Zero, end=Vector3.Zero):
    """Porosity of the box [start, end] counted on a grid of resolution³ voxels: the fraction of voxel
    centers inside no sphere (the other shapes are ignored)."""
    np = _np()
    lo, hi = np.asarray(tuple(start), dtype=float), np.asarray(tuple(end), dtype=float)
    if (lo == hi).all():
        raise ValueError('utils.voxelPorosity: cannot calculate porosity when start==end of the volume box.')
    if not (hi > lo).all() or int(resolution) < 1:
        raise ValueError('utils.voxelPorosity: end must be above start on every axis, and resolution at least 1')
    res = int(resolution)
    step = (hi - lo) / res
    full = np.zeros((res, res, res), dtype=bool)
    a = O.bodies.arrays()
    r = np.asarray(a.radius)
    pos = np.asarray(a.pos)
    axes = [lo[k] + (np.arange(res) + 0.5) * step[k] for k in range(3)]
    for c, rad in zip(pos[np.isfinite(r)], r[np.isfinite(r)]):  # (per sphere: the voxels of its box only)
        i0 = np.maximum(np.floor((c - rad - lo) / step - 0.5).astype(int), 0)
        i1 = np.minimum(np.ceil((c + rad - lo) / step - 0.5).astype(int) + 1, res)
        if (i1 <= i0).any():
            continue
        x, y, z = (axes[k][i0[k]:i1[k]] - c[k] for k in range(3))
        full[i0[0]:i1[0], i0[1]:i1[1], i0[2]:i1[2]] |= (x[:, None, None] ** 2 + y[None, :, None] ** 2 + z[None, None, :] ** 2) <= rad * rad
    return 1.0 - int(full.sum()) / full.size


def aabbDim(cutoff=0.0, centers=False):
    """Size (max - min) of aabbExtrema(cutoff, centers)."""
    lo, hi = aabbExtrema(cutoff, centers)
    return tuple(hi - lo)


def aabbExtrema2d(pts):
    """The 2d bounding box ((xmin, ymin), (xmax, ymax)) of a sequence of points: 2-tuples, Vector2 (or longer
    points, of which the first two coordinates count). Unlike the reference, whose loop updates the maximum of a
    coordinate only when that point did not lower its minimum (so that it returns, e.g., ((0, -1), (2, -inf))
    for [(0, 1), (2, -1)]), each coordinate's minimum and maximum are both taken over all points. An empty
    sequence (the reference: ((inf, inf), (-inf, -inf))), a point of fewer than 2 coordinates or a NaN
    coordinate (which the reference skips silently) raise ValueError."""
    xs, ys = [], []
    for k, p in enumerate(pts):
        try:
            x, y = p[0], p[1]
        except (IndexError, TypeError):
            raise ValueError('aabbExtrema2d: point %d has fewer than 2 coordinates: %r' % (k, p)) from None
        if x != x or y != y:
            raise ValueError('aabbExtrema2d: point %d has a NaN coordinate: %r' % (k, p))
        xs.append(x)
        ys.append(y)
    if not xs:
        raise ValueError('aabbExtrema2d: no points')
    return ((min(xs), min(ys)), (max(xs), max(ys)))


def inscribedCircleCenter(v1, v2, v3):
    """Center of the circle inscribed in the triangle v1 v2 v3 (where utils.facet puts the body)."""
    return _inscribedCircleCenter(Vector3(v1), Vector3(v2), Vector3(v3))


def ptInAABB(p, minPt, maxPt):
    """Whether point p is inside the axis-aligned box [minPt, maxPt] (bounds included)."""
    return all(minPt[i] <= p[i] <= maxPt[i] for i in range(3))


# Per-contact and per-body data as NumPy arrays (no Python loop over the scene).
def _np():
    import numpy
    return numpy


def _contacts():
    """Arrays of the real contacts: id1, id2, normalForce, shearForce, normal, contactPoint, penetrationDepth."""
    return O.interactions.arrays()


def _bodyPos():
    return _np().array(O.bodies.arrays().pos)


def _matrix(a):
    return Matrix3(*[float(x) for x in _np().asarray(a).reshape(9)])


def _ids(ids):
    np = _np()
    ids = np.asarray(list(ids), dtype=int)
    n = len(O.bodies)
    if len(ids) and (ids.min() < 0 or ids.max() >= n):
        raise IndexError('body id out of range (0..%d): %s' % (n - 1, list(ids[(ids < 0) | (ids >= n)])))
    return ids


def sumForces(ids, direction):
    """Sum over bodies `ids` of their force (O.forces, last step) projected on `direction`."""
    np = _np()
    f = np.asarray(O.bodies.arrays().force)[_ids(ids)]
    return float(f.sum(axis=0).dot(np.asarray(tuple(direction), dtype=float)))


def sumTorques(ids, axis, axisPt):
    """Sum over bodies `ids` of their moment about the axis through axisPt along `axis`:
    axis·(T + (x - axisPt) × F), with F and T their force and torque of the last step."""
    np = _np()
    ids = _ids(ids)
    a = O.bodies.arrays()
    r = _bodyPos()[ids] - np.asarray(tuple(axisPt), dtype=float)
    m = np.asarray(a.torque)[ids] + np.cross(r, np.asarray(a.force)[ids])
    return float(m.sum(axis=0).dot(np.asarray(tuple(axis), dtype=float)))


def forcesOnPlane(planePt, normal):
    """Sum of the contact forces (normal and shear) of the contacts whose two bodies lie on either
    side of the plane through planePt normal to `normal`: the force the side the normal points to
    exerts on the other one."""
    np = _np()
    c = _contacts()
    if len(c['id1']) == 0:
        return Vector3.Zero
    pos = _bodyPos()
    n = np.asarray(tuple(normal), dtype=float)
    d1 = (pos[c['id1']] - np.asarray(tuple(planePt), dtype=float)).dot(n)
    d2 = (pos[c['id2']] - np.asarray(tuple(planePt), dtype=float)).dot(n)
    f = np.asarray(c['normalForce']) + np.asarray(c['shearForce'])
    sign = np.where((d1 < 0) & (d2 >= 0), 1.0, np.where((d2 < 0) & (d1 >= 0), -1.0, 0.0))
    return Vector3(*[float(x) for x in (f * sign[:, None]).sum(axis=0)])


def forcesOnCoordPlane(coord, axis):
    """forcesOnPlane for the plane normal to axis 0, 1 or 2 at coordinate coord."""
    pt, n = Vector3.Zero, Vector3.Zero
    pt[axis], n[axis] = coord, 1
    return forcesOnPlane(pt, n)


def _loveSums():
    """Per contact: the force on the second body f (normal + shear) and the branch vector
    l = x2 - x1 between the bodies' positions (in a periodic scene, to body 2's image: + hSize·cellDist)."""
    np = _np()
    c = _contacts()
    pos = _bodyPos()
    f = np.asarray(c['normalForce']) + np.asarray(c['shearForce'])
    l = pos[c['id2']] - pos[c['id1']] + _periodicBranches(c)
    return c, f, l


def _periodicBranches(c):
    """A periodic scene's shifts hSize·cellDist of body 2's images, per contact of c (zero otherwise)."""
    np = _np()
    if not O.periodic or len(c['id1']) == 0:
        return np.zeros((len(c['id1']), 3))
    return np.asarray(c['cellDist'], dtype=float).dot(np.asarray(O.cell.hSize, dtype=float).T)


def getStress(volume=0):
    """Average stress in the volume (Love-Weber): σ = -1/V Σ_c f ⊗ l over the real contacts (f: the
    contact force on the second body, l: the branch vector from the first body's position to the
    second's, or to its image in a periodic cell), tension positive; volume 0: the periodic cell's, or
    the box around all spheres (aabbDim)."""
    np = _np()
    if volume == 0 and O.periodic:
        volume = O.cell.volume
    elif volume == 0:
        d = aabbDim()
        volume = d[0] * d[1] * d[2]
    if not volume > 0:
        raise ValueError('getStress: volume must be positive, got %r' % volume)
    c, f, l = _loveSums()
    return _matrix(-np.einsum('ci,cj->ij', f, l) / volume)


def bodyStressTensors():
    """Stress of each body (one Matrix3 per body id): 1/V_b Σ_c f ⊗ (x_c - x_b), over its real
    contacts, f the contact force on the body, x_c the contact point, V_b its volume (spheres; the
    tensors of bodies with no volume are zero)."""
    np = _np()
    n = len(O.bodies)
    c = _contacts()
    pos = _bodyPos()
    out = np.zeros((n, 3, 3))
    f = np.asarray(c['normalForce']) + np.asarray(c['shearForce'])
    cp = np.asarray(c['contactPoint'])
    shift = _periodicBranches(c)  # (body 2 touches through its image)
    for ids, sign, at in ((c['id1'], -1.0, pos[c['id1']]), (c['id2'], 1.0, pos[c['id2']] + shift)):
        np.add.at(out, ids, np.einsum('ci,cj->cij', sign * f, cp - at))
    r = np.nan_to_num(np.asarray(O.bodies.arrays().radius), nan=0.0)
    vol = 4. / 3. * math.pi * r ** 3
    with np.errstate(divide='ignore', invalid='ignore'):
        out = np.where(vol[:, None, None] > 0, out / vol[:, None, None], 0.0)
    return [_matrix(m) for m in out]


def normalShearStressTensors(compressionPositive=False, splitNormalTensor=False, thresholdForce=float('nan')):
    """The stress of the periodic cell in two parts (Thornton 2000, eq. 3), over the real contacts:
    normal σN = s/V Σ_c R N n ⊗ n and shear σT = s/V Σ_c R n ⊗ T, with R = refR1 + refR2, n the
    normal, N = f_n·n the normal force's magnitude (positive in compression), T the shear force and V
    the cell's volume; σT is made symmetric from its upper triangle. s = 1, or -1 with
    compressionPositive (the reference's signs, which this follows: compression comes out positive
    with the default). splitNormalTensor: (σN of the strong contacts, σN of the weak ones), strong
    those whose N exceeds thresholdForce (NaN: the mean N). RuntimeError in an aperiodic scene."""
    if not O.periodic:
        raise RuntimeError("Can't compute stress of periodic cell in aperiodic simulation.")
    np = _np()
    c = _contacts()
    n = np.asarray(c['normal']).reshape(-1, 3)
    N = np.einsum('ci,ci->c', np.asarray(c['normalForce']).reshape(-1, 3), n)
    R = _refRadiiSums(c)
    s = (-1.0 if compressionPositive else 1.0) / O.cell.volume
    normal = lambda sel: _matrix(s * np.einsum('c,ci,cj->ij', (R * N)[sel], n[sel], n[sel]))
    if splitNormalTensor:
        t = N.mean() if math.isnan(thresholdForce) else thresholdForce
        return (normal(N > t), normal(~(N > t)))
    shear = s * np.einsum('c,ci,cj->ij', R, n, np.asarray(c['shearForce']).reshape(-1, 3))
    shear = np.triu(shear) + np.triu(shear, 1).T
    return (normal(slice(None)), _matrix(shear))


def _refRadiiSums(c):
    """refR1 + refR2 of each contact of c (its geometry's)."""
    np = _np()
    return np.asarray(c['refR1']) + np.asarray(c['refR2'])


def stressTensorOfPeriodicCell(smallStrains=False):
    """The Love-Weber stress of the periodic cell (getStress with the cell's volume); RuntimeError in an
    aperiodic scene."""
    if not O.periodic:
        raise RuntimeError("Can't compute stress of periodic cell in aperiodic simulation.")
    return getStress()


def fabricTensor(cutoff=0.0, splitTensor=False, thresholdForce=float('nan'), extrema=[]):
    """Fabric tensor F = 1/N Σ_c n ⊗ n over the N real contacts (n: contact normal), as a 1-tuple (F,).
    cutoff in [0, 1): only the contacts whose contact point is in aabbExtrema(cutoff), the spheres' box
    shrunk by that fraction on each side; extrema=(min, max): in that box instead. splitTensor:
    (F_strong, F_weak), each over its own contacts: strong those whose signed normal force (negative
    in compression) is below thresholdForce (NaN: the mean), as the reference. A part without contacts
    is NaN there and here, with a RuntimeWarning."""
    np = _np()
    c = _contacts()
    nrm = np.asarray(c['normal'])
    keep = np.ones(len(nrm), dtype=bool)
    if len(extrema):
        if len(extrema) != 2:
            raise ValueError('fabricTensor: extrema must be two corners (min, max)')
        lo, hi = (np.asarray(tuple(v), dtype=float) for v in extrema)
    elif cutoff:
        lo, hi = (np.asarray(tuple(v), dtype=float) for v in aabbExtrema(cutoff))
    if len(extrema) or cutoff:
        cp = np.asarray(c['contactPoint']).reshape(-1, 3)
        keep = np.all((cp >= lo) & (cp <= hi), axis=1)
    nn = np.einsum('ci,cj->cij', nrm, nrm)[keep]

    def mean(part, what):
        if len(part) == 0:
            import warnings
            warnings.warn('fabricTensor: no contacts %s: a NaN tensor (as the reference)' % what, RuntimeWarning, stacklevel=3)
            return Matrix3(*[float('nan')] * 9)
        return _matrix(part.sum(axis=0) / len(part))

    if not splitTensor:
        return (mean(nn, 'considered'),)
    f = -np.einsum('ci,ci->c', np.asarray(c['normalForce']), nrm)[keep]  # (compression negative)
    t = f.mean() if math.isnan(thresholdForce) else thresholdForce
    strong = f < t
    return (mean(nn[strong], 'in the strong part'), mean(nn[~strong], 'in the weak part'))


def momentum():
    """Total linear momentum Σ m v of the bodies."""
    np = _np()
    a = O.bodies.arrays()
    ok = np.asarray(a.exists, dtype=bool)
    return Vector3(*[float(x) for x in (np.asarray(a.mass)[ok, None] * np.asarray(a.vel)[ok]).sum(axis=0)])


def angularMomentum(origin=Vector3.Zero):
    """Angular momentum of the bodies' motion about `origin`: Σ (x - origin) × m v (the orbital part,
    as the reference computes it; the spin I·ω of the bodies about their own centers is not added)."""
    np = _np()
    a = O.bodies.arrays()
    ok = np.asarray(a.exists, dtype=bool)
    r = np.asarray(a.pos)[ok] - np.asarray(tuple(origin), dtype=float)
    L = np.cross(r, np.asarray(a.mass)[ok, None] * np.asarray(a.vel)[ok]).sum(axis=0)
    return Vector3(*[float(x) for x in L])


def maxOverlapRatio():
    """Largest overlap of two spheres in contact relative to their harmonic mean radius:
    max δ/r*, r* = 2 r1 r2/(r1 + r2) (-1 without sphere-sphere contacts, as the reference)."""
    np = _np()
    c = _contacts()
    r = np.asarray(O.bodies.arrays().radius)
    if len(c['id1']) == 0:
        return -1.0
    r1, r2 = r[c['id1']], r[c['id2']]
    both = ~np.isnan(r1) & ~np.isnan(r2)
    if not both.any():
        return -1.0
    rHarmonic = 2 * r1[both] * r2[both] / (r1[both] + r2[both])
    return float((np.asarray(c['penetrationDepth'])[both] / rHarmonic).max())


def numIntrsOfEachBody():
    """Number of real interactions of each body, indexed by id."""
    np = _np()
    c = _contacts()
    counts = np.bincount(np.concatenate([c['id1'], c['id2']]).astype(int), minlength=len(O.bodies))
    return [int(x) for x in counts]


def intrsOfEachBody():
    """The real interactions of each body, indexed by id."""
    return [O.interactions.withBody(i) if O.bodies[i] is not None else [] for i in range(len(O.bodies))]


def getBodyIdsContacts(bodyID=0):
    """Ids of the bodies that body bodyID has an interaction with (real or potential)."""
    ret = []
    for i in O.interactions.withBodyAll(bodyID):
        ret.append(i.id2 if i.id1 == bodyID else i.id1)
    return ret


def psd(bins=5, mass=True, mask=-1):
    """Particle size distribution of the spheres: (diameters, cumulative fraction, cumulative sum)
    over `bins` equal intervals between the smallest and the largest diameter; the sum is of masses
    (mass=True) or of numbers of spheres."""
    np = _np()
    from ._yade import _sphereColumns
    ids, pos, r, mat = _sphereColumns(mask)
    if len(ids) == 0:
        raise RuntimeError('psd: there are no spheres')
    d = 2 * np.asarray(r)
    w = np.asarray(O.bodies.arrays().mass)[ids] if mass else np.ones(len(d))
    edges = np.linspace(d.min(), d.max(), bins + 1)
    hist, _ = np.histogram(d, bins=edges, weights=w)
    cum = np.concatenate([[0.], np.cumsum(hist)])
    return edges, cum / cum[-1], cum


def setRefSe3():
    """Set every body's reference position and orientation (State.refPos, refOri) to the current ones."""
    for b in O.bodies:
        b.state.refPos = b.state.pos
        b.state.refOri = b.state.ori


def shiftBodies(ids, shift):
    """Move bodies `ids` by `shift`; returns 1."""
    shift = Vector3(shift)
    for i in ids:
        O.bodies[i].state.pos += shift
    return 1


def calm(mask=-1):
    """Zero the velocity and angular velocity of the bodies whose mask shares a bit with `mask` (-1: all)."""
    for b in O.bodies:
        if mask == -1 or (b.mask & mask):
            b.state.vel = Vector3.Zero
            b.state.angVel = Vector3.Zero


def randomizeColors(onlyDynamic=False):
    """Give every body's shape (only dynamic bodies with onlyDynamic) a random color."""
    for b in O.bodies:
        if b.shape is not None and (b.dynamic or not onlyDynamic):
            b.shape.color = randomColor()


def highlightNone():
    """Turn Shape.highlight off for all bodies."""
    for b in O.bodies:
        if b.shape is not None:
            b.shape.highlight = False


def _setWire(wire, spheresToo=True):
    for b in O.bodies:
        if b.shape is not None and (spheresToo or not isinstance(b.shape, Sphere)):
            b.shape.wire = wire


def wireAll():
    """Draw all shapes as wireframes."""
    _setWire(True)


def wireNone():
    """Draw all shapes filled."""
    _setWire(False)


def wireNoSpheres():
    """Draw all shapes as wireframes, spheres filled."""
    _setWire(True, spheresToo=False)
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            b.shape.wire = False


def _setComponents(vec, value, axes):
    v = Vector3(vec)
    for a in axes:
        if a not in 'xyz':
            raise ValueError("axes must be letters of 'xyz', got %r" % axes)
        v['xyz'.index(a)] = value['xyz'.index(a)]
    return v


def setBodyPosition(id, pos, axis='xyz'):
    """Set the position of body `id` along the given axes."""
    O.bodies[id].state.pos = _setComponents(O.bodies[id].state.pos, Vector3(pos), axis)


def setBodyVelocity(id, vel, axis='xyz'):
    """Set the velocity of body `id` along the given axes."""
    O.bodies[id].state.vel = _setComponents(O.bodies[id].state.vel, Vector3(vel), axis)


def setBodyAngularVelocity(id, angVel):
    """Set the angular velocity of body `id`."""
    O.bodies[id].state.angVel = Vector3(angVel)


def setBodyOrientation(id, ori):
    """Set the orientation (Quaternion) of body `id`."""
    O.bodies[id].state.ori = Quaternion(ori)


def setBodyColor(id, color):
    """Set the color of body `id`'s shape."""
    O.bodies[id].shape.color = Vector3(color)


def runningInBatch():
    """Whether the script runs in a batch: yade-batch sets ``YADE_BATCH`` (table:line) for each job, as the
    reference does (its runningInBatch() ignores the older ``PARAM_TABLE``)."""
    from .params import inBatch
    return inBatch()


def replaceCollider(colliderEngine):
    """Put `colliderEngine` in O.engines in place of the current collider."""
    from ._yade import Collider
    engines = list(O.engines)
    for i, e in enumerate(engines):
        if isinstance(e, Collider):
            engines[i] = colliderEngine
            O.engines = engines
            return
    raise RuntimeError('replaceCollider: no collider in O.engines')


# --- time steps, growing particles, friction, small helpers (the reference's utils functions) ---------

def SpherePWaveTimeStep(radius, density, young):
    """P-wave critical time step of one (representative) sphere: radius / sqrt(young / density)."""
    return radius / math.sqrt(young / density)


def RayleighWaveTimeStep():
    """Rayleigh-wave critical time step: the smallest over spheres of pi·r / (0.1631·nu + 0.876605) · sqrt(rho/G),
    G = E / (2·(1 + nu)), from each sphere's elastic material (inf without spheres)."""
    dt = float('inf')
    for b in O.bodies:
        m = b.material
        if not isinstance(b.shape, Sphere) or not hasattr(m, 'poisson'):
            continue
        G = m.young / (2 * (1 + m.poisson))
        dt = min(dt, math.pi * b.shape.radius / (0.1631 * m.poisson + 0.876605) * math.sqrt(m.density / G))  # (the reference's bits)
    return dt


def _grow(b, multiplier, updateMass):
    b.shape.radius *= multiplier
    if updateMass:
        b.state.mass *= multiplier ** 3
        b.state.inertia *= multiplier ** 5


def _growRefRadii(grown, multiplier):
    """The reference radii of the real contacts of the bodies in `grown` (a set of ids)."""
    for i in O.interactions:
        if i.isReal and hasattr(i.geom, 'refR1'):
            if i.id1 in grown:
                i.geom.refR1 *= multiplier
            if i.id2 in grown:
                i.geom.refR2 *= multiplier


def growParticles(multiplier, updateMass=True, dynamicOnly=True):
    """Multiply the radius of every sphere (only dynamic ones with dynamicOnly) by `multiplier`, with their
    mass (multiplier^3) and inertia (multiplier^5) if updateMass, and the reference radii of their contacts."""
    grown = set()
    for b in O.bodies:
        if isinstance(b.shape, Sphere) and (b.dynamic or not dynamicOnly):
            _grow(b, multiplier, updateMass)
            grown.add(b.id)
    _growRefRadii(grown, multiplier)


def growParticle(bodyID, multiplier, updateMass=True):
    """growParticles for the one sphere `bodyID` (dynamic or not)."""
    b = O.bodies[bodyID]
    if b is None or not isinstance(b.shape, Sphere):
        raise TypeError('growParticle: body #%d is not a sphere' % bodyID)
    _grow(b, multiplier, updateMass)
    _growRefRadii({bodyID}, multiplier)


def setContactFriction(angleRad):
    """Set the friction angle of the materials of dynamic bodies to angleRad, and the friction of every real
    contact to tan(min) of its two bodies' friction angles."""
    for b in O.bodies:
        if b.dynamic and hasattr(b.material, 'frictionAngle'):
            b.material.frictionAngle = angleRad
    for i in O.interactions:
        if i.isReal and hasattr(i.phys, 'tangensOfFrictionAngle'):
            m1, m2 = O.bodies[i.id1].material, O.bodies[i.id2].material
            i.phys.tangensOfFrictionAngle = math.tan(min(m1.frictionAngle, m2.frictionAngle))


def sumFacetNormalForces(ids, axis=-1):
    """Sum over facets `ids` of their force (O.forces) dotted with their normal; with axis 0, 1 or 2, that
    component of the force is left out first."""
    total = 0.
    for i in ids:
        f = O.bodies[i].shape if O.bodies[i] is not None else None
        if not isinstance(f, Facet):
            raise TypeError('sumFacetNormalForces: body #%d is not a facet' % i)
        force = Vector3(O.forces.f(i))
        if axis >= 0:
            force[axis] = 0
        total += force.dot(f.normal)
    return total


def negPosExtremeIds(axis, distFactor):
    """Ids of the spheres at the two ends of the spheres' box along `axis`: ([those with
    pos - distFactor·r <= min], [those with pos + distFactor·r >= max])."""
    lo, hi = aabbExtrema()
    neg, pos = [], []
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            if b.state.pos[axis] - b.shape.radius * distFactor <= lo[axis]:
                neg.append(b.id)
            if b.state.pos[axis] + b.shape.radius * distFactor >= hi[axis]:
                pos.append(b.id)
    return (neg, pos)


def cart2spher(vec):
    """Spherical coordinates (r, theta from +z, phi from +x in the xy plane) of a Cartesian vector."""
    r = Vector3(vec).norm()
    if r == 0:
        raise ValueError('cart2spher: the zero vector has no direction')
    return Vector3(r, math.acos(vec[2] / r), math.atan2(vec[1], vec[0]))


def spher2cart(vec):
    """Cartesian coordinates of spherical (r, theta, phi), theta from +z in [0, pi]."""
    r, theta, phi = vec[0], vec[1], vec[2]
    if not 0 <= theta <= math.pi:
        import warnings
        warnings.warn('Spherical theta has to be between 0 and pi, passing %s is impossible' % theta, RuntimeWarning)
    return Vector3(r * math.sin(theta) * math.cos(phi), r * math.sin(theta) * math.sin(phi), r * math.cos(theta))


def fractionalBox(fraction=1.0, minMax=None):
    """(min, max) of the box minMax (default: aabbExtrema()) shrunk about its center to `fraction` of its size."""
    lo, hi = minMax if minMax is not None else aabbExtrema()
    d = (1 - fraction) / 2.
    return (tuple(lo[i] + d * (hi[i] - lo[i]) for i in range(3)), tuple(hi[i] - d * (hi[i] - lo[i]) for i in range(3)))


def scalarOnColorScale(x, xmin=0, xmax=1):
    """Color (RGB) of x on a blue-cyan-green-yellow-red scale from xmin to xmax (clamped at both ends)."""
    t = min(1., max(0., (x - xmin) / (xmax - xmin)))
    if t < .25:
        return Vector3(0, 4 * t, 1)
    if t < .5:
        return Vector3(0, 1, 1 - 4 * (t - .25))
    if t < .75:
        return Vector3(4 * (t - .5), 1, 0)
    return Vector3(1, 1 - 4 * (t - .75), 0)


def randomOrientation():
    """A random orientation, uniformly distributed (a unit quaternion from three uniform numbers)."""
    u1, u2, u3 = random.random(), random.random(), random.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return Quaternion(b * math.cos(2 * math.pi * u3), a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
                      b * math.sin(2 * math.pi * u3))


def perpendicularArea(axis):
    """Area of the face perpendicular to `axis` (0, 1, 2) of the box holding all spheres (aabbExtrema())."""
    lo, hi = aabbExtrema()
    a, b = (axis + 1) % 3, (axis + 2) % 3
    return (hi[a] - lo[a]) * (hi[b] - lo[b])


def getSpheresVolume2D(mask=-1):
    """Total area of the spheres seen as discs (sum of pi·r²), of those whose mask shares a bit with `mask`
    (-1: all)."""
    return sum((math.pi * b.shape.radius ** 2 for b in O.bodies if isinstance(b.shape, Sphere) and (mask == -1 or (b.mask & mask))), 0.0)


def flipCell(flip=Matrix3.Zero):
    """Flip the periodic cell (3.6.2): the same periodic space with edges hSize·(I + flip), the
    interactions' cellDist adjusted so that nothing moves. flip: integers, I + flip of determinant 1;
    zero: the flip that makes the edges least skewed (each less the whole multiples of the others it
    holds). Returns the flip applied."""
    return O._flipCell(flip)


def getTotalDynamicStress(volume=0):
    """The dynamic (kinetic) stress Σ_b m v ⊗ v / V over the bodies. In a periodic scene, v is the
    fluctuation about the homogeneous field, v - velGrad·x, and V the cell's volume; otherwise `volume`
    is required."""
    np = _np()
    a = O.bodies.arrays()
    live = np.asarray(a.exists, dtype=bool)  # (not the holes of erased bodies)
    v, m = np.asarray(a.vel)[live], np.asarray(a.mass)[live]
    if O.periodic:
        v = v - np.asarray(a.pos)[live].dot(np.asarray(O.cell.velGrad, dtype=float).T)
        volume = O.cell.volume
    elif not volume > 0:
        raise ValueError('getTotalDynamicStress: Must provide volume if scene is not periodic!')
    return _matrix(np.einsum('b,bi,bj->ij', m, v, v) / volume)


_VARS_TAG = 'pickledPythonVariablesDictionary'


def saveVars(mark='', loadNow=True, **kw):
    """Save the keyword arguments inside the simulation (O.tags, saved with it); loadVars(mark) makes them
    the module yade.params.<mark> (yade.params itself for mark ''), at once with loadNow."""
    import pickle
    O.tags[_VARS_TAG + mark] = pickle.dumps(kw, protocol=0).decode('latin-1')
    if loadNow:
        loadVars(mark)


def loadVars(mark=None):
    """Load the variables of saveVars(mark) (of every mark if None) into yade.params.<mark>."""
    import pickle
    from . import params
    if mark is None:
        marks = [k[len(_VARS_TAG):] for k in O.tags.keys() if k.startswith(_VARS_TAG)]
    else:
        if _VARS_TAG + mark not in O.tags.keys():
            raise KeyError('Invalid key: %s.' % (_VARS_TAG + mark))
        marks = [mark]
    for m in marks:
        params._paramsModule(m, pickle.loads(O.tags[_VARS_TAG + m].encode('latin-1')))


__all__ += ['SpherePWaveTimeStep', 'RayleighWaveTimeStep', 'growParticles', 'growParticle', 'setContactFriction',
            'sumFacetNormalForces', 'negPosExtremeIds', 'cart2spher', 'spher2cart', 'fractionalBox', 'scalarOnColorScale',
            'randomOrientation', 'saveVars', 'loadVars', 'perpendicularArea', 'getSpheresVolume2D', 'getTotalDynamicStress',
            'stressTensorOfPeriodicCell', 'voxelPorosity', 'flipCell']

from .params import readParamsFromTable, waitIfBatch  # noqa: E402
__all__ += ['readParamsFromTable', 'waitIfBatch']


# --- more of the reference's utils functions (behaviour found by running the reference on small scenes) ---

def _axisArg(fn, axis, message='Axis must be from {0,1,2}=x,y,z.'):
    if isinstance(axis, bool) or not isinstance(axis, int):
        raise TypeError('%s: axis must be an int 0, 1 or 2, got %r' % (fn, axis))
    if axis not in (0, 1, 2):
        raise ValueError(message)
    return axis


def _boxArg(fn, name, box):
    """() -> None; else the (min, max) corners of an axis-aligned box as NumPy arrays."""
    np = _np()
    if not isinstance(box, (tuple, list)):
        raise TypeError('%s: %s must be a tuple ((xmin,ymin,zmin),(xmax,ymax,zmax)), got %r' % (fn, name, box))
    if len(box) == 0:
        return None
    if len(box) < 2:
        raise ValueError('%s: %s needs two corners ((xmin,ymin,zmin),(xmax,ymax,zmax)), got %r' % (fn, name, box))
    try:
        lo, hi = (np.array([float(x) for x in box[k]][:3]) for k in (0, 1))
    except (TypeError, ValueError):
        raise TypeError('%s: %s corners must be 3 numbers each, got %r' % (fn, name, box))
    if len(lo) < 3 or len(hi) < 3:
        raise ValueError('%s: %s corners must be 3 numbers each, got %r' % (fn, name, box))
    return lo, hi


def _strictlyInside(pos, box):
    """Rows of pos (N x 3) strictly inside box (lo, hi) (a point on a face is outside, as in the reference)."""
    lo, hi = box
    return ((pos > lo) & (pos < hi)).all(axis=1)


def totalForceInVolume():
    """(Σ over the real contacts of the absolute values of the components of the contact force (normal + shear),
    the mean over the contacts of (kn + 2 ks)/3); (Vector3.Zero, -1.0) without contacts."""
    np = _np()
    c = _contacts()
    if len(c['id1']) == 0:
        return (Vector3.Zero, -1.0)
    f = np.abs(np.asarray(c['normalForce']) + np.asarray(c['shearForce'])).sum(axis=0)
    k = [(i.phys.kn + 2 * i.phys.ks) / 3. for i in O.interactions if i.isReal and hasattr(i.phys, 'ks')]
    return (Vector3(*[float(x) for x in f]), float(sum(k) / len(k)) if k else -1.0)


def bodyNumInteractionsHistogram(aabb):
    """Histogram of the number of real contacts of the bodies whose position is strictly inside the box
    aabb=((xmin,ymin,zmin),(xmax,ymax,zmax)): ([distinct numbers of contacts, ascending], [number of bodies with each])."""
    np = _np()
    if not isinstance(aabb, tuple):
        raise TypeError('bodyNumInteractionsHistogram: aabb must be a tuple ((xmin,ymin,zmin),(xmax,ymax,zmax)), got %r' % (aabb,))
    box = _boxArg('bodyNumInteractionsHistogram', 'aabb', aabb)
    if box is None:
        raise ValueError('bodyNumInteractionsHistogram: aabb must have two corners')
    a = O.bodies.arrays()
    n = len(O.bodies)
    if n == 0:
        return ([], [])
    ok = np.asarray(a.exists, dtype=bool) & _strictlyInside(_bodyPos(), box)
    counts = np.asarray(numIntrsOfEachBody())[ok]
    vals, freq = np.unique(counts, return_counts=True)
    return ([int(v) for v in vals], [int(x) for x in freq])


def interactionAnglesHistogram(axis, mask=0, bins=20, aabb=(), sphSph=False, minProjLen=1e-6):
    """Histogram of the directions of the contact normals projected on the plane perpendicular to `axis`:
    ([start of each of the `bins` intervals of [0, pi)], [sum of the projection lengths of the normals in each]).
    The angle is that of the projection (components (axis+1)%3, (axis+2)%3), folded into [0, pi); a normal goes
    to the interval whose start is nearest (those nearest to pi are left out, as in the reference). Only contacts
    with both bodies matching `mask` (0: all), with at least one body strictly inside `aabb` (if given), between
    two spheres (with sphSph) and with a projection at least `minProjLen` long count."""
    np = _np()
    _axisArg('interactionAnglesHistogram', axis)
    if isinstance(bins, bool) or not isinstance(bins, int):
        raise TypeError('interactionAnglesHistogram: bins must be an int, got %r' % (bins,))
    if bins < 0:
        raise ValueError('interactionAnglesHistogram: bins must not be negative, got %d' % bins)
    box = _boxArg('interactionAnglesHistogram', 'aabb', aabb)
    if bins == 0:
        return ([], [])
    step = math.pi / bins
    starts = [i * step for i in range(bins)]
    hist = np.zeros(bins)
    c = _contacts()
    if len(c['id1']):
        id1, id2 = np.asarray(c['id1']), np.asarray(c['id2'])
        ok = np.ones(len(id1), dtype=bool)
        if mask:
            masks = np.array([b.mask if b is not None else 0 for b in O.bodies])
            ok &= ((masks[id1] & mask) != 0) & ((masks[id2] & mask) != 0)
        if box is not None:
            inside = _strictlyInside(_bodyPos(), box)
            ok &= inside[id1] | inside[id2]
        if sphSph:
            r = np.asarray(O.bodies.arrays().radius)
            ok &= ~np.isnan(r[id1]) & ~np.isnan(r[id2])
        nrm = np.asarray(c['normal'])
        u, v = nrm[:, (axis + 1) % 3], nrm[:, (axis + 2) % 3]
        proj = np.hypot(u, v)
        ok &= proj >= minProjLen
        ang = np.arctan2(v, u)
        ang = np.where(ang < 0, ang + math.pi, ang)
        idx = np.floor(ang / step + .5).astype(int)
        ok &= idx < bins
        np.add.at(hist, idx[ok], proj[ok])
    return (starts, [float(x) for x in hist])


def coordsAndDisplacements(axis, Aabb=()):
    """([coordinate along axis of each body], [its displacement from the reference position along axis]), in id
    order, of all bodies or only of those strictly inside Aabb=((xmin,ymin,zmin),(xmax,ymax,zmax))."""
    np = _np()
    _axisArg('coordsAndDisplacements', axis)
    box = _boxArg('coordsAndDisplacements', 'Aabb', Aabb)
    ids = [b.id for b in O.bodies if b is not None]
    if not ids:
        return ([], [])
    pos = _bodyPos()[ids]
    ref = np.array([tuple(O.bodies[i].state.refPos) for i in ids], dtype=float)
    if box is not None:
        ok = _strictlyInside(pos, box)
        pos, ref = pos[ok], ref[ok]
    return ([float(x) for x in pos[:, axis]], [float(x) for x in pos[:, axis] - ref[:, axis]])


def _convexHullArea(pts):
    """Area of the convex hull of 2D points (N x 2 array), Andrew's monotone chain."""
    pts = sorted(set(map(tuple, pts)))
    if len(pts) < 3:
        return 0.0

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    return abs(sum(hull[i][0] * hull[i - 1][1] - hull[i - 1][0] * hull[i][1] for i in range(len(hull)))) / 2.


def approxSectionArea(coord, axis):
    """Approximate area of the section of the packing by the plane perpendicular to `axis` at `coord`: the
    convex hull of the spheres crossing the plane (|x - coord| <= r), each one replaced by the 6 points
    (r cos(k pi/3), 2 r sin(k pi/3)) around its center in the plane (components (axis+1)%3, (axis+2)%3),
    as the reference does (a single sphere gives 3 sqrt(3) r^2); 0 without such spheres."""
    np = _np()
    _axisArg('approxSectionArea', axis, 'Axis must be \u2208 {0,1,2}')
    coord = float(coord)
    r = np.asarray(O.bodies.arrays().radius)
    pos = _bodyPos()
    if len(r) == 0:
        return 0.0
    ok = ~np.isnan(r)
    ok[ok] = np.abs(pos[ok, axis] - coord) <= r[ok]
    if not ok.any():
        return 0.0
    k = np.arange(6) * math.pi / 3
    a, b = (axis + 1) % 3, (axis + 2) % 3
    xs = (pos[ok, a][:, None] + r[ok][:, None] * np.cos(k)[None, :]).ravel()
    ys = (pos[ok, b][:, None] + 2 * r[ok][:, None] * np.sin(k)[None, :]).ravel()
    return float(_convexHullArea(np.stack([xs, ys], axis=1)))


def pointInsidePolygon(pt, vertices):
    """Whether the 2D point pt=(x, y) is inside the polygon of the 2D `vertices` (even-odd rule, ray casting).
    (The reference crashes on every call, so points on the boundary follow this implementation only.)"""
    try:
        x, y = float(pt[0]), float(pt[1])
    except (TypeError, IndexError, ValueError):
        raise TypeError('pointInsidePolygon: pt must be a 2D point (x, y), got %r' % (pt,))
    try:
        vs = [(float(v[0]), float(v[1])) for v in vertices]
    except (TypeError, IndexError, ValueError):
        raise TypeError('pointInsidePolygon: vertices must be a sequence of 2D points, got %r' % (vertices,))
    if len(vs) < 3:
        raise ValueError('pointInsidePolygon: vertices must have at least 3 points, got %d' % len(vs))
    inside = False
    j = len(vs) - 1
    for i in range(len(vs)):
        xi, yi = vs[i]
        xj, yj = vs[j]
        if (yi > y) != (yj > y) and x < (xj - xi) * (y - yi) / (yj - yi) + xi:
            inside = not inside
        j = i
    return inside


def _periodicWrap(x, x0, x1):
    """x moved by a whole number of periods (x1 - x0) into [x0, x1); (wrapped x, number of periods removed)."""
    period = x1 - x0
    if period == 0 or math.isnan(period):
        return float('nan'), 0
    n = math.floor((x - x0) / period)
    return x - n * period, n


def spiralProject(pt, dH_dTheta, axis=2, periodStart=float('nan'), theta0=0):
    """Project pt on the spiral around `axis` rising dH_dTheta per radian: ((r, h), theta), with r the distance
    from the axis, theta its angle (in [0, 2 pi), from the (axis+1)%3 direction toward (axis+2)%3; with periodStart,
    moved by whole turns into [periodStart, periodStart + 2 pi)) and h the height of pt above the spiral through
    theta0: pt[axis] - dH_dTheta (theta - theta0), brought within half a turn of the spiral's height at theta when
    periodStart is NaN."""
    _axisArg('spiralProject', axis)
    try:
        p = [float(pt[k]) for k in range(3)]
    except (TypeError, IndexError, ValueError):
        raise TypeError('spiralProject: pt must be a 3D point, got %r' % (pt,))
    dH, periodStart, theta0 = float(dH_dTheta), float(periodStart), float(theta0)
    a, b = p[(axis + 1) % 3], p[(axis + 2) % 3]
    r = math.hypot(a, b)
    theta = math.atan2(b, a) if r > 0 else 0.0
    if theta < 0:
        theta += 2 * math.pi
    hRef = dH * (theta - theta0)
    if math.isnan(periodStart):
        h, _ = _periodicWrap(p[axis] - hRef, hRef - math.pi * dH, hRef + math.pi * dH)
        return ((r, h), theta)
    theta, _ = _periodicWrap(theta, periodStart, periodStart + 2 * math.pi)
    return ((r, p[axis] - dH * (theta - theta0)), theta)


def setNewVerticesOfFacet(b, v1, v2, v3):
    """Give facet body b the new vertices v1, v2, v3 (global coordinates): its position becomes their inscribed
    circle's center and its vertices are stored relative to it (its orientation is left as it is)."""
    if not isinstance(b, Body) or not isinstance(b.shape, Facet):
        raise TypeError('setNewVerticesOfFacet: b must be a body with a Facet shape, got %r' % (b,))
    vs = [_finiteVector(n, v) for n, v in (('v1', v1), ('v2', v2), ('v3', v3))]
    center = _inscribedCircleCenter(*vs)
    b.state.pos = center
    b.shape.vertices = [v - center for v in vs]


def vmData():
    """Memory use of this process: the VmData line of /proc/self/status, in kB (an int)."""
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith('VmData:'):
                return int(line.split()[1])
    raise RuntimeError('vmData: no VmData line in /proc/self/status')


def voxelPorosity(resolution=200, start=Vector3.Zero, end=Vector3.Zero):
    """Porosity (V - Vv)/V of the box from `start` to `end`, divided into resolution^3 voxels (resolution along
    each side), Vv being the voxels whose corner nearest `start` is inside a sphere; 1.0 for an empty or
    inverted box. Close to, but not voxel for voxel the same as, the reference's count."""
    np = _np()
    if isinstance(resolution, bool) or not isinstance(resolution, int):
        raise TypeError('voxelPorosity: resolution must be an int, got %r' % (resolution,))
    s, e = np.array(tuple(start), dtype=float), np.array(tuple(end), dtype=float)
    if s.shape != (3,) or e.shape != (3,):
        raise TypeError('voxelPorosity: start and end must be 3D points')
    if (s == e).all():
        raise ValueError('utils.voxelPorosity: cannot calculate porosity when start==end of the volume box.')
    if resolution < 50:
        raise ValueError("utils.voxelPorosity: it doesn't make sense to calculate porosity with voxel resolution below 50.")
    if (e <= s).any():
        return 1.0
    d = (e - s) / resolution
    grid = np.zeros((resolution,) * 3, dtype=bool)
    r = np.asarray(O.bodies.arrays().radius)
    pos = _bodyPos()
    for i in np.nonzero(~np.isnan(r))[0] if len(r) else []:
        c, rad = pos[i], r[i]
        lo = np.clip(np.floor((c - rad - s) / d).astype(int), 0, resolution)
        hi = np.clip(np.ceil((c + rad - s) / d).astype(int) + 1, 0, resolution)
        if (hi <= lo).any():
            continue
        xs, ys, zs = (s[k] + np.arange(lo[k], hi[k]) * d[k] - c[k] for k in range(3))
        inside = xs[:, None, None] ** 2 + ys[None, :, None] ** 2 + zs[None, None, :] ** 2 < rad * rad
        grid[lo[0]:hi[0], lo[1]:hi[1], lo[2]:hi[2]] |= inside
    return float(1 - grid.sum() / grid.size)


class TableParamReader(object):
    """Read a table of simulation parameters (the reference's utils.TableParamReader): one column per parameter,
    the first non-blank line gives the names, '#' starts a comment, '=' repeats the value of the line above; a
    'description' column is built from the columns whose name ends in '!' (the '!' removed), or from all columns,
    when absent ('__line=N__' appended to a repeated description). Values are kept as strings."""

    def __init__(self, file):
        if not isinstance(file, str):
            raise TypeError('TableParamReader: file must be a file name (str), got %r' % (file,))
        with open(file) as f:
            lines = f.read().splitlines()
        headings, values, prev = None, {}, None
        for lineNo, raw in enumerate(lines, start=1):
            words = raw.split('#', 1)[0].split()
            if not words:
                continue
            if headings is None:
                headings = words
                continue
            if len(words) < len(headings):
                raise ValueError('TableParamReader: %s line %d has %d values for %d columns'
                                 % (file, lineNo, len(words), len(headings)))
            row = []
            for j in range(len(headings)):
                w = words[j]
                if w == '=':
                    if prev is None:
                        raise ValueError("TableParamReader: %s line %d: '=' with no line above" % (file, lineNo))
                    w = prev[j]
                row.append(w)
            prev = row
            values[lineNo] = row
        headings = headings or []
        bangs = [h for h in headings if h.endswith('!')]
        names = [h[:-1] if h.endswith('!') else h for h in headings]
        self.values = {}
        seen = set()
        for lineNo, row in values.items():
            d = dict(zip(names, row))
            if 'description' not in d:
                use = [h[:-1] for h in bangs] if bangs else names
                desc = ','.join('%s=%s' % (n, d[n]) for n in use)
                if desc in seen:
                    desc += '__line=%d__' % lineNo
                d['description'] = desc
            seen.add(d['description'])
            self.values[lineNo] = d

    def paramDict(self):
        """{line number: {parameter name: value (str)}} of the table, '=' and '!' resolved, 'description' added."""
        return self.values


def _defaultEngines():
    from ._yade import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, Bo1_Box_Aabb, InteractionLoop,
                        Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Box_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                        Law2_ScGeom_FrictPhys_CundallStrack, GlobalStiffnessTimeStepper, NewtonIntegrator)
    return [ForceResetter(),
            InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()], label='collider'),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
                            [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()], label='interactionLoop'),
            GlobalStiffnessTimeStepper(timeStepUpdateInterval=10, label='timeStepper'),
            NewtonIntegrator(damping=.2, label='newton')]


# The reference's engine list (a list made once at import, as there).
defaultEngines = _defaultEngines()

__all__ += ['totalForceInVolume', 'bodyNumInteractionsHistogram', 'interactionAnglesHistogram', 'coordsAndDisplacements',
            'approxSectionArea', 'pointInsidePolygon', 'spiralProject', 'setNewVerticesOfFacet', 'vmData', 'voxelPorosity',
            'defaultEngines', 'TableParamReader']


class clumpTemplate:
    """A clump's shape for O.bodies.replaceByClumps: the radii and positions of its members relative
    to the sphere it replaces (the reference's class: numCM is the number of members; the lists are
    kept as given). Both lists must have the same length, at least 2; here the radii must also be
    positive and finite, and each position 3 finite numbers (the reference accepts any values)."""

    def __init__(self, relRadii=[], relPositions=[[], []]):
        if len(relRadii) != len(relPositions):
            raise ValueError('Given lists must have same length! Given lists does not match clump template structure.')
        if len(relRadii) < 2:
            raise ValueError('One or more of given lists for relative radii have length < 2! Given lists does not match clump template structure.')
        for i, r in enumerate(relRadii):
            if not (isinstance(r, numbers.Real) and not isinstance(r, bool) and math.isfinite(r) and r > 0):
                raise ValueError('clumpTemplate: relRadii[%d] must be a positive finite number, got %r' % (i, r))
        for i, p in enumerate(relPositions):
            try:
                ok = len(p) == 3 and all(math.isfinite(float(x)) for x in p)
            except (TypeError, ValueError):
                ok = False
            if not ok:
                raise ValueError('clumpTemplate: relPositions[%d] must be 3 finite numbers, got %r' % (i, p))
        self.numCM = len(relRadii)
        self.relRadii = relRadii
        self.relPositions = relPositions


__all__ += ['clumpTemplate']
