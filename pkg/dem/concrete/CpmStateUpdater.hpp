// Post-processing of the concrete particle model: the damage and the stress around each body of
// CpmState, from the CpmPhys contacts of the scene.
#pragma once
#include <core/PeriodicEngine.hpp>

namespace yade {

class CpmStateUpdater : public PeriodicEngine {
public:
    static constexpr const char* classDoc =
            "Updates the CpmState of the bodies from the CpmPhys of their cohesive contacts (run it periodically; two loops of its "
            "own, over the contacts then the bodies). With d = 1 - relResidualStrength of a contact, n its normal, L its refLength, Fn "
            "and Fs its forces, and N the body's cohesive contacts: normDmg = (Σ d + numBrokenCohesive)/(N + numBrokenCohesive); "
            "damageTensor = Σ d·(67.5·n⊗n - 13.5·I)/N (the reference's figures: trace 27·mean d); stress = Σ L/2·(Fn·n⊗n + "
            "(Fs⊗n + n⊗Fs)/2) / (4/3·π·r³/0.62); numContacts = N. avgRelResidual = Σ relResidualStrength of the cohesive contacts / "
            "(their number + the broken ones, Σ numBrokenCohesive/2); maxOmega is their largest omega.";
    Real avgRelResidual = NaN, maxOmega = NaN;
    CpmStateUpdater() { initRun = true; }
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("avgRelResidual", avgRelResidual, "Mean relative residual strength of the cohesive contacts at the last run, the broken "
                                                 "ones counting 0");
        v.attr("maxOmega", maxOmega, "Largest damage (omega) of the cohesive contacts at the last run (the reference leaves it NaN)");
    }
    void action() override;
};

} // namespace yade
