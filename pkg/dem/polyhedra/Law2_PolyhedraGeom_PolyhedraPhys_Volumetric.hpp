// The volumetric law of polyhedra (Eliáš 2014): a normal force proportional to the overlap volume (to a power), a
// Cundall-Strack shear force capped by Coulomb friction. A one-contact functor (the geometry is not ScGeom).
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/polyhedra/PolyhedraGeom.hpp>
#include <pkg/dem/polyhedra/PolyhedraPhys.hpp>

namespace yade {

class Scene;

class Law2_PolyhedraGeom_PolyhedraPhys_Volumetric : public LawFunctorOf<PolyhedraGeom, PolyhedraPhys> {
public:
    static constexpr const char* classDoc = "Calculate physical response of 2 Polyhedra in interaction, based on penetration configuration given by PolyhedraGeom. Normal force is proportional to the volume of intersection: kn·V^volumePower along the normal; the shear force grows by -ks·shearInc and is capped at tan(φ)·|normal force|.";
    Real volumePower = 1;
    Vector3r shearForce = Vector3r::Zero();
    bool traceEnergy = false;
    Real plasticDissipation = 0; // summed while traceEnergy (atomically: the law runs in parallel)
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("volumePower", volumePower, "Power of volume used in evaluation of normal force. Default is 1.0 - normal force is linearly proportional to volume. 1.0/3.0 would mean that normal force is proportional to the cube root of volume, approximation of penetration depth.", Attr::positive);
        v.attr("shearForce", shearForce, "Kept for scripts: in the reference the shear force of the contact handled last; not written here (the contacts run in parallel), read each contact's phys.shearForce");
        v.attr("traceEnergy", traceEnergy, "Sum the energy dissipated in plastic slips at all contacts (plasticDissipation())");
    }
    bool go(PolyhedraGeom& geom, PolyhedraPhys& phys, Interaction& I) override;
    // Sum over the real PolyhedraPhys contacts of (|normalForce|²/kn + |shearForce|²/ks)/2 [J].
    static Real elasticEnergy(const Scene& scene);
};

} // namespace yade
