// Hertz's normal force kno·u^(3/2) with a linear (or, with nonLin, Mindlin-stiffness) shear spring
// and Coulomb sliding; no damping, no adhesion, no moments (Law2_ScGeom_MindlinPhys_Mindlin has those).
#pragma once
#include <core/ContactKernel.hpp>
#include <cmath>
#include <pkg/dem/MindlinPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_MindlinPhys_HertzWithLinearShear : public LawKernelFunctor<Law2_ScGeom_MindlinPhys_HertzWithLinearShear, ScGeom, MindlinPhys> {
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
    bool separated(MindlinPhys& phys) const {
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    template <class T>
    YADE_KERNEL ContactForce<T> kernel(const ScGeom::Values<T>& g, Rows<MindlinPhys, T>& phys, const ContactBodies<T>& b, const LaneEnergy<T>&) {
        using P = MindlinPhys;
        const T u = g.penetrationDepth;
        const Vec3<T> n = g.normal, cp = g.contactPoint;
        const T fn = phys.get(&P::kno) * perLane(u, [](Real x) { return std::pow(x, 1.5); }); // (so, not kno·sqrt(u)·u: the reference's bits)
        const Vec3<T> normalForce = fn * n;
        phys.set(&P::normalForce, normalForce);
        const T kso = phys.get(&P::kso);
        const T ks = nonLin > 0 ? kso * sqrt(u) : kso;
        Vec3<T> fs = g.rotated(phys.get(&P::shearForce)) - ks * g.shearInc;
        const T maxFs = phys.get(&P::tangensOfFrictionAngle) * fn;
        fs = select(greater(squaredNorm(fs), maxFs * maxFs), fs * (maxFs / norm(fs)), fs); // sliding
        phys.set(&P::shearForce, fs);
        const Vec3<T> f1 = -(normalForce + fs); // on body 1
        return {f1, cross(cp - b.pos1(), f1), cross(cp - b.pos2(), -f1), allSet<T>()};
    }
};

} // namespace yade
