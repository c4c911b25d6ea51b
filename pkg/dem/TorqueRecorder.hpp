// Writes the total torque of a set of bodies about an axis to a file, periodically.
#pragma once
#include <pkg/common/Recorder.hpp>
#include <vector>

namespace yade {

class TorqueRecorder : public Recorder {
public:
    static constexpr const char* classDoc =
            "Writes the torque about the axis rotationAxis through zeroPoint of the forces and torques on the bodies in ids "
            "(sum of torque + (pos - zeroPoint) x force, projected on the axis) to file, one line per run: iteration and the "
            "torque (e.g. the torque on a ball mill).";
    std::vector<int> ids;
    Vector3r rotationAxis = Vector3r::UnitX(), zeroPoint = Vector3r::Zero();
    Real totalTorque = 0;
    template <class V> void visit(V& v) {
        Recorder::visit(v);
        v.attr("ids", ids, "Ids of the bodies whose torques are summed");
        v.attr("rotationAxis", rotationAxis, "Axis the torque is taken about (its direction)", Attr::finite);
        v.attr("zeroPoint", zeroPoint, "A point of the axis [m]", Attr::finite);
        v.attr("totalTorque", totalTorque, "The torque at the last run [N·m]", Attr::readonly);
    }
    TorqueRecorder() { initRun = true; }
    void action() override;
};

} // namespace yade
