#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/concrete/Ip2_CpmMat_CpmMat_CpmPhys.hpp>
#include <stdexcept>

namespace yade {

namespace {
// The damage parameters a material needs unless neverDamage (the reference takes NaN silently).
void checkDamageParameters(const CpmMat& m) {
    const auto bad = [&](const char* name, Real value) {
        throw std::invalid_argument("Ip2_CpmMat_CpmMat_CpmPhys: CpmMat" + (m.label.empty() ? std::string() : " '" + m.label + "'") +
                                    " (material #" + std::to_string(m.id) + ") needs a positive " + name + ", got " + std::to_string(value) +
                                    " (or neverDamage=True)");
    };
    if (m.damLaw != 0 && m.damLaw != 1)
        throw std::invalid_argument("Ip2_CpmMat_CpmMat_CpmPhys: CpmMat.damLaw must be 0 (linear) or 1 (exponential), got " + std::to_string(m.damLaw));
    if (m.neverDamage) return;
    if (!(m.sigmaT >= 0 && std::isfinite(m.sigmaT))) bad("sigmaT", m.sigmaT);
    if (!(m.epsCrackOnset > 0 && std::isfinite(m.epsCrackOnset))) bad("epsCrackOnset", m.epsCrackOnset);
    if (!(m.relDuctility > 0 && std::isfinite(m.relDuctility))) bad("relDuctility", m.relDuctility);
    if (m.damLaw == 0 && !(m.relDuctility > 1)) bad("relDuctility above 1 with damLaw=0 (linear softening)", m.relDuctility);
}
} // namespace

void Ip2_CpmMat_CpmMat_CpmPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto& a = static_cast<const CpmMat&>(*m1);
    const auto& b = static_cast<const CpmMat&>(*m2);
    checkDamageParameters(a);
    checkDamageParameters(b);
    auto p = std::make_shared<CpmPhys>();
    p->damLaw = a.damLaw;
    p->isCohesive = cohesiveThresholdIter < 0 || scene->iter < cohesiveThresholdIter;
    const bool shared = &a == &b || (a.id >= 0 && a.id == b.id);
    const auto mean = [&](Real CpmMat::*x) { return shared ? a.*x : (a.*x + b.*x) / 2; };
    p->epsCrackOnset = mean(&CpmMat::epsCrackOnset);
    p->relDuctility = mean(&CpmMat::relDuctility);
    p->dmgTau = mean(&CpmMat::dmgTau);
    p->dmgRateExp = mean(&CpmMat::dmgRateExp);
    p->plTau = mean(&CpmMat::plTau);
    p->plRateExp = mean(&CpmMat::plRateExp);
    p->isoPrestress = mean(&CpmMat::isoPrestress);
    p->equivStrainShearContrib = mean(&CpmMat::equivStrainShearContrib);
    p->neverDamage = a.neverDamage || b.neverDamage;
    p->tanFrictionAngle = std::tan(mean(&CpmMat::frictionAngle));
    p->undamagedCohesion = mean(&CpmMat::sigmaT);
    p->E = E ? (*E)(a.id, b.id, a.young, b.young) : mean(&CpmMat::young);
    p->G = p->E * mean(&CpmMat::poisson);
    I.phys = p;
}

} // namespace yade
