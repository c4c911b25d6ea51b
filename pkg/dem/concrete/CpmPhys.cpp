#include <cmath>
#include <pkg/dem/concrete/CpmPhys.hpp>
#include <stdexcept>
#include <string>

namespace yade {

Real CpmPhys::funcG(Real kappaD, Real epsCrackOnset, Real epsFracture, bool neverDamage, int damLaw) {
    if (damLaw != 0 && damLaw != 1) throw std::invalid_argument("CpmPhys.funcG: damLaw must be 0 (linear) or 1 (exponential), got " + std::to_string(damLaw));
    if (kappaD <= epsCrackOnset || neverDamage) return 0;
    if (damLaw == 0) return (1 - epsCrackOnset / kappaD) * epsFracture / (epsFracture - epsCrackOnset); // linear softening (not capped at 1)
    return 1 - (epsCrackOnset / kappaD) * std::exp(-(kappaD - epsCrackOnset) / epsFracture);             // exponential
}

Real CpmPhys::funcGInv(Real omega, Real epsCrackOnset, Real epsFracture, bool neverDamage, int damLaw) {
    if (damLaw != 0 && damLaw != 1) throw std::invalid_argument("CpmPhys.funcGInv: damLaw must be 0 (linear) or 1 (exponential), got " + std::to_string(damLaw));
    if (omega == 0 || neverDamage) return 0;
    if (damLaw == 0) return epsCrackOnset / (1 - omega * (epsFracture - epsCrackOnset) / epsFracture);
    // exponential: Newton's method on 1 - (ε0/κ)·exp(-(κ-ε0)/εf) = ω, which rises with κ (no root for ω >= 1)
    Real k = epsCrackOnset;
    for (int i = 0; i < 100 && omega < 1; ++i) {
        const Real e = std::exp(-(k - epsCrackOnset) / epsFracture);
        const Real f = 1 - epsCrackOnset / k * e - omega;
        const Real df = epsCrackOnset * e * (1 / (k * k) + 1 / (k * epsFracture));
        const Real next = k - f / df;
        if (!std::isfinite(next) || next <= 0) break;
        if (std::abs(next - k) <= 1e-15 * std::abs(k)) return next;
        k = next;
    }
    throw std::runtime_error("CpmPhys.funcGInv: no convergence (no strain gives the damage " + std::to_string(omega) + ")");
}

void CpmPhys::setDamage(Real dmg) {
    if (!std::isfinite(epsCrackOnset) || !std::isfinite(epsFracture))
        throw std::invalid_argument("CpmPhys.setDamage: epsCrackOnset and epsFracture must be set (finite)");
    omega = dmg;
    kappaD = funcGInv(dmg, epsCrackOnset, epsFracture, neverDamage, damLaw);
}

} // namespace yade
