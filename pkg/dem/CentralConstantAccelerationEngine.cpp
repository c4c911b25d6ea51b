#include <core/Scene.hpp>
#include <pkg/dem/CentralConstantAccelerationEngine.hpp>
#include <stdexcept>

namespace yade {

void CentralConstantAccelerationEngine::action() {
    Scene& s = *scene;
    if (!s.bodies.exists(centralBody))
        throw std::out_of_range("CentralConstantAccelerationEngine.centralBody=" + std::to_string(centralBody) + " is not the id of a body in O.bodies");
    const Vector3r center = s.bodies[centralBody]->state->pos();
    Vector3r sum = Vector3r::Zero();
    for (size_t id = 0; id < s.bodies.size(); ++id) {
        const auto& b = s.bodies[(Body::id_t)id];
        if (!b || (int)id == centralBody || (mask != 0 && !(b->mask & mask))) continue;
        const Vector3r toCenter = center - b->state->pos();
        const Real dist = toCenter.norm();
        if (dist == 0) continue;
        const Vector3r f = (accel * b->state->mass() / dist) * toCenter;
        s.forces.addForce((int)id, f);
        sum += f;
    }
    if (reciprocal) s.forces.addForce(centralBody, -sum);
}

} // namespace yade
