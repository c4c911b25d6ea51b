#include <pkg/dem/Ip2_FrictMat_FrictMat_FrictPhys.hpp>
#include <pkg/dem/concrete/Ip2_FrictMat_CpmMat_FrictPhys.hpp>

namespace yade {

void Ip2_FrictMat_CpmMat_FrictPhys::go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) {
    if (I.phys) return;
    Ip2_FrictMat_FrictMat_FrictPhys plain; // (a CpmMat is a FrictMat: the same constants)
    plain.frictAngle = frictAngle;
    plain.go(m1, m2, I);
}

} // namespace yade
