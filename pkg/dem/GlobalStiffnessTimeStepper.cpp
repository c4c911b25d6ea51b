#include <core/Scene.hpp>
#include <pkg/dem/CriticalTimeStep.hpp>
#include <pkg/dem/GlobalStiffnessTimeStepper.hpp>
#include <pkg/dem/Shop.hpp>

namespace yade {

void GlobalStiffnessTimeStepper::action() {
    const CriticalStep crit = criticalTimeStep(*scene);
    Real dt;
    if (std::isfinite(crit.dt)) dt = timestepSafetyCoefficient * crit.dt;
    else if (defaultDt > 0) dt = defaultDt;
    else dt = timestepSafetyCoefficient * Shop::PWaveTimeStep(*scene); // no contact yet
    dt = std::min(dt, maxDt);
    scene->setDt(dt);
    previousDt = dt;
}

} // namespace yade
