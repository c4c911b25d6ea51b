#include <core/Scene.hpp>
#include <pkg/dem/AxialGravityEngine.hpp>
#include <stdexcept>

namespace yade {

void AxialGravityEngine::action() {
    Scene& s = *scene;
    if (!(axisDirection.squaredNorm() > 0)) throw std::invalid_argument("AxialGravityEngine.axisDirection must not be zero");
    const Vector3r axis = axisDirection.normalized();
    for (size_t id = 0; id < s.bodies.size(); ++id) {
        const auto& b = s.bodies[(Body::id_t)id];
        if (!b || (mask != 0 && !(b->mask & mask))) continue;
        const Vector3r r = b->state->pos() - axisPoint;
        const Vector3r radial = r - axis * axis.dot(r); // from the axis to the body
        const Real dist = radial.norm();
        if (dist == 0) continue;
        s.forces.addForce((int)id, (-acceleration * b->state->mass() / dist) * radial);
    }
}

} // namespace yade
