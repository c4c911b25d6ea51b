// FrictPhys of a new contact between two FrictMat bodies (3.2.1): springs in series.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class Ip2_FrictMat_FrictMat_FrictPhys : public IPhysFunctorOf<FrictMat, FrictMat, FrictPhys> {
public:
    template <class V> void visit(V& v) { IPhysFunctor::visit(v); }
    // kn = 2 E1 r1 E2 r2/(E1 r1 + E2 r2), ks the same with E·ν, friction angle the smaller one.
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
