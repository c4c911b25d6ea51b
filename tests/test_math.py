"""Tests of the math types (minieigen API): Vector2, Vector2i, Vector3, Vector3i, Vector6, Matrix3, Quaternion."""
import copy
import math
import pickle

import numpy
import pytest

from yade import Matrix3, Quaternion, Vector2, Vector2i, Vector3, Vector3i, Vector6

ALL_SAMPLES = [
    Vector2(1.5, -2),
    Vector2i(3, -4),
    Vector3(0.1, 2, -3e-20),
    Vector3i(1, 2, -3),
    Vector6(1, 2, 3, 4, 5, 6.25),
    Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 10),
    Quaternion((0, 0, 1), math.pi / 3),
]

# ---------------------------------------------------------------- constructors


def test_vector_constructors():
    assert tuple(Vector3()) == (0, 0, 0)
    assert tuple(Vector3(1, 2, 3)) == (1.0, 2.0, 3.0)
    assert tuple(Vector3((1, 2, 3))) == (1, 2, 3)
    assert tuple(Vector3([1.5, 2, 3])) == (1.5, 2, 3)
    assert tuple(Vector3(numpy.array([1.0, 2.0, 3.0]))) == (1, 2, 3)
    assert tuple(Vector3(numpy.array([1, 2, 3]))) == (1, 2, 3)
    assert tuple(Vector3(Vector3i(4, 5, 6))) == (4, 5, 6)
    assert tuple(Vector2(1, 2)) == (1, 2) and tuple(Vector2()) == (0, 0)
    assert tuple(Vector2i(1, 2)) == (1, 2) and tuple(Vector2i((3, 4))) == (3, 4)
    assert tuple(Vector3i(1, 2, 3)) == (1, 2, 3) and tuple(Vector3i()) == (0, 0, 0)
    assert tuple(Vector6(1, 2, 3, 4, 5, 6)) == (1, 2, 3, 4, 5, 6)
    assert tuple(Vector6(range(6))) == (0, 1, 2, 3, 4, 5)
    assert tuple(Vector6()) == (0,) * 6
    assert Vector6((1, 2, 3), (4, 5, 6)) == Vector6(1, 2, 3, 4, 5, 6)
    v = Vector3(1, 2, 3)
    w = Vector3(v)
    assert w == v and w is not v
    w[0] = 10
    assert v[0] == 1  # copy, not alias
    assert isinstance(Vector3i(1, 2, 3)[0], int)


def test_constructor_errors():
    with pytest.raises(ValueError, match="Vector3"):
        Vector3((1, 2))
    with pytest.raises(ValueError, match="3 numbers"):
        Vector3([1, 2, 3, 4])
    with pytest.raises(TypeError):
        Vector3(1, 2)
    with pytest.raises(TypeError):
        Vector3("abc")
    with pytest.raises(TypeError):
        Vector3((1, "a", 3))
    with pytest.raises(TypeError):
        Vector3i(1.5, 2, 3)
    with pytest.raises(TypeError):
        Vector3i((1.5, 2, 3))
    with pytest.raises(ValueError):
        Vector6((1, 2, 3))
    with pytest.raises(ValueError):
        Matrix3((1, 2, 3, 4))
    with pytest.raises(ValueError):
        Matrix3(((1, 2, 3), (4, 5), (7, 8, 9)))
    with pytest.raises((TypeError, ValueError)):
        Quaternion((1, 2, 3, 4, 5))


def test_matrix_constructors():
    assert Matrix3() == Matrix3.Zero
    m = Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9)
    assert m[0, 1] == 2 and m[1, 0] == 4 and m[2, 2] == 9  # row-major
    assert Matrix3((1, 2, 3), (4, 5, 6), (7, 8, 9)) == m
    assert Matrix3(Vector3(1, 2, 3), Vector3(4, 5, 6), Vector3(7, 8, 9)) == m
    assert Matrix3((1, 2, 3), (4, 5, 6), (7, 8, 9), cols=True) == m.transpose()
    assert Matrix3(((1, 2, 3), (4, 5, 6), (7, 8, 9))) == m
    assert Matrix3(range(1, 10)) == m
    assert Matrix3(numpy.arange(1, 10).reshape(3, 3)) == m
    assert Matrix3(m) == m
    assert Matrix3(Vector3(1, 2, 3)) == Matrix3(1, 0, 0, 0, 2, 0, 0, 0, 3)
    assert Matrix3((1, 2, 3)) == Matrix3(1, 0, 0, 0, 2, 0, 0, 0, 3)


