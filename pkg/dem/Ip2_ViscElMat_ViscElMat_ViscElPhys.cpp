#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/Ip2_ViscElMat_ViscElMat_ViscElPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <stdexcept>

namespace yade {

namespace {
bool given(Real x) { return !std::isnan(x); }
// Two materials' constants connected in series.
Real series(Real a, Real b) { return a + b != 0 ? a * b / (a + b) : 0; }
// The restitution coefficient of a linear spring-dashpot whose damping is x times the critical one, the
// normal force cut at zero (the contact ends when k·u + c·u' reaches 0), in units of the natural frequency:
// e = exp(-x/w·(π - atan2(2xw, w² - x²))), w = sqrt(1 - x²), below critical damping; above it the overlap
// A·(exp(s1·t) - exp(s2·t)), s = -x ± w', w' = sqrt(x² - 1), and e = -u'(t)/u'(0) at the t where the force is 0.
Real linearRestitution(Real x) {
    if (x <= 0) return 1;
    if (x < 1) {
        const Real w = std::sqrt(1 - x * x);
        return std::exp(-x / w * (M_PI - std::atan2(2 * x * w, w * w - x * x)));
    }
    if (x == 1) return std::exp(-2.);
    const Real w = std::sqrt(x * x - 1), s1 = -x + w, s2 = -x - w;
    const Real t = std::log((1 + 2 * x * s2) / (1 + 2 * x * s1)) / (2 * w);
    return -(s1 * std::exp(s1 * t) - s2 * std::exp(s2 * t)) / (2 * w);
}
// A material's contact time and restitution coefficients, where given: tc > 0, en and et in (0, 1].
void checkPournin(const ViscElMat& m) {
    const auto bad = [&](const char* what, Real x) {
        throw std::invalid_argument("ViscElMat (material " + std::to_string(m.id) + "): " + what + ", got " + std::to_string(x));
    };
    if (given(m.tc) && !(m.tc > 0)) bad("the contact time tc must be positive", m.tc);
    if (given(m.en) && !(m.en > 0 && m.en <= 1)) bad("the restitution coefficient en must be in (0, 1]", m.en);
    if (given(m.et) && !(m.et > 0 && m.et <= 1)) bad("the restitution coefficient et must be in (0, 1]", m.et);
}
} // namespace

Real Ip2_ViscElMat_ViscElMat_ViscElPhys::linearDampingForRestitution(Real e, Real k, Real m) {
    if (!(e > 0 && e <= 1)) throw std::invalid_argument("ViscElMat: the restitution coefficient en must be in (0, 1], got " + std::to_string(e));
    if (e == 1) return 0;
    Real lo = 0, hi = 1; // the ratio to the critical damping: e falls from 1 towards 0 as it grows
    while (hi < 1e6 && linearRestitution(hi) > e) hi *= 2;
    for (int i = 0; i < 200 && hi - lo > 1e-16 * hi; ++i) {
        const Real mid = 0.5 * (lo + hi);
        (linearRestitution(mid) > e ? lo : hi) = mid;
    }
    return (lo + hi) * std::sqrt(k * m); // c = 2·x·sqrt(k·m), x the midpoint
}

void Ip2_ViscElMat_ViscElMat_ViscElPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto& a = static_cast<const ViscElMat&>(*m1);
    const auto& b = static_cast<const ViscElMat&>(*m2);
    if (a.lubrication || b.lubrication)
        throw std::invalid_argument("ViscElMat.lubrication is not available in this build (materials " + std::to_string(a.id) + ", " +
                std::to_string(b.id) + "); set it to False");
    checkPournin(a);
    checkPournin(b);
    const auto* geom = dynamic_cast<const ScGeom*>(I.geom.get());
    if (!geom) throw std::runtime_error("Ip2_ViscElMat_ViscElMat_ViscElPhys needs an ScGeom geometry, got " + I.geom->getClassName());

    // the reduced mass of the pair (a body of mass 0, a facet or a wall, counts as the other's mass)
    Real mass1 = scene->bodies.hot().columns().mass[I.id1], mass2 = scene->bodies.hot().columns().mass[I.id2];
    if (mass1 == 0) mass1 = mass2;
    if (mass2 == 0) mass2 = mass1;
    const Real massR = mass1 + mass2 > 0 ? mass1 * mass2 / (mass1 + mass2) : 0;

