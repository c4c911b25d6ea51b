#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/TorqueEngine.hpp>

namespace yade {

void TorqueEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    for (int id : ids) scene->forces.addTorque(id, moment);
}

} // namespace yade
