// What the two Ip2 functors of FrictViscoPhys share: the MatchMaker attributes kn, kRatio and
// frictAngle, and the making of the physics from two materials and a damping ratio betan.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictViscoPhys.hpp>
#include <pkg/dem/MatchMaker.hpp>

namespace yade {

template <class M1, class M2> class FrictViscoPhysMaker : public IPhysFunctorOf<M1, M2, FrictViscoPhys> {
public:
    std::shared_ptr<MatchMaker> kn, kRatio, frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("kn", kn, "Normal stiffness per pair of materials [N/m] (MatchMaker or number; default: from the materials' young and the radii)");
        v.attr("kRatio", kRatio, "Ratio ks/kn per pair of materials (MatchMaker or number; default: ks from the materials' young·poisson and "
                                 "the radii)");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker or number; default: the smaller one)");
    }

protected:
    // The FrictViscoPhys of bodies I.id1, I.id2 of materials a, b with the damping ratio betan.
    std::shared_ptr<FrictViscoPhys> makePhys(const Interaction& I, const FrictMat& a, const FrictMat& b, Real betan) const {
        return makeFrictViscoPhys(*this->scene, I, a, b, betan, kn.get(), kRatio.get(), frictAngle.get(), this->getClassName());
    }
};

// kn, ks and tan φ as Ip2_FrictMat_FrictMat_FrictPhys (or the MatchMakers, which may be null), and
// cn = betan·2·sqrt(m*·kn) (FrictViscoPhysMaker.cpp).
std::shared_ptr<FrictViscoPhys> makeFrictViscoPhys(Scene& scene, const Interaction& I, const FrictMat& a, const FrictMat& b, Real betan,
        const MatchMaker* kn, const MatchMaker* kRatio, const MatchMaker* frictAngle, const std::string& functorName);

} // namespace yade