    auto phys = std::make_shared<ViscElPhys>();
    const Real Tc = tc ? (*tc)(a.id, b.id) : 0.5 * (a.tc + b.tc);
    const Real En = en ? (*en)(a.id, b.id) : 0.5 * (a.en + b.en);
    const Real Et = et ? (*et)(a.id, b.id) : 0.5 * (a.et + b.et);
    if (given(Tc) && given(En) && given(Et)) { // Pournin et al. 2001
        if (!(Tc > 0)) throw std::invalid_argument("ViscElMat: the contact time tc must be positive, got " + std::to_string(Tc));
        if (!(En > 0 && En <= 1 && Et > 0 && Et <= 1))
            throw std::invalid_argument("ViscElMat: the restitution coefficients en, et must be in (0, 1], got " + std::to_string(En) + ", " +
                    std::to_string(Et));
        const Real ln = std::log(En), lt = std::log(Et);
        phys->kn = massR * (M_PI * M_PI + ln * ln) / (Tc * Tc);
        phys->cn = -2 * massR * ln / Tc + 0.0; // (+0.0: no -0 for en = 1)
        phys->ks = 2. / 7. * massR * (M_PI * M_PI + lt * lt) / (Tc * Tc);
        phys->cs = -2. / 7. * 2 * massR * lt / Tc + 0.0;
    } else if (given(a.kn) && given(a.ks) && given(a.cn) && given(a.cs) && given(b.kn) && given(b.ks) && given(b.cn) && given(b.cs)) {
        phys->kn = series(a.kn, b.kn);
        phys->ks = series(a.ks, b.ks);
        phys->cn = series(a.cn, b.cn);
        phys->cs = series(a.cs, b.cs);
    } else if (!given(a.kn) && !given(a.ks) && !given(b.kn) && !given(b.ks) &&
               ((given(a.cn) && given(a.cs) && given(b.cn) && given(b.cs)) || (given(a.en) && given(b.en)))) {
        // from Young's modulus: kn = young·(2·radius), ks = poisson·kn (a flat boundary takes the other's radius)
        const Real r1 = geom->refR1 > 0 ? geom->refR1 : geom->refR2, r2 = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
        const Real kn1 = a.young * 2 * r1, kn2 = b.young * 2 * r2;
        phys->kn = series(kn1, kn2);
        phys->ks = series(a.poisson * kn1, b.poisson * kn2);
        if (given(a.cn) && given(a.cs) && given(b.cn) && given(b.cs)) {
            phys->cn = series(a.cn, b.cn);
            phys->cs = series(a.cs, b.cs);
        } else {
            phys->cn = linearDampingForRestitution(0.5 * (a.en + b.en), phys->kn, massR);
            phys->cs = 0;
        }
    } else {
        throw std::invalid_argument("ViscElMat: materials " + std::to_string(a.id) + " and " + std::to_string(b.id) +
                " do not give the contact's constants: give both of them tc, en and et, or kn, ks, cn and cs, or cn and cs (or en) "
                "with young and poisson");
    }
    if (!(std::isfinite(phys->kn) && std::isfinite(phys->ks) && std::isfinite(phys->cn) && std::isfinite(phys->cs)))
        throw std::invalid_argument("ViscElMat: materials " + std::to_string(a.id) + " and " + std::to_string(b.id) +
                " give a contact constant that is not finite");
    const Real angle = frictAngle ? (*frictAngle)(a.id, b.id, a.frictionAngle, b.frictionAngle) : std::min(a.frictionAngle, b.frictionAngle);
    phys->tangensOfFrictionAngle = std::tan(angle);
    phys->mR = a.mR + b.mR > 0 ? 2 * a.mR * b.mR / (a.mR + b.mR) : 0;
    phys->mRtype = a.mRtype;
    if (phys->mR > 0 && phys->mRtype != 1 && phys->mRtype != 2) // (the reference aborts the process)
        throw std::invalid_argument("ViscElMat (material " + std::to_string(a.id) + "): mRtype must be 1 or 2, got " +
                std::to_string(a.mRtype));
    I.phys = phys;
}

} // namespace yade
