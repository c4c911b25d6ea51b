// An infinite axis-aligned plane through the body position, normal to `axis`.
#pragma once
#include <core/Shape.hpp>

namespace yade {

class Wall : public Shape {
public:
    static constexpr const char* classDoc = "Geometry of an infinite axis-aligned plane through the body's position, normal to axis; sense -1/+1 makes only one side interact.";
    int axis = 0;  // 0, 1, 2 for x, y, z
    int sense = 0; // which side interacts: -1 negative, +1 positive, 0 both
    template <class V> void visit(V& v) {
        Shape::visit(v);
        v.attr("axis", axis, "Axis of the normal: 0, 1 or 2 (x, y, z)");
        v.attr("sense", sense, "Side that interacts: -1 negative only, 1 positive only, 0 both");
    }
    void postLoad() override;
    YADE_INDEXABLE(Wall)
};

} // namespace yade
