"""Versions of the libraries this build uses (as Yade's yade.libVersions): getAllVersionsCpp() (what
the compiled module reports), getAllVersionsCmake() (what the build found) and printAllVersions().
Each version is [(major, minor, patch), 'text'], or [] when unknown."""
import platform
import sys

from . import _yade, config


def _parse(text):
    nums = []
    for part in str(text).replace('-', '.').split('.'):
        digits = ''.join(ch for ch in part if ch.isdigit())
        if not digits:
            break
        nums.append(int(digits))
    nums = (nums + [0, 0, 0])[:3]
    return [tuple(nums), str(text)]


def getAllVersionsCpp():
    """{library: [(major, minor, patch), 'version']} as compiled in: compiler, Eigen, pybind11, Python."""
    v = dict(_yade._libVersions())
    return {k: _parse(t) for k, t in v.items()}


def getAllVersionsCmake():
    """{library: [(major, minor, patch), 'version']} of the build tools and Python packages found at run time."""
    ret = {'python': _parse(platform.python_version())}
    for name in ('numpy', 'IPython', 'mpmath'):
        try:
            mod = __import__(name)
            ret[name.lower()] = _parse(mod.__version__)
        except Exception:
            pass
    return ret


def printAllVersions(rstFormat=False):
    """Print the version of yade, its features and the libraries' versions (as a table in rstFormat)."""
    cpp, cmake = getAllVersionsCpp(), getAllVersionsCmake()
    print('Yade version   : ', config.version)
    print('Yade features  : ', ' '.join(config.features))
    print('Yade precision : ', '%d bits, %d decimal places, %s' % (config.highPrecisionBits, config.highPrecisionDecimalPlaces,
                                                                  config.highPrecisionName))
    libs = sorted(set(cpp) | set(cmake))
    if rstFormat:
        print('\n| library       | cmake                 | C++                 |')
        print('| ------------- | --------------------- | ------------------- |')
        for k in libs:
            print('| %-13s | %-21s | %-19s |' % (k, cmake.get(k, ['', ''])[1] if cmake.get(k) else '', cpp.get(k, ['', ''])[1] if cpp.get(k) else ''))
    else:
        for k in libs:
            print('%-13s cmake: %-21s C++: %s' % (k, cmake[k][1] if cmake.get(k) else '', cpp[k][1] if cpp.get(k) else ''))
    print('Python         : ', sys.version.split()[0], ', little endian:', sys.byteorder == 'little')


def getAllVersions():
    """{library: [(major, minor, patch), 'version']}: the compiled-in versions, completed by those found at run time."""
    ret = getAllVersionsCmake()
    ret.update(getAllVersionsCpp())
    return ret


def getVersion(libName):
    """(major, minor, patch) of library libName, (0, 0, 0) if unknown."""
    v = getAllVersions().get(libName)
    return v[0] if v else (0, 0, 0)


def getArchitecture():
    """The machine's architecture with Debian's names (amd64, arm64, i386, ppc64el, s390x...)."""
    m = platform.machine()
    return {'x86_64': 'amd64', 'aarch64': 'arm64', 'i686': 'i386', 'i386': 'i386', 'ppc64le': 'ppc64el'}.get(m, m)


def getLinuxVersion():
    """The Linux distribution's name and version (from /etc/os-release), or the platform's description."""
    try:
        with open('/etc/os-release') as f:
            info = dict(line.rstrip('\n').split('=', 1) for line in f if '=' in line)
        return info.get('PRETTY_NAME', '').strip('"') or platform.platform()
    except OSError:
        return platform.platform()
