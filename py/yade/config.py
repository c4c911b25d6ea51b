"""Build configuration (as in Yade's yade.config): version, revision, features, install paths and the
precision of Real."""
import os

from . import _yade

version = revision = '0.1.0'
# Optional parts compiled in, with the reference's spelling (upper case).
features = (['OPENMP'] if _yade.openmp else []) + ['LOGGER'] + (['VTK'] if _yade.vtk else [])
prefix = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the build directory holding yade/
suffix = ''
libDir = os.path.dirname(os.path.abspath(__file__))
libPATH = 'lib'
sourceRoot = _yade._sourceRoot
confDir = os.path.join(os.path.expanduser('~'), '.config', 'yade')
oldConfDir = os.path.join(os.path.expanduser('~'), '.yade')
libstdcxx = ''
# Real is a C++ double.
highPrecisionBits = 53
highPrecisionDecimalPlaces = 15
highPrecisionName = 'PrecisionDouble'
try:
    import mpmath  # noqa: F401
    highPrecisionMpmath = True
except ImportError:
    highPrecisionMpmath = False
metadata = {
    'short_desc': 'Yade-compatible discrete element engine',
    'long_desc': 'A C++/Python discrete element engine following the Python interface of Yade; version %s with features %s.'
                 % (version, ','.join(features)),
}
