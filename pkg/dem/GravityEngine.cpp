#include <core/Scene.hpp>
#include <pkg/dem/GravityEngine.hpp>

namespace yade {

void GravityEngine::action() {
    Scene& s = *scene;
    const long n = (long)s.bodies.size();
    const int gravId = s.trackEnergy ? s.energy.term("gravWork", true) : -1;
#pragma omp parallel for schedule(static)
    for (long id = 0; id < n; ++id) {
        const auto& b = s.bodies[(Body::id_t)id];
        if (!b || !b->isDynamic() || (mask != 0 && !(b->mask & mask))) continue;
        s.forces.addForce((int)id, gravity * b->state->mass());
        if (gravId >= 0) s.energy.add(gravId, -b->state->mass() * gravity.dot(b->state->vel()) * s.dt); // move x_{n-1} -> x_n
    }
}

} // namespace yade
