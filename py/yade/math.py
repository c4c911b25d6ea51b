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
    """x (a number or a string of one) as a Real."""
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


def isEqualFuzzy(a, b, eps):
    return abs(a - b) <= eps


def isApprox(a, b, eps):
    return abs(a - b) <= eps * min(abs(a), abs(b))


def isApproxOrLessThan(a, b, eps):
    return a <= b or isApprox(a, b, eps)


def isMuchSmallerThan(a, b, eps):
    return abs(a) <= abs(b) * eps


def getDecomposedReal(x):
    """The parts of the double x: sign (-1, 0 or 1), exp and the 53 bits of the significand, x = sign · 1.bits₂ · 2**exp
    (bits '1010…' with exp 0 is 1.25), with the C fpclassify of x (FP_NAN 0, FP_INFINITE 1, FP_ZERO 2,
    FP_SUBNORMAL 3, FP_NORMAL 4) and whether rebuilding x from its parts failed ('wrong')."""
    x = float(x)
    cls = 0 if _m.isnan(x) else 1 if _m.isinf(x) else 2 if x == 0 else 3 if _builtins.abs(x) < _sys.float_info.min else 4
    bits, e = '0' * 53, 0
    if cls in (3, 4):
        m, e = _m.frexp(_builtins.abs(x))
        bits = ''
        for _ in range(53):
            m *= 2
            bits += '1' if m >= 1 else '0'
            m -= int(m)
    sign = 0 if x == 0 or cls == 0 else (-1 if x < 0 else 1)
    rebuilt = sign * fromBits(bits, e - 1) if cls in (3, 4) else x
    return {'reconstructed': rebuilt, 'sign': sign, 'exp': e - 1, 'bits': bits, 'wrong': not (rebuilt == x or cls < 2),
            'fpInf': cls == 1, 'fpNan': cls == 0, 'fpNormal': cls == 4, 'fpSubNormal': cls == 3, 'fpZero': cls == 2, 'fpClassify': cls,
            'type': 'double', 'input': '%.19g' % x}


abs = _builtins.abs  # |x| of a Real, a complex number (its modulus) or a vector (its norm)
max = _builtins.max
min = _builtins.min
degrees, radians = _m.degrees, _m.radians
degreesHP1, radiansHP1 = degrees, radians


def factorial(k):
    """k! as a Real (NaN past the largest double, 170!, as the reference's)."""
    v = _m.factorial(k)
    return float(v) if v <= _sys.float_info.max else _m.nan



def _isComplex(x):
    return isinstance(x, complex) or (hasattr(x, 'dtype') and getattr(x.dtype, 'kind', '') == 'c')


def _wrap(name, realFn, complexFn=None):
    """A function of Real (and, with complexFn, of complex numbers too). Outside the real domain it returns
    NaN and on overflow ±inf as the C++ functions do (Python's math module raises there instead)."""
    def f(*args):
        if complexFn is not None and _builtins.any(_isComplex(a) for a in args):
            return complexFn(*args)
        try:
            return realFn(*args)
        except ValueError:
            return _m.nan
        except OverflowError:
            x = args[0]
            if name in ('sinh', 'ldexp'):
                return _m.copysign(_m.inf, x)
            if name == 'power' and x < 0 and float(args[1]).is_integer() and int(args[1]) % 2:
                return -_m.inf
            return _m.inf
    f.__name__ = f.__qualname__ = name
    f.__doc__ = 'The C++ %s(…) of Real%s arguments.' % (name, ' or complex' if complexFn else '')
    return f


import cmath as _cm

for _name in ('acos', 'acosh', 'asin', 'asinh', 'atan', 'atanh', 'cos', 'cosh', 'exp', 'log', 'log10', 'sin', 'sinh', 'sqrt', 'tan', 'tanh'):
    globals()[_name] = _wrap(_name, getattr(_m, _name), getattr(_cm, _name))
