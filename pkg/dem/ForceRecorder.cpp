#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/ForceRecorder.hpp>

namespace yade {

void ForceRecorder::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    Vector3r sum = Vector3r::Zero();
    for (int id : ids) sum += scene->forces.getForce(id);
    totalForce = sum;
    out() << scene->iter << " " << sum[0] << " " << sum[1] << " " << sum[2] << " " << sum.norm() << std::endl;
}

} // namespace yade