def test_quaternion_constructors():
    assert Quaternion() == Quaternion.Identity
    q = Quaternion(1, 0, 0, 0)
    assert q == Quaternion.Identity
    assert (q[0], q[1], q[2], q[3]) == (0, 0, 0, 1)  # x, y, z, w
    q = Quaternion(0.5, 0.1, 0.2, 0.3)
    assert tuple(q) == (0.1, 0.2, 0.3, 0.5) and len(q) == 4
    a = Quaternion((0, 0, 1), math.pi / 2)
    assert a.isApprox(Quaternion(math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)))
    assert Quaternion(Vector3(0, 0, 1), math.pi / 2) == a
    assert Quaternion([0, 0, 1], math.pi / 2) == a
    assert Quaternion(numpy.array([0.0, 0.0, 1.0]), math.pi / 2) == a
    assert Quaternion(math.pi / 2, (0, 0, 1)) == a
    assert Quaternion(((0, 0, 1), math.pi / 2)) == a
    assert Quaternion((0, 0, 2), math.pi / 2).isApprox(a)  # axis is normalized
    assert Quaternion(axis=(0, 0, 1), angle=math.pi / 2) == a
    assert Quaternion(a) == a
    assert Quaternion(a.toRotationMatrix()).isApprox(a)
    assert Quaternion((1, 0, 0), 0) == Quaternion.Identity


# ---------------------------------------------------------------- implicit conversions


def test_implicit_conversion_from_sequences():
    v = Vector3(1, 2, 3)
    assert v + (1, 1, 1) == Vector3(2, 3, 4)
    assert v + [1, 1, 1] == Vector3(2, 3, 4)
    assert v + numpy.array([1, 1, 1]) == Vector3(2, 3, 4)
    assert (1, 1, 1) + v == Vector3(2, 3, 4)
    assert (1, 1, 1) - v == Vector3(0, -1, -2)
    assert v.dot((1, 0, 0)) == 1
    assert v.cross([0, 0, 1]) == Vector3(2, -1, 0)
    assert v == (1, 2, 3) and v == [1, 2, 3] and v != (1, 2, 4)
    assert v + Vector3i(1, 1, 1) == Vector3(2, 3, 4)
    m = Matrix3.Identity
    assert m * (1, 2, 3) == Vector3(1, 2, 3)  # 3 numbers: a vector, not a diagonal matrix
    assert m * ((1, 2, 3), (4, 5, 6), (7, 8, 9)) == Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9)
    assert m + [0] * 9 == m
    m[1] = (7, 8, 9)  # row assignment from a tuple
    assert m.row(1) == Vector3(7, 8, 9)
    q = Quaternion((0, 0, 1), math.pi / 2)
    assert (q * (1, 0, 0)).isApprox(Vector3(0, 1, 0))
    assert q * ((0, 0, 1), math.pi / 2) == q * q
    assert Vector6(1, 2, 3, 4, 5, 6) + (1,) * 6 == Vector6(2, 3, 4, 5, 6, 7)
    assert Vector2(1, 2) + (1, 1) == Vector2(2, 3)
    assert Vector2i(1, 2) + (1, 1) == Vector2i(2, 3)


def test_implicit_conversion_errors():
    v = Vector3(1, 2, 3)
    with pytest.raises(TypeError):
        v + (1, 2)
    with pytest.raises(TypeError):
        v + (1, 2, 3, 4)
    with pytest.raises(TypeError):
        v.dot((1, "x", 3))
    with pytest.raises(TypeError):
        v + "abc"
    with pytest.raises(TypeError):
        Vector3i(1, 2, 3) + (1.5, 0, 0)  # floats do not convert to int vectors
    with pytest.raises(TypeError):
        Matrix3.Identity * (1, 2)
    assert (v == None) is False  # noqa: E711
    assert v != None  # noqa: E711
    assert v != (1, 2)


# ---------------------------------------------------------------- indexing


def test_indexing():
    v = Vector3(1, 2, 3)
    assert len(v) == 3 and v[0] == 1 and v[2] == 3 and v[-1] == 3 and v[-3] == 1
    with pytest.raises(IndexError):
        v[3]
    with pytest.raises(IndexError):
        v[-4]
    v[1] = 20
    v[-1] = 30
    assert v == Vector3(1, 20, 30)
    with pytest.raises(IndexError):
        v[3] = 1
    assert list(v) == [1, 20, 30]
    assert [x for x in Vector6(range(6))] == [0, 1, 2, 3, 4, 5]
    w = Vector6(range(6))
    w[5] = -1
    assert w[-1] == -1 and len(w) == 6
    with pytest.raises(IndexError):
        w[6]
    assert len(Vector2()) == 2 and len(Vector2i()) == 2 and len(Vector3i()) == 3


