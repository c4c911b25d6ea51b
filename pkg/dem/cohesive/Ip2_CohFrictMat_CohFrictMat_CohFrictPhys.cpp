#include <algorithm>
#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/cohesive/Ip2_CohFrictMat_CohFrictMat_CohFrictPhys.hpp>
#include <pkg/dem/cohesive/ScGeom6D.hpp>
#include <pkg/dem/grid/GridNodeGeom6D.hpp>
#include <stdexcept>

namespace yade {

namespace {
    Real harmonicMean(Real a, Real b) { return a + b == 0 ? 0 : 2 * a * b / (a + b); }
} // namespace

void Ip2_CohFrictMat_CohFrictMat_CohFrictPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto& a = static_cast<const CohFrictMat&>(*m1);
    const auto& b = static_cast<const CohFrictMat&>(*m2);
    const auto* geom = dynamic_cast<const GenericSpheresContact*>(I.geom.get());
    if (!geom) throw std::runtime_error(getClassName() + " needs a ScGeom6D geometry, got " + I.geom->getClassName());
    // a flat boundary takes the other body's radius
    const Real r1 = geom->refR1 > 0 ? geom->refR1 : geom->refR2, r2 = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
    auto phys = std::make_shared<CohFrictPhys>();
    phys->kn = 2 * a.young * r1 * b.young * r2 / (a.young * r1 + b.young * r2);
    phys->ks = 2 * a.young * r1 * a.poisson * b.young * r2 * b.poisson / (a.young * r1 * a.poisson + b.young * r2 * b.poisson);
    phys->tangensOfFrictionAngle =
            std::tan(frictAngle ? (*frictAngle)(a.id, b.id, a.frictionAngle, b.frictionAngle) : std::min(a.frictionAngle, b.frictionAngle));
    phys->kr = phys->ks * harmonicMean(a.alphaKr, b.alphaKr) * r1 * r2;
    phys->ktw = phys->ks * harmonicMean(a.alphaKtw, b.alphaKtw) * r1 * r2;
    phys->maxRollPl = std::min(a.etaRoll * r1, b.etaRoll * r2);
    phys->maxTwistPl = std::min(a.etaTwist * r1, b.etaTwist * r2);
    if (const auto* grid = dynamic_cast<const GridNodeGeom6D*>(geom)) setBeamStiffness(*phys, a, *grid);
    phys->momentRotationLaw = a.momentRotationLaw && b.momentRotationLaw;
    phys->fragile = a.fragile || b.fragile;
    if ((setCohesionOnNewContacts || setCohesionNow) && a.isCohesive && b.isCohesive) makeCohesive(*phys, a, b, r1, r2);
    I.phys = phys;
}

// The bond of two grid nodes is a beam of node 1's material, of the node's radius r and of the nodes' distance L
// (Effeindzourou et al. 2016): kn = EA/L, ks = 12EI/L³, kr = EI/L, ktw = GJ/L (A = πr², I = πr⁴/4, J = 2I), and its
// length now is the length at rest (unp = the penetration depth now).
void Ip2_CohFrictMat_CohFrictMat_CohFrictPhys::setBeamStiffness(CohFrictPhys& phys, const CohFrictMat& a, const GridNodeGeom6D& g) {
    const Real r = g.refR1, L = g.refR1 + g.refR2 - g.penetrationDepth;
    if (!(L > 0)) throw std::runtime_error("Ip2_CohFrictMat_CohFrictMat_CohFrictPhys: two grid nodes at the same place (a bond of length 0)");
    const Real area = M_PI * r * r, I = M_PI * std::pow(r, 4) / 4, G = a.young / (2 * (1 + a.poisson));
    phys.kn = a.young * area / L;
    phys.ks = 12 * a.young * I / std::pow(L, 3);
    phys.kr = a.young * I / L;
    phys.ktw = G * 2 * I / L;
    phys.unp = g.penetrationDepth;
}

void Ip2_CohFrictMat_CohFrictMat_CohFrictPhys::makeCohesive(CohFrictPhys& phys, const CohFrictMat& a, const CohFrictMat& b, Real r1, Real r2) const {
    // (the reference calls these MatchMakers without the materials' values: algo 'avg' etc. is an error)
    const Real cn = normalCohesion ? (*normalCohesion)(a.id, b.id) : std::min(a.normalCohesion, b.normalCohesion);
    const Real cs = shearCohesion ? (*shearCohesion)(a.id, b.id) : std::min(a.shearCohesion, b.shearCohesion);
    const Real r = std::min(r1, r2);
    phys.cohesionBroken = false;
    phys.normalAdhesion = cn * r * r;
    phys.shearAdhesion = cs * r * r;
}

void Ip2_CohFrictMat_CohFrictMat_CohFrictPhys::prepare() {
    if (!scene) return;
    if (setCohesionNow && cohesionIter >= 0 && cohesionIter != scene->iter) { // applied at the last step: done
        setCohesionNow = false;
        cohesionIter = -1;
    }
    const bool now = setCohesionNow && cohesionIter < 0;
    if (now) cohesionIter = scene->iter;
    initExistingContacts(now);
}

// The CohFrictPhys contacts flagged initCohesion (or all of them): cohesive from now on, their
// rotations counted from the bodies' orientations now (the geometry of this step then finds none).
void Ip2_CohFrictMat_CohFrictMat_CohFrictPhys::initExistingContacts(bool all) {
    InteractionContainer& intrs = scene->interactions;
    const BodyStore::Columns cols = scene->bodies.hot().columns();
    for (size_t p = 0; p < intrs.poolCount(); ++p) {
        ContactPool* pool = intrs.pools[p].get();
        if (!pool || pool->size() == 0 || !dynamic_cast<CohFrictPhys*>(pool->phys(0))) continue;
        for (size_t slot = 0; slot < pool->size(); ++slot) {
            auto& phys = static_cast<CohFrictPhys&>(*pool->phys(slot));
            if (!all && !phys.initCohesion) continue;
            phys.initCohesion = false;
            const size_t k = pool->header(slot).k;
            const Body::id_t id1 = intrs.pairIds[2 * k], id2 = intrs.pairIds[2 * k + 1];
            const auto* a = dynamic_cast<const CohFrictMat*>(scene->bodies[id1]->material.get());
            const auto* b = dynamic_cast<const CohFrictMat*>(scene->bodies[id2]->material.get());
            auto* geom = dynamic_cast<ScGeom6D*>(pool->geom(slot));
            if (!a || !b || !geom || !a->isCohesive || !b->isCohesive) continue;
            const Real r1 = geom->refR1 > 0 ? geom->refR1 : geom->refR2, r2 = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
            makeCohesive(phys, *a, *b, r1, r2);
            geom->initRotations(cols.ori[id1], cols.ori[id2]);
        }
    }
}

} // namespace yade
