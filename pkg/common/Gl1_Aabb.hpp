// Draws axis-aligned bounding boxes in the 3D view (OpenGLRenderer.bound).
#pragma once
#include <pkg/common/Aabb.hpp>
#include <pkg/common/GlFunctors.hpp>

namespace yade {

class Gl1_Aabb : public GlFunctorOf<GlBoundFunctor, Aabb> {
public:
    static constexpr const char* classDoc = "Draws axis-aligned bounding boxes in the 3D view (shown when OpenGLRenderer.bound is set).";
    template <class V> void visit(V& v) { GlBoundFunctor::visit(v); }
};

} // namespace yade
