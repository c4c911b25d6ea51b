"""Dense random packings, as yade.pack.randomDensePack and randomPeriPack: a loose periodic cloud
(SpherePack.makeCloud) compressed by PeriIsoCompressor in the secondary scene (O.switchScene), so
that the user's scene is left as it was; then repeated (SpherePack.cellFill) and cut to the
predicate (filterSpherePack). Packings may be memoized in an sqlite database. doc/pack-dense.md."""
import math
import os
import sqlite3
import tempfile
import time

from ._yade import (O, SpherePack, Vector3, FrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                    Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, PeriIsoCompressor,
                    NewtonIntegrator)
from . import utils

# the compression: stiff frictionless spheres pushed to a high stress, then unloaded to a low one
# (overlaps of about 1e-4 of the radius at the end); porosity and sphere counts as the reference's
_YOUNG, _STRESSES, _MAX_STEPS = 30e9, [-1e8, -1e6], 200000
_FRICTION_PERI, _FRICTION_DENSE = 0., .5
_MAX_UNBALANCED = 1e-2
_DENSE_FILL = .56  # (about what the compression reaches with _FRICTION_DENSE)
_LOOSE_POROSITY = .85  # of the initial cloud of randomDensePack's spheresInCell spheres


def _positive(who, name, x):
    try:
        x = float(x)
    except (TypeError, ValueError):
        raise TypeError('%s: %s must be a number, got %s' % (who, name, type(x).__name__)) from None
    if not (x > 0 and math.isfinite(x)):
        raise ValueError('%s: %s must be positive and finite, got %r' % (who, name, x))
    return x


def _fuzz(who, rRelFuzz):
    try:
        rRelFuzz = float(rRelFuzz)
    except (TypeError, ValueError):
        raise TypeError('%s: rRelFuzz must be a number, got %s' % (who, type(rRelFuzz).__name__)) from None
    if not (0 <= rRelFuzz < 1):
        raise ValueError('%s: rRelFuzz must be in [0, 1), got %r' % (who, rRelFuzz))
    return rRelFuzz


def _compress(cloud, radius, friction):
    """The periodic cloud compressed in the secondary scene; returns the dense periodic SpherePack.
    The current scene is not touched (O.switchScene there and back, the secondary scene reset)."""
    O.switchScene()  # (raises, with the reference's words, while the simulation runs)
    try:
        O.resetThisScene()
        mat = O.materials.append(FrictMat(young=_YOUNG, poisson=.5, frictionAngle=friction, density=2400))
        cloud.toSimulation(material=mat)  # (sets the periodic cell)
        O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=.05 * radius),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                     PeriIsoCompressor(charLen=2 * radius, stresses=_STRESSES, maxUnbalanced=_MAX_UNBALANCED, doneHook='import yade; yade.O.pause()', globalUpdateInt=5,
                                       keepProportions=True), NewtonIntegrator(damping=.6)]
        O.dt = .5 * utils.PWaveTimeStep()
        O.run(_MAX_STEPS, True)
        if O.engines[3].state < len(_STRESSES):
            raise RuntimeError('randomDensePack: the periodic compression did not converge in %d steps' % _MAX_STEPS)
        dense = SpherePack()
        dense.fromSimulation()
        return dense
    finally:
        O.resetThisScene()
        O.switchScene()


def _spheresFor(size, radius, rRelFuzz):
    """Spheres of a dense packing (solid fraction _DENSE_FILL) of about 1.1 times the box of size (so that
    one compressed cell covers it)."""
    mean = 4 / 3. * math.pi * radius ** 3 * (1 + rRelFuzz ** 2)
    return max(1, int(math.ceil(1.1 * size[0] * size[1] * size[2] * _DENSE_FILL / mean)))


def _cloud(size, radius, rRelFuzz, seed, num=-1):
    cloud = SpherePack()
    cloud.makeCloud(Vector3(0, 0, 0), Vector3(size), rMean=radius, rRelFuzz=rRelFuzz, num=num, periodic=True, seed=seed)
    if len(cloud) == 0:
        raise ValueError('the periodic cell %s is too small for spheres of radius %g' % (tuple(size), radius))
    return cloud


def randomPeriPack(radius, initSize, rRelFuzz=0.0, memoizeDb=None, noPrint=False, seed=-1):
    """Periodic dense packing: a periodic cell of initSize filled with as many spheres of radius
    radius·(1±rRelFuzz) as fit (makeCloud), compressed isotropically by PeriIsoCompressor; returns the
    periodic SpherePack (its cellSize the compressed cell). memoizeDb: an sqlite file where it is
    looked up first and stored after (as in randomDensePack); noPrint: no message."""
    radius, rRelFuzz = _positive('randomPeriPack', 'radius', radius), _fuzz('randomPeriPack', rRelFuzz)
    size = Vector3(initSize)
    for x in size:
        _positive('randomPeriPack', 'initSize', x)
    if memoizeDb:
        sp = _memoLoad(memoizeDb, radius, rRelFuzz, None, noPrint)
        if sp is not None:
            return sp
    if not noPrint:
        print("No suitable packing in database found, running PERIODIC compression")
    sp = _compress(_cloud(size, radius, rRelFuzz, seed), radius, _FRICTION_PERI)
    if memoizeDb:
        _memoSave(memoizeDb, sp, radius, rRelFuzz)
    return sp


