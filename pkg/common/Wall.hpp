// An infinite axis-aligned plane through the body position, normal to `axis`.
#pragma once
#include <core/Shape.hpp>

namespace yade {

class Wall : public Shape {
public:
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
