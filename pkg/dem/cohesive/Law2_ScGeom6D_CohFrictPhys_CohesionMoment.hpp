// The cohesive-frictional contact law with moments: linear normal, shear, rolling and twisting
// springs; a bond with tensile and shear strengths that breaks (fragile) or yields (plastic);
// Mohr-Coulomb sliding, and rolling/twisting moments capped in proportion to the normal force.
// Written as a one-contact functor, not a kernel: its branches (breakage, plasticity, the
// moments' two forms) and its geometry (ScGeom6D's rotations) do not fit the two-lane pass.
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/cohesive/CohFrictPhys.hpp>
#include <pkg/dem/cohesive/ScGeom6D.hpp>

namespace yade {

class Law2_ScGeom6D_CohFrictPhys_CohesionMoment
        : public LawFunctorBatched<Law2_ScGeom6D_CohFrictPhys_CohesionMoment, ScGeom6D, CohFrictPhys> {
public:
    static constexpr const char* classDoc =
            "Law2 functor: linear traction-compression, shear, bending and twisting with cohesion and friction (Law2_ScGeom_FrictPhys_"
            "CundallStrack with adhesion and moments). Fn = kn·(u - unp), positive in compression; in tension beyond normalAdhesion a "
            "fragile bond breaks and the contact ends, a plastic one yields (Fn = -normalAdhesion, unp grows; past unpMax the contact "
            "ends). Shear: Fs = rotated(Fs) - ks·Δus, capped at Fn·tan φ + shearAdhesion (shearAdhesion alone with "
            "cohesionDisablesFriction); a fragile bond exceeded in shear breaks (adhesions 0) and the cap becomes Fn·tan φ; while sliding a "
            "tensile normal force is not applied. Moments (momentRotationLaw of both materials, on cohesive contacts or with "
            "always_use_moment_law): twist·ktw·n and bending·kr (total form, from ScGeom6D) or their increments -ktw·Δθtwist, "
            "-kr·Δθbend added to the rotated moments (useIncrementalForm); capped at maxRollPl·|Fn| and maxTwistPl·|Fn| when these are not "
            "negative; body 1 gets -(twist + bending moment), body 2 the opposite.";
    bool neverErase = false, always_use_moment_law = false, shear_creep = false, twist_creep = false, traceEnergy = false,
         useIncrementalForm = false;
    Real creep_viscosity = 1;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Accepted for compatibility: a contact that ends (tension beyond the bond's strength, or unpMax "
                                         "exceeded) becomes a potential interaction either way, as the reference does with neverErase");
        v.attr("always_use_moment_law", always_use_moment_law, "Moments at all contacts (true) or only at cohesive ones (false); both need "
                                                               "CohFrictPhys.momentRotationLaw");
        v.attr("shear_creep", shear_creep, "Creep of the shear force: the elastic shear displacement relaxes as du/dt = -Fs/creep_viscosity, "
                                           "i.e. Fs -= ks·Fs·dt/creep_viscosity at every step (unstable when ks·dt/creep_viscosity > 2)");
        v.attr("twist_creep", twist_creep, "Creep of the twisting moment (not implemented here: setting it is an error at the next step)");
        v.attr("traceEnergy", traceEnergy, "Sum the energy dissipated by sliding in plasticDissipation() even without O.trackEnergy (with "
                                           "O.trackEnergy it is summed anyway, and O.energy gets shearDissip, bendingDissip, twistDissip)");
        v.attr("useIncrementalForm", useIncrementalForm, "Moments from the increments of relative rotation (ω2 - ω1)·dt added to the "
                                                         "rotated moments, instead of from ScGeom6D's total twist and bending");
        v.attr("creep_viscosity", creep_viscosity, "Creep viscosity of shear_creep [N·s/m] (positive)");
    }
    void prepare() override; // energy terms; creep refused
    bool go(ScGeom6D& geom, CohFrictPhys& phys, const Contact& c);
    Real plasticDissipation = 0; // energy dissipated by sliding, summed with traceEnergy or O.trackEnergy (Python: plasticDissipation())
    // Python: the elastic energies of the CohFrictPhys contacts of a scene, Σ Fn²/(2kn), Σ |Fs|²/(2ks), Σ |Mb|²/(2kr), Σ |Mt|²/(2ktw)
    enum class Spring { normal, shear, bending, twist, all };
    static Real elasticEnergy(const Scene& scene, Spring which);

private:
    int shearId = -1, bendingId = -1, twistId = -1; // O.energy's shearDissip, bendingDissip, twistDissip (with O.trackEnergy)
    // the bond is gone: no adhesion any more
    static void breakBond(CohFrictPhys& phys) {
        phys.cohesionBroken = true;
        phys.normalAdhesion = phys.shearAdhesion = 0;
    }
    // the rolling and twisting moments of this step; returns their sum (applied as -m on body 1, m on body 2)
    Vector3r moments(const ScGeom6D& geom, CohFrictPhys& phys, const Contact& c);
    // caps the moment m at maxPl·|Fn| when maxPl >= 0; returns the energy dissipated
    static Real capMoment(Vector3r& m, Real maxPl, Real fn, Real stiffness);
    void dissipate(int term, Real e);
};

} // namespace yade
