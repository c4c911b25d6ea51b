// Aabb of a (possibly rotated) box.
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/common/Box.hpp>

namespace yade {

class Bo1_Box_Aabb : public BoundFunctorOf<Box, Aabb> {
public:
    static constexpr const char* classDoc = "Bo1 functor computing the Aabb of a (possibly rotated) Box.";
    template <class V> void visit(V& v) { BoundFunctor::visit(v); }
    void go(const Box& b, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