for _name in ('atan2', 'ceil', 'erf', 'erfc', 'expm1', 'fabs', 'floor', 'fmod', 'frexp', 'hypot', 'isfinite', 'isinf', 'isnan', 'ldexp',
              'log1p', 'log2', 'modf', 'remainder', 'trunc'):
    globals()[_name] = _wrap(_name, getattr(_m, _name))
del _name


def _lgamma(x):
    try:
        return _m.lgamma(x)
    except ValueError:  # the poles 0, -1, -2...: the C++ lgamma gives +inf there
        return _m.inf


def _tgamma(x):
    try:
        return _m.gamma(x)
    except ValueError:  # a pole: ±inf at ±0 as C++, NaN at the negative integers
        return _m.copysign(_m.inf, x) if x == 0 else _m.nan
    except OverflowError:
        return _m.inf


lgamma = _wrap('lgamma', _lgamma)
tgamma = _wrap('tgamma', _tgamma)
pow = _wrap('power', _m.pow, lambda a, b: complex(a) ** complex(b))
pow.__name__ = 'pow'


def conj(x):
    """The complex conjugate of x (a Real is taken as a complex number with a zero imaginary part)."""
    return complex(x).conjugate()


def real(x):
    """The real part of the complex number x."""
    return float(complex(x).real)


def imag(x):
    """The imaginary part of the complex number x."""
    return float(complex(x).imag)


def arg(x):
    """The phase angle of the complex number x in radians (π for a negative Real)."""
    return _cm.phase(complex(x))


def polar(rho, theta):
    """The complex number of length rho and angle theta (C++ std::polar)."""
    return complex(rho * _m.cos(theta), rho * _m.sin(theta))


def proj(x):
    """The projection of x onto the Riemann sphere (C++ std::proj): x, or (inf, ±0) when a part of x is infinite."""
    z = complex(x)
    if _m.isinf(z.real) or _m.isinf(z.imag):
        return complex(_m.inf, _m.copysign(0., z.imag))
    return z


def squaredNorm(x):
    """x² for a Real, |x|² for a complex number (C++ std::norm)."""
    if _isComplex(x):
        return x.real * x.real + x.imag * x.imag
    return x * x


def roundTrip(x):
    """x as a Real (a double): the digits a double cannot hold are cut."""
    return float(x)


# Eigen's NumTraits of Real (a double) and of its complex type: the reference's values, constants of the type.
ReadCost, AddCost, MulCost = 1, 1, 1
ComplexReadCost, ComplexAddCost, ComplexMulCost = 2, 2, 6
IsInteger, IsSigned, IsComplex = 0, 1, 0
RequireInitialization = 0  # a double needs no constructor (the multiprecision types do)
hasInfinityNan = True  # a double has inf and NaN
testCgalNumTraits = True  # the CGAL_* functions below exist


class Var:
    """A Real (val) and a complex number (cpl), to test the conversions of numbers to and from Python: they
    start at -71.23 and -71.23+33.23j and accept numbers only (a string raises TypeError)."""
    __slots__ = ('_val', '_cpl')

    def __init__(self):
        self._val = -71.23
        self._cpl = complex(-71.23, 33.23)

    @property
    def val(self):
        return self._val

    @val.setter
    def val(self, v):
        if isinstance(v, (str, bytes)) or v is None or _isComplex(v):
            raise TypeError('Var.val takes a real number, not %s' % type(v).__name__)
        self._val = float(v)

    @property
    def cpl(self):
        return self._cpl

    @cpl.setter
    def cpl(self, v):
        if isinstance(v, (str, bytes)) or v is None:
            raise TypeError('Var.cpl takes a number, not %s' % type(v).__name__)
        self._cpl = complex(v)


