// Elastic material: Young's modulus and Poisson's ratio (used as shear/normal stiffness ratio).
#pragma once
#include <core/Material.hpp>

namespace yade {

class ElastMat : public Material {
public:
    static constexpr const char* classDoc = "Elastic material: Young's modulus and Poisson's ratio (used as the ratio of shear to normal contact stiffness).";
    Real young = 1e9;
    Real poisson = 0.25;
    template <class V> void visit(V& v) {
        Material::visit(v);
        v.attr("young", young, "Young's modulus [Pa]", Attr::positive);
        v.attr("poisson", poisson, "Poisson's ratio, or the ratio ks/kn in FrictPhys laws [-]", Attr::finite);
    }
    YADE_INDEXABLE(ElastMat)
};

} // namespace yade
