// Approximate collision detection (3.1): creates potential interactions from overlapping bounds.
#pragma once
#include <core/BoundDispatcher.hpp>

namespace yade {

class Collider : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Approximate collision detection (3.1): creates potential interactions between bodies whose Bounds overlap.";
    std::shared_ptr<BoundDispatcher> boundDispatcher = std::make_shared<BoundDispatcher>();
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("boundDispatcher", boundDispatcher, "Computes the bounds (Bo1 functors)");
    }
};

} // namespace yade
