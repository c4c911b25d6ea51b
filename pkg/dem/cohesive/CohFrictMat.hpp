// Material of the cohesive-frictional contact with moments (Law2_ScGeom6D_CohFrictPhys_CohesionMoment):
// a FrictMat with tensile and shear strengths and rolling/twisting stiffnesses and strengths.
#pragma once
#include <pkg/common/FrictMat.hpp>

namespace yade {

class CohFrictMat : public FrictMat {
public:
    static constexpr const char* classDoc =
            "Material of the cohesive-frictional contacts (Ip2_CohFrictMat_CohFrictMat_CohFrictPhys, "
            "Law2_ScGeom6D_CohFrictPhys_CohesionMoment): FrictMat with a tensile and a shear strength (normalCohesion, shearCohesion, "
            "as pressures), rolling and twisting stiffnesses relative to the shear stiffness (alphaKr, alphaKtw) and strengths (etaRoll, "
            "etaTwist).";
    bool isCohesive = true, fragile = true, momentRotationLaw = false;
    Real alphaKr = 2.0, alphaKtw = 2.0, etaRoll = -1.0, etaTwist = -1.0, normalCohesion = -1, shearCohesion = -1;
    template <class V> void visit(V& v) {
        FrictMat::visit(v);
        v.attr("isCohesive", isCohesive, "Whether bodies of this material may make cohesive contacts (both must; see "
                                         "Ip2_CohFrictMat_CohFrictMat_CohFrictPhys.setCohesionNow and setCohesionOnNewContacts)");
        v.attr("alphaKr", alphaKr, "Rolling stiffness relative to the shear stiffness: kr = ks·alphaKr·R1·R2 (two materials: their harmonic mean) [-]");
        v.attr("alphaKtw", alphaKtw, "Twisting stiffness relative to the shear stiffness: ktw = ks·alphaKtw·R1·R2 (two materials: their harmonic "
                                     "mean) [-]");
        v.attr("etaRoll", etaRoll, "Rolling strength relative to the radius: the rolling moment is capped at etaRoll·R·Fn (the smaller of "
                                   "the two bodies' etaRoll·R); negative: elastic [-]");
        v.attr("etaTwist", etaTwist, "Twisting strength relative to the radius: the twisting moment is capped at etaTwist·R·Fn (the smaller "
                                     "of the two bodies' etaTwist·R); negative: elastic [-]");
        v.attr("normalCohesion", normalCohesion, "Tensile strength, a pressure: the normal adhesion of a contact is normalCohesion·min(R1,R2)² "
                                                 "(the smaller of the two materials'); negative: no tensile strength [Pa]");
        v.attr("shearCohesion", shearCohesion, "Shear strength, a pressure: the shear adhesion of a contact is shearCohesion·min(R1,R2)² "
                                               "(the smaller of the two materials'); negative: no shear strength [Pa]");
        v.attr("fragile", fragile, "Whether a cohesive bond breaks when its strength is exceeded (contact fragile if either material is); "
                                   "false: perfectly plastic");
        v.attr("momentRotationLaw", momentRotationLaw, "Whether contacts carry rolling and twisting moments (only if both materials say so; "
                                                       "see Law2_ScGeom6D_CohFrictPhys_CohesionMoment.always_use_moment_law)");
    }
    YADE_INDEXABLE(CohFrictMat)
};

} // namespace yade
