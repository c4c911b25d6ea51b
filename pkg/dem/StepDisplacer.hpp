// Moves bodies by a fixed displacement and rotation at every step (contact-law tests, prescribed motions).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class StepDisplacer : public PartialEngine {
public:
    static constexpr const char* classDoc =
            "Moves the bodies of ids by mov and turns them by rot at every step; with setVelocities, sets instead their "
            "velocity to mov/O.dt and their angular velocity to the rotation of rot over O.dt (NewtonIntegrator then moves them).";
    Vector3r mov = Vector3r::Zero();
    Quaternionr rot = Quaternionr::Identity();
    bool setVelocities = false;
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("mov", mov, "Displacement added to the position at every step [m]", Attr::finite);
        v.attr("rot", rot, "Rotation applied to the orientation at every step");
        v.attr("setVelocities", setVelocities, "Set velocities (mov/dt, rot/dt) instead of moving the bodies");
    }
    void action() override;
};

} // namespace yade
