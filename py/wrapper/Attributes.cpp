#include <core/Body.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <cmath>
#include <limits>
#include <py/wrapper/Attributes.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;
using namespace pybind11::literals;

namespace yade {

const ClassInfo& classInfoOf(const Serializable& s) { return ClassRegistry::instance().get(typeid(s)); }

static const char* kindName(AttrKind k) {
    switch (k) {
        case AttrKind::Bool: return "bool";
        case AttrKind::Int:
        case AttrKind::Long: return "int";
        case AttrKind::Real: return "float";
        case AttrKind::String: return "str";
        case AttrKind::Vector2r: return "Vector2";
        case AttrKind::Vector2i: return "Vector2i";
        case AttrKind::Vector3r: return "Vector3";
        case AttrKind::Vector3i: return "Vector3i";
        case AttrKind::Vector6r: return "Vector6";
        case AttrKind::Vector6i: return "Vector6i";
        case AttrKind::Matrix3r: return "Matrix3";
        case AttrKind::Quaternionr: return "Quaternion";
        case AttrKind::IntVector: return "list of int";
        case AttrKind::RealVector: return "list of float";
        case AttrKind::StringVector: return "list of str";
        case AttrKind::Vector3rVector: return "list of Vector3";
        case AttrKind::Vector2rVector: return "list of Vector2";
        case AttrKind::QuaternionrVector: return "list of Quaternion";
        case AttrKind::Ptr:
        case AttrKind::PtrVector: return "object";
    }
    return "?";
}

static std::string pointeeName(const AttrInfo& a) {
    const ClassInfo* c = ClassRegistry::instance().find(*a.pointee);
    return c ? c->name : std::string("object");
}

template <class T> static py::object view(T* p, py::handle owner) {
    return py::cast(p, py::return_value_policy::reference_internal, owner);
}

// A contact's geometry or physics that shows a record of a ContactPool (doc/storage.md): its
// vectors are given as copies, since a record moves when another contact ends.
static bool isViewOfRecord(const Serializable& s) {
    if (const auto* g = dynamic_cast<const IGeom*>(&s)) return g->viewTarget() != nullptr;
    if (const auto* p = dynamic_cast<const IPhys*>(&s)) return p->viewTarget() != nullptr;
    return false;
}

static py::object copyOf(Serializable& s, const AttrInfo& a);

py::object getAttr(Serializable& s, const AttrInfo& a, py::handle owner) {
    void* p = a.address(s);
    if (!owner.is_none() && ((a.flags & Attr::readCopy) || isViewOfRecord(s))) return copyOf(s, a);
    switch (a.kind) {
        case AttrKind::Bool: return py::cast(*static_cast<bool*>(p));
        case AttrKind::Int: return py::cast(*static_cast<int*>(p));
        case AttrKind::Long: return py::cast(*static_cast<long long*>(p));
        case AttrKind::Real: return py::cast(*static_cast<Real*>(p));
        case AttrKind::String: return py::cast(*static_cast<std::string*>(p));
        case AttrKind::Vector2r: return view(static_cast<Vector2r*>(p), owner);
        case AttrKind::Vector2i: return view(static_cast<Vector2i*>(p), owner);
        case AttrKind::Vector3r: return view(static_cast<Vector3r*>(p), owner);
        case AttrKind::Vector3i: return view(static_cast<Vector3i*>(p), owner);
        case AttrKind::Vector6r: return view(static_cast<Vector6r*>(p), owner);
        case AttrKind::Vector6i: return view(static_cast<Vector6i*>(p), owner);
        case AttrKind::Matrix3r: return view(static_cast<Matrix3r*>(p), owner);
        case AttrKind::Quaternionr: return view(static_cast<Quaternionr*>(p), owner);
        case AttrKind::IntVector: return py::cast(*static_cast<std::vector<int>*>(p));
        case AttrKind::RealVector: return py::cast(*static_cast<std::vector<Real>*>(p));
        case AttrKind::StringVector: return py::cast(*static_cast<std::vector<std::string>*>(p));
        case AttrKind::Vector3rVector: return py::cast(*static_cast<std::vector<Vector3r>*>(p));
        case AttrKind::Vector2rVector: return py::cast(*static_cast<std::vector<Vector2r>*>(p));
        case AttrKind::QuaternionrVector: return py::cast(*static_cast<std::vector<Quaternionr>*>(p));
        case AttrKind::Ptr: {
            std::shared_ptr<Serializable> v = a.getPtr(p);
            if (const auto* b = dynamic_cast<const Body*>(&s); b && v && v == b->stateStandIn) return py::none(); // (b.state = None)
            return py::cast(v);
        }
        case AttrKind::PtrVector: return py::cast(a.getPtrVector(p));
    }
    return py::none();
}

static bool allFinite(const Real* x, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(x[i])) return false;
    return true;
}

