// PolyhedraPhys of a new contact of two PolyhedraMat bodies: stiffnesses in series.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/dem/polyhedra/PolyhedraMat.hpp>
#include <pkg/dem/polyhedra/PolyhedraPhys.hpp>

namespace yade {

class Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys : public IPhysFunctorOf<PolyhedraMat, PolyhedraMat, PolyhedraPhys> {
public:
    static constexpr const char* classDoc = "Computes the PolyhedraPhys of a new contact from the two PolyhedraMat: 1/kn = 1/Y1 + 1/Y2, 1/ks = 1/(Y1 P1) + 1/(Y2 P2) (Y: young, P: poisson), friction angle the smaller of the two. The units of kn depend on Law2_PolyhedraGeom_PolyhedraPhys_Volumetric.volumePower.";
    template <class V> void visit(V& v) { IPhysFunctor::visit(v); }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
