#include <cmath>
#include <pkg/dem/HertzRestitution.hpp>
#include <pkg/dem/Ip2_FrictMat_FrictMat_MindlinPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <stdexcept>

namespace yade {

namespace {
// A damping ratio from either a restitution coefficient or a ratio (one of the two), or -1: none.
Real dampingRatio(const std::shared_ptr<MatchMaker>& e, const std::shared_ptr<MatchMaker>& beta, int id1, int id2, const char* eName,
        const char* betaName) {
    if (e && beta)
        throw std::invalid_argument(std::string("Ip2_FrictMat_FrictMat_MindlinPhys: ") + eName + " and " + betaName + " are both given; give one");
    if (beta) return (*beta)(id1, id2);
    if (e) return hertzDampingRatio((*e)(id1, id2));
    return -1;
}
} // namespace

void Ip2_FrictMat_FrictMat_MindlinPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto* geom = dynamic_cast<const ScGeom*>(I.geom.get());
    if (!geom) throw std::runtime_error("Ip2_FrictMat_FrictMat_MindlinPhys needs an ScGeom geometry, got " + I.geom->getClassName());
    const auto& a = static_cast<const FrictMat&>(*m1);
    const auto& b = static_cast<const FrictMat&>(*m2);
    // A radius of 0 or less is a flat boundary: the effective radius is then the other one.
    const Real r1 = geom->refR1, r2 = geom->refR2;
    const Real R = r1 > 0 && r2 > 0 ? r1 * r2 / (r1 + r2) : std::max(r1, r2);
    // (E* = 1/((1-ν1²)/E1 + (1-ν2²)/E2) written as the reference computes it: the same bits)
    const Real E = a.young * b.young / ((1 - a.poisson * a.poisson) * b.young + (1 - b.poisson * b.poisson) * a.young);
    const Real Ga = a.young / (2 * (1 + a.poisson)), Gb = b.young / (2 * (1 + b.poisson));
    const Real G = 1 / ((2 - a.poisson) / Ga + (2 - b.poisson) / Gb);

    auto phys = std::make_shared<MindlinPhys>();
    phys->kno = 4. / 3. * E * std::sqrt(R);
    phys->kso = 8 * G * std::sqrt(R);
    // (kn and ks are the law's to write, as in the reference: 0 until it runs)
    phys->initD = geom->penetrationDepth;
    const Real angle = frictAngle ? (*frictAngle)(a.id, b.id, a.frictionAngle, b.frictionAngle) : std::min(a.frictionAngle, b.frictionAngle);
    phys->tangensOfFrictionAngle = std::tan(angle);

    const Real bn = dampingRatio(en, betan, a.id, b.id, "en", "betan");
    const Real bs = dampingRatio(es, betas, a.id, b.id, "es", "betas");
    phys->betan = bn >= 0 ? bn : 0;
    phys->betas = bs >= 0 ? bs : phys->betan;

    if (krot != 0 || ktwist != 0 || eta != 0 || gamma != 0) { // (else the defaults, 0: nothing made)
        MindlinPhys::Extra& x = phys->extra.edit();
        x.kr = krot;
        x.ktw = ktwist;
        x.maxBendPl = eta * 0.5 * (r1 + r2); // (the reference's: eta times the mean radius)
        x.adhesionForce = 4 * M_PI * R * gamma;
    }
    I.phys = phys;
}

} // namespace yade
