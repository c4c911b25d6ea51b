#include <pkg/dem/Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys.hpp>

namespace yade {

void Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    const auto& a = static_cast<const FrictViscoMat&>(*m1);
    const auto& b = static_cast<const FrictViscoMat&>(*m2);
    // the reference's rule: the mean, unless one of them is 0
    const Real betan = a.betan == 0 ? b.betan : b.betan == 0 ? a.betan : (a.betan + b.betan) / 2;
    I.phys = makePhys(I, a, b, betan);
}

} // namespace yade
