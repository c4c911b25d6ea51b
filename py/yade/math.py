"""Real numbers and their functions (as in Yade's yade.math): here Real is a C++ double, so only the
precision level 1 exists (RealHPConfig.getSupportedByMinieigen() == (1,)), and the functions work on
Python floats. The math types (Vector3, Matrix3, Quaternion...) are in yade.minieigenHP."""
import builtins as _builtins
import math as _m
import random as _random
import sys as _sys

from .minieigenHP import *  # noqa: F401,F403  (the math types, as yade.math offers them too)

Real = float
defprec = 53  # bits of the mantissa of Real


class RealHPConfig:
    """The precision levels of Real: one level (double) in this engine."""
    extraStringDigits10 = 4
    isEnabledRealHP = False
    isFloat128Present = False
    isFloat128Broken = False
    workaroundSlowBoostBinFloat = 1

    @staticmethod
    def getSupportedByMinieigen():
        return (1,)

    @staticmethod
    def getSupportedByEigenCgal():
        return (1,)

    @staticmethod
    def getDigits10(N=1):
        _level(N)
        return 15

    @staticmethod
    def getDigits2(N=1):
        _level(N)
        return 53


def _level(N):
    if N != 1:
        raise ValueError('precision level %r does not exist: Real is a double here, the only level is 1' % (N,))


def getDigits10(N=1):
    """Decimal digits of Real at precision level N (15)."""
    return RealHPConfig.getDigits10(N)


def getDigits2(N=1):
    """Bits of the mantissa of Real at precision level N (53)."""
    return RealHPConfig.getDigits2(N)


def getRealHPCppDigits10():
    return (15,)


def getRealHPPythonDigits10():
    return (15,)


def needsMpmathAtN(N=1):
    """Whether level N needs mpmath in Python (never: Real is a double)."""
    _level(N)
    return False


def usesHP():
    """Whether Real is a high-precision type (no)."""
    return False


def toDouble(x):
    return float(x)


def toLongDouble(x):
    return float(x)


def toHP1(x):
    return float(x)


def toInt(x):
    return int(x)


def toLong(x):
    return int(x)


def epsilon():
    return _sys.float_info.epsilon


def lowest():
    return -_sys.float_info.max


def highest():
    return _sys.float_info.max


def smallest_positive():
    return _sys.float_info.min


def dummy_precision():
    return 1e-12


max_exp2 = _sys.float_info.max_exp


def Pi():
    return _m.pi


def Euler():
    return 0.5772156649015329


def Log2():
    return _m.log(2.)


def Catalan():
    return 0.915965594177219


def random(a=None, b=None):
    """Uniform random number in [0, 1) (or [a, b))."""
    r = _random.random()
    return r if a is None else a + (b - a) * r


def linspace(a, b, num):
    import numpy
    return numpy.linspace(a, b, num)


def sgn(x):
    return (x > 0) - (x < 0)


sign = sgn


def round(x):
    """Nearest integer, halfway cases away from zero (C's round)."""
    return float(_m.copysign(_m.floor(abs(x) + 0.5), x))


def rint(x):
    """Nearest integer, halfway cases to even (C's rint)."""
    return float(_builtins.round(x))


def fma(a, b, c):
    return a * b + c


def remquo(x, y):
    r = _m.remainder(x, y)
    return (r, int(_builtins.round((x - r) / y)))


def ilogb(x):
    return _m.frexp(x)[1] - 1


def logb(x):
    return float(_m.frexp(x)[1] - 1)


def cbrt(x):
    return _m.copysign(abs(x) ** (1. / 3.), x)


def exp2(x):
    return 2. ** x


def squaredNorm(x):
    return x * x


def isEqualFuzzy(a, b, eps):
    return abs(a - b) <= eps


def isApprox(a, b, eps):
    return abs(a - b) <= eps * min(abs(a), abs(b))


def isApproxOrLessThan(a, b, eps):
    return a <= b or isApprox(a, b, eps)


def isMuchSmallerThan(a, b, eps):
    return abs(a) <= abs(b) * eps


def getDecomposedReal(x):
    """Sign, exponent and mantissa bits of the double x: x = sign · 0.bits · 2**exp."""
    m, e = _m.frexp(abs(float(x)))
    bits = ''
    for _ in range(53):
        m *= 2
        bits += '1' if m >= 1 else '0'
        m -= int(m)
    return {'sign': -1 if _m.copysign(1., x) < 0 else 1, 'exp': e, 'bits': bits, 'reconstructed': float(x), 'type': 'double'}


abs = _builtins.abs
max = _builtins.max
min = _builtins.min
degrees, radians = _m.degrees, _m.radians
for _name in ('acos', 'acosh', 'asin', 'asinh', 'atan', 'atan2', 'atanh', 'ceil', 'cos', 'cosh', 'erf', 'erfc', 'exp', 'expm1', 'fabs',
              'floor', 'fmod', 'frexp', 'hypot', 'isfinite', 'isinf', 'isnan', 'ldexp', 'lgamma', 'log', 'log10', 'log1p', 'log2', 'modf',
              'pow', 'remainder', 'sin', 'sinh', 'sqrt', 'tan', 'tanh', 'trunc'):
    globals()[_name] = getattr(_m, _name)
tgamma = _m.gamma
factorial = _m.factorial
del _name

# The precision levels (as Yade's yade.math.HP1...): one here, HP1, holding the same functions.
import types as _types

HP1 = _types.ModuleType('yade.math.HP1', 'The functions of Real at precision level 1 (double): the same as yade.math.')
HP1.__dict__.update({_k: _v for _k, _v in dict(globals()).items() if not _k.startswith('_') and _k != 'HP1'})
