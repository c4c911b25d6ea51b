// Physics of a polyhedra contact: FrictPhys whose kn, ks are volumetric stiffnesses.
#pragma once
#include <pkg/dem/FrictPhys.hpp>

namespace yade {

class PolyhedraPhys : public FrictPhys {
public:
    static constexpr const char* classDoc = "Simple elastic material with friction for volumetric constitutive laws: kn [N/m³ with volumePower 1] multiplies the overlap volume, ks [N/m] the shear displacement.";
    template <class V> void visit(V& v) { FrictPhys::visit(v); }
    YADE_INDEXABLE(PolyhedraPhys)
};

} // namespace yade
