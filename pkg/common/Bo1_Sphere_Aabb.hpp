// Aabb of a sphere: center ± radius, enlarged by aabbEnlargeFactor (3.1.3).
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

class Bo1_Sphere_Aabb : public BoundFunctorOf<Sphere, Aabb> {
public:
    static constexpr const char* classDoc = "Bo1 functor computing the Aabb of a Sphere: center ± radius, enlarged by aabbEnlargeFactor (3.1.3).";
    Real aabbEnlargeFactor = -1;
    template <class V> void visit(V& v) {
        BoundFunctor::visit(v);
        v.attr("aabbEnlargeFactor", aabbEnlargeFactor, "Scale the box by this factor around the center (negative: no scaling)");
    }
    void go(const Sphere& s, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
