// The Cundall-Strack contact law (3.4): linear normal spring, incremental shear spring with
// Mohr-Coulomb sliding; forces and torques applied at the contact point.
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_FrictPhys_CundallStrack : public LawKernelFunctor<Law2_ScGeom_FrictPhys_CundallStrack, ScGeom, FrictPhys> {
public:
    static constexpr const char* classDoc = "Law2 functor: the Cundall-Strack contact law (3.4), Fn = kn·uN, incremental shear force Ft += ks·Δus limited by |Ft| ≤ Fn·tan φ (Mohr-Coulomb).";
    bool neverErase = false;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated (forces zeroed) instead of removing them");
    }
    void prepare() override; // energy terms
    bool separated(FrictPhys& phys) const {
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = Vector3r::Zero();
        return true;
    }
    template <class T>
    YADE_KERNEL ContactForce<T> kernel(const ScGeom::Values<T>& g, Rows<FrictPhys, T>& phys, const ContactBodies<T>&, const LaneEnergy<T>& energy) {
        const T kn = phys.get(&FrictPhys::kn), ks = phys.get(&FrictPhys::ks), tanPhi = phys.get(&FrictPhys::tangensOfFrictionAngle);
        const Vec3<T> normalForce = (kn * g.penetrationDepth) * g.normal;
        const Vec3<T> trial = g.rotated(phys.get(&FrictPhys::shearForce)) - ks * g.shearInc; // trial shear force
        const T maxFs2 = squaredNorm(normalForce) * tanPhi * tanPhi, fs2 = squaredNorm(trial);
        const MaskOf<T> sliding = greater(fs2, maxFs2); // Mohr-Coulomb return where set
        const Vec3<T> shearForce = select(sliding, trial * (sqrt(maxFs2) / sqrt(fs2)), trial);
        if (energy.tracker) {
            const T dissipated = dot(trial - shearForce, shearForce) / ks;
            energy.add(plastId, dissipated, sliding & greater(dissipated, T(0.0))); // (frictionless contacts dissipate nothing)
            energy.add(elastId, T(0.5) * (squaredNorm(normalForce) / kn + select(greater(ks, T(0.0)), squaredNorm(shearForce) / ks, T(0.0))),
                    allSet<T>());
        }
        phys.set(&FrictPhys::normalForce, normalForce);
        phys.set(&FrictPhys::shearForce, shearForce);
        const Vec3<T> force = -normalForce - shearForce; // on body 1
        const Vec3<T> arm = cross(g.normal, force);
        const T half(0.5);
        return {force, (g.refR1 - half * g.penetrationDepth) * arm, (g.refR2 - half * g.penetrationDepth) * arm, allSet<T>()};
    }

private:
    int elastId = -1, plastId = -1; // O.energy terms elastPotential, plastDissip (when tracked)
};

} // namespace yade
