#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/polyhedra/Ip2_FrictMat_PolyhedraMat_FrictPhys.hpp>
#include <cmath>
#include <stdexcept>

namespace yade {

void Ip2_FrictMat_PolyhedraMat_FrictPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto* geom = dynamic_cast<const GenericSpheresContact*>(I.geom.get());
    if (!geom) throw std::runtime_error("Ip2_FrictMat_PolyhedraMat_FrictPhys needs a ScGeom (Ig2_Sphere_Polyhedra_ScGeom), got " + I.geom->getClassName());
    const auto* fm = dynamic_cast<const PolyhedraMat*>(m1.get()) ? m2.get() : m1.get(); // (the dispatcher may give either order)
    const auto& a = static_cast<const FrictMat&>(*fm);
    const auto& b = static_cast<const PolyhedraMat&>(fm == m1.get() ? *m2 : *m1);
    const Real r = geom->refR1 > 0 ? geom->refR1 : geom->refR2;
    // the reference takes 1e9 Pa for the polyhedron's Young modulus whatever PolyhedraMat.young is (kn unchanged when it is
    // doubled), and its Poisson ratio
    const Real E0 = 1e9;
    auto phys = std::make_shared<FrictPhys>();
    phys->kn = 2 * r * a.young * E0 / (a.young + E0);
    const Real sa = a.young * a.poisson, sb = E0 * b.poisson;
    phys->ks = 2 * r * sa * sb / (sa + sb);
    phys->tangensOfFrictionAngle = std::tan(std::min(a.frictionAngle, b.frictionAngle));
    I.phys = phys;
}

} // namespace yade
