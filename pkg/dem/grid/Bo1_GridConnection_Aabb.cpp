#include <core/Scene.hpp>
#include <pkg/dem/grid/Bo1_GridConnection_Aabb.hpp>
#include <stdexcept>

namespace yade {

void Bo1_GridConnection_Aabb::go(const GridConnection& s, Aabb& aabb, const State&, const Body&) {
    const Real r = aabbEnlargeFactor > 0 ? s.radius * aabbEnlargeFactor : s.radius;
    if (!scene) throw std::runtime_error("Bo1_GridConnection_Aabb: called outside a scene");
    Vector3r p1, p2;
    s.nodePositions(*scene, p1, p2);
    aabb.min = p1.cwiseMin(p2) - Vector3r::Constant(r);
    aabb.max = p1.cwiseMax(p2) + Vector3r::Constant(r);
}

} // namespace yade
