// Python bindings of Yade's math types, exposing the API of "minieigen" that Yade scripts use.
//
// Design notes
//  * Every type is a pybind11 class holding the Eigen object by value; attributes of other classes
//    may return references to these objects, so the in-place operators (+=, -=, *=, /=) modify the
//    object itself and return the very same Python object.
//  * Implicit conversion: for each type T a marker type SequenceOf<T> is registered with
//    py::implicitly_convertible<SequenceOf<T>, T>(). Its caster accepts any Python sequence (tuple,
//    list, numpy array, another math object; not str/bytes) whose *shape* fits T; pybind11 then calls
//    T(sequence), i.e. the sequence constructor below, which converts the elements. Hence a C++
//    function taking `const Vector3r&` accepts (1,2,3), [1,2,3] or numpy.array([1,2,3]); a sequence of
//    the wrong shape or with non-numeric items is not convertible (TypeError from pybind11).
//  * Dense types share one set of templates (defDense / defVector); only Matrix3 and Quaternion have
//    type-specific parts.
#include <lib/base/ExternalWrites.hpp>
#include <py/wrapper/Math.hpp>

#include <lib/base/Math.hpp>

#include <pybind11/numpy.h>

#include <charconv>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace yade {
namespace {

	// marker type: "a Python sequence that can be converted to T" (see the type_caster below)
	template <class T> struct SequenceOf { };

	template <class T> struct PyName;
	template <> struct PyName<Vector2r> { static constexpr const char* value = "Vector2"; };
	template <> struct PyName<Vector2i> { static constexpr const char* value = "Vector2i"; };
	template <> struct PyName<Vector3r> { static constexpr const char* value = "Vector3"; };
	template <> struct PyName<Vector3i> { static constexpr const char* value = "Vector3i"; };
	template <> struct PyName<Vector6r> { static constexpr const char* value = "Vector6"; };
	template <> struct PyName<Vector6i> { static constexpr const char* value = "Vector6i"; };
	template <> struct PyName<Matrix3r> { static constexpr const char* value = "Matrix3"; };
	template <> struct PyName<Quaternionr> { static constexpr const char* value = "Quaternion"; };

	template <class T> std::string nameOf() { return PyName<T>::value; }

	// ---------------------------------------------------------------- small helpers

	// shortest representation that reads back to the same double (eval(repr(v)) == v)
	std::string num(double x)
	{
		char buf[64];
		auto res = std::to_chars(buf, buf + sizeof(buf), x);
		return std::string(buf, res.ptr);
	}
	std::string num(int x) { return std::to_string(x); }

	std::string typeName(py::handle h) { return Py_TYPE(h.ptr())->tp_name; }

	bool isSequence(py::handle h)
	{
		PyObject* o = h.ptr();
		return PySequence_Check(o) && !PyUnicode_Check(o) && !PyBytes_Check(o) && !PyByteArray_Check(o);
	}

	// length of a sequence, -1 if it has none
	py::ssize_t seqLen(py::handle h)
	{
		py::ssize_t n = PySequence_Size(h.ptr());
		if (n < 0) PyErr_Clear();
		return n;
	}

	py::object seqItem(py::handle h, py::ssize_t i)
	{
		PyObject* item = PySequence_GetItem(h.ptr(), i);
		if (!item) throw py::error_already_set();
		return py::reinterpret_steal<py::object>(item);
	}

	// Python number -> Scalar (int or double), TypeError with the class name if not possible
	template <class S> S toScalar(py::handle h, const std::string& who)
	{
		py::detail::make_caster<S> caster;
		if (!caster.load(h, true)) {
			throw py::type_error(
			        who + ": expected " + (std::is_integral_v<S> ? "an integer" : "a number") + ", got " + typeName(h));
		}
		return py::detail::cast_op<S>(caster);
	}

	// Python index (negative counts from the end) -> checked C++ index
	Eigen::Index normIndex(py::ssize_t i, Eigen::Index n, const std::string& who)
	{
		py::ssize_t j = (i < 0 ? i + n : i);
		if (j < 0 || j >= n) {
			throw py::index_error(who + ": index " + std::to_string(i) + " out of range 0.." + std::to_string(n - 1));
		}
		return j;
	}

