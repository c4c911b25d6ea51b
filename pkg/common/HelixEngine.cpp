#include <core/Scene.hpp>
#include <pkg/common/HelixEngine.hpp>

namespace yade {

void HelixEngine::apply(const std::vector<int>& bodyIds) {
    rotateAroundZero = true; // (a helix always turns around its axis)
    angleTurned += angularVelocity * scene->dt;
    RotationEngine::apply(bodyIds);
    const Vector3r v = linearVelocity * rotationAxis;
    for (int id : bodyIds) scene->bodies[id]->state->vel() += v;
}

} // namespace yade