// Applies the positive / nonNegative / finite flags to n real components.
static void checkValue(const std::string& where, const AttrInfo& a, const Real* x, int n) {
    for (int i = 0; i < n; ++i) {
        const bool fin = std::isfinite(x[i]);
        const char* problem = nullptr;
        if (a.has(Attr::positive) && !(fin && x[i] > 0)) problem = "must be positive and finite";
        else if (a.has(Attr::nonNegative) && !(fin && x[i] >= 0)) problem = "must be non-negative and finite";
        else if (a.has(Attr::finite) && !fin) problem = "must be finite";
        if (problem) {
            std::ostringstream os;
            os << where << " " << problem << " (got ";
            for (int j = 0; j < n; ++j) os << (j ? ", " : "") << x[j];
            os << ")";
            throw py::value_error(os.str());
        }
    }
}

template <class T> static T castOr(py::handle v, const std::string& where, const std::string& expected) {
    try {
        return py::cast<T>(v);
    } catch (py::cast_error&) {
        throw py::type_error(where + ": expected " + expected + ", got " + std::string(py::str(py::type::of(v).attr("__name__"))));
    }
}

template <class M> static void setMatrixLike(void* p, py::handle v, const std::string& where, const AttrInfo& a) {
    M m = castOr<M>(v, where, kindName(a.kind));
    if constexpr (std::is_same_v<typename M::Scalar, Real>) checkValue(where, a, m.data(), (int)m.size());
    *static_cast<M*>(p) = m;
}

// A copy of the current value (not a view), to put back if the new one is refused.
static py::object copyOf(Serializable& s, const AttrInfo& a) {
    void* p = a.address(s);
    switch (a.kind) {
        case AttrKind::Vector2r: return py::cast(Vector2r(*static_cast<Vector2r*>(p)));
        case AttrKind::Vector2i: return py::cast(Vector2i(*static_cast<Vector2i*>(p)));
        case AttrKind::Vector3r: return py::cast(Vector3r(*static_cast<Vector3r*>(p)));
        case AttrKind::Vector3i: return py::cast(Vector3i(*static_cast<Vector3i*>(p)));
        case AttrKind::Vector6r: return py::cast(Vector6r(*static_cast<Vector6r*>(p)));
        case AttrKind::Vector6i: return py::cast(Vector6i(*static_cast<Vector6i*>(p)));
        case AttrKind::Matrix3r: return py::cast(Matrix3r(*static_cast<Matrix3r*>(p)));
        case AttrKind::Quaternionr: return py::cast(Quaternionr(*static_cast<Quaternionr*>(p)));
        default: return getAttr(s, a, py::none());
    }
}

static void assign(Serializable& s, const AttrInfo& a, py::handle v);

void setAttr(Serializable& s, const AttrInfo& a, py::handle v) {
    noteExternalWrite();
    py::object old = copyOf(s, a);
    assign(s, a, v);
    try {
        s.postLoad(); // may refuse the combination (Wall.axis=5, a degenerate Facet)
    } catch (...) {
        assign(s, a, old); // leave the object as it was
        s.postLoad();
        throw;
    }
}

