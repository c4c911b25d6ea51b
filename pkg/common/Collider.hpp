// Approximate collision detection (3.1): creates potential interactions from overlapping bounds.
#pragma once
#include <core/BoundDispatcher.hpp>

namespace yade {

class Collider : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Approximate collision detection (3.1): creates potential interactions between bodies whose Bounds overlap.";
    std::shared_ptr<BoundDispatcher> boundDispatcher = std::make_shared<BoundDispatcher>();
    int avoidSelfInteractionMask = 0;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("boundDispatcher", boundDispatcher, "Computes the bounds (Bo1 functors)");
        v.attr("avoidSelfInteractionMask", avoidSelfInteractionMask,
                "Bodies of one and the same mask that has a bit in common with this one never interact with each other (0: none excluded)");
    }
    // Body::mayCollide (masks share a bit, distinct, one dynamic), and not two bodies of one mask that avoids itself
    bool mayCollide(const Body& a, const Body& b) const { return Body::mayCollide(a, b) && !avoidsItself(a.mask, b.mask); }
    bool avoidsItself(int maskA, int maskB) const { return maskA == maskB && (maskA & avoidSelfInteractionMask) != 0; }
};

} // namespace yade
