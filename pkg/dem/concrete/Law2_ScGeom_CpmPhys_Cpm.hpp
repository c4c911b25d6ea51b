// The contact law of the concrete particle model (CPM, Šmilauer 2010), in its public form (the one the
// reference's build has): damage in tension, Mohr-Coulomb plasticity in shear with a cohesion that the
// damage lowers. A one-contact functor, not a kernel: a contact's first step reads the bodies' shapes,
// and a contact that broke is removed and counted on its bodies' CpmState.
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/concrete/CpmPhys.hpp>

namespace yade {

class Law2_ScGeom_CpmPhys_Cpm : public LawFunctorBatched<Law2_ScGeom_CpmPhys_Cpm, ScGeom, CpmPhys> {
public:
    static constexpr const char* classDoc =
            "Constitutive law of the concrete particle model (see CpmMat), the public model of the reference's build. At a contact's "
            "first step: refLength (the distance of the centers; a sphere's radius against another shape), crossSection = "
            "π·min(r1, r2)², refPD, kn = E·crossSection/refLength, ks = G·crossSection/refLength, epsFracture = relDuctility·"
            "epsCrackOnset. At every step: epsN = (refPD - penetrationDepth)/refLength + isoPrestress/E; epsT turned with the contact "
            "plane plus the shear increment over refLength; kappaD = max(kappaD, epsN, 0); omega = funcG(kappaD) (1 if not cohesive); "
            "sigmaN = (1 - omega if epsN > 0 else 1)·E·epsN - isoPrestress; sigmaT = G·epsT capped at max(0, undamagedCohesion·"
            "(1 - omega) - sigmaN·tanFrictionAngle) (epsT is not reduced); Fn = sigmaN·crossSection, Fs = sigmaT·crossSection, "
            "normalForce = -Fn·n, shearForce = -Fs, applied at the contact point. A contact in tension (epsN > 0) whose omega passed "
            "omegaThreshold is removed and counted in its bodies' CpmState.numBrokenCohesive, and so is one that is not cohesive as "
            "soon as it is stretched (the reference's rule, found by running it: it counts those too). yieldSurfType, yieldLogSpeed, yieldEllipseShift, epsSoft and relKnSoft belong to the full model, which "
            "the reference's build lacks: they are stored and not used.";
    int yieldSurfType = 2;
    Real yieldLogSpeed = 0.1, yieldEllipseShift = NaN, omegaThreshold = 1, epsSoft = 1, relKnSoft = 0.3;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("omegaThreshold", omegaThreshold, "Damage above which a cohesive contact in tension is removed (omega reaches 1 only at "
                                                 "infinite strain: >= 1 never removes one)");
        v.attr("yieldSurfType", yieldSurfType, "Yield function of the full model (0 Mohr-Coulomb, 1 parabolic, 2 logarithmic, 3 log + "
                                               "linear in tension, 4 elliptic, 5 elliptic + log); not used: the public model is "
                                               "Mohr-Coulomb, as in the reference's build");
        v.attr("yieldLogSpeed", yieldLogSpeed, "Scaling of the logarithmic yield surface of the full model (not used)");
        v.attr("yieldEllipseShift", yieldEllipseShift, "Horizontal shift of the elliptic yield surface of the full model (not used)");
        v.attr("epsSoft", epsSoft, "Strain where softening in compression starts in the full model (not used; non-negative "
                                   "deactivates it there too)");
        v.attr("relKnSoft", relKnSoft, "Relative rigidity of the softening branch in compression of the full model (not used)");
    }
    bool go(ScGeom& geom, CpmPhys& phys, const Contact& c);
    // The radius of the yield surface the law uses: max(0, undamagedCohesion·(1 - omega) - sigmaN·tanFrictionAngle).
    static Real yieldSigmaTMagnitude(Real sigmaN, Real omega, Real undamagedCohesion, Real tanFrictionAngle);
    // Python: the elastic energy of the CpmPhys contacts of a scene, Σ (|normalForce|²/kn + |shearForce|²/ks)/2.
    static Real elasticEnergy(const Scene& scene);

private:
    void initialize(const ScGeom& geom, CpmPhys& phys, const Contact& c) const; // the contact's first step
    void countBroken(Body::id_t id) const;                                       // CpmState.numBrokenCohesive += 1
};

} // namespace yade
