// FrictPhys of a new contact of a FrictMat sphere and a PolyhedraMat polyhedron (with Ig2_Sphere_Polyhedra_ScGeom).
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/polyhedra/PolyhedraMat.hpp>

namespace yade {

class Ip2_FrictMat_PolyhedraMat_FrictPhys : public IPhysFunctorOf<FrictMat, PolyhedraMat, FrictPhys> {
public:
    static constexpr const char* classDoc = "FrictPhys of a new contact of a FrictMat and a PolyhedraMat body, as the reference computes it (found by running it): kn = 2 r E1 E0/(E1 + E0), ks = 2 r E1 P1 E0 P2/(E1 P1 + E0 P2), r the sphere's radius, E1, P1 the FrictMat's young and poisson, P2 the PolyhedraMat's poisson and E0 = 1e9 Pa in place of its young; friction angle the smaller one.";
    template <class V> void visit(V& v) { IPhysFunctor::visit(v); }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
