// Physics of a Hertz-Mindlin contact: the constants of the non-linear stiffnesses, the damping
// ratios, and the elastic and viscous parts of the forces (Law2_ScGeom_MindlinPhys_Mindlin).
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class MindlinPhys : public FrictPhys {
public:
    static constexpr const char* classDoc =
            "Hertz-Mindlin contact physics: normal force kno·u^(3/2) (kno = 4/3·E*·sqrt(R*)), shear stiffness kso·u^(1/2) "
            "(kso = 8·G*·sqrt(R*)), viscous damping ratios betan, betas; kn and ks hold the current tangent stiffnesses.";
    // (what the law reads and writes every step first, in as few cache lines as can be: a contact's
    // record is read from memory at every step)
    Real kno = 0, kso = 0;
    Real betan = 0, betas = 0;
    bool isAdhesive = false, isSliding = false, isBroken = false;
    Vector3r normalViscous = Vector3r::Zero(), shearViscous = Vector3r::Zero(), shearElastic = Vector3r::Zero();
    Vector3r usElastic = Vector3r::Zero(), usTotal = Vector3r::Zero();
    Real adhesionForce = 0;
    // (only with includeMoment, or never written by the law)
    Real kr = 0, ktw = 0, maxBendPl = 0;
    Vector3r momentBend = Vector3r::Zero(), momentTwist = Vector3r::Zero();
    Real initD = 0, radius = NaN;
    Vector3r prevU = Vector3r::Zero();
    Vector2r Fs = Vector2r::Zero();
    template <class V> void visit(V& v) {
        FrictPhys::visit(v);
        v.attr("kno", kno, "Constant of the normal stiffness: Fn = kno·u^(3/2), kno = 4/3·E*·sqrt(R*) [N/m^1.5]");
        v.attr("kso", kso, "Constant of the shear stiffness: ks = kso·u^(1/2), kso = 8·G*·sqrt(R*) [N/m^1.5]");
        v.attr("kr", kr, "Rolling stiffness [N·m/rad] (Law2_ScGeom_MindlinPhys_Mindlin.includeMoment)");
        v.attr("ktw", ktw, "Twisting stiffness [N·m/rad] (Law2_ScGeom_MindlinPhys_Mindlin.includeMoment)");
        v.attr("maxBendPl", maxBendPl, "Coefficient of the plastic bending moment: |momentBend| <= maxBendPl·R·|Fn| (0: no limit)");
        v.attr("betan", betan, "Normal damping ratio c_n/c_n,crit");
        v.attr("betas", betas, "Shear damping ratio c_s/c_s,crit");
        v.attr("adhesionForce", adhesionForce, "DMT pull-off force 4·π·R*·gamma [N] (Law2_ScGeom_MindlinPhys_Mindlin.includeAdhesion)");
        v.attr("initD", initD, "Overlap when the contact was made [m]");
        v.attr("radius", radius, "Contact radius (kept for compatibility; not computed)");
        v.attr("isAdhesive", isAdhesive, "Whether the net normal force is attractive (adhesion)");
        v.attr("isSliding", isSliding, "Whether the shear force is at its Coulomb limit");
        v.attr("isBroken", isBroken, "Kept for compatibility with other laws; always False here");
        v.attr("normalViscous", normalViscous, "Viscous part of the normal force: c_n times the normal relative velocity [N]");
        v.attr("shearViscous", shearViscous, "Viscous part of the shear force: c_s times the shear relative velocity [N]");
        v.attr("shearElastic", shearElastic, "Elastic part of the shear force [N]");
        v.attr("usElastic", usElastic, "Elastic part of the shear displacement [m]");
        v.attr("usTotal", usTotal, "Total shear displacement [m]");
        v.attr("prevU", prevU, "Kept for compatibility; not used");
        v.attr("momentBend", momentBend, "Bending (rolling) moment [N·m]");
        v.attr("momentTwist", momentTwist, "Twisting moment [N·m]");
        v.attr("Fs", Fs, "Kept for compatibility; not used");
    }
    YADE_INDEXABLE(MindlinPhys)
};

} // namespace yade
