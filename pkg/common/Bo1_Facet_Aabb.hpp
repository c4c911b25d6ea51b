// Aabb of a facet: the box around its three vertices.
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/common/Facet.hpp>

namespace yade {

class Bo1_Facet_Aabb : public BoundFunctorOf<Facet, Aabb> {
public:
    static constexpr const char* classDoc = "Bo1 functor computing the Aabb of a Facet: the box around its three vertices.";
    template <class V> void visit(V& v) { BoundFunctor::visit(v); }
    void go(const Facet& f, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
