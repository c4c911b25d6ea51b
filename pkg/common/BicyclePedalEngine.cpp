#include <core/Scene.hpp>
#include <pkg/common/BicyclePedalEngine.hpp>
#include <cmath>
#include <stdexcept>

namespace yade {

void BicyclePedalEngine::apply(const std::vector<int>& bodyIds) {
    if (!(rotationAxis.norm() > 0)) throw std::invalid_argument("BicyclePedalEngine.rotationAxis must not be zero");
    normalizeDirection(rotationAxis);
    const Quaternionr toAxis = Quaternionr::FromTwoVectors(Vector3r::UnitZ(), rotationAxis);
    const Real dt = scene->dt, next = fi + angularVelocity * dt;
    const Vector3r before(-radius * std::cos(fi), -radius * std::sin(fi), 0), after(-radius * std::cos(next), -radius * std::sin(next), 0);
    const Vector3r vel = toAxis * ((after - before) / dt);
    for (int id : bodyIds) scene->bodies[id]->state->vel() += vel;
    fi = next;
}

} // namespace yade
