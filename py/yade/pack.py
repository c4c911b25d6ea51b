"""Sphere packings, as in yade.pack: SpherePack (geometry only: centers and radii) and its makeCloud
loose random packing.

    from yade import pack
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, rRelFuzz=.3, seed=1)
    ids = sp.toSimulation(color=(0, 0, 1))   # keywords go to utils.sphere

SpherePack is implemented in C++ (pkg/dem/SpherePack); toSimulation is added here.
"""
from ._yade import O, SpherePack
from . import utils

__all__ = ['SpherePack']


def _periodicCell(sp):
    """Make the scene periodic with the packing's cell, as Yade does; not possible in this engine yet."""
    try:
        O.periodic = True
        O.cell.setBox(sp.cellSize)
    except (ValueError, AttributeError) as e:
        if O.periodic:
            O.periodic = False
        raise NotImplementedError(
            'SpherePack.toSimulation: this packing is periodic (cellSize=%s), but this engine has no periodic cell yet; '
            'set sp.cellSize=(0,0,0) to add the spheres without a periodic cell' % (tuple(sp.cellSize),)) from e


def _toSimulation(self, **kw):
    """Add the spheres to the simulation as bodies made by utils.sphere(center, radius, **kw), in one
    O.bodies.append call; returns the list of their ids. A periodic packing also sets the periodic cell."""
    if self.isPeriodic:
        _periodicCell(self)
    return O.bodies.append([utils.sphere(c, r, **kw) for c, r in self])


SpherePack.toSimulation = _toSimulation
