#include <pkg/dem/Ip2_FrictMat_FrictViscoMat_FrictViscoPhys.hpp>
#include <stdexcept>

namespace yade {

void Ip2_FrictMat_FrictViscoMat_FrictViscoPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    // The FrictViscoMat gives betan: the second material when both are (as the reference), else whichever is. (The
    // reference stops on a failed assertion when the FrictViscoMat body is the first; here the order does not matter.)
    const auto* visco = dynamic_cast<const FrictViscoMat*>(m2.get());
    if (!visco) visco = dynamic_cast<const FrictViscoMat*>(m1.get());
    if (!visco)
        throw std::invalid_argument("Ip2_FrictMat_FrictViscoMat_FrictViscoPhys: neither material is a FrictViscoMat (" + m1->getClassName() + ", " +
                m2->getClassName() + ")");
    I.phys = makePhys(I, static_cast<const FrictMat&>(*m1), static_cast<const FrictMat&>(*m2), visco->betan);
}

} // namespace yade
