// Aabb of a wall: infinite along the two axes of its plane.
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/common/Wall.hpp>

namespace yade {

class Bo1_Wall_Aabb : public BoundFunctorOf<Wall, Aabb> {
public:
    static constexpr const char* classDoc = "Bo1 functor computing the Aabb of a Wall: infinite along the two axes of its plane.";
    template <class V> void visit(V& v) { BoundFunctor::visit(v); }
    void go(const Wall& w, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
