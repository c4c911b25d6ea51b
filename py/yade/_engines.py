"""Python side of the engines: ``engine1 + engine2`` on kinematic engines builds a
CombinedKinematicEngine, and the old name CentralGravityEngine."""
import warnings as _warnings

from ._yade import KinematicEngine, CombinedKinematicEngine, CentralConstantAccelerationEngine

__all__ = ['CentralGravityEngine']


def _parts(engine):
    """The kinematic engines that `engine` stands for, in order."""
    if isinstance(engine, CombinedKinematicEngine):
        return list(engine.comb)
    if isinstance(engine, KinematicEngine):
        return [engine]
    return None


def _kinematic_add(self, other):
    """A CombinedKinematicEngine acting on self.ids with both engines' motions."""
    parts = _parts(other)
    if parts is None:
        return NotImplemented
    return CombinedKinematicEngine(ids=list(self.ids), comb=[self] + parts)


def _combined_add(self, other):
    """Appends other's motion to this combination (and returns it, as the reference does)."""
    parts = _parts(other)
    if parts is None:
        return NotImplemented
    self.comb = list(self.comb) + parts
    return self


KinematicEngine.__add__ = _kinematic_add
CombinedKinematicEngine.__add__ = _combined_add


def CentralGravityEngine(**kw):
    """Old name of CentralConstantAccelerationEngine (which it returns, with a DeprecationWarning)."""
    _warnings.warn("CentralGravityEngine was renamed to CentralConstantAccelerationEngine, update your code",
                   DeprecationWarning, stacklevel=2)
    return CentralConstantAccelerationEngine(**kw)
