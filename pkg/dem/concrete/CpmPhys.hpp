// Physics of a contact of the concrete particle model: the constants that Ip2_CpmMat_CpmMat_CpmPhys
// and the first step of Law2_ScGeom_CpmPhys_Cpm give it, and the strains, stresses and damage that the
// law updates.
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class CpmPhys : public NormShearPhys {
public:
    static constexpr const char* classDoc =
            "Physics of a contact of the concrete particle model (see CpmMat), made by Ip2_CpmMat_CpmMat_CpmPhys and evolved by "
            "Law2_ScGeom_CpmPhys_Cpm: the moduli E and G, the cross-section and the reference length (kn = E·crossSection/refLength, "
            "ks = G·crossSection/refLength, set at the contact's first step), the damage parameters, and the strains (epsN, epsT), "
            "stresses (sigmaN, sigmaT) and damage (kappaD, omega) of the last step.";
    // constants
    Real E = NaN, G = NaN, tanFrictionAngle = NaN, undamagedCohesion = NaN, crossSection = NaN, refLength = NaN, refPD = NaN;
    Real epsCrackOnset = NaN, relDuctility = NaN, epsFracture = NaN, equivStrainShearContrib = NaN;
    Real dmgTau = -1, dmgRateExp = 0, dmgStrain = 0, dmgOverstress = 0, plTau = -1, plRateExp = 0, isoPrestress = 0;
    bool neverDamage = false, isCohesive = false;
    int damLaw = 1;
    // state of the last step
    Real omega = 0, kappaD = 0, epsN = 0, sigmaN = 0, Fn = 0, epsNPl = 0, relResidualStrength = 0;
    Vector3r epsT = Vector3r::Zero(), sigmaT = Vector3r::Zero(), Fs = Vector3r::Zero(), epsTPl = Vector3r::Zero();
    template <class V> void visit(V& v) {
        NormShearPhys::visit(v);
        v.attr("E", E, "Normal modulus of the contact (stiffness / crossSection · refLength) [Pa]");
        v.attr("G", G, "Shear modulus of the contact [Pa]");
        v.attr("tanFrictionAngle", tanFrictionAngle, "Tangent of the internal friction angle [-]");
        v.attr("undamagedCohesion", undamagedCohesion, "Cohesion of the virgin material (sigmaT of the materials) [Pa]");
        v.attr("crossSection", crossSection, "Equivalent cross-section of the contact, π·min(r1, r2)² (3.3.2) [m²]");
        v.attr("refLength", refLength, "Initial length of the contact: the distance of the centers (a sphere's radius against a facet "
                                       "or a wall) [m]");
        v.attr("refPD", refPD, "Initial penetration depth of the contact [m]");
        v.attr("epsCrackOnset", epsCrackOnset, "Normal strain where damage starts [-]");
        v.attr("relDuctility", relDuctility, "Relative ductility of the bond in the normal direction [-]");
        v.attr("epsFracture", epsFracture, "Strain of the damage law, relDuctility·epsCrackOnset [-]");
        v.attr("equivStrainShearContrib", equivStrainShearContrib, "Coefficient of the shear contribution to the equivalent strain "
                                                                   "(not used)");
        v.attr("dmgTau", dmgTau, "Characteristic time of damage (not used: no rate dependence) [s]");
        v.attr("dmgRateExp", dmgRateExp, "Exponent of the rate-dependent damage evolution (not used)");
        v.attr("dmgStrain", dmgStrain, "Damage strain (not used)");
        v.attr("dmgOverstress", dmgOverstress, "Damage viscous overstress (not used)");
        v.attr("plTau", plTau, "Characteristic time of the visco-plasticity (not used) [s]");
        v.attr("plRateExp", plRateExp, "Exponent of the rate-dependent visco-plasticity (not used)");
        v.attr("isoPrestress", isoPrestress, "Prestress of this contact (an isotropic stress of the specimen) [Pa]");
        v.attr("neverDamage", neverDamage, "If true, the damage stays 0");
        v.attr("isCohesive", isCohesive, "Whether the contact is cohesive; one that is not carries no tension (damage 1) and is "
                                         "removed as soon as it is stretched");
        v.attr("damLaw", damLaw, "Damage law in tension: 0 linear softening, 1 exponential (default)");
        v.attr("omega", omega, "Damage of the last step, funcG(kappaD) (1 for a contact that is not cohesive) [-]");
        v.attr("kappaD", kappaD, "Largest normal strain so far (non-decreasing) [-]");
        v.attr("epsN", epsN, "Normal strain of the last step, (refPD - penetrationDepth)/refLength + isoPrestress/E [-]");
        v.attr("sigmaN", sigmaN, "Normal stress of the last step (positive in tension) [Pa]");
        v.attr("Fn", Fn, "Normal force of the last step, sigmaN·crossSection (positive in tension) [N]");
        v.attr("epsNPl", epsNPl, "Normal plastic strain (not used: 0) [-]");
        v.attr("relResidualStrength", relResidualStrength, "Relative residual strength: (1 - omega)·kappaD/epsCrackOnset, 1 while kappaD < epsCrackOnset, 0 if not cohesive [-]");
        v.attr("epsT", epsT, "Shear strain: the sum of the shear displacement increments over refLength, turned with the contact [-]");
        v.attr("sigmaT", sigmaT, "Shear stress of the last step, G·epsT capped by the yield stress [Pa]");
        v.attr("Fs", Fs, "Shear force of the last step, sigmaT·crossSection [N]");
        v.attr("epsTPl", epsTPl, "Shear plastic strain (not used: 0) [-]");
    }
    // The damage law ω(κ_D): 0 up to epsCrackOnset, then exponential (damLaw 1) or linear softening (damLaw 0).
    static Real funcG(Real kappaD, Real epsCrackOnset, Real epsFracture, bool neverDamage, int damLaw);
    // Its inverse: the κ_D of damage ω.
    static Real funcGInv(Real omega, Real epsCrackOnset, Real epsFracture, bool neverDamage, int damLaw);
    // Sets the damage omega and the strain kappaD that gives it (relResidualStrength is left, as in the reference).
    void setDamage(Real dmg);
    YADE_INDEXABLE(CpmPhys)
};

} // namespace yade
