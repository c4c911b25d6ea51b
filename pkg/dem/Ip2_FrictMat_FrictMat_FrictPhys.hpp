// FrictPhys of a new contact between two FrictMat bodies (3.2.1): springs in series.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/MatchMaker.hpp>

namespace yade {

class Ip2_FrictMat_FrictMat_FrictPhys : public IPhysFunctorOf<FrictMat, FrictMat, FrictPhys> {
public:
    static constexpr const char* classDoc = "Ip2 functor: FrictPhys of a new contact of two FrictMat bodies (3.2.1), kn = 2 E1 r1 E2 r2/(E1 r1 + E2 r2) (springs in series), ks = kn·(ks/kn of the materials), friction = min of the two angles.";
    std::shared_ptr<MatchMaker> kn, ks, frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("kn", kn, "Normal stiffness per pair of materials [N/m] (MatchMaker or number; default: the formula above)");
        v.attr("ks", ks, "Shear stiffness per pair of materials [N/m] (MatchMaker or number; default: the formula above)");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker or number; default: the smaller one)");
    }
    // kn = 2 E1 r1 E2 r2/(E1 r1 + E2 r2), ks the same with E·ν, friction angle the smaller one.
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