	// row-major flat access into a dense matrix/vector
	template <class T> decltype(auto) flat(T& t, Eigen::Index k)
	{
		constexpr Eigen::Index C = std::decay_t<T>::ColsAtCompileTime;
		return t(k / C, k % C);
	}

	template <class T> constexpr Eigen::Index sizeOf() { return T::SizeAtCompileTime; }

	// ---------------------------------------------------------------- sequence -> T

	// A dense T from a sequence of Size numbers; matrices also take a sequence of rows.
	template <class T> T denseFromSequence(py::handle h)
	{
		using S                     = typename T::Scalar;
		constexpr Eigen::Index R    = T::RowsAtCompileTime;
		constexpr Eigen::Index C    = T::ColsAtCompileTime;
		constexpr Eigen::Index N    = R * C;
		const std::string      who  = nameOf<T>();
		const std::string      want = "a sequence of " + std::to_string(N) + " numbers" + (C > 1 ? " or of " + std::to_string(R) + " rows" : "");
		if (!isSequence(h)) throw py::type_error(who + ": expected " + want + ", got " + typeName(h));
		const py::ssize_t n = seqLen(h);
		T                 ret;
		if (n == N) {
			for (Eigen::Index k = 0; k < N; k++)
				flat(ret, k) = toScalar<S>(seqItem(h, k), who);
			return ret;
		}
		if (C > 1 && n == R) {
			for (Eigen::Index i = 0; i < R; i++) {
				py::object row = seqItem(h, i);
				if (!isSequence(row) || seqLen(row) != C) {
					throw py::value_error(who + ": row " + std::to_string(i) + " must be a sequence of " + std::to_string(C) + " numbers");
				}
				for (Eigen::Index j = 0; j < C; j++)
					ret(i, j) = toScalar<S>(seqItem(row, j), who);
			}
			return ret;
		}
		throw py::value_error(who + ": expected " + want + ", got " + std::to_string(n) + " items");
	}

	Quaternionr quatFromAxisAngle(const Vector3r& axis, Real angle) { return Quaternionr(AngleAxisr(angle, axis.normalized())); }

	bool isNumber(py::handle h) { return PyNumber_Check(h.ptr()) && !isSequence(h); }

	// Quaternion from a 2-sequence (axis, angle) or (angle, axis)
	Quaternionr quatFromSequence(py::handle h)
	{
		if (!isSequence(h) || seqLen(h) != 2) {
			throw py::type_error("Quaternion: expected a sequence (axis, angle) or (angle, axis), got " + typeName(h));
		}
		py::object a = seqItem(h, 0), b = seqItem(h, 1);
		if (isNumber(a)) return quatFromAxisAngle(denseFromSequence<Vector3r>(b), toScalar<Real>(a, "Quaternion"));
		return quatFromAxisAngle(denseFromSequence<Vector3r>(a), toScalar<Real>(b, "Quaternion"));
	}

	// Which sequences may be converted implicitly to T. Only the shape is checked here; the items are
	// converted (and checked) by the constructor that pybind11 calls afterwards.
	template <class T> bool implicitShapeOk(py::handle h)
	{
		if (!isSequence(h)) return false;
		const py::ssize_t n = seqLen(h);
		if constexpr (std::is_same_v<T, Quaternionr>) {
			return n == 2;
		} else {
			if (n == sizeOf<T>()) return true;
			// matrix given as rows; a 3-sequence of numbers is *not* a Matrix3 (unlike the explicit
			// Matrix3(diagonal) constructor), so that e.g. `m * (1,2,3)` is a matrix-vector product
			if (T::ColsAtCompileTime > 1 && n == T::RowsAtCompileTime) return isSequence(seqItem(h, 0));
			return false;
		}
	}

} // namespace
} // namespace yade

namespace pybind11 {
namespace detail {
	template <class T> struct type_caster<yade::SequenceOf<T>> {
		PYBIND11_TYPE_CASTER(yade::SequenceOf<T>, const_name("Sequence"));
		bool          load(handle src, bool /*convert*/) { return yade::implicitShapeOk<T>(src); }
		static handle cast(const yade::SequenceOf<T>&, return_value_policy, handle) { return none().release(); }
	};
} // namespace detail
} // namespace pybind11

