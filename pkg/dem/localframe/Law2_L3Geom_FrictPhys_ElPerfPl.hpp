// Elastic-perfectly plastic law on L3Geom: linear springs in the local frame, Mohr-Coulomb slip, no
// cohesion. A one-contact functor (not a kernel of core/ContactKernel.hpp, which is written for ScGeom).
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/localframe/L3Geom.hpp>

namespace yade {

class Law2_L3Geom_FrictPhys_ElPerfPl : public LawFunctor {
public:
    static constexpr const char* classDoc =
            "Basic law for testing L3Geom: local force F = (kn·(u-u0)_x, ks·(u-u0)_y, ks·(u-u0)_z); the contact breaks when (u-u0)_x > 0 "
            "(unless noBreak) and the shear force is capped at -F_x·tan φ (Mohr-Coulomb, unless noSlip), the slip going into u0. "
            "No cohesion.";
    bool noBreak = false, noSlip = false;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("noBreak", noBreak, "Do not break contacts when particles separate");
        v.attr("noSlip", noSlip, "No plastic slipping");
    }
    std::vector<std::string> argTypes() const override { return {"L3Geom", "FrictPhys"}; }
    bool go(IGeom& geom, IPhys& phys, Interaction& I) final;
    void goBatch(const Contact* c, size_t n, char* keep) final;
    void prepare() override; // energy terms
    // One contact; false: the contact ends.
    virtual bool goLocal(L3Geom& geom, FrictPhys& phys, Body::id_t id1, Body::id_t id2);

protected:
    // Applies the local force F (and the local torque T, if not null) on the two bodies, F on body 1 and -F on body 2 at the
    // branches (r_i + u_x/2)·n from the centres; sets phys's normalForce and shearForce (global).
    void applyLocal(const L3Geom& geom, FrictPhys& phys, Body::id_t id1, Body::id_t id2, const Vector3r& F, const Vector3r* T) const;
    int elastId = -1, plastId = -1; // O.energy terms elastPotential, plastDissip (O.trackEnergy)
};

} // namespace yade
