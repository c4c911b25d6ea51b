"""Yade-compatible discrete element engine: `from yade import *` gives O, the classes and math types."""
import os as _os

if 'OMP_NUM_THREADS' not in _os.environ:
    _os.environ['OMP_NUM_THREADS'] = '1'  # as in Yade: one thread unless -j says otherwise

from ._yade import *  # noqa: F401,F403  (O, classes, math types)
from ._yade import O, setNumThreads  # noqa: F401

version = '0.1.0'

from . import _persistence  # noqa: E402,F401  (O.save, O.load, O.reload)
from ._engines import *  # noqa: E402,F401,F403  (engine1 + engine2, CentralGravityEngine)
from . import utils, geom  # noqa: E402,F401
from . import pack  # noqa: E402,F401
