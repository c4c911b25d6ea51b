#include <pkg/common/ElastMat.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/Shop.hpp>
#include <stdexcept>

namespace yade {

Real Shop::PWaveTimeStep(const Scene& scene) {
    Real dt = Inf;
    for (const auto& b : scene.bodies) {
        if (!b || !b->shape || !b->material) continue;
        const auto* s = dynamic_cast<const Sphere*>(b->shape.get());
        const auto* m = dynamic_cast<const ElastMat*>(b->material.get());
        if (!s || !m) continue;
        // The density seen by the dynamics is the body's mass over its volume.
        const Real volume = 4.0 / 3.0 * Mathr_PI * std::pow(s->radius, 3);
        const Real density = b->state->mass > 0 ? b->state->mass / volume : m->density;
        dt = std::min(dt, s->radius / std::sqrt(m->young / density));
    }
    if (!std::isfinite(dt)) throw std::runtime_error("PWaveTimeStep: no sphere with an elastic material (ElastMat) in the scene");
    return dt;
}

} // namespace yade
