"""The math types (as in Yade's yade.minieigenHP): vectors, matrices and quaternions of Real with the
minieigen API (Vector3(1, 2, 3).norm(), Quaternion(axis, angle), Matrix3.Identity, ...)."""
from . import _yade

__all__ = [n for n in ('Vector2', 'Vector2i', 'Vector3', 'Vector3i', 'Vector4', 'Vector6', 'Vector6i', 'Matrix3', 'Matrix6', 'Quaternion',
                       'AlignedBox2', 'AlignedBox3', 'VectorX', 'MatrixX') if hasattr(_yade, n)]
globals().update({n: getattr(_yade, n) for n in __all__})

# The precision levels (as Yade's minieigenHP.HP1, HP2...): Real is a double here, so there is one, HP1.
import types as _types

HP1 = _types.ModuleType('yade.minieigenHP.HP1', 'The math types at precision level 1 (double): the same as yade.minieigenHP.')
HP1.__dict__.update({n: globals()[n] for n in __all__})

# Vectors and matrices of complex numbers (as the reference's Vector2c, Vector3c, Vector6c, Matrix3c, Matrix6c),
# in Python: entries are Python complex numbers; their str/repr round-trips through eval.
import cmath as _cmath
import math as _math

vectorize = False  # no vectorized (aligned, SIMD) Vector3na type here: Vector3 is the only 3-vector of Real


def _fmtC(z):
    """A complex number as the reference writes it: '2-10j', '3j', '6' (the parts that are not zero)."""
    def num(x):
        r = repr(x)
        return r[:-2] if r.endswith('.0') else r
    z = complex(z)
    if z.imag == 0:
        return num(z.real)
    im = num(z.imag) + 'j'
    if z.real == 0:
        return im
    return num(z.real) + ('' if im.startswith('-') else '+') + im


def _toC(v):
    if isinstance(v, (str, bytes)) or v is None:
        raise TypeError('a number is needed, not %s' % type(v).__name__)
    return complex(v)