static void assign(Serializable& s, const AttrInfo& a, py::handle v) {
    const std::string where = classInfoOf(s).name + "." + a.name;
    if (a.has(Attr::readonly)) throw py::attribute_error(where + " is read-only");
    void* p = a.address(s);
    const std::string expected = kindName(a.kind);
    switch (a.kind) {
        case AttrKind::Bool:
            if (!py::isinstance<py::bool_>(v) && !py::isinstance<py::int_>(v))
                throw py::type_error(where + ": expected bool, got " + std::string(py::str(py::type::of(v).attr("__name__"))));
            *static_cast<bool*>(p) = PyObject_IsTrue(v.ptr()) == 1; // (an int of any size: non-zero is true)
            break;
        case AttrKind::Int: {
            if (py::isinstance<py::float_>(v)) throw py::type_error(where + ": expected int, got float");
            const long long x = castOr<long long>(v, where, expected);
            if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max())
                throw py::value_error(where + ": " + std::to_string(x) + " is out of the range of a 32-bit int");
            const Real xr = (Real)x;
            checkValue(where, a, &xr, 1);
            *static_cast<int*>(p) = (int)x;
            break;
        }
        case AttrKind::Long: {
            if (py::isinstance<py::float_>(v)) throw py::type_error(where + ": expected int, got float");
            const long long x = castOr<long long>(v, where, expected);
            const Real xr = (Real)x;
            checkValue(where, a, &xr, 1);
            *static_cast<long long*>(p) = x;
            break;
        }
        case AttrKind::Real: {
            if (py::isinstance<py::str>(v) || py::isinstance<py::bool_>(v))
                throw py::type_error(where + ": expected float, got " + std::string(py::str(py::type::of(v).attr("__name__"))));
            Real x = castOr<Real>(v, where, expected);
            checkValue(where, a, &x, 1);
            *static_cast<Real*>(p) = x;
            break;
        }
        case AttrKind::String:
            if (!py::isinstance<py::str>(v)) throw py::type_error(where + ": expected str, got " + std::string(py::str(py::type::of(v).attr("__name__"))));
            *static_cast<std::string*>(p) = py::cast<std::string>(v);
            break;
        case AttrKind::Vector2r: setMatrixLike<Vector2r>(p, v, where, a); break;
        case AttrKind::Vector2i: setMatrixLike<Vector2i>(p, v, where, a); break;
        case AttrKind::Vector3r: setMatrixLike<Vector3r>(p, v, where, a); break;
        case AttrKind::Vector3i: setMatrixLike<Vector3i>(p, v, where, a); break;
        case AttrKind::Vector6r: setMatrixLike<Vector6r>(p, v, where, a); break;
        case AttrKind::Vector6i: setMatrixLike<Vector6i>(p, v, where, a); break;
        case AttrKind::Matrix3r: setMatrixLike<Matrix3r>(p, v, where, a); break;
        case AttrKind::Quaternionr: {
            Quaternionr q = castOr<Quaternionr>(v, where, expected);
            if (!allFinite(q.coeffs().data(), 4) || q.norm() == 0) throw py::value_error(where + " must be a finite non-zero quaternion");
            // normalized, unless of unit length to within rounding: kept as given then (its bits, as the reference keeps them)
            const bool unit = std::abs(q.squaredNorm() - 1) <= 8 * std::numeric_limits<Real>::epsilon();
            *static_cast<Quaternionr*>(p) = unit ? q : q.normalized();
            break;
        }
        case AttrKind::IntVector: *static_cast<std::vector<int>*>(p) = castOr<std::vector<int>>(v, where, expected); break;
        case AttrKind::RealVector: {
            auto x = castOr<std::vector<Real>>(v, where, expected);
            checkValue(where, a, x.data(), (int)x.size());
            *static_cast<std::vector<Real>*>(p) = x;
            break;
        }
        case AttrKind::StringVector: *static_cast<std::vector<std::string>*>(p) = castOr<std::vector<std::string>>(v, where, expected); break;
        case AttrKind::Vector3rVector: {
            auto x = castOr<std::vector<Vector3r>>(v, where, expected);
            for (const auto& e : x) checkValue(where, a, e.data(), 3);
            *static_cast<std::vector<Vector3r>*>(p) = x;
            break;
        }
        case AttrKind::Vector2rVector: {
            auto x = castOr<std::vector<Vector2r>>(v, where, expected);
            for (const auto& e : x) checkValue(where, a, e.data(), 2);
            *static_cast<std::vector<Vector2r>*>(p) = x;
            break;
        }
        case AttrKind::QuaternionrVector: {
            auto x = castOr<std::vector<Quaternionr>>(v, where, expected);
            for (auto& e : x) {
                if (!e.coeffs().allFinite() || e.coeffs().squaredNorm() == 0) throw py::value_error(where + ": a quaternion is not finite or zero");
                e.normalize();
            }
            *static_cast<std::vector<Quaternionr>*>(p) = x;
            break;
        }
        case AttrKind::Ptr: {
            std::shared_ptr<Serializable> obj;
            if (pointeeName(a) == "MatchMaker" && (py::isinstance<py::float_>(v) || py::isinstance<py::int_>(v)) && !py::isinstance<py::bool_>(v)) {
                // a number where a MatchMaker is expected: one that always gives it, as in the reference
                const Real x = py::cast<Real>(v);
                if (!std::isfinite(x)) throw py::value_error(where + " must be finite, got " + std::string(py::str(v)));
                obj = MatchMaker::constant(x);
            } else if (!v.is_none())
                obj = castOr<std::shared_ptr<Serializable>>(v, where, pointeeName(a));
            if (!a.setPtr(p, obj)) throw py::type_error(where + ": expected " + pointeeName(a) + ", got " + obj->getClassName());
            break;
        }
        case AttrKind::PtrVector: {
            if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v))
                throw py::type_error(where + ": expected a list of " + pointeeName(a));
            std::vector<std::shared_ptr<Serializable>> objs;
            for (py::handle item : v) {
                auto obj = item.is_none() ? nullptr : castOr<std::shared_ptr<Serializable>>(item, where, "a list of " + pointeeName(a));
                if (!obj || !std::dynamic_pointer_cast<Serializable>(obj))
                    throw py::type_error(where + ": expected a list of " + pointeeName(a) + ", got None in it");
                objs.push_back(obj);
            }
            if (!a.setPtrVector(p, objs)) {
                for (const auto& o : objs)
                    if (!ClassRegistry::instance().isSubclass(o->getClassName(), pointeeName(a)))
                        throw py::type_error(where + ": expected a list of " + pointeeName(a) + ", got " + o->getClassName() + " in it");
                throw py::type_error(where + ": expected a list of " + pointeeName(a));
            }
            break;
        }
    }
}

