#include <pkg/common/Bo1_Wall_Aabb.hpp>

namespace yade {

void Bo1_Wall_Aabb::go(const Wall& w, Aabb& aabb, const State& state, const Body&) {
    aabb.min = Vector3r::Constant(-Inf);
    aabb.max = Vector3r::Constant(Inf);
    aabb.min[w.axis] = aabb.max[w.axis] = state.pos()[w.axis];
}

} // namespace yade
