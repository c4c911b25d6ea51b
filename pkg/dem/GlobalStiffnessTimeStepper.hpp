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
    template <class V> void visit(V& v) {
        TimeStepper::visit(v);
        v.attr("timestepSafetyCoefficient", timestepSafetyCoefficient, "O.dt = this × the critical step", Attr::positive);
        v.attr("defaultDt", defaultDt, "Step used while there is no contact (negative: PWaveTimeStep() times the safety coefficient)");
        v.attr("maxDt", maxDt, "Upper limit of O.dt", Attr::positive);
        v.attr("previousDt", previousDt, "O.dt set at the previous update", Attr::readonly);
    }
    void action() override;
};

} // namespace yade
