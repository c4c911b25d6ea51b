// A triangle, for boundaries (3.1). Vertices are relative to the body position, which
// utils.facet puts at the center of the inscribed circle.
#pragma once
#include <core/Shape.hpp>

namespace yade {

class Facet : public Shape {
public:
    static constexpr const char* classDoc = "Geometry of a triangle, used for boundaries (3.1); vertices are relative to the body's position (the center of the inscribed circle).";
    std::vector<Vector3r> vertices = std::vector<Vector3r>(3, Vector3r::Constant(NaN));
    Vector3r normal = Vector3r::Constant(NaN);
    Real area = NaN;
    // Derived from the vertices by postLoad(): in-plane outward edge normals, radius of the
    // inscribed circle, distances and unit directions from the origin to the vertices.
    Vector3r ne[3], vu[3];
    Real icr = NaN, vl[3] = {NaN, NaN, NaN};
    template <class V> void visit(V& v) {
        Shape::visit(v);
        v.attr("vertices", vertices, "The three vertices, relative to the body position [m]", Attr::finite);
        v.attr("normal", normal, "Unit normal, (v1-v0)×(v2-v1) normalized", Attr::readonly | Attr::noSave);
        v.attr("area", area, "Area [m²]", Attr::readonly | Attr::noSave);
    }
    void postLoad() override; // throws std::invalid_argument for a degenerate triangle
    YADE_INDEXABLE(Facet)
};

} // namespace yade