namespace yade {
namespace {

	template <std::size_t, class S> using Repeat = S;

	// py::init taking Size scalars, filling T in row-major order
	template <class T, std::size_t... I> auto initFromScalars(std::index_sequence<I...>)
	{
		return py::init([](Repeat<I, typename T::Scalar>... s) {
			T t;
			((flat(t, static_cast<Eigen::Index>(I)) = s), ...);
			return t;
		});
	}

	template <class T> std::string denseRepr(const T& t)
	{
		constexpr Eigen::Index C = T::ColsAtCompileTime;
		constexpr Eigen::Index N = T::SizeAtCompileTime;
		// coefficients grouped by rows for matrices, by 3 for Vector6: Vector6(1,2,3, 4,5,6)
		constexpr Eigen::Index group = (C > 1 ? C : (N > 3 ? 3 : N));
		std::string            s     = nameOf<T>() + "(";
		for (Eigen::Index k = 0; k < N; k++) {
			if (k > 0) s += (k % group == 0 ? ", " : ",");
			s += num(flat(t, k));
		}
		return s + ")";
	}

	template <class T> py::tuple flatTuple(const T& t)
	{
		py::tuple ret(sizeOf<T>());
		for (Eigen::Index k = 0; k < sizeOf<T>(); k++)
			ret[k] = py::cast(flat(t, k));
		return ret;
	}

	// numpy.array(obj) support; int types give numpy's default integer (int64)
	template <class T> py::object denseToArray(const T& t, const py::object& dtype)
	{
		using A = std::conditional_t<std::is_integral_v<typename T::Scalar>, std::int64_t, double>;
		std::vector<py::ssize_t> shape;
		if (T::ColsAtCompileTime > 1) shape = { T::RowsAtCompileTime, T::ColsAtCompileTime };
		else shape = { T::RowsAtCompileTime };
		py::array_t<A> arr(shape);
		A*             p = arr.mutable_data();
		for (Eigen::Index k = 0; k < sizeOf<T>(); k++)
			p[k] = static_cast<A>(flat(t, k));
		if (!dtype.is_none()) return arr.attr("astype")(dtype);
		return py::object(std::move(arr));
	}

	// The reference's minieigen adds a 3-vector's terms as x + (y + z) in norm, squaredNorm and dot (found by
	// running it on thousands of vectors): its Python-visible reductions follow it bit for bit. The engine's
	// own Eigen arithmetic is not changed.
	template <class T> typename T::Scalar refDot(const T& a, const T& b)
	{
		if constexpr (T::SizeAtCompileTime == 3) return a[0] * b[0] + (a[1] * b[1] + a[2] * b[2]);
		else return a.dot(b);
	}
	template <class T> typename T::Scalar refSquaredNorm(const T& a)
	{
		if constexpr (T::IsVectorAtCompileTime) return refDot(a, a);
		else return a.squaredNorm();
	}
	template <class T> T refNormalized(const T& a)
	{
		const typename T::Scalar n2 = refSquaredNorm(a);
		return n2 > 0 ? T(a / std::sqrt(n2)) : a; // (a zero vector is left as it is, as Eigen does)
	}

