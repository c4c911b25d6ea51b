#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/DomainLimiter.hpp>
#include <vector>

namespace yade {

void DomainLimiter::action() {
    std::vector<Body::id_t> out;
    for (const auto& b : scene->bodies) {
        if (!b || (mask != -1 && !(b->mask & mask))) continue;
        const auto* sphere = dynamic_cast<const Sphere*>(b->shape.get());
        if (!sphere) continue;
        const Vector3r& p = b->state->pos();
        if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) out.push_back(b->id);
    }
    for (const Body::id_t id : out) {
        const Body& b = *scene->bodies[id];
        const Real r = static_cast<const Sphere&>(*b.shape).radius;
        mDeleted += b.state->mass();
        vDeleted += 4. / 3. * Mathr_PI * r * r * r;
        ++nDeleted;
        scene->eraseBody(id);
    }
}

} // namespace yade
