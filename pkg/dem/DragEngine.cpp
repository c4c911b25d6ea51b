#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/DragEngine.hpp>

namespace yade {

void DragEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    for (int id : ids) {
        const Body& b = *scene->bodies[id];
        const auto* sphere = dynamic_cast<const Sphere*>(b.shape.get());
        const Vector3r& v = b.state->vel();
        const Real speed2 = v.squaredNorm();
        if (!sphere || speed2 == 0) continue;
        const Real area = Mathr_PI * sphere->radius * sphere->radius;
        scene->forces.addForce(id, -v.normalized() * (0.5 * Rho * speed2 * Cd * area));
    }
}

} // namespace yade
