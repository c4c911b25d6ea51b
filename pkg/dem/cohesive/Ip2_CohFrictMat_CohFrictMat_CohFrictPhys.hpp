// CohFrictPhys of a contact between two CohFrictMat bodies: the stiffnesses of
// Ip2_FrictMat_FrictMat_FrictPhys, rotational stiffnesses and strengths, and, when the contact is
// made cohesive, the bond's strengths.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pkg/dem/cohesive/CohFrictMat.hpp>
#include <pkg/dem/cohesive/CohFrictPhys.hpp>

namespace yade {

class Ip2_CohFrictMat_CohFrictMat_CohFrictPhys : public IPhysFunctorOf<CohFrictMat, CohFrictMat, CohFrictPhys> {
public:
    static constexpr const char* classDoc =
            "Makes CohFrictPhys for two CohFrictMat (Law2_ScGeom6D_CohFrictPhys_CohesionMoment). kn, ks and tan φ as "
            "Ip2_FrictMat_FrictMat_FrictPhys; kr = ks·αr·R1·R2 and ktw = ks·αtw·R1·R2, α the harmonic mean of the materials' alphaKr, "
            "alphaKtw; maxRollPl = min(etaRoll1·R1, etaRoll2·R2), maxTwistPl likewise; fragile if either material is, momentRotationLaw "
            "if both are. A contact is made cohesive (both materials isCohesive) when it starts with setCohesionOnNewContacts or "
            "setCohesionNow, or, for existing contacts, with setCohesionNow or CohFrictPhys.initCohesion: then normalAdhesion = "
            "Cn·min(R1,R2)², shearAdhesion = Cs·min(R1,R2)², C the smaller of the materials' normalCohesion, shearCohesion (or the "
            "MatchMakers' values), and the contact's rotations start from the bodies' orientations at that step.";
    bool setCohesionNow = false, setCohesionOnNewContacts = false;
    std::shared_ptr<MatchMaker> normalCohesion, shearCohesion, frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("setCohesionNow", setCohesionNow, "Make all existing contacts (and those starting in this step) cohesive at the next step; "
                                                 "the flag turns false by itself one step later");
        v.attr("setCohesionOnNewContacts", setCohesionOnNewContacts, "Make every new contact cohesive (else only setCohesionNow and "
                                                                     "CohFrictPhys.initCohesion make cohesive contacts)");
        v.attr("normalCohesion", normalCohesion, "Tensile strength per pair of materials [Pa] (MatchMaker or number, called without the "
                                                 "materials' values: only matches and algo='val'; default: the smaller normalCohesion)");
        v.attr("shearCohesion", shearCohesion, "Cohesive shear strength per pair of materials [Pa] (MatchMaker or number, as normalCohesion; "
                                               "default: the smaller shearCohesion)");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker or number; default: the smaller one)");
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
    // Before each step: setCohesionNow and CohFrictPhys.initCohesion on existing contacts.
    void prepare() override;

private:
    long long cohesionIter = -1; // the step setCohesionNow was applied (it turns false at the next one)
    void makeCohesive(CohFrictPhys& phys, const CohFrictMat& a, const CohFrictMat& b, Real r1, Real r2) const;
    void initExistingContacts(bool all);
    static void setBeamStiffness(CohFrictPhys& phys, const CohFrictMat& a, const class GridNodeGeom6D& g);
};

} // namespace yade
