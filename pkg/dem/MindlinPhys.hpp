// Physics of a Hertz-Mindlin contact: the constants of the non-linear stiffnesses, the damping
// ratios, and the elastic and viscous parts of the forces (Law2_ScGeom_MindlinPhys_Mindlin).
#pragma once
#include <lib/base/OutOfLine.hpp>
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class MindlinPhys : public FrictPhys {
public:
    static constexpr const char* classDoc =
            "Hertz-Mindlin contact physics: normal force kno·u^(3/2) (kno = 4/3·E*·sqrt(R*)), shear stiffness kso·u^(1/2) "
            "(kso = 8·G*·sqrt(R*)), viscous damping ratios betan, betas; kn and ks hold the current tangent stiffnesses.";
    // (what the law reads and writes every step, and nothing else: a contact's record is read from
    // memory at every step; with these, a record of ScGeom and MindlinPhys is 448 bytes, 7 cache lines
    // exactly, instead of 576, and the DEM8 drum runs about 3 % faster: doc/performance.md)
    Real kno = 0, kso = 0;
    Real betan = 0, betas = 0;
    bool isAdhesive = false, isSliding = false, isBroken = false;
    Vector3r normalViscous = Vector3r::Zero(), shearViscous = Vector3r::Zero(), shearElastic = Vector3r::Zero();
    Vector3r usElastic = Vector3r::Zero(), usTotal = Vector3r::Zero();
    Real initD = 0;
    // The attributes the law reads only with includeAdhesion or includeMoment, or never: out of the
    // record (made when one is written: by Ip2 with gamma, krot, ktwist or eta, by the law with
    // includeMoment, or from Python).
    struct Extra {
        Real adhesionForce = 0;
        Real kr = 0, ktw = 0, maxBendPl = 0;
        Vector3r momentBend = Vector3r::Zero(), momentTwist = Vector3r::Zero();
        Real radius = NaN;
        Vector3r prevU = Vector3r::Zero();
        Vector2r Fs = Vector2r::Zero();
    };
    OutOfLine<Extra> extra;
    using SideRecord = Extra; // (AttrCollector: the attributes declared on members of extra)
    static constexpr bool hasSideRecord = true;
    const Extra* sideRecord() { return &extra.edit(); }
    void* sideAddress(std::ptrdiff_t offset) { return reinterpret_cast<char*>(&extra.edit()) + offset; }
    const void* sidePeek(std::ptrdiff_t offset) const { return reinterpret_cast<const char*>(&extra.get()) + offset; }
    template <class V> void visit(V& v) {
        FrictPhys::visit(v);
        v.attr("kno", kno, "Constant of the normal stiffness: Fn = kno·u^(3/2), kno = 4/3·E*·sqrt(R*) [N/m^1.5]");
        v.attr("kso", kso, "Constant of the shear stiffness: ks = kso·u^(1/2), kso = 8·G*·sqrt(R*) [N/m^1.5]");
        v.attr("kr", extra.edit().kr, "Rolling stiffness [N·m/rad] (Law2_ScGeom_MindlinPhys_Mindlin.includeMoment)");
        v.attr("ktw", extra.edit().ktw, "Twisting stiffness [N·m/rad] (Law2_ScGeom_MindlinPhys_Mindlin.includeMoment)");
        v.attr("maxBendPl", extra.edit().maxBendPl, "Limit of the bending moment per unit normal force: |momentBend| <= maxBendPl·|Fn| (Ip2 eta times the mean radius; 0: no limit) [m]");
        v.attr("betan", betan, "Normal damping ratio c_n/c_n,crit");
        v.attr("betas", betas, "Shear damping ratio c_s/c_s,crit");
        v.attr("adhesionForce", extra.edit().adhesionForce, "DMT pull-off force 4·π·R*·gamma [N] (Law2_ScGeom_MindlinPhys_Mindlin.includeAdhesion)");
        v.attr("initD", initD, "Overlap when the contact was made [m]");
        v.attr("radius", extra.edit().radius, "Contact radius (kept for compatibility; not computed)");
        v.attr("isAdhesive", isAdhesive, "Whether the net normal force is attractive (adhesion)");
        v.attr("isSliding", isSliding, "Whether the shear force is at its Coulomb limit");
        v.attr("isBroken", isBroken, "Kept for compatibility with other laws; always False here");
        v.attr("normalViscous", normalViscous, "Viscous part of the normal force: c_n times the normal relative velocity [N]");
        v.attr("shearViscous", shearViscous, "Viscous part of the shear force: c_s times the shear relative velocity [N]");
        v.attr("shearElastic", shearElastic, "Elastic part of the shear force [N]");
        v.attr("usElastic", usElastic, "Elastic part of the shear displacement [m]");
        v.attr("usTotal", usTotal, "Total shear displacement [m]");
        v.attr("prevU", extra.edit().prevU, "Kept for compatibility; not used");
        v.attr("momentBend", extra.edit().momentBend, "Bending (rolling) moment [N·m]");
        v.attr("momentTwist", extra.edit().momentTwist, "Twisting moment [N·m]");
        v.attr("Fs", extra.edit().Fs, "Kept for compatibility; not used");
    }
    YADE_INDEXABLE(MindlinPhys)
};

} // namespace yade
