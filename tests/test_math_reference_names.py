"""yade.math and yade.minieigenHP names the reference's testMath and testMinieigenHP call: the figures below were
printed by the reference (yade 2023.02a, double) with `yade -n -x`."""
import math
import pickle

import pytest

from yade import math as ym
from yade import minieigenHP as mne


def test_numtraits_constants():
    # Eigen's NumTraits of double and std::complex<double>, the reference's values
    assert (ym.ReadCost, ym.AddCost, ym.MulCost) == (1, 1, 1)
    assert (ym.ComplexReadCost, ym.ComplexAddCost, ym.ComplexMulCost) == (2, 2, 6)
    assert (ym.IsInteger, ym.IsSigned, ym.IsComplex, ym.RequireInitialization) == (0, 1, 0, 0)
    assert ym.hasInfinityNan is True and ym.testCgalNumTraits is True and ym.defprec == 53 and ym.max_exp2 == 1024
    assert ym.HP1.ComplexMulCost == 6 and ym.HP1.Var is ym.Var


def test_var():
    v = ym.Var()
    assert v.val == -71.23 and v.cpl == complex(-71.23, 33.23)
    v.val, v.cpl = 10, 1 - 1j
    assert v.val == 10.0 and type(v.val) is float and v.cpl == 1 - 1j
    v.val = True
    v.cpl = 2
    assert v.val == 1.0 and v.cpl == 2 + 0j
    for bad in ('13123-123123*123', None, 1 + 2j):
        with pytest.raises(TypeError):
            v.val = bad
    with pytest.raises(TypeError):
        v.cpl = '1.5'
    assert ym.Var().val == -71.23  # each Var starts afresh


def test_fromBits_ulp_rawBits():
    assert ym.fromBits('101') == 1.25 and ym.fromBits('101', 3) == 10.0 and ym.fromBits('101', 3, -1) == -10.0
    assert ym.fromBits('011') == 0.75 and ym.fromBits('') == 0.0 and ym.fromBits('0') == 0.0 and ym.fromBits('101', 0, 2) == 2.5
    assert ym.fromBits('1' * 53) == 1.9999999999999998 and ym.fromBits('1' * 54) == 2.0 and ym.fromBits('1' * 60) == 2.0
    assert ym.fromBits('101', 2000) == math.inf and ym.fromBits('101', -2000) == 0.0
    with pytest.raises(RuntimeError):
        ym.fromBits('12')
    assert ym.getFloatDistanceULP(1.0, 1.0000000000000002) == 1.0 and ym.getFloatDistanceULP(1.0000000000000002, 1.0) == -1.0
    assert ym.getFloatDistanceULP(1.0, 2.0) == 4503599627370496.0 and ym.getFloatDistanceULP(-1.0, 1.0) == 9.214364837600035e+18
    assert ym.getFloatDistanceULP(0.0, 5e-324) == 1.0 and ym.getFloatDistanceULP(-0.0, 0.0) == 0.0
    with pytest.raises(RuntimeError):
        ym.getFloatDistanceULP(1.0, math.nan)
    assert ym.getRawBits(1.0) == '0011111111110000000000000000000000000000000000000000000000000000'
    assert ym.getRawBits(-2.5) == '1100000000000100000000000000000000000000000000000000000000000000'
    assert ym.getRawBits(0.1) == '0011111110111001100110011001100110011001100110011001100110011010'
    assert ym.getDemangledName() == 'double' and ym.getDemangledNameComplex() == 'std::complex<double>'
    assert ym.isThisSystemLittleEndian() is True and ym.roundTrip(3) == 3.0 and type(ym.roundTrip(3)) is float
    assert ym.Real1('1.5') == 1.5 and ym.toHP1(2) == 2.0 and ym.degreesHP1(1.) == 57.29577951308232 and ym.radiansHP1(90) == 1.5707963267948966


def test_getDecomposedReal():
    d = ym.getDecomposedReal(1.25)
    assert (d['sign'], d['exp'], d['bits'], d['reconstructed'], d['fpClassify'], d['fpNormal'], d['input']) == (
        1, 0, '101' + '0' * 50, 1.25, 4, True, '1.25')
    d = ym.getDecomposedReal(-0.1)
    assert (d['sign'], d['exp'], d['bits'], d['input'], d['wrong']) == (
        -1, -4, '11001100110011001100110011001100110011001100110011010', '-0.1000000000000000056', False)
    d = ym.getDecomposedReal(0.)
    assert (d['sign'], d['exp'], d['bits'], d['fpZero'], d['fpClassify'], d['input']) == (0, -1, '0' * 53, True, 2, '0')


