#include <pkg/common/Bo1_Facet_Aabb.hpp>

namespace yade {

void Bo1_Facet_Aabb::go(const Facet& f, Aabb& aabb, const State& state, const Body&) {
    const Matrix3r rot = state.ori().toRotationMatrix();
    aabb.min = aabb.max = state.pos() + rot * f.vertices[0];
    for (int i = 1; i < 3; ++i) {
        const Vector3r v = state.pos() + rot * f.vertices[i];
        aabb.min = aabb.min.cwiseMin(v);
        aabb.max = aabb.max.cwiseMax(v);
    }
}

} // namespace yade