	// Parts shared by all dense types (vectors and Matrix3): constructors from scalars, arithmetic,
	// comparison, reductions, constants, repr, pickling, numpy.
	template <class T> void defDense(py::class_<T>& cls)
	{
		using S                = typename T::Scalar;
		constexpr bool isFloat = std::is_floating_point_v<S>;

		cls.def(py::init([]() { return T(T::Zero()); }))
		        .def(py::init<const T&>())
		        .def(initFromScalars<T>(std::make_index_sequence<T::SizeAtCompileTime>()));

		// arithmetic; in-place operators modify self and return the same object
		cls.def("__add__", [](const T& a, const T& b) -> T { return a + b; }, py::is_operator())
		        .def("__radd__", [](const T& a, const T& b) -> T { return b + a; }, py::is_operator())
		        .def("__sub__", [](const T& a, const T& b) -> T { return a - b; }, py::is_operator())
		        .def("__rsub__", [](const T& a, const T& b) -> T { return b - a; }, py::is_operator())
		        .def("__neg__", [](const T& a) -> T { return -a; }, py::is_operator())
		        .def("__mul__", [](const T& a, S s) -> T { return a * s; }, py::is_operator())
		        .def("__rmul__", [](const T& a, S s) -> T { return s * a; }, py::is_operator())
		        .def("__iadd__", [](py::object self, const T& b) { noteExternalWrite(); self.cast<T&>() += b; return self; }, py::is_operator())
		        .def("__isub__", [](py::object self, const T& b) { noteExternalWrite(); self.cast<T&>() -= b; return self; }, py::is_operator())
		        .def("__imul__", [](py::object self, S s) { noteExternalWrite(); self.cast<T&>() *= s; return self; }, py::is_operator());
		if constexpr (isFloat) {
			cls.def("__truediv__", [](const T& a, S s) -> T { return a / s; }, py::is_operator())
			        .def("__itruediv__", [](py::object self, S s) { noteExternalWrite(); self.cast<T&>() /= s; return self; }, py::is_operator());
		}

		// exact comparison; mutable, hence unhashable
		cls.def("__eq__", [](const T& a, const T& b) { return a == b; }, py::is_operator())
		        .def("__ne__", [](const T& a, const T& b) { return a != b; }, py::is_operator());
		cls.attr("__hash__") = py::none();

		// reductions and element-wise functions
		cls.def("sum", [](const T& a) -> S { return a.sum(); })
		        .def("prod", [](const T& a) -> S { return a.prod(); })
		        .def("maxCoeff", [](const T& a) -> S { return a.maxCoeff(); })
		        .def("minCoeff", [](const T& a) -> S { return a.minCoeff(); })
		        .def("maxAbsCoeff", [](const T& a) -> S { return a.cwiseAbs().maxCoeff(); })
		        .def("squaredNorm", [](const T& a) -> S { return refSquaredNorm(a); })
		        .def("abs", [](const T& a) -> T { return a.cwiseAbs(); });
		if constexpr (isFloat) {
			cls.def("norm", [](const T& a) -> S { return std::sqrt(refSquaredNorm(a)); })
			        .def("__abs__", [](const T& a) -> S { return std::sqrt(refSquaredNorm(a)); }) // abs(v): the norm, as minieigen
			        .def("isApprox",
			             [](const T& a, const T& b, S prec) { return a.isApprox(b, prec); },
			             py::arg("other"),
			             py::arg("prec") = 1e-12);
		}

		// constants: static read-only properties returning a fresh object at each access
		cls.def_property_readonly_static("Zero", [](const py::object&) { return T(T::Zero()); })
		        .def_property_readonly_static("Ones", [](const py::object&) { return T(T::Ones()); });

		cls.def("__repr__", &denseRepr<T>).def("__str__", &denseRepr<T>);
		// pickle/copy: type(self)(*coefficients)
		cls.def("__reduce__", [](const py::object& self) {
			return py::make_tuple(self.attr("__class__"), flatTuple(self.cast<const T&>()));
		});
		cls.def("__array__",
		        [](const T& a, const py::object& dtype, const py::object& /*copy*/) { return denseToArray(a, dtype); },
		        py::arg("dtype") = py::none(),
		        py::arg("copy")  = py::none());
		// numpy must not turn `numpy.float64(2) * v` into an ndarray: it defers to our operators
		cls.attr("__array_ufunc__") = py::none();
	}

