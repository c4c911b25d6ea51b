// The Cundall-Strack contact law (3.4): linear normal spring, incremental shear spring with
// Mohr-Coulomb sliding; forces and torques applied at the contact point.
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_FrictPhys_CundallStrack : public LawFunctorBatched<Law2_ScGeom_FrictPhys_CundallStrack, ScGeom, FrictPhys> {
public:
    static constexpr const char* classDoc = "Law2 functor: the Cundall-Strack contact law (3.4), Fn = kn·uN, incremental shear force Ft += ks·Δus limited by |Ft| ≤ Fn·tan φ (Mohr-Coulomb).";
    bool neverErase = false;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated (forces zeroed) instead of removing them");
    }
    bool go(ScGeom& geom, FrictPhys& phys, const Contact& c);
    void prepare() override; // energy terms

private:
    int elastId = -1, plastId = -1; // O.energy terms elastPotential, plastDissip (when tracked)
};

} // namespace yade
