"""Every class of the engine (as in Yade's yade.wrapper): `from yade.wrapper import *` gives all the
registered classes (Sphere, FrictMat, NewtonIntegrator, ...), Omega and the O instance."""
from . import _yade

__all__ = sorted(_yade._classNames()) + ['Omega', 'O']
globals().update({name: getattr(_yade, name) for name in __all__})
