#include <core/Scene.hpp>
#include <pkg/dem/localframe/Law2_L3Geom_FrictPhys_ElPerfPl.hpp>
#include <pkg/dem/localframe/LocalFrameMath.hpp>

namespace yade {

bool Law2_L3Geom_FrictPhys_ElPerfPl::go(IGeom& geom, IPhys& phys, Interaction& I) {
    return goLocal(static_cast<L3Geom&>(geom), static_cast<FrictPhys&>(phys), I.id1, I.id2);
}

void Law2_L3Geom_FrictPhys_ElPerfPl::goBatch(const Contact* c, size_t n, char* keep) {
    for (size_t j = 0; j < n; ++j) keep[j] = goLocal(static_cast<L3Geom&>(*c[j].geom), static_cast<FrictPhys&>(*c[j].phys), c[j].id1, c[j].id2);
}

void Law2_L3Geom_FrictPhys_ElPerfPl::prepare() {
    if (!scene->trackEnergy) return;
    elastId = scene->energy.term("elastPotential", false);
    plastId = scene->energy.term("plastDissip", true);
}

bool Law2_L3Geom_FrictPhys_ElPerfPl::goLocal(L3Geom& g, FrictPhys& p, Body::id_t id1, Body::id_t id2) {
    const Vector3r uel = g.u - g.u0;
    if (uel[0] > 0 && !noBreak) return false;
    Vector3r F(p.kn * uel[0], p.ks * uel[1], p.ks * uel[2]);
    if (!noSlip) { // Mohr-Coulomb: back onto the cone (no shear force in tension), the slip into u0
        const Real maxFs = -std::min(Real(0), F[0] * p.tangensOfFrictionAngle);
        const Real fs2 = F[1] * F[1] + F[2] * F[2];
        if (fs2 > maxFs * maxFs) {
            const Real ratio = std::sqrt(maxFs * maxFs / fs2); // (so written, the reference's bits)
            const Real slip1 = (1 - ratio) * uel[1], slip2 = (1 - ratio) * uel[2];
            g.u0[1] += slip1;
            g.u0[2] += slip2;
            F[1] *= ratio;
            F[2] *= ratio;
            if (scene->trackEnergy) scene->energy.add(plastId, std::abs(F[1] * slip1 + F[2] * slip2));
        }
    }
    if (scene->trackEnergy)
        scene->energy.add(elastId, 0.5 * (F[0] * F[0] / p.kn + (p.ks > 0 ? (F[1] * F[1] + F[2] * F[2]) / p.ks : 0)));
    g.F = F;
    applyLocal(g, p, id1, id2, F, nullptr);
    return true;
}

void Law2_L3Geom_FrictPhys_ElPerfPl::applyLocal(const L3Geom& g, FrictPhys& p, Body::id_t id1, Body::id_t id2, const Vector3r& F,
        const Vector3r* T) const {
    const Vector3r globalF = localframe::transposedTimes(g.trsf, F);
    p.normalForce = localframe::dot(g.normal, globalF) * g.normal;
    p.shearForce = globalF - p.normalForce;
    const Vector3r b1 = g.normal * (g.refR1 + 0.5 * g.u[0]), b2 = -g.normal * (g.refR2 + 0.5 * g.u[0]);
    Vector3r t1 = b1.cross(globalF), t2 = b2.cross(-globalF);
    if (T) {
        const Vector3r globalT = localframe::transposedTimes(g.trsf, *T);
        t1 += globalT;
        t2 -= globalT;
    }
    scene->forces.addContact(id1, id2, globalF, t1, t2);
}

} // namespace yade
