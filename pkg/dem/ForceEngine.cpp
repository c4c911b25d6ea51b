#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/ForceEngine.hpp>

namespace yade {

void ForceEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    for (int id : ids) scene->forces.addForce(id, force);
}

} // namespace yade