def test_matrix_indexing():
    m = Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9)
    assert len(m) == 3
    assert m[0, 0] == 1 and m[1, 2] == 6 and m[-1, -1] == 9 and m[2, 0] == 7
    assert m[1] == Vector3(4, 5, 6) and m[-1] == Vector3(7, 8, 9)
    assert list(m) == [Vector3(1, 2, 3), Vector3(4, 5, 6), Vector3(7, 8, 9)]
    row = m[0]
    row[0] = 100
    assert m[0, 0] == 1  # m[i] is a copy
    m[0, 0] = -1
    assert m[0, 0] == -1
    m[2] = Vector3(0, 0, 0)
    assert m.row(2) == Vector3.Zero
    with pytest.raises(IndexError):
        m[3, 0]
    with pytest.raises(IndexError):
        m[0, 3]
    with pytest.raises(IndexError):
        m[3]
    assert m.row(1) == Vector3(4, 5, 6) and m.col(1) == Vector3(2, 5, 0)
    assert m.diagonal() == Vector3(-1, 5, 0)


# ---------------------------------------------------------------- arithmetic


def test_vector_arithmetic():
    a, b = Vector3(1, 2, 3), Vector3(4, 5, 6)
    assert a + b == Vector3(5, 7, 9)
    assert b - a == Vector3(3, 3, 3)
    assert -a == Vector3(-1, -2, -3)
    assert a * 2 == Vector3(2, 4, 6) and 2 * a == Vector3(2, 4, 6)
    assert a * 0.5 == Vector3(0.5, 1, 1.5)
    assert a / 2 == Vector3(0.5, 1, 1.5)
    assert numpy.float64(2) * a == Vector3(2, 4, 6)
    assert isinstance(numpy.float64(2) * a, Vector3)
    assert Vector3i(1, 2, 3) * 3 == Vector3i(3, 6, 9) and 3 * Vector3i(1, 2, 3) == Vector3i(3, 6, 9)
    assert Vector2(1, 2) * 2 == Vector2(2, 4)
    assert Vector6(range(6)) * 2 == Vector6(0, 2, 4, 6, 8, 10)
    with pytest.raises(TypeError):
        a * b
    with pytest.raises(TypeError):
        a * "x"
    # results are new objects
    c = a + b
    c[0] = 0
    assert a[0] == 1 and b[0] == 4


def test_inplace_ops_modify_object():
    v = Vector3(1, 2, 3)
    v2 = v
    v *= 2
    assert v2 is v and v == Vector3(2, 4, 6)
    v += (1, 1, 1)
    assert v2 is v and v == Vector3(3, 5, 7)
    v -= Vector3(3, 5, 7)
    assert v2 is v and v == Vector3.Zero
    v += (4, 4, 4)
    v /= 4
    assert v2 is v and v == Vector3.Ones
    v *= -1
    assert v2 is v and v == -Vector3.Ones
    i = Vector3i(1, 2, 3)
    j = i
    i *= 2
    i += (1, 1, 1)
    assert j is i and i == Vector3i(3, 5, 7)
    m = Matrix3.Identity
    n = m
    m *= 2
    assert n is m and m == 2 * Matrix3.Identity
    m += Matrix3.Identity
    assert n is m and m == 3 * Matrix3.Identity
    m *= Matrix3(Vector3(1, 2, 3))
    assert n is m and m == Matrix3(Vector3(3, 6, 9))
    m -= m
    assert n is m and m == Matrix3.Zero
    m += Matrix3.Ones
    m /= 2
    assert m == Matrix3.Ones * 0.5
    q = Quaternion()
    r = q
    q *= Quaternion((0, 0, 1), 1)
    assert r is q and q == Quaternion((0, 0, 1), 1)


def test_matrix_arithmetic():
    m = Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 10)
    assert m * Matrix3.Identity == m and Matrix3.Identity * m == m
    assert m * Vector3(1, 0, 0) == Vector3(1, 4, 7)
    assert m * Vector3(1, 1, 1) == Vector3(6, 15, 25)
    assert m + m == 2 * m and m * 2 == m + m and m - m == Matrix3.Zero
    assert -m == m * -1 and m / 2 == m * 0.5
    assert m * m == Matrix3(30, 36, 45, 66, 81, 102, 109, 134, 169)


