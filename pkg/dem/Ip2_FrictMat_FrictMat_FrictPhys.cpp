#include <pkg/dem/Ip2_FrictMat_FrictMat_FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <stdexcept>

namespace yade {

void Ip2_FrictMat_FrictMat_FrictPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto* geom = dynamic_cast<const GenericSpheresContact*>(I.geom.get());
    if (!geom) throw std::runtime_error("Ip2_FrictMat_FrictMat_FrictPhys needs a GenericSpheresContact geometry (ScGeom), got " + I.geom->getClassName());
    const auto& a = static_cast<const FrictMat&>(*m1);
    const auto& b = static_cast<const FrictMat&>(*m2);
    // A flat boundary (facet, wall) has no radius of its own: it takes the other body's.
    const Real ra = geom->refR1 > 0 ? geom->refR1 : geom->refR2;
    const Real rb = geom->refR2 > 0 ? geom->refR2 : geom->refR1;
    auto phys = std::make_shared<FrictPhys>();
    phys->kn = 2 * a.young * ra * b.young * rb / (a.young * ra + b.young * rb);
    phys->ks = 2 * a.young * ra * a.poisson * b.young * rb * b.poisson / (a.young * ra * a.poisson + b.young * rb * b.poisson);
    if (kn) phys->kn = (*kn)(a.id, b.id, phys->kn, phys->kn);
    if (ks) phys->ks = (*ks)(a.id, b.id, phys->ks, phys->ks);
    phys->tangensOfFrictionAngle =
            std::tan(frictAngle ? (*frictAngle)(a.id, b.id, a.frictionAngle, b.frictionAngle) : std::min(a.frictionAngle, b.frictionAngle));
    I.phys = phys;
}

} // namespace yade
