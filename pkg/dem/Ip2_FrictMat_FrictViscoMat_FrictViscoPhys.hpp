// FrictViscoPhys of a new contact between a FrictMat and a FrictViscoMat body: the stiffnesses of
// Ip2_FrictMat_FrictMat_FrictPhys, and the normal viscous constant cn = betan·2·sqrt(m*·kn).
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictViscoMat.hpp>
#include <pkg/dem/FrictViscoPhys.hpp>
#include <pkg/dem/MatchMaker.hpp>

namespace yade {

class Ip2_FrictMat_FrictViscoMat_FrictViscoPhys : public IPhysFunctorOf<FrictMat, FrictViscoMat, FrictViscoPhys> {
public:
    static constexpr const char* classDoc =
            "Makes FrictViscoPhys for a FrictMat and a FrictViscoMat: Ip2_FrictMat_FrictMat_FrictPhys with damping in the normal "
            "direction. kn = 2·E1·r1·E2·r2/(E1·r1 + E2·r2), ks = the same with E·ν (or kRatio·kn), tan φ of the smaller friction "
            "angle; cn = betan·cn_crit with betan the FrictViscoMat's, cn_crit = 2·sqrt(m*·kn), m* = m1·m2/(m1+m2), or the mass of "
            "the dynamic body when the other is not dynamic. With betan = 0, cn = 0 and cn_crit is not computed (NaN).";
    std::shared_ptr<MatchMaker> kn, kRatio, frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("kn", kn, "Normal stiffness per pair of materials [N/m] (MatchMaker or number; default: from the materials' young and the radii)");
        v.attr("kRatio", kRatio, "Ratio ks/kn per pair of materials (MatchMaker or number; default: ks from the materials' young·poisson and "
                                 "the radii)");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker or number; default: the smaller one)");
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;

    // The FrictViscoPhys of bodies I.id1, I.id2 of materials a, b with the damping ratio betan (used by
    // Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys too); kn, kRatio, frictAngle may be null.
    static std::shared_ptr<FrictViscoPhys> makePhys(Scene& scene, const Interaction& I, const FrictMat& a, const FrictMat& b, Real betan,
            const MatchMaker* kn, const MatchMaker* kRatio, const MatchMaker* frictAngle, const char* functorName);
};

} // namespace yade