class _VectorCBase:
    """A fixed-size vector of complex numbers with the minieigen API."""
    _size = 0
    __slots__ = ('_v',)

    def __init__(self, *args):
        if len(args) == 1 and not isinstance(args[0], (int, float, complex)) and hasattr(args[0], '__len__'):
            args = tuple(args[0])
        if len(args) == 0:
            args = (0,) * self._size
        if len(args) != self._size:
            raise TypeError('%s takes %d numbers, not %d' % (type(self).__name__, self._size, len(args)))
        self._v = [_toC(a) for a in args]

    @classmethod
    def _make(cls, values):
        r = cls.__new__(cls)
        r._v = list(values)
        return r

    def __len__(self):
        return len(self._v)

    def __getitem__(self, i):
        if isinstance(i, slice):
            return self._v[i]
        if not -len(self._v) <= i < len(self._v):
            raise IndexError('index %d out of range 0..%d' % (i, len(self._v) - 1))
        return self._v[i]

    def __setitem__(self, i, value):
        if not -len(self._v) <= i < len(self._v):
            raise IndexError('index %d out of range 0..%d' % (i, len(self._v) - 1))
        self._v[i] = _toC(value)

    def __iter__(self):
        return iter(self._v)

    def __str__(self):
        parts = [_fmtC(z) for z in self._v]
        groups = [','.join(parts[i:i + 3]) for i in range(0, len(parts), 3)]
        return '%s(%s)' % (type(self).__name__, ', '.join(groups))

    __repr__ = __str__

    def __eq__(self, other):
        return type(other) is type(self) and self._v == other._v

    def __ne__(self, other):
        return not self == other

    __hash__ = None

    def __reduce__(self):
        return (type(self), tuple(self._v))

    def _same(self, other):
        if type(other) is not type(self):
            raise TypeError('%s and %s cannot be combined' % (type(self).__name__, type(other).__name__))
        return other._v

    def __add__(self, o):
        return self._make(a + b for a, b in zip(self._v, self._same(o)))

    def __sub__(self, o):
        return self._make(a - b for a, b in zip(self._v, self._same(o)))

    def __neg__(self):
        return self._make(-a for a in self._v)

    def __mul__(self, k):
        if not isinstance(k, (int, float, complex)):
            return NotImplemented
        return self._make(a * k for a in self._v)

    __rmul__ = __mul__

    def __truediv__(self, k):
        if not isinstance(k, (int, float, complex)):
            return NotImplemented
        return self._make(a / k for a in self._v)

    def __iadd__(self, o):
        return self + o

    def __isub__(self, o):
        return self - o

    def __imul__(self, k):
        return self * k

    def __itruediv__(self, k):
        return self / k

    def dot(self, o):
        """Σ conj(self[i])·o[i] (Eigen's dot product of complex vectors)."""
        return sum((a.conjugate() * b for a, b in zip(self._v, self._same(o))), 0j)

    def squaredNorm(self):
        return float(sum(a.real * a.real + a.imag * a.imag for a in self._v))

    def norm(self):
        return _math.sqrt(self.squaredNorm())

    def normalized(self):
        n = self.norm()
        return self._make(a / n for a in self._v) if n else self._make(self._v)

    def normalize(self):
        self._v = self.normalized()._v

    def maxAbsCoeff(self):
        return max(abs(a) for a in self._v)

    def sum(self):
        return sum(self._v, 0j)

    def prod(self):
        r = 1 + 0j
        for a in self._v:
            r *= a
        return r

    def mean(self):
        return self.sum() / len(self._v)

    def pruned(self, absTol=1e-6):
        """The vector with the real and imaginary parts smaller than absTol in magnitude set to 0."""
        return self._make(complex(a.real if abs(a.real) > absTol else 0., a.imag if abs(a.imag) > absTol else 0.) for a in self._v)

    def isApprox(self, other, prec=1e-12):
        d = self - other
        return d.norm() <= prec * min(self.norm(), other.norm())

    def rows(self):
        return len(self._v)

    def cols(self):
        return 1

    def outer(self, o):
        """self · oᵀ (no conjugation)."""
        return self._matrix._make([[a * b for b in self._same(o)] for a in self._v])

    def asDiagonal(self):
        n = len(self._v)
        return self._matrix._make([[self._v[i] if i == j else 0j for j in range(n)] for i in range(n)])

    @classmethod
    def Unit(cls, i):
        return cls._make(1 + 0j if k == i else 0j for k in range(cls._size))

    @classmethod
    def Random(cls):
        import random
        return cls._make(complex(random.uniform(-1, 1), random.uniform(-1, 1)) for _ in range(cls._size))


