// The linear visco-elastic contact law (Pournin et al. 2001): a spring and a dashpot in parallel in the
// normal direction, a spring and a dashpot in parallel in series with a Coulomb slider in the shear
// direction; optional rolling resistance (Zhou et al. 1999).
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/ViscElPhys.hpp>

namespace yade {

class Law2_ScGeom_ViscElPhys_Basic : public LawKernelFunctor<Law2_ScGeom_ViscElPhys_Basic, ScGeom, ViscElPhys> {
public:
    static constexpr const char* classDoc =
            "Linear visco-elastic law on ScGeom and ViscElPhys: normal force kn·u + cn·v_n (v_n the approach speed), none while that "
            "sum is not positive (no attraction); shear force: an elastic part updated by -ks·Δus plus the viscous -cs·v_s, the sum "
            "capped at tan(φ)·|Fn| (Coulomb); with ViscElPhys.mR > 0 a rolling-resistance torque against the relative rotation.";
    template <class V> void visit(V& v) { LawFunctor::visit(v); }
    bool separated(ViscElPhys&) const { return false; }
    template <class T>
    YADE_KERNEL ContactForce<T> kernel(const ScGeom::Values<T>& g, Rows<ViscElPhys, T>& phys, const ContactBodies<T>& b, const LaneEnergy<T>&) {
        using P = ViscElPhys;
        const T zero(0.0), dt(scene->dt);
        const Vec3<T> n = g.normal, cp = g.contactPoint;
        const Vec3<T> arm1 = cp - b.pos1(), arm2 = cp - b.pos2();
        const Vec3<T> w1 = b.angVel1(), w2 = b.angVel2();
        const Vec3<T> spin1 = cross(w1, arm1), spin2 = cross(w2, arm2);
        const Vec3<T> relVel = (b.vel2() + spin2) - (b.vel1() + spin1); // of body 2's surface, at the contact point

        // normal: spring and dashpot in parallel; nothing while they pull (the contact is kept)
        const T vn = dot(relVel, n);
        const T Fn = phys.get(&P::kn) * g.penetrationDepth, Fv = (-phys.get(&P::cn)) * vn;
        phys.set(&P::Fn, Fn);
        phys.set(&P::Fv, Fv);
        const T fn = Fn + Fv;
        const MaskOf<T> pushes = !(greater(zero, fn) | equal(fn, zero)); // (not fn <= 0)
        const Vec3<T> normalForce = fn * n;

        // shear: the elastic part (kept in shearForce) capped at tan(φ)·fn; the dashpot acts while it sticks
        const Vec3<T> shearVel = relVel - vn * n;
        Vec3<T> elastic = g.rotated(phys.get(&P::shearForce)) - (phys.get(&P::ks) * dt) * shearVel;
        const T maxFs = fn * phys.get(&P::tangensOfFrictionAngle);
        const MaskOf<T> sliding = greater(squaredNorm(elastic), maxFs * maxFs);
        elastic = select(sliding, elastic * (maxFs / norm(elastic)), elastic);
        const Vec3<T> shear = select(sliding, elastic, elastic - phys.get(&P::cs) * shearVel);
        phys.set(&P::normalForce, select(pushes, normalForce, Vec3<T>::zero()));
        phys.set(&P::shearForce, select(pushes, elastic, Vec3<T>::zero()));

        const Vec3<T> f1 = -(normalForce + shear); // on body 1
        Vec3<T> t1 = cross(arm1, f1), t2 = cross(arm2, -f1);
        const T mR = phys.get(&P::mR);
        const MaskOf<T> rolling = greater(mR, zero);
        if (anySet(rolling)) { // rolling resistance, against the relative spin: mRtype 1 mR·fn·Δω, mRtype 2 also times |Δ(ω × arm)|
            const Vec3<T> dw = w1 - w2;
            const MaskOf<T> type2 = greater(phys.getVia([](const P& p) { return p.mRtype == 2 ? 1.0 : 0.0; }), zero);
            const T k = mR * fn * select(type2, norm(spin1 - spin2), T(1.0));
            t1 = select(rolling, t1 - k * dw, t1);
            t2 = select(rolling, t2 + k * dw, t2);
        }
        return {f1, t1, t2, pushes};
    }
};

} // namespace yade
