#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_Mindlin.hpp>

namespace yade {

void Law2_ScGeom_MindlinPhys_Mindlin::prepare() { shearEnergyIter.v = -1; }

void Law2_ScGeom_MindlinPhys_Mindlin::startShearEnergySum(long long iter) {
    if (shearEnergyIter.v.load(std::memory_order_acquire) == iter) return;
#pragma omp critical(mindlinShearEnergy)
    if (shearEnergyIter.v.load(std::memory_order_relaxed) != iter) {
        shearEnergy = 0;
        shearEnergyIter.v.store(iter, std::memory_order_release);
    }
}

template <class F> static void forEachMindlin(const Scene& s, F f) {
    const InteractionContainer& ic = s.interactions;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const MindlinPhys*>(ic.phys(k))) f(*p, ic.geom(k));
}

Real Law2_ScGeom_MindlinPhys_Mindlin::normElastEnergy(const Scene& s) {
    Real e = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom* g) {
        const Real u = static_cast<const ScGeom*>(g)->penetrationDepth;
        if (u > 0) e += 0.4 * p.kno * std::pow(u, 2.5);
    });
    return e;
}

Real Law2_ScGeom_MindlinPhys_Mindlin::ratioSlidingContacts(const Scene& s) {
    long all = 0, sliding = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom*) {
        ++all;
        sliding += p.isSliding;
    });
    return all ? Real(sliding) / all : 0;
}

long Law2_ScGeom_MindlinPhys_Mindlin::contactsAdhesive(const Scene& s) {
    long n = 0;
    forEachMindlin(s, [&](const MindlinPhys& p, const IGeom*) { n += p.isAdhesive; });
    return n;
}

} // namespace yade