	// Vectors: the dense API plus sequence constructor, indexing, dot, unit vectors, normalization.
	template <class T> void defVector(py::class_<T>& cls)
	{
		using S                  = typename T::Scalar;
		constexpr Eigen::Index N = T::SizeAtCompileTime;

		defDense(cls);
		cls.def(py::init([](const py::object& seq) { return denseFromSequence<T>(seq); }), py::arg("seq"));

		cls.def("__len__", [](const T&) { return N; })
		        .def("__getitem__", [](const T& a, py::ssize_t i) -> S { return a[normIndex(i, N, nameOf<T>())]; })
		        .def("__setitem__", [](T& a, py::ssize_t i, S x) { noteExternalWrite(); a[normIndex(i, N, nameOf<T>())] = x; });

		cls.def("dot", [](const T& a, const T& b) -> S { return refDot(a, b); }, py::arg("other"));
		if constexpr (std::is_floating_point_v<S>) {
			cls.def("normalized", [](const T& a) -> T { return refNormalized(a); })
			        .def("normalize", [](T& a) { noteExternalWrite(); a = refNormalized(a); });
		}
		if constexpr (N == 3) cls.def("cross", [](const T& a, const T& b) -> T { return a.cross(b); }, py::arg("other"));

		cls.def_static("Unit", [](py::ssize_t i) { return T(T::Unit(normIndex(i, N, nameOf<T>()))); }, py::arg("index"));
		if constexpr (N <= 3) {
			cls.def_property_readonly_static("UnitX", [](const py::object&) { return T(T::UnitX()); })
			        .def_property_readonly_static("UnitY", [](const py::object&) { return T(T::UnitY()); });
		}
		if constexpr (N == 3) cls.def_property_readonly_static("UnitZ", [](const py::object&) { return T(T::UnitZ()); });

		py::implicitly_convertible<SequenceOf<T>, T>();
	}

	void defMatrix3(py::class_<Matrix3r>& cls)
	{
		defDense(cls);
		// one argument: Matrix3, Vector3 or 3 numbers (diagonal), 9 numbers (row-major) or 3 rows
		cls.def(py::init([](const py::object& arg) -> Matrix3r {
			        if (py::isinstance<Vector3r>(arg)) return arg.cast<const Vector3r&>().asDiagonal();
			        if (isSequence(arg) && seqLen(arg) == 3 && isNumber(seqItem(arg, 0))) {
				        return denseFromSequence<Vector3r>(arg).asDiagonal();
			        }
			        return denseFromSequence<Matrix3r>(arg);
		        }),
		        py::arg("seq"));
		cls.def(py::init([](const Vector3r& a, const Vector3r& b, const Vector3r& c, bool cols) {
			        Matrix3r m;
			        if (cols) m << a, b, c;
			        else m << a.transpose(), b.transpose(), c.transpose();
			        return m;
		        }),
		        py::arg("r0"),
		        py::arg("r1"),
		        py::arg("r2"),
		        py::arg("cols") = false);

		cls.def_property_readonly_static("Identity", [](const py::object&) { return Matrix3r(Matrix3r::Identity()); });

		// m[i,j], m[i] (row i, a copy), len(m) == 3 (iteration gives rows)
		const auto at = [](Matrix3r& m, std::pair<py::ssize_t, py::ssize_t> ij) -> Real& {
			return m(normIndex(ij.first, 3, "Matrix3"), normIndex(ij.second, 3, "Matrix3"));
		};
		cls.def("__len__", [](const Matrix3r&) { return 3; })
		        .def("__getitem__", [at](Matrix3r& m, std::pair<py::ssize_t, py::ssize_t> ij) -> Real { return at(m, ij); })
		        .def("__getitem__", [](const Matrix3r& m, py::ssize_t i) -> Vector3r { return m.row(normIndex(i, 3, "Matrix3")); })
		        .def("__setitem__", [at](Matrix3r& m, std::pair<py::ssize_t, py::ssize_t> ij, Real x) { noteExternalWrite(); at(m, ij) = x; })
		        .def("__setitem__", [](Matrix3r& m, py::ssize_t i, const Vector3r& r) { noteExternalWrite(); m.row(normIndex(i, 3, "Matrix3")) = r; });

		cls.def("__mul__", [](const Matrix3r& a, const Matrix3r& b) -> Matrix3r { return a * b; }, py::is_operator())
		        .def("__mul__", [](const Matrix3r& a, const Vector3r& v) -> Vector3r { return a * v; }, py::is_operator())
		        .def("__imul__", [](py::object self, const Matrix3r& b) { noteExternalWrite(); self.cast<Matrix3r&>() *= b; return self; }, py::is_operator());

		cls.def("trace", [](const Matrix3r& m) { return m.trace(); })
		        .def("determinant", [](const Matrix3r& m) { return m.determinant(); })
		        .def("transpose", [](const Matrix3r& m) -> Matrix3r { return m.transpose(); })
		        .def("inverse", [](const Matrix3r& m) -> Matrix3r { return m.inverse(); })
		        .def("diagonal", [](const Matrix3r& m) -> Vector3r { return m.diagonal(); })
		        .def("row", [](const Matrix3r& m, py::ssize_t i) -> Vector3r { return m.row(normIndex(i, 3, "Matrix3")); }, py::arg("row"))
		        .def("col", [](const Matrix3r& m, py::ssize_t i) -> Vector3r { return m.col(normIndex(i, 3, "Matrix3")); }, py::arg("col"));

		py::implicitly_convertible<SequenceOf<Matrix3r>, Matrix3r>();
	}

