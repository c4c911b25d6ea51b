// Rotation around the axis through zeroPoint combined with a translation along that axis.
#pragma once
#include <pkg/common/RotationEngine.hpp>

namespace yade {

class HelixEngine : public RotationEngine {
public:
    static constexpr const char* classDoc = "Kinematic engine moving the bodies in ids along a helix: rotation around the axis through zeroPoint (rotateAroundZero is always on) plus the velocity linearVelocity·rotationAxis.";
    Real linearVelocity = 0;
    Real angleTurned = 0;
    template <class V> void visit(V& v) {
        RotationEngine::visit(v);
        v.attr("linearVelocity", linearVelocity, "Velocity along the axis [m/s]", Attr::finite);
        v.attr("angleTurned", angleTurned, "Angle turned so far (updated every step) [rad]");
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
