"""Yade-compatible discrete element engine: `from yade import *` gives O, the classes and math types."""
import os as _os

if 'OMP_NUM_THREADS' not in _os.environ:
    _os.environ['OMP_NUM_THREADS'] = '1'  # as in Yade: one thread unless -j says otherwise

from ._yade import *  # noqa: F401,F403  (O, classes, math types)
from ._yade import O, setNumThreads  # noqa: F401

from . import config, wrapper, system, _customConverters  # noqa: E402,F401  (module layout of Yade)
from . import math, minieigenHP, libVersions  # noqa: E402,F401
from .libVersions import printAllVersions  # noqa: E402,F401
from .minieigenHP import Vector2c, Vector3c, Vector6c, Matrix3c, Matrix6c, HP1  # noqa: E402,F401  (at top level, as in the reference)
version = config.version
# old names of renamed classes (GranularMat, InteractionGeometry...): they warn and build the current class
globals().update({_k: _v for _k, _v in system.cxxCtorsDict().items() if _k not in globals()})

from . import _persistence  # noqa: E402,F401  (O.save, O.load, O.reload)
from ._engines import *  # noqa: E402,F401,F403  (engine1 + engine2, CentralGravityEngine)
from . import utils, geom  # noqa: E402,F401
from . import pack  # noqa: E402,F401
from ._packPredicates import *  # noqa: E402,F401,F403  (inSphere, inCylinder... at top level, as in the reference)
from .pack import regularOrtho, regularHexa, filterSpherePack, cloudBestFitOBB, SpherePackIterator, SpherePack_toSimulation, randomDensePack, randomPeriPack  # noqa: E402,F401
from . import ymport, export  # noqa: E402,F401
from . import _clumps  # noqa: E402,F401  (O.bodies.replaceByClumps)


def _defaultEngines():
    """The engines of the scene at start-up, as in the reference (O.reset() empties the list): spheres,
    facets and boxes with FrictMat and Cundall-Strack contacts, a time step from GlobalStiffnessTimeStepper
    (O.dynDt is True) and NewtonIntegrator with damping 0.2, labeled as there."""
    return [
        ForceResetter(),  # noqa: F405
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()], label='collider'),  # noqa: F405
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],  # noqa: F405
                        [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()], label='interactionLoop'),  # noqa: F405
        GlobalStiffnessTimeStepper(timeStepUpdateInterval=10, timestepSafetyCoefficient=0.8, label='timeStepper'),  # noqa: F405
        NewtonIntegrator(damping=0.2, label='newton'),  # noqa: F405
    ]


if O.iter == 0 and len(O.engines) == 0 and len(O.bodies) == 0:  # (the first import in this process)
    O.engines = _defaultEngines()

# `from yade import *` gives the classes, O and the helper modules a script uses by name (utils, pack,
# ...), not the submodules whose names would hide Python's own (math) or the reference's layout
# modules (config, system, wrapper...). Keep this block last.
__all__ = [_n for _n in dict(globals()) if not _n.startswith('_') and _n not in (
    'math', 'minieigenHP', 'config', 'system', 'wrapper', 'ymport', 'export', 'libVersions')]


def __getattr__(name):
    """`yade.qt` reached without importing it first (`yade.qt.Renderer()`), as in the reference, whose launcher
    imports it when it has a GUI."""
    if name == 'qt':
        import importlib
        return importlib.import_module('yade.qt')
    raise AttributeError("module 'yade' has no attribute %r" % name)
