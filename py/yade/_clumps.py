"""O.bodies.replaceByClumps: standalone spheres replaced by clumps of the same volume, shaped by
utils.clumpTemplate (a set-up step, run once: written here, the clumps themselves are made by
O.bodies.appendClumped in C++, pkg/common/Clump.cpp).

As in the reference (found by running it): amounts are fractions of the standalone spheres, int(a*n)
of them per template, all of the first template's first; the spheres are chosen at random (Python's
`random`, so random.seed() repeats a choice); each clump is turned at random, its members' mean
position put at the sphere's centre, and scaled so that the volume of the union of its members
(counted on a grid of cells of a fifth of the smallest member radius, as the reference counts it)
equals the sphere's; members take the sphere's material, color and velocity."""
import math
import random

from ._yade import O, Quaternion, Sphere, Vector3


def templateVolume(relRadii, relPositions):
    """Volume of the union of the template's spheres, counted on a grid of cells of size min(radius)/5
    (centres from the box's lower corner)."""
    import numpy as np  # (on first use: `import yade` does not load numpy)
    c = np.array([[float(x) for x in p] for p in relPositions])
    r = np.array([float(x) for x in relRadii])
    lo, hi = (c - r[:, None]).min(0), (c + r[:, None]).max(0)
    h = r.min() / 5
    axes = [lo[k] + h * (np.arange(int(math.ceil((hi[k] - lo[k]) / h - .5))) + .5) for k in range(3)]
    count = 0
    for x in axes[0]:  # (one slice at a time: the grid of a long template may be large)
        Y, Z = np.meshgrid(axes[1], axes[2], indexing='ij')
        P = np.stack([np.full(Y.shape, x), Y, Z], -1).reshape(-1, 3)
        inside = np.zeros(len(P), bool)
        for ci, ri in zip(c, r):
            inside |= ((P - ci) ** 2).sum(1) < ri * ri
        count += int(inside.sum())
    return count * h ** 3


def randomOrientation():
    """A rotation uniformly distributed (a unit quaternion of four normal deviates)."""
    while True:
        q = [random.gauss(0, 1) for _ in range(4)]
        n = math.sqrt(sum(x * x for x in q))
        if n > 1e-6:
            return Quaternion(q[0] / n, q[1] / n, q[2] / n, q[3] / n)


def replaceByClumps(self, ctList, amounts, discretization=0):
    """Replace standalone spheres by clumps of the templates in ctList (utils.clumpTemplate), a fraction
    amounts[i] of the spheres by template i; each clump has the volume of the sphere it replaces. Returns
    [(clumpId, [memberIds]), ...]."""
    from .utils import sphere
    ctList, amounts = list(ctList), list(amounts)
    if len(ctList) != len(amounts):
        raise ValueError('replaceByClumps: ctList and amounts must have the same length (%d and %d)' % (len(ctList), len(amounts)))
    for t in ctList:
        if not (hasattr(t, 'relRadii') and hasattr(t, 'relPositions')):
            raise TypeError('replaceByClumps: ctList must hold clump templates (utils.clumpTemplate), got %s' % type(t).__name__)
    for a in amounts:
        if not (isinstance(a, (int, float)) and not isinstance(a, bool) and 0 <= a <= 1):
            raise ValueError('replaceByClumps: each amount must be a fraction in [0, 1], got %r' % (a,))
    if sum(amounts) > 1 + 1e-12:
        raise ValueError('replaceByClumps: the amounts sum to %g, more than all the spheres' % sum(amounts))
    if not (isinstance(discretization, int) and discretization >= 0):
        raise ValueError('replaceByClumps: discretization must be 0 or a positive int, got %r' % (discretization,))
    spheres = [b for b in self if b.isStandalone and isinstance(b.shape, Sphere)]
    chosen = random.sample(spheres, len(spheres))
    shapes = []
    for t, a in zip(ctList, amounts):  # (each template's scale and centre once, before any change)
        pos = [Vector3(*[float(x) for x in p]) for p in t.relPositions]
        centre = sum(pos, Vector3.Zero) / len(pos)
        unit = (4 / 3 * math.pi / templateVolume(t.relRadii, t.relPositions)) ** (1 / 3)
        shapes.append((int(a * len(spheres)), [p - centre for p in pos], [float(r) for r in t.relRadii], unit))
    out, k = [], 0
    for count, pos, radii, unit in shapes:
        for b in chosen[k:k + count]:
            R, c, q = b.shape.radius, b.state.pos, randomOrientation()
            scale = R * unit
            members = []
            for p, r in zip(pos, radii):
                m = sphere(c + q * (p * scale), r * scale, material=b.material, color=b.shape.color)
                members.append(m)
            vel, angVel = b.state.vel, b.state.angVel
            self.erase(b.id)
            cid, ids = self.appendClumped(members, discretization=discretization)
            self[cid].state.vel = vel
            out.append((cid, ids))
        k += count
    return out


type(O.bodies).replaceByClumps = replaceByClumps
