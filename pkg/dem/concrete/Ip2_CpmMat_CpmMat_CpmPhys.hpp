// CpmPhys of a new contact between two CpmMat bodies: the materials' parameters, copied when the two
// bodies share the material, averaged otherwise; kn and ks follow at the contact's first step in
// Law2_ScGeom_CpmPhys_Cpm, which knows the initial distance.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pkg/dem/concrete/CpmMat.hpp>
#include <pkg/dem/concrete/CpmPhys.hpp>

namespace yade {

class Ip2_CpmMat_CpmMat_CpmPhys : public IPhysFunctorOf<CpmMat, CpmMat, CpmPhys> {
public:
    static constexpr const char* classDoc =
            "Makes CpmPhys for two CpmMat bodies: the parameters are copied from the material when both bodies share it, else "
            "averaged (arithmetic means; neverDamage if either has it; damLaw of the first). E = the mean young (or the MatchMaker E), "
            "G = E·poisson (the mean poisson), undamagedCohesion = the mean sigmaT, tanFrictionAngle = tan of the mean frictionAngle. "
            "Contacts made before step cohesiveThresholdIter are cohesive. A material that can be damaged needs sigmaT, "
            "epsCrackOnset and relDuctility (else ValueError).";
    std::shared_ptr<MatchMaker> E;
    long long cohesiveThresholdIter = 10;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("E", E, "Normal modulus of the contact per pair of materials [Pa] (MatchMaker or number; None: the mean young)");
        v.attr("cohesiveThresholdIter", cohesiveThresholdIter, "Contacts made before this step are cohesive, later ones are not; 0: "
                                                               "never cohesive; negative: always cohesive");
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