def test_quaternion_rotation():
    q = Quaternion((0, 0, 1), math.pi / 2)
    r = q * Vector3.UnitX
    assert (r - Vector3.UnitY).norm() < 1e-15
    assert (q.Rotate(Vector3.UnitX) - Vector3.UnitY).norm() < 1e-15
    assert (q.toRotationMatrix() * Vector3.UnitX - Vector3.UnitY).norm() < 1e-15
    assert ((q * q) * Vector3.UnitX - (-Vector3.UnitX)).norm() < 1e-15
    assert (q * q.conjugate()).isApprox(Quaternion.Identity)
    assert (q * q.inverse()).isApprox(Quaternion.Identity)
    assert abs(q.norm() - 1) < 1e-15
    axis, angle = q.toAxisAngle()
    assert isinstance(axis, Vector3) and (axis - Vector3.UnitZ).norm() < 1e-15
    assert abs(angle - math.pi / 2) < 1e-15
    angle2, axis2 = q.toAngleAxis()
    assert angle2 == angle and axis2 == axis
    p = Quaternion(2, 0, 0, 0)
    assert p.norm() == 2 and p.normalized() == Quaternion.Identity and p.norm() == 2
    p.normalize()
    assert p == Quaternion.Identity
    assert abs(Quaternion.Identity.angularDistance(q) - math.pi / 2) < 1e-15
    half = Quaternion.Identity.slerp(0.5, q)
    assert half.isApprox(Quaternion((0, 0, 1), math.pi / 4))
    m = Quaternion((1, 1, 1), 2.0).toRotationMatrix()
    assert (m * m.transpose()).isApprox(Matrix3.Identity)
    assert abs(m.determinant() - 1) < 1e-14
    q[3] = 5  # w
    assert q[3] == 5 and q[-1] == 5
    with pytest.raises(IndexError):
        q[4]


# ---------------------------------------------------------------- methods


def test_vector_methods():
    v = Vector3(3, -4, 0)
    assert v.norm() == 5 and v.squaredNorm() == 25
    assert v.normalized() == Vector3(0.6, -0.8, 0) and v == Vector3(3, -4, 0)
    w = Vector3(v)
    w.normalize()
    assert w == Vector3(0.6, -0.8, 0)
    assert v.dot(Vector3(1, 1, 1)) == -1
    assert Vector3.UnitX.cross(Vector3.UnitY) == Vector3.UnitZ
    assert Vector3i(1, 0, 0).cross(Vector3i(0, 1, 0)) == Vector3i(0, 0, 1)
    assert v.sum() == -1 and v.maxCoeff() == 3 and v.minCoeff() == -4 and v.maxAbsCoeff() == 4
    assert v.abs() == Vector3(3, 4, 0)
    assert Vector3(1, 2, 3).prod() == 6
    assert Vector3(1, 2, 3).asDiagonal() == Matrix3(1, 0, 0, 0, 2, 0, 0, 0, 3)
    assert Vector3(1, 2, 3).outer(Vector3(1, 10, 100)) == Matrix3(1, 10, 100, 2, 20, 200, 3, 30, 300)
    assert Vector3(1, 2, 3).isApprox(Vector3(1, 2, 3 + 1e-14))
    assert not Vector3(1, 2, 3).isApprox(Vector3(1, 2, 3.1))
    assert Vector3i(-5, 2, 3).maxAbsCoeff() == 5 and Vector3i(1, 2, 3).squaredNorm() == 14
    assert Vector3i(-5, 2, 3).abs() == Vector3i(5, 2, 3)
    assert Vector2(3, 4).norm() == 5 and Vector2i(1, 2).dot((3, 4)) == 11
    v6 = Vector6(1, 2, 3, 4, 5, 6)
    assert v6.head() == Vector3(1, 2, 3) and v6.tail() == Vector3(4, 5, 6)
    assert v6.norm() == math.sqrt(91) and v6.sum() == 21
    assert Vector3.Unit(1) == Vector3.UnitY and Vector6.Unit(5) == Vector6(0, 0, 0, 0, 0, 1)


