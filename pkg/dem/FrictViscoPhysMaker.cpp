#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/FrictViscoPhysMaker.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <stdexcept>

namespace yade {

std::shared_ptr<FrictViscoPhys> makeFrictViscoPhys(Scene& scene, const Interaction& I, const FrictMat& a, const FrictMat& b, Real betan,
        const MatchMaker* kn, const MatchMaker* kRatio, const MatchMaker* frictAngle, const std::string& functorName) {
    const auto* geom = dynamic_cast<const GenericSpheresContact*>(I.geom.get());
    if (!geom)
        throw std::runtime_error(functorName + " needs a GenericSpheresContact geometry (ScGeom), got " + I.geom->getClassName());
    auto phys = std::make_shared<FrictViscoPhys>();
    // the stiffnesses of Ip2_FrictMat_FrictMat_FrictPhys (a flat boundary takes the other body's radius)
    const Real ra = geom->refR1 > 0 ? geom->refR1 : geom->refR2;
    const Real rb = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
    phys->kn = 2 * a.young * ra * b.young * rb / (a.young * ra + b.young * rb);
    phys->ks = 2 * a.young * ra * a.poisson * b.young * rb * b.poisson / (a.young * ra * a.poisson + b.young * rb * b.poisson);
    // (the reference calls these MatchMakers without the materials' values: algo 'avg' etc. is an error)
    if (kn) phys->kn = (*kn)(a.id, b.id);
    if (kRatio) phys->ks = (*kRatio)(a.id, b.id) * phys->kn;
    phys->tangensOfFrictionAngle =
            std::tan(frictAngle ? (*frictAngle)(a.id, b.id, a.frictionAngle, b.frictionAngle) : std::min(a.frictionAngle, b.frictionAngle));
    if (betan != 0) {
        // the effective mass: a body that is not dynamic counts as infinitely heavy (both not dynamic: the reduced mass)
        const BodyStore::Columns c = scene.bodies.hot().columns();
        const Real m1 = c.mass[I.id1], m2 = c.mass[I.id2];
        const bool dynamic1 = (c.blockedDOFsMask[I.id1] & State::DOF_ALL) != State::DOF_ALL, dynamic2 = (c.blockedDOFsMask[I.id2] & State::DOF_ALL) != State::DOF_ALL;
        const Real mass = (dynamic1 && !dynamic2) ? m1 : (dynamic2 && !dynamic1) ? m2 : m1 * m2 / (m1 + m2);
        phys->cn_crit = 2 * std::sqrt(mass * phys->kn);
        phys->cn = betan * phys->cn_crit;
    } else {
        phys->cn = 0; // (cn_crit stays NaN, as in the reference)
    }
    return phys;
}

} // namespace yade
