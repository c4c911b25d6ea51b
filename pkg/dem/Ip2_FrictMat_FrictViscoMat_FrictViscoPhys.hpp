// FrictViscoPhys of a new contact between a FrictMat and a FrictViscoMat body: the stiffnesses of
// Ip2_FrictMat_FrictMat_FrictPhys, and the normal viscous constant cn = betan·2·sqrt(m*·kn).
#pragma once
#include <pkg/dem/FrictViscoMat.hpp>
#include <pkg/dem/FrictViscoPhysMaker.hpp>

namespace yade {

class Ip2_FrictMat_FrictViscoMat_FrictViscoPhys : public FrictViscoPhysMaker<FrictMat, FrictViscoMat> {
public:
    static constexpr const char* classDoc =
            "Makes FrictViscoPhys for a FrictMat and a FrictViscoMat: Ip2_FrictMat_FrictMat_FrictPhys with damping in the normal "
            "direction. kn = 2·E1·r1·E2·r2/(E1·r1 + E2·r2), ks = the same with E·ν (or kRatio·kn), tan φ of the smaller friction "
            "angle; cn = betan·cn_crit with betan the FrictViscoMat's, cn_crit = 2·sqrt(m*·kn), m* = m1·m2/(m1+m2), or the mass of "
            "the dynamic body when the other is not dynamic. With betan = 0, cn = 0 and cn_crit is not computed (NaN).";
    template <class V> void visit(V& v) { FrictViscoPhysMaker::visit(v); } // (kn, kRatio, frictAngle)
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
