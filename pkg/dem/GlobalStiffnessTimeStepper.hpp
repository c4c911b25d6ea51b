// Sets O.dt from the stiffness of the current contacts (3.5.5, eq. 3.5.18-3.5.20), so that a
// stiff scene runs at the largest stable step.
#pragma once
#include <core/TimeStepper.hpp>

namespace yade {

class GlobalStiffnessTimeStepper : public TimeStepper {
public:
    static constexpr const char* classDoc = "Engine setting O.dt from the stiffness of the current contacts (3.5.5): Δt = timestepSafetyCoefficient · min sqrt(2m/K) (3.5.18-3.5.20).";
    Real timestepSafetyCoefficient = 0.8;
    Real defaultDt = -1;
    Real maxDt = Inf;
    Real previousDt = Inf;
    bool parallelMode = false, densityScaling = false, viscEl = false;
    Real targetDt = 1;
    template <class V> void visit(V& v) {
        TimeStepper::visit(v);
        v.attr("timestepSafetyCoefficient", timestepSafetyCoefficient, "O.dt = this × the critical step", Attr::positive);
        v.attr("defaultDt", defaultDt, "Step used while no contact ever gave one; negative: set at the first update to PWaveTimeStep() times the safety coefficient");
        v.attr("maxDt", maxDt, "Upper limit of a step found from the contacts", Attr::positive);
        v.attr("previousDt", previousDt, "The last step found from the contacts (a new one is at most 1.05 times it; inf: none yet)", Attr::readonly);
        v.attr("parallelMode", parallelMode, "Accepted for scripts written for Yade; the critical step is found in one pass here either way");
        v.attr("densityScaling", densityScaling, "Scale the densities to reach targetDt: not supported here (True is refused at the first update)");
        v.attr("targetDt", targetDt, "The step densityScaling would aim at", Attr::positive);
        v.attr("viscEl", viscEl, "Accepted for scripts written for Yade: there is no ViscElPhys here, so no contact it would count");
    }
    void action() override;
};

} // namespace yade
