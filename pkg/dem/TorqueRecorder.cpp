#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/TorqueRecorder.hpp>
#include <stdexcept>

namespace yade {

void TorqueRecorder::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    if (!(rotationAxis.norm() > 0)) throw std::invalid_argument("TorqueRecorder.rotationAxis must not be zero");
    const Vector3r axis = rotationAxis.normalized();
    Real sum = 0;
    for (int id : ids) {
        const Vector3r arm = scene->bodies[id]->state->pos() - zeroPoint;
        sum += axis.dot(scene->forces.getTorque(id) + arm.cross(scene->forces.getForce(id)));
    }
    totalTorque = sum;
    out() << scene->iter << " " << sum << std::endl;
}

} // namespace yade
