// Adds a constant torque to the bodies in ids every step.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class TorqueEngine : public PartialEngine {
public:
    static constexpr const char* classDoc = "Adds the constant torque `moment` to each body in ids every step (angular acceleration moment/inertia on a free sphere).";
    Vector3r moment = Vector3r::Zero();
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("moment", moment, "Torque added to each body [N·m]", Attr::finite);
    }
    void action() override;
};

} // namespace yade
