#include <core/Scene.hpp>
#include <pkg/common/CombinedKinematicEngine.hpp>

namespace yade {

void CombinedKinematicEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    KinematicEngine::resetVelocities(*scene, ids);
    for (const auto& e : comb) {
        if (!e || e->dead) continue;
        e->scene = scene;
        e->apply(ids);
    }
}

} // namespace yade
