// FrictViscoPhys of a new contact between two FrictViscoMat bodies: the stiffnesses of
// Ip2_FrictMat_FrictMat_FrictPhys, and the normal viscous constant cn = betan·2·sqrt(m*·kn).
#pragma once
#include <pkg/dem/FrictViscoMat.hpp>
#include <pkg/dem/FrictViscoPhysMaker.hpp>

namespace yade {

class Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys : public FrictViscoPhysMaker<FrictViscoMat, FrictViscoMat> {
public:
    static constexpr const char* classDoc =
            "Makes FrictViscoPhys for two FrictViscoMat: Ip2_FrictMat_FrictMat_FrictPhys with damping in the normal direction. "
            "kn = 2·E1·r1·E2·r2/(E1·r1 + E2·r2), ks = the same with E·ν (or kRatio·kn), tan φ of the smaller friction angle; "
            "cn = betan·cn_crit, cn_crit = 2·sqrt(m*·kn), m* = m1·m2/(m1+m2), or the mass of the dynamic body when the other is not "
            "dynamic; betan is the materials' mean, or the one that is not 0 when the other is 0 (then cn = 0 and cn_crit NaN if both are).";
    template <class V> void visit(V& v) { FrictViscoPhysMaker::visit(v); } // (kn, kRatio, frictAngle)
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
