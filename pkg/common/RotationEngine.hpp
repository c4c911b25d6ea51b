// Prescribed rotation: angVel += angularVelocity·rotationAxis; with rotateAroundZero the bodies
// also turn around the axis through zeroPoint (their velocity is the chord of that turn in one step).
#pragma once
#include <pkg/common/KinematicEngine.hpp>

namespace yade {

class RotationEngine : public KinematicEngine {
public:
    static constexpr const char* classDoc = "Kinematic engine rotating the bodies in ids: angVel = angularVelocity·rotationAxis; with rotateAroundZero they also turn around the axis through zeroPoint (velocity (R(ω·dt)·r - r)/dt, r = pos - zeroPoint, so that positions follow the circle exactly).";
    Real angularVelocity = 0;
    Vector3r rotationAxis = Vector3r::UnitX();
    bool rotateAroundZero = false;
    Vector3r zeroPoint = Vector3r::Zero();
    template <class V> void visit(V& v) {
        KinematicEngine::visit(v);
        v.attr("angularVelocity", angularVelocity, "Angular velocity [rad/s]", Attr::finite);
        v.attr("rotationAxis", rotationAxis, "Axis of rotation (normalized when set)", Attr::finite);
        v.attr("rotateAroundZero", rotateAroundZero, "If True, the bodies also turn around the axis through zeroPoint, not only around their centers");
        v.attr("zeroPoint", zeroPoint, "A point of the axis the bodies turn around when rotateAroundZero is True [m]", Attr::finite);
    }
    void postLoad() override;
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