def fromBits(bits, exp=0, sign=1):
    """The Real with the binary digits bits ('1' then the fraction: '101' is 1.01₂ = 1.25), times 2**exp and sign;
    rounded to the nearest double when bits are more than 53."""
    import fractions
    if _builtins.any(c not in '01' for c in bits):
        raise RuntimeError("error: value different than '0' or '1' encountered.")
    if not bits:
        return 0.
    value = fractions.Fraction(int(bits, 2), 1) * fractions.Fraction(2) ** (exp - len(bits) + 1)
    try:
        return float(value) * sign  # Fraction → float rounds correctly, to 0 on underflow
    except OverflowError:
        return _m.inf * sign


def _orderedBits(x):
    import struct
    i = struct.unpack('<q', struct.pack('<d', float(x)))[0]
    return i if i >= 0 else -(i & 0x7fffffffffffffff)  # the doubles in order as integers, -0 and +0 both 0


def getFloatDistanceULP(a, b):
    """The signed number of doubles from a to b (b > a: positive), as a Real; both must be finite."""
    for name, v in (('a', a), ('b', b)):
        if not _m.isfinite(v):
            raise RuntimeError('Error in function float_distance<double>(double, double): Argument %s must be finite, but got %r' % (name, float(v)))
    return float(_orderedBits(b) - _orderedBits(a))


def isThisSystemLittleEndian():
    return _sys.byteorder == 'little'


def getRawBits(x):
    """The 64 bits of the double x as stored (sign, 11 exponent bits, 52 fraction bits), most significant first."""
    import struct
    return format(struct.unpack('>Q', struct.pack('>d', float(x)))[0], '064b')


def getDemangledName():
    """The C++ type of Real."""
    return 'double'


def getDemangledNameComplex():
    """The C++ type of the complex numbers of Real."""
    return 'std::complex<double>'


Real1 = toHP1


def eig(a):
    """Eigenvalues and eigenvectors of the square matrix a (numpy.linalg.eig)."""
    import numpy
    return numpy.linalg.eig(numpy.array(a, dtype=float) if not _isComplex(numpy.array(a)) else numpy.array(a))


# CGAL's number-type traits of Real (the functions its algebraic foundations call).
def CGAL_Is_valid(x):
    """Whether x is a number (not NaN); inf is valid."""
    return not _m.isnan(x)


def CGAL_Is_finite(x):
    return _m.isfinite(x)


def CGAL_Sgn(x):
    """-1, 0 or 1 (0 for NaN too)."""
    return (x > 0) - (x < 0)


def CGAL_Square(x):
    return x * x


def CGAL_Sqrt(x):
    return sqrt(float(x))


def CGAL_Kth_root(k, x):
    """x**(1/k), k > 0 (NaN for a negative x)."""
    if k <= 0:
        raise RuntimeError('CGAL ERROR: precondition violation!')
    return pow(float(x), 1. / k)


def CGAL_To_interval(x):
    """The interval of doubles holding x: (x, x) as Real is a double."""
    return (float(x), float(x))


def CGAL_simpleTest():
    """The distance between a plane and a point through the functions above (3.0): the plane x + 2y + 2z = 6
    and the point (3, 3, 3)."""
    n = (1., 2., 2.)
    d = -6.
    p = (3., 3., 3.)
    length = CGAL_Sqrt(_builtins.sum(CGAL_Square(c) for c in n))
    return abs(_builtins.sum(a * b for a, b in zip(n, p)) + d) / length


# Special functions.
def laguerre(n, m, x):
    """The associated Laguerre polynomial L_n^m(x), by the three-term recurrence in n."""
    if n < 0 or m < 0:
        raise OverflowError("can't convert negative value to unsigned int")
    p0, p1 = 1., 1. + m - x
    if n == 0:
        return p0
    for k in range(1, n):
        p0, p1 = p1, ((2 * k + 1 + m - x) * p1 - (k + m) * p0) / (k + 1)
    return p1


