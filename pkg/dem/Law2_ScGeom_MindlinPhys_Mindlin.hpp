// The Hertz-Mindlin contact law: Hertz's normal force kno·u^(3/2), Mindlin's no-slip shear
// stiffness kso·u^(1/2) (incremental), Mohr-Coulomb sliding, viscous damping from
// MindlinPhys.betan/betas; optional DMT adhesion and rolling/twisting moments.
#pragma once
#include <atomic>
#include <core/BodyStore.hpp>
#include <core/ContactKernel.hpp>
#include <core/State.hpp>
#include <pkg/dem/MindlinPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Scene;

class Law2_ScGeom_MindlinPhys_Mindlin : public LawKernelFunctor<Law2_ScGeom_MindlinPhys_Mindlin, ScGeom, MindlinPhys> {
public:
    static constexpr const char* classDoc =
            "Hertz-Mindlin law: normal force kno·u^(3/2) minus the viscous force c_n·v_n, c_n = 2·betan·sqrt(m*·(3/2)·kno·u^(1/2)) "
            "(m* the effective mass; a body that is not dynamic counts as infinitely heavy); no attraction (the normal force is cut "
            "at zero) unless includeAdhesion. Shear: elastic part updated by -kso·u^(1/2)·Δus, capped at tan(φ)·|Fn| (sliding), "
            "minus the viscous force c_s·v_s (c_s = 2·betas·sqrt(m*·kso·u^(1/2))) while not sliding.";
    bool neverErase = false, includeAdhesion = false, includeMoment = false, calcEnergy = false, nothing = false;
    Real frictionDissipation = 0, shearEnergy = 0, normDampDissip = 0, shearDampDissip = 0;
    template <class V> void visit(V& v) {
        LawFunctor::visit(v);
        v.attr("neverErase", neverErase, "Keep contacts whose bodies separated (forces zeroed) instead of removing them");
        v.attr("includeAdhesion", includeAdhesion, "DMT adhesion: the normal force is reduced by MindlinPhys.adhesionForce and may pull");
        v.attr("includeMoment", includeMoment, "Rolling and twisting moments from MindlinPhys.kr and ktw (Ip2 krot, ktwist)");
        v.attr("calcEnergy", calcEnergy, "Sum the energies below (costs a little time)");
        v.attr("nothing", nothing, "Placeholder for deprecated attributes (preventGranularRatcheting); has no effect");
        v.attr("frictionDissipation", frictionDissipation, "Energy dissipated by sliding since calcEnergy was set [J]");
        v.attr("shearEnergy", shearEnergy, "Elastic shear energy of the contacts in the last step [J]");
        v.attr("normDampDissip", normDampDissip, "Energy dissipated by normal viscous damping [J]");
        v.attr("shearDampDissip", shearDampDissip, "Energy dissipated by shear viscous damping [J]");
    }
    void prepare() override;
    bool separated(MindlinPhys& phys) const {
        if (!neverErase) return false;
        phys.normalForce = phys.shearForce = phys.normalViscous = phys.shearViscous = Vector3r::Zero();
        phys.kn = phys.ks = 0;
        return true;
    }
    template <class T>
    YADE_KERNEL ContactForce<T> kernel(const ScGeom::Values<T>& g, Rows<MindlinPhys, T>& phys, const ContactBodies<T>& b, const LaneEnergy<T>&) {
        using P = MindlinPhys;
        const T u = g.penetrationDepth, dt(scene->dt), zero(0.0);
        const Vec3<T> n = g.normal, cp = g.contactPoint, x1 = b.pos1(), x2 = b.pos2();
        const T sqrtU = sqrt(u);
        const T mbar = b.perPair([&](long id1, long id2) { return effectiveMass(b.b.store, id1, id2); });
        const T kno = phys.get(&P::kno), kn = T(1.5) * kno * sqrtU, ks = phys.get(&P::kso) * sqrtU; // tangent stiffnesses
        phys.set(&P::kn, kn);
        phys.set(&P::ks, ks);

        // normal: elastic (Hertz) minus viscous; cut at zero (no attraction) unless adhesive
        const Vec3<T> relVel = (b.vel2() + cross(b.angVel2(), cp - x2)) - (b.vel1() + cross(b.angVel1(), cp - x1));
        const T vn = dot(relVel, n);
        const T fnElastic = kno * u * sqrtU;
        const T betan = phys.get(&P::betan);
        const T cn = select(greater(betan, zero), T(2.0) * betan * sqrt(mbar * kn), zero);
        phys.set(&P::normalViscous, (cn * vn) * n);
        T fn = fnElastic - cn * vn;
        T adhesion = zero;
        if (includeAdhesion) {
            adhesion = phys.getVia([](const P& p) { return p.extra.get().adhesionForce; });
            fn = fn - adhesion;
            phys.set(&P::isAdhesive, greater(zero, fn));
        } else {
            fn = maxZero(fn);
        }
        const Vec3<T> normalForce = fn * n;
        phys.set(&P::normalForce, normalForce);

        // shear: incremental elastic part, Coulomb limit, viscous part while sticking
        const Vec3<T> shearInc = g.shearInc;
        Vec3<T> fsElastic = g.rotated(phys.get(&P::shearElastic)) - ks * shearInc;
        phys.set(&P::usTotal, g.rotated(phys.get(&P::usTotal)) - shearInc);
        Vec3<T> usElastic = g.rotated(phys.get(&P::usElastic)) - shearInc;
        const T maxFs = phys.get(&P::tangensOfFrictionAngle) * maxZero(includeAdhesion ? fn + adhesion : fn);
        const T fsNorm = norm(fsElastic);
        const MaskOf<T> sliding = greater(fsNorm, maxFs);
        const T ratio = select(greater(fsNorm, zero), maxFs / fsNorm, zero);
        if (calcEnergy) {
            const T lost = dot(fsElastic * (T(1.0) - ratio), fsElastic * ratio) / perLane(ks, [](Real k) { return std::max(k, Real(1e-300)); });
            phys.forLive([&](int i) { if (lane(sliding, i)) atomicAdd(frictionDissipation, lane(lost, i)); });
        }
        fsElastic = select(sliding, fsElastic * ratio, fsElastic);
        usElastic = select(sliding, usElastic * ratio, usElastic);
        phys.set(&P::isSliding, sliding);
        const T betas = phys.get(&P::betas);
        const T cs = select(greater(betas, zero), T(2.0) * betas * sqrt(mbar * ks), zero);
        const Vec3<T> shearViscous = select(sliding, Vec3<T>::zero(), cs * (shearInc / dt));
        const Vec3<T> shearForce = select(sliding, fsElastic, fsElastic - shearViscous);
        phys.set(&P::shearViscous, shearViscous);
        phys.set(&P::shearElastic, fsElastic);
        phys.set(&P::usElastic, usElastic);
        phys.set(&P::shearForce, shearForce);
        if (calcEnergy) {
            startShearEnergySum(scene->iter);
            const T elastic = T(0.5) * squaredNorm(fsElastic) / ks, normalDamping = abs(cn * vn * vn) * dt, shearDamping = abs(dot(shearViscous, shearInc));
            phys.forLive([&](int i) {
                if (lane(ks, i) > 0) atomicAdd(shearEnergy, lane(elastic, i));
            });
            phys.forLive([&](int i) { atomicAdd(normDampDissip, lane(normalDamping, i)); });
            phys.forLive([&](int i) { atomicAdd(shearDampDissip, lane(shearDamping, i)); });
        }

        const Vec3<T> f1 = -(normalForce + shearForce); // on body 1
        Vec3<T> t1 = cross(cp - x1, f1), t2 = cross(cp - x2, -f1);
        if (includeMoment) { // rolling and twisting moments, the bending one capped at maxBendPl·|fn|
            const Vec3<T> relRot = (b.angVel2() - b.angVel1()) * dt;
            const Vec3<T> twist = dot(relRot, n) * n, bend = relRot - twist;
            const T ktw = phys.getVia([](P& p) { return p.extra.edit().ktw; }), kr = phys.getVia([](P& p) { return p.extra.edit().kr; });
            const T maxBendPl = phys.getVia([](P& p) { return p.extra.edit().maxBendPl; });
            const Vec3<T> momentTwist = g.rotated(phys.getVecVia([](P& p) -> Vector3r& { return p.extra.edit().momentTwist; })) - ktw * twist;
            Vec3<T> momentBend = g.rotated(phys.getVecVia([](P& p) -> Vector3r& { return p.extra.edit().momentBend; })) - kr * bend;
            const T maxBend = maxBendPl * abs(fn), m = norm(momentBend);
            momentBend = select(greater(maxBendPl, zero) & greater(m, maxBend), momentBend * (maxBend / m), momentBend);
            phys.setVecVia([](P& p) -> Vector3r& { return p.extra.edit().momentTwist; }, momentTwist);
            phys.setVecVia([](P& p) -> Vector3r& { return p.extra.edit().momentBend; }, momentBend);
            t1 = t1 - (momentBend + momentTwist);
            t2 = t2 + (momentBend + momentTwist);
        }
        return {f1, t1, t2, allSet<T>()};
    }
    // Effective mass of the pair; a body that is not dynamic counts as infinitely heavy.
    static Real effectiveMass(const BodyStore::Columns& b, long id1, long id2) {
        const bool d1 = (b.blockedDOFsMask[id1] & State::DOF_ALL) != State::DOF_ALL, d2 = (b.blockedDOFsMask[id2] & State::DOF_ALL) != State::DOF_ALL;
        const Real m1 = b.mass[id1], m2 = b.mass[id2];
        if (d1 && d2) return m1 * m2 / (m1 + m2);
        return d1 ? m1 : d2 ? m2 : std::max(m1, m2);
    }
    // Python methods: the normal elastic energy (sum of 2/5·kno·u^(5/2)), the fraction of real
    // contacts that slide, and the number that pull (adhesion).
    static Real normElastEnergy(const Scene& s);
    static Real ratioSlidingContacts(const Scene& s);
    static long contactsAdhesive(const Scene& s);

private:
    struct Iter { // (copyable, as functors are)
        std::atomic<long long> v{-1};
        Iter() = default;
        Iter(const Iter& o) : v(o.v.load()) {}
        Iter& operator=(const Iter& o) { v = o.v.load(); return *this; }
    } shearEnergyIter; // the step shearEnergy was last reset
    void startShearEnergySum(long long iter);   // shearEnergy = 0 at the first contact of a step
    static void atomicAdd(Real& target, Real x) {
#pragma omp atomic
        target += x;
    }
};

} // namespace yade