def test_complex_functions():
    assert ym.sin(1 + 2j) == pytest.approx(3.165778513216168 + 1.9596010414216063j, rel=1e-15)
    assert ym.pow(1 + 1j, 2 - 1j) == pytest.approx(1.4900141243594487 + 4.12574447016181j, rel=1e-15)
    assert ym.log10(1j) == pytest.approx(0.6821881769209206j, rel=1e-15) and ym.sqrt(-1 + 0j) == 1j
    assert ym.acos(2 + 0j) == pytest.approx(-1.3169578969248166j, rel=1e-15)
    assert ym.atanh(0.5 + 0.5j) == pytest.approx(0.40235947810852507 + 0.5535743588970452j, rel=1e-15)
    assert ym.arg(1j) == 1.5707963267948966 and ym.arg(-1.) == 3.141592653589793
    assert ym.conj(1 + 2j) == 1 - 2j and ym.conj(2.) == 2 - 0j and ym.real(1 + 2j) == 1.0 and ym.imag(1 + 2j) == 2.0
    assert ym.polar(2., 0.5) == pytest.approx(1.7551651237807455 + 0.958851077208406j, rel=1e-15)
    assert ym.proj(1 + 2j) == 1 + 2j and ym.proj(complex(math.inf, -1)) == complex(math.inf, -0.)
    assert ym.squaredNorm(3 + 4j) == 25.0 and ym.squaredNorm(3.) == 9.0 and ym.abs(3 + 4j) == 5.0
    # outside the real domain NaN, on overflow inf, as the reference's C++ functions
    assert math.isnan(ym.sqrt(-1.)) and math.isnan(ym.log(-1.)) and math.isnan(ym.acosh(0.5)) and math.isnan(ym.pow(-8., 1 / 3))
    assert ym.exp(1000) == math.inf and ym.sinh(-1000) == -math.inf
    assert ym.sin(1.) == 0.8414709848078965 and type(ym.sin(1.)) is float


def test_special_functions():
    assert ym.factorial(5) == 120.0 and type(ym.factorial(5)) is float and math.isnan(ym.factorial(171))
    assert ym.laguerre(3, 2, 1.5) == pytest.approx(0.0625, rel=1e-14) and ym.laguerre(0, 0, 1.5) == 1.0
    assert ym.laguerre(5, 0, -2.5) == pytest.approx(79.74348958333333, rel=1e-14) and ym.laguerre(2, 3, 0.7) == pytest.approx(6.745, rel=1e-14)
    assert ym.sphericalHarmonic(2, 1, 0.5, 0.3) == pytest.approx(-0.3105211711209513 - 0.09605545449894312j, rel=1e-14)
    assert ym.sphericalHarmonic(3, -2, 1.1, 2.0) == pytest.approx(-0.2406648211186583 + 0.2786468518040367j, rel=1e-14)
    assert ym.sphericalHarmonic(0, 0, 0.1, 0.1) == pytest.approx(0.28209479177387814, rel=1e-15)
    assert ym.sphericalHarmonic(4, 4, 2.5, 5.0) == pytest.approx(0.023166937590138555 + 0.05182816797395005j, rel=1e-13)
    assert ym.sphericalHarmonic(2, 3, 0.5, 0.3) == 0j
    assert ym.cylBesselJ(3, -2.5) == pytest.approx(-0.21660039103911352, rel=1e-14)
    assert ym.cylBesselJ(-2, 1.5) == pytest.approx(0.23208767214421472, rel=1e-14) and ym.cylBesselJ(0, 0) == 1.0
    # the reference returns NaN for J_0(1.5) and J_15(30); these are the values of mpmath.besselj
    assert ym.cylBesselJ(0, 1.5) == pytest.approx(0.511827671735918, rel=1e-14)
    assert ym.cylBesselJ(15, 30.) == pytest.approx(-0.156247068390358, rel=1e-12)


def test_cgal():
    assert ym.CGAL_simpleTest() == 3.0 and ym.CGAL_To_interval(0.1) == (0.1, 0.1) and ym.CGAL_To_interval(-3) == (-3.0, -3.0)
    assert ym.CGAL_Kth_root(3, 27.) == 3.0 and math.isnan(ym.CGAL_Kth_root(3, -8.)) and math.isnan(ym.CGAL_Sqrt(-4.))
    with pytest.raises(RuntimeError):
        ym.CGAL_Kth_root(0, 8.)
    assert ym.CGAL_Sqrt(2.) == 1.4142135623730951 and ym.CGAL_Square(-1.5) == 2.25
    assert (ym.CGAL_Sgn(-0.0), ym.CGAL_Sgn(math.nan), ym.CGAL_Sgn(-2.3), ym.CGAL_Sgn(2.5)) == (0, 0, -1, 1)
    assert ym.CGAL_Is_valid(math.inf) and not ym.CGAL_Is_valid(math.nan) and not ym.CGAL_Is_finite(math.inf) and ym.CGAL_Is_finite(1.)


def test_self_tests_run():
    assert ym.testConstants() is None and ym.testArray() is None and ym.testLoopRealHP() is None and ym.HP1.testConstants() is None


