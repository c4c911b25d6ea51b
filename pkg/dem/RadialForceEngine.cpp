#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/RadialForceEngine.hpp>
#include <stdexcept>

namespace yade {

void RadialForceEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    if (!(axisDir.norm() > 0)) throw std::invalid_argument("RadialForceEngine.axisDir must not be zero");
    const Vector3r axis = axisDir.normalized();
    for (int id : ids) {
        const Vector3r d = scene->bodies[id]->state->pos() - axisPt;
        const Vector3r radial = d - axis.dot(d) * axis;
        if (radial.norm() > 0) scene->forces.addForce(id, radial.normalized() * fNorm);
    }
}

} // namespace yade
