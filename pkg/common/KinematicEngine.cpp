#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <stdexcept>

namespace yade {

void KinematicEngine::checkIds(const Scene& s, const std::vector<int>& bodyIds, const std::string& who) {
    for (int id : bodyIds)
        if (!s.bodies.exists(id)) throw std::out_of_range(who + ".ids contains " + std::to_string(id) + ", which is not the id of a body in O.bodies");
}

void KinematicEngine::resetVelocities(Scene& s, const std::vector<int>& bodyIds) {
    for (int id : bodyIds) {
        State& st = *s.bodies[id]->state;
        st.vel() = Vector3r::Zero();
        st.angVel() = Vector3r::Zero();
    }
}

void KinematicEngine::action() {
    checkIds(*scene, ids, getClassName());
    resetVelocities(*scene, ids);
    apply(ids);
}

} // namespace yade