def test_complex_vectors():
    assert str(mne.Vector2c(2 - 10j, 1)) == repr(mne.Vector2c(2 - 10j, 1)) == 'Vector2c(2-10j,1)'
    assert mne.Vector2c(2 - 10j, 1) + mne.Vector2c(3, 5) == mne.Vector2c(5 - 10j, 6)
    assert str(mne.Vector6c(1, 2, 3, 4, 5, 6j)) == 'Vector6c(1,2,3, 4,5,6j)'
    v = mne.Vector3c(2.1 + 1j, 1.1 + 2.5j, 4.3 - 1j) * 3
    assert eval('mne.' + str(v)) == v and type(v[1]) is complex and len(v) == 3
    assert mne.Vector2c(1j, 2).dot(mne.Vector2c(1j, 1)) == 3 + 0j and mne.Vector2c(1, 2).norm() == 2.23606797749979
    assert mne.Vector3c(1j, 2, 3).cross(mne.Vector3c(1, 1, 0)) == mne.Vector3c(-3, 3, -2 - 1j)
    assert mne.Vector3c(1j, 2, 3) * (1 + 1j) == mne.Vector3c(-1 + 1j, 2 + 2j, 3 + 3j) == (1 + 1j) * mne.Vector3c(1j, 2, 3)
    assert mne.Vector3c(1j, 2, 3) / 2 == mne.Vector3c(0.5j, 1, 1.5) and -mne.Vector3c(1j, 2, 3) == mne.Vector3c(-1j, -2, -3)
    assert mne.Vector3c(1j, 2, 3) - mne.Vector3c(1, 1, 1) == mne.Vector3c(-1 + 1j, 1, 2)
    assert mne.Vector3c(mne.Vector3(1, 2, 3)) == mne.Vector3c((1, 2, 3)) == mne.Vector3c([1, 2, 3])
    assert mne.Vector3c(1, 2, 3).squaredNorm() == 14.0 and mne.Vector3c(1, 2, 3).sum() == 6 + 0j and mne.Vector3c(1, 2, 3).maxAbsCoeff() == 3.0
    assert str(mne.Vector3c.Ones) == 'Vector3c(1,1,1)' and str(mne.Vector3c.UnitX) == 'Vector3c(1,0,0)' and str(mne.Vector2c.Zero) == 'Vector2c(0,0)'
    assert str(mne.Vector3c(1, 2, 3).asDiagonal()) == 'Matrix3c(1,0,0, 0,2,0, 0,0,3)'
    assert pickle.loads(pickle.dumps(v)) == v
    with pytest.raises(TypeError):
        mne.Vector3c('a', 1, 2)
    with pytest.raises(IndexError):
        v[3]


def test_complex_matrices():
    a = mne.Matrix3c(1 + 1j, 2, 3, 4, 5, 6, 7, 8, 9 - 9j)
    assert str(a) == 'Matrix3c(1+1j,2,3, 4,5,6, 7,8,9-9j)' and str(a.transpose()) == 'Matrix3c(1+1j,4,7, 2,5,8, 3,6,9-9j)'
    assert a[0] == mne.Vector3c(1 + 1j, 2, 3) and a.diagonal() == mne.Vector3c(1 + 1j, 5, 9 - 9j)
    assert a.maxAbsCoeff() == pytest.approx(12.727922061357855, rel=1e-15)
    b = a.transpose()
    assert eval('mne.' + str(b)) == b
    m = mne.Matrix3c(1j, 2, 3, 4, 5, 6, 7, 8, 10)
    assert m.determinant() == -5 + 2j and m.trace() == 15 + 1j and m[1, 2] == 6 + 0j
    assert m.row(1) == mne.Vector3c(4, 5, 6) and m.col(1) == mne.Vector3c(2, 5, 8) and m.rows() == 3
    inv = m.inverse()
    assert inv[0, 0] == pytest.approx(-0.3448275862068965747 - 0.1379310344827586188j, rel=1e-14)
    assert inv[1, 1] == pytest.approx(4.310344827586207295 - 0.2758620689655173486j, rel=1e-14)
    assert inv[2, 1] == pytest.approx(-2.965517241379310498 + 0.4137931034482760229j, rel=1e-14)
    assert (m * inv - mne.Matrix3c.Identity).maxAbsCoeff() < 1e-14
    assert mne.Matrix3c(1, 2, 3, 4, 5, 6, 7, 8, 9) * mne.Vector3c(1, 1j, 1) == mne.Vector3c(4 + 2j, 10 + 5j, 16 + 8j)
    assert mne.Matrix3c(1, 2, 3, 4, 5, 6, 7, 8, 9) * mne.Matrix3c.Identity == mne.Matrix3c(mne.Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9))
    assert mne.Matrix3c(mne.Vector3c(1, 2, 3), mne.Vector3c(4, 5, 6), mne.Vector3c(7, 8, 9)) == mne.Matrix3c(1, 2, 3, 4, 5, 6, 7, 8, 9)
    assert str(mne.Matrix3c.Zero) == 'Matrix3c(0,0,0, 0,0,0, 0,0,0)' and mne.Matrix6c.Identity.determinant() == 1


def test_minieigen_levels():
    assert mne.vectorize is False and mne.HP1.vectorize is False and not hasattr(mne, 'Vector3na')  # no SIMD type here
    assert mne.HP1.Vector3c is mne.Vector3c and 'Matrix3c' in mne.__all__