class _MatrixCBase:
    """A fixed-size square matrix of complex numbers with the minieigen API; m[i] is row i, m[i, j] an entry."""
    _size = 0
    _vector = None
    __slots__ = ('_m',)

    def __init__(self, *args):
        n = self._size
        if len(args) == 1 and not isinstance(args[0], (int, float, complex)):  # a Matrix3, Matrix3c, a list of rows...
            args = tuple(args[0][i] for i in range(len(args[0])))
        if len(args) == 0:
            self._m = [[0j] * n for _ in range(n)]
        elif len(args) == n and all(hasattr(a, '__len__') for a in args):  # the rows
            if any(len(a) != n for a in args):
                raise TypeError('%s takes %d rows of %d numbers' % (type(self).__name__, n, n))
            self._m = [[_toC(x) for x in a] for a in args]
        elif len(args) == n * n:
            self._m = [[_toC(args[i * n + j]) for j in range(n)] for i in range(n)]
        else:
            raise TypeError('%s takes %d numbers or %d rows' % (type(self).__name__, n * n, n))

    @classmethod
    def _make(cls, rows):
        r = cls.__new__(cls)
        r._m = [list(row) for row in rows]
        return r

    def _index(self, ij):
        i, j = ij
        n = self._size
        if not (-n <= i < n and -n <= j < n):
            raise IndexError('index (%d, %d) out of range' % (i, j))
        return i, j

    def __len__(self):
        return self._size

    def __getitem__(self, ij):
        if isinstance(ij, tuple):
            i, j = self._index(ij)
            return self._m[i][j]
        if not -self._size <= ij < self._size:
            raise IndexError('row %d out of range' % ij)
        return self._vector._make(self._m[ij])

    def __setitem__(self, ij, value):
        if isinstance(ij, tuple):
            i, j = self._index(ij)
            self._m[i][j] = _toC(value)
        else:
            if not -self._size <= ij < self._size:
                raise IndexError('row %d out of range' % ij)
            if len(value) != self._size:
                raise TypeError('a row of %d numbers is needed' % self._size)
            self._m[ij] = [_toC(x) for x in value]

    def __str__(self):
        return '%s(%s)' % (type(self).__name__, ', '.join(','.join(_fmtC(z) for z in row) for row in self._m))

    __repr__ = __str__

    def __eq__(self, other):
        return type(other) is type(self) and self._m == other._m

    def __ne__(self, other):
        return not self == other

    __hash__ = None

    def __reduce__(self):
        return (type(self), tuple(z for row in self._m for z in row))

    def _same(self, other):
        if type(other) is not type(self):
            raise TypeError('%s and %s cannot be combined' % (type(self).__name__, type(other).__name__))
        return other._m

    def __add__(self, o):
        return self._make([a + b for a, b in zip(r, s)] for r, s in zip(self._m, self._same(o)))

    def __sub__(self, o):
        return self._make([a - b for a, b in zip(r, s)] for r, s in zip(self._m, self._same(o)))

    def __neg__(self):
        return self._make([-a for a in r] for r in self._m)

    def __mul__(self, o):
        n = self._size
        if isinstance(o, (int, float, complex)):
            return self._make([a * o for a in r] for r in self._m)
        if isinstance(o, self._vector):
            return self._vector._make(sum((r[k] * o._v[k] for k in range(n)), 0j) for r in self._m)
        if type(o) is type(self):
            return self._make([sum((self._m[i][k] * o._m[k][j] for k in range(n)), 0j) for j in range(n)] for i in range(n))
        return NotImplemented

    def __rmul__(self, k):
        if isinstance(k, (int, float, complex)):
            return self * k
        return NotImplemented

    def __truediv__(self, k):
        if not isinstance(k, (int, float, complex)):
            return NotImplemented
        return self._make([a / k for a in r] for r in self._m)

    def __iadd__(self, o):
        return self + o

    def __isub__(self, o):
        return self - o

    def __imul__(self, o):
        return self * o

    def __itruediv__(self, k):
        return self / k

    def rows(self):
        return self._size

    def cols(self):
        return self._size

    def row(self, i):
        return self[i]

    def col(self, j):
        return self._vector._make(r[j] for r in self._m)

    def transpose(self):
        return self._make(zip(*self._m))

    def diagonal(self):
        return self._vector._make(self._m[i][i] for i in range(self._size))

    def trace(self):
        return sum(self.diagonal()._v, 0j)

    def determinant(self):
        """By the cofactors for 3×3, else by Gaussian elimination with partial pivoting."""
        a = [list(r) for r in self._m]
        n, det = self._size, 1 + 0j
        if n == 3:
            return sum((a[0][j] * self._cofactor(0, j) for j in range(3)), 0j)
        for c in range(n):
            p = max(range(c, n), key=lambda i: abs(a[i][c]))
            if a[p][c] == 0:
                return 0j
            if p != c:
                a[c], a[p] = a[p], a[c]
                det = -det
            det *= a[c][c]
            for i in range(c + 1, n):
                f = a[i][c] / a[c][c]
                for j in range(c, n):
                    a[i][j] -= f * a[c][j]
        return det

    def _cofactor(self, i, j):
        a = self._m
        r, c = [k for k in range(3) if k != i], [k for k in range(3) if k != j]
        return (-1) ** (i + j) * (a[r[0]][c[0]] * a[r[1]][c[1]] - a[r[0]][c[1]] * a[r[1]][c[0]])

    def inverse(self):
        """The adjugate over the determinant for 3×3, else Gauss-Jordan elimination with partial pivoting (a
        singular matrix gives infinite or NaN entries)."""
        n = self._size
        if n == 3:
            det = self.determinant()
            if det == 0:
                return self._make([[complex(_math.nan, _math.nan)] * n for _ in range(n)])
            return self._make([self._cofactor(j, i) / det for j in range(3)] for i in range(3))
        a = [list(r) + [1 + 0j if i == j else 0j for j in range(n)] for i, r in enumerate(self._m)]
        for c in range(n):
            p = max(range(c, n), key=lambda i: abs(a[i][c]))
            a[c], a[p] = a[p], a[c]
            piv = a[c][c]
            if piv == 0:
                return self._make([[complex(_math.nan, _math.nan)] * n for _ in range(n)])
            a[c] = [x / piv for x in a[c]]
            for i in range(n):
                if i != c and a[i][c] != 0:
                    f = a[i][c]
                    a[i] = [x - f * y for x, y in zip(a[i], a[c])]
        return self._make(r[n:] for r in a)

    def squaredNorm(self):
        return float(sum(a.real * a.real + a.imag * a.imag for r in self._m for a in r))

    def norm(self):
        return _math.sqrt(self.squaredNorm())

    def normalized(self):
        nn = self.norm()
        return self / nn if nn else self._make(self._m)

    def normalize(self):
        self._m = self.normalized()._m

    def maxAbsCoeff(self):
        return max(abs(a) for r in self._m for a in r)

    def sum(self):
        return sum((a for r in self._m for a in r), 0j)

    def prod(self):
        p = 1 + 0j
        for r in self._m:
            for a in r:
                p *= a
        return p

    def mean(self):
        return self.sum() / (self._size * self._size)

    def pruned(self, absTol=1e-6):
        return self._make([complex(a.real if abs(a.real) > absTol else 0., a.imag if abs(a.imag) > absTol else 0.) for a in r] for r in self._m)

    def isApprox(self, other, prec=1e-12):
        return (self - other).norm() <= prec * min(self.norm(), other.norm())

    @classmethod
    def Random(cls):
        import random
        return cls._make([complex(random.uniform(-1, 1), random.uniform(-1, 1)) for _ in range(cls._size)] for _ in range(cls._size))


