#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/LinearDragEngine.hpp>

namespace yade {

void LinearDragEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    for (int id : ids) {
        const Body& b = *scene->bodies[id];
        if (const auto* sphere = dynamic_cast<const Sphere*>(b.shape.get())) scene->forces.addForce(id, -(6 * Mathr_PI * nu * sphere->radius) * b.state->vel());
    }
}

} // namespace yade
