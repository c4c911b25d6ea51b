// A cuboid of half-sizes `extents`, centered at the body position, turned by its orientation.
#pragma once
#include <core/Shape.hpp>

namespace yade {

class Box : public Shape {
public:
    static constexpr const char* classDoc = "Geometry of a cuboid of half-sizes extents, centered at the body's position and turned by its orientation.";
    Vector3r extents = Vector3r::Constant(NaN);
    template <class V> void visit(V& v) {
        Shape::visit(v);
        v.attr("extents", extents, "Half-sizes along the local axes [m] (0: a plate)", Attr::nonNegative);
    }
    YADE_INDEXABLE(Box)
};

} // namespace yade