// A class-wide attribute (Attr::classWide, a static member) is a pybind11 static property: its getter and
// setter get the class, and reach the static member through one instance made for that purpose, so that
// `Gl1_Sphere.quality = 2` sets it (a plain property would be replaced by the number) and every instance
// shows it. A vector is read as a view of the static member, which lives as long as the program.
static void defineClassWideProperty(py::handle cls, const ClassInfo& info, const AttrInfo* a, const std::string& doc) {
    // pybind11's static property type, subclassed so that its objects have a __dict__ for __doc__ (pybind11's
    // own def_property_static fails there on Python 3.11: "attribute '__doc__' is read-only").
    static py::object classWideAttr = py::module_::import("builtins").attr("type")(
            "ClassWideAttribute", py::make_tuple(py::handle(reinterpret_cast<PyObject*>(py::detail::get_internals().static_property_type))),
            py::dict("__module__"_a = "yade.wrapper"));
    std::shared_ptr<Serializable> any = info.factory();
    py::cpp_function getter([any, a](py::object) { return getAttr(*any, *a, py::none()); });
    py::cpp_function setter([any, a](py::object, py::object v) { setAttr(*any, *a, v); });
    py::object property = classWideAttr(getter, setter);
    property.attr("__doc__") = doc;
    cls.attr(a->name.c_str()) = property;
}

void defineAttrProperties(py::handle cls, const ClassInfo& info) {
    auto property = py::module_::import("builtins").attr("property");
    for (size_t i = info.ownAttrsBegin; i < info.attrs.size(); ++i) {
        const AttrInfo* a = &info.attrs[i];
        if (a->has(Attr::hidden)) continue;
        std::string doc = a->doc + " (" + kindName(a->kind) + (a->has(Attr::readonly) ? ", read-only" : "") +
                          (a->has(Attr::classWide) ? ", one value for the class" : "") + ")";
        if (a->has(Attr::classWide)) {
            defineClassWideProperty(cls, info, a, doc);
            continue;
        }
        py::cpp_function getter([a](py::object self) { return getAttr(py::cast<Serializable&>(self), *a, self); });
        py::cpp_function setter([a](py::object self, py::object v) { setAttr(py::cast<Serializable&>(self), *a, v); });
        cls.attr(a->name.c_str()) = property(getter, setter, py::none(), doc);
    }
}

py::dict attrDict(Serializable& s, py::handle owner) {
    py::dict d;
    for (const AttrInfo& a : classInfoOf(s).attrs)
        if (!a.has(Attr::hidden)) d[a.name.c_str()] = getAttr(s, a, owner);
    return d;
}

} // namespace yade