def randomDensePack(predicate, radius, material=-1, dim=None, cropLayers=0, rRelFuzz=0.0, spheresInCell=0, memoizeDb=None,
                    useOBB=False, memoDbg=False, color=None, returnSpherePack=None, seed=-1, **kw):
    """Random dense packing of spheres of radius radius·(1±rRelFuzz) (uniform) filling the predicate:
    a periodic packing compressed by PeriIsoCompressor (spheresInCell spheres in the cell, repeated by
    cellFill to the predicate's size; spheresInCell=0: one cell the size of the predicate's box, or of
    dim), cut to the predicate by filterSpherePack. returnSpherePack=True: a SpherePack; else a list of
    bodies made by utils.sphere(material=material, color=color, **kw). memoizeDb: an sqlite file where
    a suitable packing (same rRelFuzz, scaled to radius) is looked up first and the new one stored
    after; memoDbg prints why each is taken or not. useOBB is accepted and has no effect here."""
    from .pack import filterSpherePack, Predicate
    if not isinstance(predicate, Predicate):
        raise TypeError('randomDensePack: predicate must be a volume predicate (pack.inSphere(...), ...), got %s' % type(predicate).__name__)
    radius, rRelFuzz = _positive('randomDensePack', 'radius', radius), _fuzz('randomDensePack', rRelFuzz)
    if int(spheresInCell) != spheresInCell or spheresInCell < 0:
        raise ValueError('randomDensePack: spheresInCell must be a non-negative integer, got %r' % (spheresInCell,))
    size = Vector3(dim) if dim is not None else Vector3(predicate.dim())
    for x in size:
        _positive('randomDensePack', 'the dimensions (predicate.dim() or dim)', x)
    size = size + Vector3(1, 1, 1) * (2 * radius * (1 + rRelFuzz) * cropLayers)
    sp = _memoLoad(memoizeDb, radius, rRelFuzz, spheresInCell or None, False, memoDbg) if memoizeDb else None
    if sp is None:
        print("No suitable packing in database found, running PERIODIC compression")
        n = int(spheresInCell) or _spheresFor(size, radius, rRelFuzz)
        volume = n * 4 / 3. * math.pi * radius ** 3 * (1 + rRelFuzz ** 2) / (1 - _LOOSE_POROSITY)
        cloud = _cloud(Vector3(1, 1, 1) * volume ** (1 / 3.), radius, rRelFuzz, seed, n)
        sp = _compress(cloud, radius, _FRICTION_DENSE)
        if memoizeDb:
            _memoSave(memoizeDb, sp, radius, rRelFuzz)
    sp.cellFill(size)
    return filterSpherePack(predicate, sp, returnSpherePack=returnSpherePack, material=material, color=color, **kw)


# ---------------------------------------------------------------- memoization (sqlite)

def _memoSave(db, sp, radius, rRelFuzz):
    with tempfile.TemporaryDirectory() as d:
        f = os.path.join(d, 'pack.txt')
        sp.save(f)
        text = open(f).read()
    con = sqlite3.connect(db)
    with con:
        con.execute('create table if not exists packings (radius real, rRelFuzz real, dimx real, dimy real, dimz real, N integer, '
                    'timestamp real, periodic integer, pack blob)')
        c = sp.cellSize
        con.execute('insert into packings values (?,?,?,?,?,?,?,?,?)', (radius, rRelFuzz, c[0], c[1], c[2], len(sp), time.time(), 1, text))
    con.close()
    print('Packing saved to the database', db)


def _memoLoad(db, radius, rRelFuzz, spheresInCell, quiet, dbg=False):
    """The stored periodic packing with the same rRelFuzz, scaled to radius, with at least spheresInCell
    spheres (if given); the one with fewest spheres; None if none."""
    if not os.path.exists(db):
        return None
    con = sqlite3.connect(db)
    try:
        rows = con.execute('select radius, rRelFuzz, dimx, dimy, dimz, N, timestamp, pack from packings').fetchall()
    except sqlite3.DatabaseError as e:
        raise RuntimeError('randomDensePack: %s is not a packing database (%s)' % (db, e)) from None
    finally:
        con.close()
    best = None
    for r, fuzz, sx, sy, sz, n, stamp, text in rows:
        if abs(fuzz - rRelFuzz) > 1e-6 * max(1, rRelFuzz):
            why = 'rRelFuzz %g differs' % fuzz
        elif not isinstance(text, str) or not text.startswith('##PERIODIC::'):
            why = 'not a packing of this engine'
        elif spheresInCell and n < spheresInCell:
            why = 'only %d spheres in the cell' % n
        else:
            why = None
        if dbg:
            print('Packing with %d spheres, radius %g, cell (%g, %g, %g): %s' % (n, r, sx, sy, sz, why or 'suitable'))
        if why is None and (best is None or n < best[0]):
            best = (n, r, text, (sx, sy, sz), stamp)
    if best is None:
        return None
    with tempfile.TemporaryDirectory() as d:
        f = os.path.join(d, 'pack.txt')
        open(f, 'w').write(best[2])
        sp = SpherePack()
        sp.load(f)
    sp.scale(radius / best[1])
    sp.translate(-Vector3(sp.center()) + Vector3(sp.cellSize) / 2)  # (scale is about the centre)
    if not quiet:
        d = best[3]
        print('Found suitable packing in %s (radius=%g±%g,N=%d,dim=%.4g×%.4g×%.4g,periodic,scale=%g), created %s'
              % (db, radius, rRelFuzz, best[0], d[0], d[1], d[2], radius / best[1], time.ctime(best[4])))
    return sp
