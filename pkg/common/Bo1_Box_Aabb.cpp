#include <pkg/common/Bo1_Box_Aabb.hpp>

namespace yade {

void Bo1_Box_Aabb::go(const Box& b, Aabb& aabb, const State& state, const Body&) {
    // half-size of the rotated box along each global axis: |R|·extents
    const Vector3r half = state.ori().toRotationMatrix().cwiseAbs() * b.extents;
    aabb.min = state.pos() - half;
    aabb.max = state.pos() + half;
}

} // namespace yade
