// Hertz's normal force kno·u^(3/2) with a linear (or, with nonLin, Mindlin-stiffness) shear spring
// and Coulomb sliding; no damping, no adhesion, no moments (Law2_ScGeom_MindlinPhys_Mindlin has those).
#pragma once
#include <core/LawDispatcher.hpp>
#include <pkg/dem/MindlinPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_MindlinPhys_HertzWithLinearShear : public LawFunctorBatched<Law2_ScGeom_MindlinPhys_HertzWithLinearShear, ScGeom, MindlinPhys> {
public:
    static constexpr const char* classDoc =
            "Hertz normal force kno·u^(3/2) (MindlinPhys.kno) and an incremental shear spring of stiffness MindlinPhys.kso "
            "(with nonLin > 0: kso·u^(1/2), as in Hertz-Mindlin), capped at tan(φ)·|Fn|. No viscosity or damping: for those, "
            "Law2_ScGeom_MindlinPhys_Mindlin. MindlinPhys.kn and ks are not written.";
    bool neverErase = false;
    int nonLin = 0;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated (forces zeroed) instead of removing them");
        v.attr("nonLin", nonLin, "Shear stiffness: 0 the constant MindlinPhys.kso; above 0 kso·u^(1/2) as in Hertz-Mindlin "
                                 "(the reference's values 1, 2 and 3 all behave so)");
    }
    bool go(ScGeom& geom, MindlinPhys& phys, const Contact& c);
};

} // namespace yade
