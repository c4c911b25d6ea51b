"""The class hierarchy seen from Python (as in Yade's yade.system): childClasses, cxxCtorsDict and the
renamed classes still accepted under their old names."""
import warnings

from . import _yade, config  # noqa: F401  (config: as the reference's yade.system exposes it)
from ._yade import O  # noqa: F401

# Old class names -> current ones, for the classes this engine has (a script using an old name gets
# the current class and a DeprecationWarning).
_deprecated = {
    'GranularMat': 'FrictMat',
    'ElasticMat': 'ElastMat',
    'NormalInteraction': 'NormPhys',
    'NormalShearInteraction': 'NormShearPhys',
    'ElasticContactInteraction': 'FrictPhys',
    'Ip2_FrictMat_FrictMat_NormShearPhys': 'Ip2_FrictMat_FrictMat_FrictPhys',
    'SimpleElasticRelationships': 'Ip2_FrictMat_FrictMat_FrictPhys',
    'Law2_ScGeom_FrictPhys_Basic': 'Law2_ScGeom_FrictPhys_CundallStrack',
    'ef2_Spheres_Elastic_ElasticLaw': 'Law2_ScGeom_FrictPhys_CundallStrack',
    'PeriodicPythonRunner': 'PyRunner',
    'InteractionDispatchers': 'InteractionLoop',
    'InteractionGeometry': 'IGeom',
    'InteractionPhysics': 'IPhys',
    'InteractionGeometryFunctor': 'IGeomFunctor',
    'InteractionPhysicsFunctor': 'IPhysFunctor',
    'InteractionGeometryDispatcher': 'IGeomDispatcher',
    'InteractionPhysicsDispatcher': 'IPhysDispatcher',
    'MomentEngine': 'TorqueEngine',
    'SpiralEngine': 'HelixEngine',
    'SimpleViscoelasticMat': 'ViscElMat',
    'SimpleViscoelasticPhys': 'ViscElPhys',
    'Ip2_SimleViscoelasticMat_SimpleViscoelasticMat_SimpleViscoelasticPhys': 'Ip2_ViscElMat_ViscElMat_ViscElPhys',
    'Law2_Spheres_Viscoelastic_SimpleViscoelastic': 'Law2_ScGeom_ViscElPhys_Basic',
}

_proxiedClasses = set()


def _classes():
    """{name: Python class} of every registered class."""
    return {name: getattr(_yade, name) for name in _yade._classNames()}


def _allSerializables():
    """Names of all classes deriving from Serializable (Serializable itself included)."""
    return set(_yade._classNames())


def childClasses(base, recurse=True, includeBase=False):
    """Names of the classes deriving from the class named `base` (a string), all generations unless
    recurse=False (then the direct children only); includeBase adds `base` itself. An unknown name
    gives an empty set."""
    if not isinstance(base, str):
        raise TypeError('childClasses: base must be a class name (str), not %s' % type(base).__name__)
    classes = _classes()
    if base not in classes:
        return set()
    root = classes[base]
    if recurse:
        ret = {n for n, c in classes.items() if c is not root and issubclass(c, root)}
    else:
        ret = {n for n, c in classes.items() if c is not root and c.__bases__ and c.__bases__[0] is root}
    if includeBase:
        ret.add(base)
    return ret


def _renamed(old, new, cls):
    def ctor(*args, **kw):
        warnings.warn("Class `%s' was renamed to (or replaced by) `%s', update your code!" % (old, new), DeprecationWarning, stacklevel=2)
        return cls(*args, **kw)

    ctor.__name__ = old
    ctor.__doc__ = 'Old name of %s (constructs a %s and warns).\n\n%s' % (new, new, cls.__doc__ or '')
    return ctor


def cxxCtorsDict(proxyNamespace=None):
    """{name: constructor} of every class, with the old names of renamed classes (their constructor
    warns and builds the current class); to update a namespace with."""
    ret = _classes()
    for old, new in _deprecated.items():
        if new in ret and old not in ret:
            ret[old] = _renamed(old, new, ret[new])
    if proxyNamespace is not None:
        proxyNamespace.update(ret)
    return ret


__all__ = ['childClasses', 'cxxCtorsDict']
