// Linear law on L6Geom: springs in the local frame for the three displacements and the three rotations.
#pragma once
#include <pkg/dem/localframe/L6Geom.hpp>
#include <pkg/dem/localframe/Law2_L3Geom_FrictPhys_ElPerfPl.hpp>

namespace yade {

class Law2_L6Geom_FrictPhys_Linear : public Law2_L3Geom_FrictPhys_ElPerfPl {
public:
    static constexpr const char* classDoc =
            "Basic law for testing L6Geom, linear in both normal and shear sense, without slip or breakage: local force "
            "(kn·(u-u0)_x, ks·(u-u0)_y, ks·(u-u0)_z), local torque (kn·charLen·(phi-phi0)_x, ks·charLen·(phi-phi0)_y, "
            "ks·charLen·(phi-phi0)_z) on body 1, their opposites on body 2.";
    Real charLen = 1;
    template <class V> void visit(V& v) {
        Law2_L3Geom_FrictPhys_ElPerfPl::visit(v);
        v.attr("charLen", charLen, "Characteristic length with the meaning of the stiffness ratios bending/shear and torsion/normal [m]");
    }
    std::vector<std::string> argTypes() const override { return {"L6Geom", "FrictPhys"}; }
    bool goLocal(L3Geom& geom, FrictPhys& phys, Body::id_t id1, Body::id_t id2) override;
};

} // namespace yade
