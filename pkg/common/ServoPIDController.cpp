#include <core/Scene.hpp>
#include <pkg/common/ServoPIDController.hpp>

namespace yade {

void ServoPIDController::apply(const std::vector<int>& bodyIds) {
    Scene& s = *scene;
    if (iterPrevStart < 0 || s.iter - iterPrevStart >= iterPeriod) {
        if (axis.squaredNorm() > 0) axis.normalize();
        translationAxis = axis;
        Vector3r sum = Vector3r::Zero();
        for (int id : bodyIds)
            if ((size_t)id < s.forces.size()) sum += s.forces.getForce(id);
        current = axis * axis.dot(sum);
        errorCur = current.norm() - target;
        iTerm += kI * errorCur;
        curVel = kP * errorCur + iTerm + kD * (errorCur - errorPrev);
        if (std::abs(curVel) > maxVelocity) curVel = std::copysign(maxVelocity, curVel);
        errorPrev = errorCur;
        iterPrevStart = s.iter;
    }
    velocity = curVel;
    TranslationEngine::apply(bodyIds);
}

} // namespace yade