def _finishC(vec, mat, n):
    vec._size = mat._size = n
    vec._matrix, mat._vector = mat, vec
    vec.Zero = vec._make([0j] * n)
    vec.Ones = vec._make([1 + 0j] * n)
    vec.Identity = vec.Unit(0)
    mat.Zero = mat._make([[0j] * n for _ in range(n)])
    mat.Ones = mat._make([[1 + 0j] * n for _ in range(n)])
    mat.Identity = mat._make([[1 + 0j if i == j else 0j for j in range(n)] for i in range(n)])
    for c in (vec, mat):
        c.__module__ = 'yade.minieigenHP'


class Vector2c(_VectorCBase):
    """2 complex numbers."""
    __slots__ = ()


class Vector3c(_VectorCBase):
    """3 complex numbers; the cross product is conjugated (as Eigen's: conj(a × b))."""
    __slots__ = ()

    def cross(self, o):
        a, b = self._v, self._same(o)
        return self._make(z.conjugate() for z in (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]))


class Vector6c(_VectorCBase):
    """6 complex numbers."""
    __slots__ = ()

    def head(self):
        return Vector3c._make(self._v[:3])

    def tail(self):
        return Vector3c._make(self._v[3:])


class _Matrix2c(_MatrixCBase):
    __slots__ = ()


class Matrix3c(_MatrixCBase):
    """3×3 complex numbers."""
    __slots__ = ()


class Matrix6c(_MatrixCBase):
    """6×6 complex numbers."""
    __slots__ = ()


_finishC(Vector2c, _Matrix2c, 2)
_finishC(Vector3c, Matrix3c, 3)
_finishC(Vector6c, Matrix6c, 6)
for _i, _n in enumerate('XYZ'):
    setattr(Vector3c, 'Unit' + _n, Vector3c.Unit(_i))
Vector2c.UnitX, Vector2c.UnitY = Vector2c.Unit(0), Vector2c.Unit(1)
for _a, _b in ((0, 1), (0, 2), (1, 0), (1, 2), (2, 0), (2, 1)):
    setattr(Vector3c, 'xyz'[_a] + 'xyz'[_b], (lambda a, b: lambda self: Vector2c._make((self._v[a], self._v[b])))(_a, _b))
del _i, _n, _a, _b

_complexNames = ('Vector2c', 'Vector3c', 'Vector6c', 'Matrix3c', 'Matrix6c')
__all__ = __all__ + list(_complexNames) + ['vectorize']
HP1.__dict__.update({n: globals()[n] for n in _complexNames + ('vectorize',)})
