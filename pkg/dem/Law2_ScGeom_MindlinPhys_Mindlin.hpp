// The Hertz-Mindlin contact law: Hertz's normal force kno·u^(3/2), Mindlin's no-slip shear
// stiffness kso·u^(1/2) (incremental), Mohr-Coulomb sliding, viscous damping from
// MindlinPhys.betan/betas; optional DMT adhesion and rolling/twisting moments.
#pragma once
#include <atomic>
#include <core/BodyStore.hpp>
#include <core/LawDispatcher.hpp>
#include <core/State.hpp>
#include <pkg/dem/MindlinPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Scene;

class Law2_ScGeom_MindlinPhys_Mindlin : public LawFunctorBatched<Law2_ScGeom_MindlinPhys_Mindlin, ScGeom, MindlinPhys> {
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
    bool go(ScGeom& geom, MindlinPhys& phys, const Contact& c);
    void prepare() override;
    // Effective mass of the pair; a body that is not dynamic counts as infinitely heavy.
    static Real effectiveMass(const BodyStore::Columns& b, long id1, long id2) {
        const bool d1 = b.blockedDOFsMask[id1] != State::DOF_ALL, d2 = b.blockedDOFsMask[id2] != State::DOF_ALL;
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
};

} // namespace yade