def sphericalHarmonic(l, m, theta, phi):
    """The spherical harmonic Y_l^m(theta, phi) with the Condon-Shortley phase (complex); 0 when |m| > l."""
    if l < 0:
        raise OverflowError("can't convert negative value to unsigned int")
    am = _builtins.abs(m)
    if am > l:
        return 0j
    x, s = _m.cos(theta), _m.sin(theta)
    # the normalised associated Legendre functions, by the stable recurrences upward in l
    pmm = _m.sqrt(1. / (4 * _m.pi))
    for k in range(1, am + 1):
        pmm *= -_m.sqrt((2. * k + 1) / (2. * k)) * s
    if l == am:
        plm = pmm
    else:
        prev, cur = pmm, x * _m.sqrt(2. * am + 3) * pmm
        for ll in range(am + 2, l + 1):
            a = _m.sqrt((4. * ll * ll - 1) / (ll * ll - am * am))
            b = _m.sqrt(((ll - 1.) ** 2 - am * am) / (4. * (ll - 1) ** 2 - 1))
            prev, cur = cur, a * (x * cur - b * prev)
        plm = cur
    y = complex(plm * _m.cos(am * phi), plm * _m.sin(am * phi))
    if m < 0:
        y = y.conjugate() * (-1 if am % 2 else 1)
    return y


def cylBesselJ(k, x):
    """The Bessel function of the first kind J_k(x) of integer order k: the trapezoidal rule on Bessel's
    integral (1/π)∫₀^π cos(kτ - x sin τ)dτ, exact to rounding for enough points as the integrand is periodic."""
    k, x = int(k), float(x)
    if not _m.isfinite(x):
        return 0. if _m.isinf(x) else _m.nan
    n = 2 * (int(_builtins.abs(x)) + _builtins.abs(k)) + 64
    h = 2 * _m.pi / n
    return _m.fsum(_m.cos(k * i * h - x * _m.sin(i * h)) for i in range(n)) / n


# Self-tests (the reference runs C++ checks of its constants and arrays; these check the same things of Real).
def testConstants():
    """Checks the constants of Real: Pi, Euler, Log2, Catalan against independent sums and epsilon, the
    limits against the bits of a double; raises AssertionError when one is off."""
    import fractions
    eps = epsilon()
    assert Pi() == 4 * _m.atan(1.) and _builtins.abs(Pi() - 3.14159265358979323846) <= eps
    assert _builtins.abs(Log2() - _m.fsum(1. / (k * 2 ** k) for k in range(1, 70))) <= 2 * eps
    catalan = _m.fsum((-1) ** k / (2. * k + 1) ** 2 for k in range(200000))
    assert _builtins.abs(Catalan() - catalan) <= 1e-11
    assert _builtins.abs(Euler() - (_m.fsum(1. / k for k in range(1, 100001)) - _m.log(100000.) - 1. / 200000 + 1. / 12e10)) <= 1e-12
    assert 1. + eps != 1. and 1. + eps / 2 == 1. and eps == fractions.Fraction(1, 2 ** (getDigits2() - 1))
    assert highest() == (2 - eps) * 2. ** (max_exp2 - 1) and lowest() == -highest() and smallest_positive() == 2. ** -1022


def testArray():
    """Checks reading Reals through an array's memory: numpy and array.array hold 8-byte doubles of 53 bits."""
    import array
    import numpy
    values = [Pi() * k for k in range(10)]
    a = numpy.array(values, dtype=float)
    assert a.itemsize == 8 and list(memoryview(a).cast('B').cast('d')) == values
    assert list(array.array('d', a.tobytes())) == values and numpy.finfo(a.dtype).nmant + 1 == getDigits2()


def testLoopRealHP():
    """testConstants and testArray at every precision level (one here)."""
    for N in RealHPConfig.getSupportedByMinieigen():
        _level(N)
        testConstants()
        testArray()


# The precision levels (as Yade's yade.math.HP1...): one here, HP1, holding the same functions.
import types as _types

HP1 = _types.ModuleType('yade.math.HP1', 'The functions of Real at precision level 1 (double): the same as yade.math.')
HP1.__dict__.update({_k: _v for _k, _v in dict(globals()).items() if not _k.startswith('_') and _k != 'HP1'})
