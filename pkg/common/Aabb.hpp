// Axis-aligned bounding box: the Bound used by InsertionSortCollider (min and max in Bound).
#pragma once
#include <core/Bound.hpp>

namespace yade {

class Aabb : public Bound {
public:
    static constexpr const char* classDoc = "Axis-aligned bounding box: the Bound that InsertionSortCollider sorts (corners min and max).";
    template <class V> void visit(V& v) { Bound::visit(v); }
    YADE_INDEXABLE(Aabb)
};

} // namespace yade
