// The state of a body of CpmMat: State with the damage and stress around the body, written by
// CpmStateUpdater (post-processing only; the contact law reads none of it) and the count of the
// cohesive contacts that broke, written by Law2_ScGeom_CpmPhys_Cpm.
#pragma once
#include <core/State.hpp>

namespace yade {

class CpmState : public State {
public:
    static constexpr const char* classDoc =
            "State of a body of the concrete particle model (CpmMat makes it: Material.newAssocState, which utils.sphere calls): State with "
            "the damage around the body (normDmg, damageTensor), the number of its contacts and of its cohesive contacts that broke, and "
            "its stress tensor. Written by CpmStateUpdater and Law2_ScGeom_CpmPhys_Cpm; used for post-processing only.";
    Real normDmg = 0, epsVolumetric = 0;
    int numBrokenCohesive = 0, numContacts = 0;
    Matrix3r stress = Matrix3r::Zero(), damageTensor = Matrix3r::Zero();
    CpmState() = default;
    CpmState(const CpmState& o) = default;
    template <class V> void visit(V& v) {
        State::visit(v);
        v.attr("normDmg", normDmg, "Average damage of the body's contacts, the broken ones (deleted) included: 1 - mean relative residual "
                                   "strength (CpmStateUpdater) [-]");
        v.attr("numBrokenCohesive", numBrokenCohesive, "Number of the body's contacts that broke: removed in tension, a cohesive one once "
                                                       "its damage passed Law2_ScGeom_CpmPhys_Cpm.omegaThreshold, one that was not cohesive at "
                                                       "once (counted too, as in the reference)");
        v.attr("numContacts", numContacts, "Number of the body's contacts (CpmStateUpdater)");
        v.attr("epsVolumetric", epsVolumetric, "Volumetric strain around the body (not computed, as in the reference) [-]");
        v.attr("stress", stress, "Stress tensor of the body (CpmStateUpdater): Σ over its contacts of (-Fn·n + Fs) ⊗ (c - x) over the "
                                 "volume 4/3·π·r³/0.62 (packing fraction 0.62) [Pa]");
        v.attr("damageTensor", damageTensor, "Damage tensor (CpmStateUpdater): the mean over the body's contacts of ω·n⊗n; its trace "
                                             "is the mean damage [-]");
    }
    YADE_INDEXABLE(CpmState)
};

} // namespace yade
