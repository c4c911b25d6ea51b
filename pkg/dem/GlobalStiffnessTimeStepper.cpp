#include <core/Scene.hpp>
#include <pkg/dem/CriticalTimeStep.hpp>
#include <pkg/dem/GlobalStiffnessTimeStepper.hpp>
#include <pkg/dem/Shop.hpp>

namespace yade {

// As the reference does (checked on its output, doc/compatibility.md): the first update sets defaultDt
// from the P-wave step where it is negative; a step found from the contacts is capped by maxDt and
// grows by at most 5 % per update; without contacts O.dt is defaultDt until contacts first gave a
// step (previousDt is then finite; it is saved with the scene), and is left as it is after that (the last
// contacts' step, or what the script set).
void GlobalStiffnessTimeStepper::action() {
    if (densityScaling) throw std::invalid_argument("GlobalStiffnessTimeStepper.densityScaling is not supported here (set it to False)");
    if (defaultDt < 0) {
        bool elastic = false; // (a sphere with an ElastMat: else there is no P-wave step yet, and nothing to move either)
        try {
            defaultDt = timestepSafetyCoefficient * Shop::PWaveTimeStep(*scene);
            elastic = true;
        } catch (const std::runtime_error&) {
        }
        if (!elastic) defaultDt = -1;
    }
    const CriticalStep crit = criticalTimeStep(*scene);
    if (std::isfinite(crit.dt)) {
        const Real dt = std::min({timestepSafetyCoefficient * crit.dt, maxDt, 1.05 * previousDt});
        scene->setDt(dt);
        previousDt = dt;
    } else if (!std::isfinite(previousDt) && defaultDt > 0)
        scene->setDt(defaultDt);
}

} // namespace yade