	std::string quatRepr(const Quaternionr& q)
	{
		const AngleAxisr aa(q);
		const Vector3r&  ax = aa.axis();
		return "Quaternion((" + num(ax[0]) + "," + num(ax[1]) + "," + num(ax[2]) + ")," + num(aa.angle()) + ")";
	}

	void defQuaternion(py::class_<Quaternionr>& cls)
	{
		using Q = Quaternionr;
		cls.def(py::init([]() { return Q(Q::Identity()); }))
		        .def(py::init<const Q&>())
		        .def(py::init([](Real w, Real x, Real y, Real z) { return Q(w, x, y, z); }), py::arg("w"), py::arg("x"), py::arg("y"), py::arg("z"))
		        .def(py::init(&quatFromAxisAngle), py::arg("axis"), py::arg("angle"))
		        .def(py::init([](Real angle, const Vector3r& axis) { return quatFromAxisAngle(axis, angle); }), py::arg("angle"), py::arg("axis"))
		        .def(py::init([](const Matrix3r& rot) { return Q(rot); }), py::arg("rotMatrix"))
		        .def(py::init([](const py::object& seq) { return quatFromSequence(seq); }), py::arg("seq"));

		cls.def_property_readonly_static("Identity", [](const py::object&) { return Q(Q::Identity()); });

		// q[0..3] = x, y, z, w (minieigen's order, i.e. Eigen's storage order)
		cls.def("__len__", [](const Q&) { return 4; })
		        .def("__getitem__", [](const Q& q, py::ssize_t i) { return q.coeffs()[normIndex(i, 4, "Quaternion")]; })
		        .def("__abs__", [](const Q& q) { return q.norm(); })
		        .def("__setitem__", [](Q& q, py::ssize_t i, Real x) { noteExternalWrite(); q.coeffs()[normIndex(i, 4, "Quaternion")] = x; });

		cls.def("__mul__", [](const Q& a, const Q& b) -> Q { return a * b; }, py::is_operator())
		        .def("__mul__", [](const Q& q, const Vector3r& v) -> Vector3r { return q * v; }, py::is_operator())
		        .def("__imul__", [](py::object self, const Q& b) { noteExternalWrite(); self.cast<Q&>() *= b; return self; }, py::is_operator())
		        .def("__eq__", [](const Q& a, const Q& b) { return a.coeffs() == b.coeffs(); }, py::is_operator())
		        .def("__ne__", [](const Q& a, const Q& b) { return a.coeffs() != b.coeffs(); }, py::is_operator());
		cls.attr("__hash__") = py::none();

		cls.def("toAxisAngle", [](const Q& q) { const AngleAxisr aa(q); return py::make_tuple(Vector3r(aa.axis()), aa.angle()); })
		        .def("toAngleAxis", [](const Q& q) { const AngleAxisr aa(q); return py::make_tuple(aa.angle(), Vector3r(aa.axis())); })
		        .def("toRotationMatrix", [](const Q& q) -> Matrix3r { return q.toRotationMatrix(); })
		        .def("Rotate", [](const Q& q, const Vector3r& v) -> Vector3r { return q * v; }, py::arg("v"))
		        .def("conjugate", [](const Q& q) -> Q { return q.conjugate(); })
		        .def("inverse", [](const Q& q) -> Q { return q.inverse(); })
		        .def("norm", [](const Q& q) { return q.norm(); })
		        .def("squaredNorm", [](const Q& q) { return q.squaredNorm(); })
		        .def("normalize", [](Q& q) { noteExternalWrite(); q.normalize(); })
		        .def("setFromTwoVectors", [](Q& q, const Vector3r& a, const Vector3r& b) { noteExternalWrite(); q.setFromTwoVectors(a, b); },
		             py::arg("u"), py::arg("v"), "Set in place to the rotation that turns the direction of u into that of v")
		        .def("normalized", [](const Q& q) -> Q { return q.normalized(); })
		        .def("dot", [](const Q& a, const Q& b) { return a.dot(b); }, py::arg("other"))
		        .def("angularDistance", [](const Q& a, const Q& b) { return a.angularDistance(b); }, py::arg("other"))
		        .def("slerp", [](const Q& a, Real t, const Q& b) -> Q { return a.slerp(t, b); }, py::arg("t"), py::arg("other"))
		        .def("isApprox",
		             [](const Q& a, const Q& b, Real prec) { return a.isApprox(b, prec); },
		             py::arg("other"),
		             py::arg("prec") = 1e-12);

		cls.def("__repr__", &quatRepr).def("__str__", &quatRepr);
		cls.def("__reduce__", [](const py::object& self) {
			const Q& q = self.cast<const Q&>();
			return py::make_tuple(self.attr("__class__"), py::make_tuple(q.w(), q.x(), q.y(), q.z()));
		});

		py::implicitly_convertible<SequenceOf<Q>, Q>();
	}

} // namespace

void registerMath(py::module_& m)
{
	// all classes are created first, so that signatures and default arguments can refer to each other
	py::class_<Vector2r>    v2(m, "Vector2", "2d vector of reals (minieigen API)");
	py::class_<Vector2i>    v2i(m, "Vector2i", "2d vector of integers (minieigen API)");
	py::class_<Vector3r>    v3(m, "Vector3", "3d vector of reals (minieigen API)");
	py::class_<Vector3i>    v3i(m, "Vector3i", "3d vector of integers (minieigen API)");
	py::class_<Vector6r>    v6(m, "Vector6", "6d vector of reals (minieigen API)");
	py::class_<Vector6i>    v6i(m, "Vector6i", "6d vector of integers (minieigen API)");
	py::class_<Matrix3r>    m3(m, "Matrix3", "3x3 matrix of reals (minieigen API)");
	py::class_<Quaternionr> q(m, "Quaternion", "quaternion representing a rotation (minieigen API)");

	defVector(v2);
	defVector(v2i);
	defVector(v3);
	defVector(v3i);
	defVector(v6);
	defVector(v6i);
	defMatrix3(m3);
	defQuaternion(q);

	// type-specific vector methods
	v3.def("outer", [](const Vector3r& a, const Vector3r& b) -> Matrix3r { return a * b.transpose(); }, py::arg("other"))
	        .def("asDiagonal", [](const Vector3r& a) -> Matrix3r { return a.asDiagonal(); });
	v6.def(py::init([](const Vector3r& head, const Vector3r& tail) {
		      Vector6r v;
		      v << head, tail;
		      return v;
	      }),
	       py::arg("head"),
	       py::arg("tail"))
	        .def("head", [](const Vector6r& v) -> Vector3r { return v.head<3>(); })
	        .def("tail", [](const Vector6r& v) -> Vector3r { return v.tail<3>(); });
	v6i.def(py::init([](const Vector3i& head, const Vector3i& tail) {
		       Vector6i v;
		       v << head, tail;
		       return v;
	       }),
	        py::arg("head"),
	        py::arg("tail"))
	        .def("head", [](const Vector6i& v) -> Vector3i { return v.head<3>(); })
	        .def("tail", [](const Vector6i& v) -> Vector3i { return v.tail<3>(); });
}

} // namespace yade