def test_matrix_methods():
    m = Matrix3(2, 0, 1, 1, 3, 0, 0, 1, 4)
    assert m.trace() == 9
    assert abs(m.determinant() - 25) < 1e-13
    assert m.transpose() == Matrix3(2, 1, 0, 0, 3, 1, 1, 0, 4)
    inv = m.inverse()
    expected = Matrix3(12, 1, -3, -4, 8, 1, 1, -2, 6) / 25
    assert (inv - expected).maxAbsCoeff() < 1e-15
    assert (m * inv).isApprox(Matrix3.Identity)
    assert Matrix3.Identity.determinant() == 1 and Matrix3.Identity.inverse() == Matrix3.Identity
    assert m.diagonal() == Vector3(2, 3, 4)
    assert m.maxCoeff() == 4 and m.minCoeff() == 0 and m.sum() == 12
    assert Matrix3(-5, 0, 0, 0, 0, 0, 0, 0, 1).maxAbsCoeff() == 5
    assert Matrix3.Identity.norm() == math.sqrt(3) and Matrix3.Ones.squaredNorm() == 9
    assert Matrix3(-1, 0, 0, 0, 0, 0, 0, 0, 0).abs() == Matrix3(1, 0, 0, 0, 0, 0, 0, 0, 0)


# ---------------------------------------------------------------- constants


def test_constants():
    assert Vector3.Zero == Vector3(0, 0, 0) and Vector3.Ones == Vector3(1, 1, 1)
    assert Vector3.UnitX == Vector3(1, 0, 0) and Vector3.UnitY == Vector3(0, 1, 0) and Vector3.UnitZ == Vector3(0, 0, 1)
    assert Vector2.UnitX == Vector2(1, 0) and Vector2.UnitY == Vector2(0, 1)
    assert Vector2.Zero == Vector2(0, 0) and Vector2.Ones == Vector2(1, 1)
    assert Vector2i.Zero == Vector2i(0, 0) and Vector2i.Ones == Vector2i(1, 1) and Vector2i.UnitY == Vector2i(0, 1)
    assert Vector3i.Zero == Vector3i(0, 0, 0) and Vector3i.Ones == Vector3i(1, 1, 1) and Vector3i.UnitZ == Vector3i(0, 0, 1)
    assert Vector6.Zero == Vector6((0,) * 6) and Vector6.Ones == Vector6((1,) * 6)
    assert Matrix3.Zero == Matrix3(0, 0, 0, 0, 0, 0, 0, 0, 0)
    assert Matrix3.Ones == Matrix3((1,) * 9)
    assert Matrix3.Identity == Matrix3(1, 0, 0, 0, 1, 0, 0, 0, 1)
    assert Quaternion.Identity == Quaternion(1, 0, 0, 0)


def test_constants_are_fresh_copies():
    z = Vector3.Zero
    z += (1, 1, 1)
    z[0] = 5
    assert Vector3.Zero == Vector3(0, 0, 0)
    assert Vector3.Zero is not Vector3.Zero
    u = Vector3.UnitX
    u *= 3
    assert Vector3.UnitX == Vector3(1, 0, 0)
    i = Matrix3.Identity
    i[0, 0] = 7
    i *= 2
    assert Matrix3.Identity == Matrix3(1, 0, 0, 0, 1, 0, 0, 0, 1)
    q = Quaternion.Identity
    q[0] = 3
    assert Quaternion.Identity == Quaternion(1, 0, 0, 0)
    with pytest.raises(AttributeError):
        Vector3.Zero = Vector3(1, 1, 1)
    assert Vector3.Zero == Vector3(0, 0, 0)


# ---------------------------------------------------------------- equality, hashing


def test_equality_and_hash():
    assert Vector3(1, 2, 3) == Vector3(1, 2, 3)
    assert not (Vector3(1, 2, 3) != Vector3(1, 2, 3))
    assert Vector3(1, 2, 3) != Vector3(1, 2, 3 + 1e-15)
    assert Matrix3.Identity != Matrix3.Zero
    assert Quaternion(1, 0, 0, 0) != Quaternion(0, 1, 0, 0)
    for obj in ALL_SAMPLES:
        with pytest.raises(TypeError):
            hash(obj)


# ---------------------------------------------------------------- repr, pickling, numpy


def test_repr():
    assert repr(Vector3(1, 2, 3)) == "Vector3(1,2,3)"
    assert str(Vector3(1, 2, 3)) == "Vector3(1,2,3)"
    assert repr(Vector3(0.1, -2.5, 1e16)) == "Vector3(0.1,-2.5,1e+16)"
    assert repr(Vector3i(1, 2, 3)) == "Vector3i(1,2,3)"
    assert repr(Vector2(1, 2)) == "Vector2(1,2)"
    assert repr(Vector2i(-1, 2)) == "Vector2i(-1,2)"
    assert repr(Matrix3.Identity) == "Matrix3(1,0,0, 0,1,0, 0,0,1)"
    assert repr(Vector6(1, 2, 3, 4, 5, 6)) == "Vector6(1,2,3, 4,5,6)"
    assert repr(Quaternion.Identity) == "Quaternion((1,0,0),0)"
    assert repr(Quaternion((0, 0, 1), 0.5)) == "Quaternion((0,0,1),0.5)"


