// Aabb of a GridConnection: the box of its two nodes' spheres.
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/dem/grid/GridConnection.hpp>

namespace yade {

class Bo1_GridConnection_Aabb : public BoundFunctorOf<GridConnection, Aabb> {
public:
    static constexpr const char* classDoc =
            "Bo1 functor computing the Aabb of a GridConnection: the box holding the spheres of its radius at its two nodes (node2 in "
            "its periodic image for a periodic connection), each radius scaled by aabbEnlargeFactor when positive.";
    Real aabbEnlargeFactor = -1;
    template <class V> void visit(V& v) {
        BoundFunctor::visit(v);
        v.attr("aabbEnlargeFactor", aabbEnlargeFactor, "Scale the radius by this factor (negative: no scaling)");
    }
    void go(const GridConnection& s, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
