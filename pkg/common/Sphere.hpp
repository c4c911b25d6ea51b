// A sphere given by its radius (1.2.1).
#pragma once
#include <core/Shape.hpp>

namespace yade {

class Sphere : public Shape {
public:
    static constexpr const char* classDoc = "Geometry of a spherical particle, given by its radius.";
    Real radius = NaN;
    template <class V> void visit(V& v) {
        Shape::visit(v);
        v.attr("radius", radius, "Radius [m]", Attr::positive);
    }
    YADE_INDEXABLE(Sphere)
};

} // namespace yade