@pytest.mark.parametrize("obj", ALL_SAMPLES[:-1], ids=lambda o: type(o).__name__)
def test_repr_roundtrip_exact(obj):
    assert eval(repr(obj)) == obj
    if not isinstance(obj, (Vector2i, Vector3i)):
        x = obj / 3.0  # coefficients with many decimals
        assert eval(repr(x)) == x


def test_repr_roundtrip_quaternion():
    q = Quaternion((1, 2, 3), 1.234)
    assert eval(repr(q)).isApprox(q, 1e-15)


@pytest.mark.parametrize("obj", ALL_SAMPLES, ids=lambda o: type(o).__name__)
def test_pickle_and_copy(obj):
    for proto in range(pickle.HIGHEST_PROTOCOL + 1):
        back = pickle.loads(pickle.dumps(obj, proto))
        assert type(back) is type(obj) and back == obj and back is not obj
    c = copy.copy(obj)
    d = copy.deepcopy(obj)
    assert c == obj and d == obj and c is not obj and d is not obj
    c *= Quaternion((1, 0, 0), 1) if isinstance(c, Quaternion) else 2  # the copy is independent
    assert c != obj and d == obj


def test_numpy():
    a = numpy.array(Vector3(1, 2, 3))
    assert a.shape == (3,) and a.dtype == numpy.float64 and list(a) == [1, 2, 3]
    assert numpy.array(Vector2(1, 2)).shape == (2,)
    assert numpy.array(Vector6(range(6))).shape == (6,)
    i = numpy.array(Vector3i(1, 2, 3))
    assert i.shape == (3,) and numpy.issubdtype(i.dtype, numpy.integer) and list(i) == [1, 2, 3]
    assert numpy.issubdtype(numpy.array(Vector2i(1, 2)).dtype, numpy.integer)
    m = numpy.array(Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9))
    assert m.shape == (3, 3) and m.dtype == numpy.float64
    assert m[0, 1] == 2 and m[1, 0] == 4
    assert (numpy.array(Vector3(1, 2, 3), dtype=numpy.float32)).dtype == numpy.float32
    stacked = numpy.array([Vector3(1, 2, 3), Vector3(4, 5, 6)])
    assert stacked.shape == (2, 3) and stacked[1, 2] == 6
    assert numpy.dot(numpy.array(Matrix3.Identity), numpy.array(Vector3(1, 2, 3))).tolist() == [1, 2, 3]
    # numpy -> math types
    assert Matrix3(numpy.eye(3)) == Matrix3.Identity
    assert Vector3(numpy.array([1.5, 2, 3])) == Vector3(1.5, 2, 3)
    assert Vector3i(numpy.array([1, 2, 3])) == Vector3i(1, 2, 3)
    assert Vector3(*numpy.array([1.0, 2.0, 3.0])) == Vector3(1, 2, 3)


def test_quaternion_setFromTwoVectors_in_place():
    """As minieigen's (reference figures, Yade 2023.02a): returns None, changes q, leaves Identity alone."""
    q = Quaternion.Identity
    assert q.setFromTwoVectors(Vector3(1, 2, 3), Vector3(2, 3, 4)) is None
    axis, angle = q.toAxisAngle()
    assert angle == pytest.approx(0.12186756768575521, rel=1e-14)
    assert list(axis) == pytest.approx([-0.4082482904638629, 0.8164965809277263, -0.4082482904638629], rel=1e-14)
    assert q.norm() == pytest.approx(1, abs=1e-15)
    turned = q * Vector3(1, 2, 3)
    assert list(turned.normalized()) == pytest.approx(list(Vector3(2, 3, 4).normalized()), abs=1e-15)
    assert Quaternion.Identity == Quaternion((1, 0, 0), 0)
    q.setFromTwoVectors(Vector3(1, 0, 0), Vector3(0, 1, 0))
    assert q.toAxisAngle()[1] == pytest.approx(math.pi / 2) and list(q.toAxisAngle()[0]) == pytest.approx([0, 0, 1])
