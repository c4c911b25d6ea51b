#include <pkg/dem/polyhedra/Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys.hpp>
#include <cmath>

namespace yade {

void Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto& a = static_cast<const PolyhedraMat&>(*m1);
    const auto& b = static_cast<const PolyhedraMat&>(*m2);
    auto phys = std::make_shared<PolyhedraPhys>();
    phys->kn = a.young * b.young / (a.young + b.young);
    const Real sa = a.young * a.poisson, sb = b.young * b.poisson;
    phys->ks = sa * sb / (sa + sb);
    phys->tangensOfFrictionAngle = std::tan(std::min(a.frictionAngle, b.frictionAngle));
    I.phys = phys;
}

} // namespace yade
