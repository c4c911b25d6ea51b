// The single attribute declaration: every class lists its attributes once in
//   template <class V> void visit(V& v) { Base::visit(v); v.attr("name", member, "doc", flags); }
// and the binding layer, the keyword constructor, dict(), repr and the serializer all walk it.
#pragma once
#include <lib/base/Math.hpp>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace yade {

class Serializable;

namespace Attr {
    enum Flags : unsigned {
        none = 0,
        readonly = 1u << 0,    // visible from Python, not assignable
        noSave = 1u << 1,      // not written by the serializer
        hidden = 1u << 2,      // not shown in dict() nor as a Python property
        positive = 1u << 3,    // value (or each component) must be > 0 and finite
        nonNegative = 1u << 4, // value must be >= 0 and finite
        finite = 1u << 5,      // value (or each component) must be finite
        readCopy = 1u << 6,    // read from Python as a copy, not a view (the reference's properties, State.pos)
        classWide = 1u << 7,   // a static member: one value for the class, read and set as Class.name as well
                               // as through any instance (the drawing functors' settings, Gl1_Sphere.quality)
    };
}

// What kind of C++ value an attribute holds; the binding layer and the serializer switch on it.
enum class AttrKind {
    Bool, Int, Long, Real, String,
    Vector2r, Vector2i, Vector3r, Vector3i, Vector6r, Matrix3r, Quaternionr,
    IntVector, RealVector, StringVector, Vector3rVector,
    Ptr,      // std::shared_ptr<T>, T derived from Serializable
    PtrVector, // std::vector<std::shared_ptr<T>>
    // (added later: appended, since the block format stores a kind by its number)
    Vector6i, Vector2rVector, QuaternionrVector
};

template <class M, class Enable = void> struct AttrKindOf; // unsupported member types fail to compile here
#define YADE_ATTR_KIND(Type, Kind) \
    template <> struct AttrKindOf<Type> { static constexpr AttrKind kind = AttrKind::Kind; }
YADE_ATTR_KIND(bool, Bool);
YADE_ATTR_KIND(int, Int);
YADE_ATTR_KIND(long long, Long);
YADE_ATTR_KIND(Real, Real);
YADE_ATTR_KIND(std::string, String);
YADE_ATTR_KIND(Vector2r, Vector2r);
YADE_ATTR_KIND(Vector2i, Vector2i);
YADE_ATTR_KIND(Vector3r, Vector3r);
YADE_ATTR_KIND(Vector3i, Vector3i);
YADE_ATTR_KIND(Vector6r, Vector6r);
YADE_ATTR_KIND(Vector6i, Vector6i);
YADE_ATTR_KIND(Matrix3r, Matrix3r);
YADE_ATTR_KIND(Quaternionr, Quaternionr);
YADE_ATTR_KIND(std::vector<int>, IntVector);
YADE_ATTR_KIND(std::vector<Real>, RealVector);
YADE_ATTR_KIND(std::vector<std::string>, StringVector);
YADE_ATTR_KIND(std::vector<Vector3r>, Vector3rVector);
YADE_ATTR_KIND(std::vector<Vector2r>, Vector2rVector);
YADE_ATTR_KIND(std::vector<Quaternionr>, QuaternionrVector);
#undef YADE_ATTR_KIND
template <class T> struct AttrKindOf<std::shared_ptr<T>, std::enable_if_t<std::is_base_of_v<Serializable, T>>> {
    static constexpr AttrKind kind = AttrKind::Ptr;
};
template <class T> struct AttrKindOf<std::vector<std::shared_ptr<T>>, std::enable_if_t<std::is_base_of_v<Serializable, T>>> {
    static constexpr AttrKind kind = AttrKind::PtrVector;
};

} // namespace yade
