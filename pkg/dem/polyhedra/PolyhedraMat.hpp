// Material of polyhedra: FrictMat with the reference's attributes of breakage (kept; breakage is not computed here).
#pragma once
#include <pkg/common/FrictMat.hpp>

namespace yade {

class PolyhedraMat : public FrictMat {
public:
    static constexpr const char* classDoc = "Elastic material with Coulomb friction, for Polyhedra: young and poisson give the volumetric stiffnesses of Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys. The breakage attributes are kept for scripts; breakage itself is not computed in this engine.";
    bool IsSplitable = false;
    Real strength = 100;
    Real strengthTau = -1;
    Real sigmaCZ = -1;
    Real sigmaCD = -1;
    int Wei_m = -1;
    Real Wei_S0 = -1;
    Real Wei_V0 = 1e-9;
    Real Wei_P = -1;
    template <class V> void visit(V& v) {
        FrictMat::visit(v);
        v.attr("IsSplitable", IsSplitable, "To be split ... or not (breakage is not computed in this engine)");
        v.attr("strength", strength, "Stress at which a polyhedron of volume 4/3·π mm³ breaks [Pa] (not used here)");
        v.attr("strengthTau", strengthTau, "Tangential stress at which a polyhedron of volume 4/3·π mm³ breaks [Pa] (not used here)");
        v.attr("sigmaCZ", sigmaCZ, "Mohr-Coulomb failure criterion: maximal tensile strength [Pa], negative: disabled (not used here)");
        v.attr("sigmaCD", sigmaCD, "Mohr-Coulomb failure criterion: maximal compressive strength [Pa], negative: disabled (not used here)");
        v.attr("Wei_m", Wei_m, "Weibull formulation: Weibull modulus m, negative: disabled (not used here)");
        v.attr("Wei_S0", Wei_S0, "Weibull formulation: sigma0 [Pa], negative: disabled (not used here)");
        v.attr("Wei_V0", Wei_V0, "Weibull formulation: representative volume V0 [m³] (not used here)");
        v.attr("Wei_P", Wei_P, "Weibull formulation: failure probability P (not used here)");
    }
    YADE_INDEXABLE(PolyhedraMat)
};

} // namespace yade
