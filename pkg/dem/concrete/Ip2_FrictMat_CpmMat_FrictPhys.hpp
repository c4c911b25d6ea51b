// FrictPhys of a new contact between a FrictMat and a CpmMat body: as between two FrictMat bodies.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pkg/dem/concrete/CpmMat.hpp>

namespace yade {

class Ip2_FrictMat_CpmMat_FrictPhys : public IPhysFunctorOf<FrictMat, CpmMat, FrictPhys> {
public:
    static constexpr const char* classDoc =
            "Makes FrictPhys for a FrictMat and a CpmMat body from their young, poisson and frictionAngle, as "
            "Ip2_FrictMat_FrictMat_FrictPhys (the reference's rule, found by running it): kn = 2·E1·r1·E2·r2/(E1·r1 + E2·r2), ks the "
            "same with E·ν, tan φ of the smaller friction angle (or of frictAngle). Law2_ScGeom_FrictPhys_CundallStrack then acts.";
    std::shared_ptr<MatchMaker> frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker or number; default: the smaller "
                                         "one), as Ip2_FrictMat_FrictMat_FrictPhys.frictAngle");
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
