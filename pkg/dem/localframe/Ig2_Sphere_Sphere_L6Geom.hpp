// L6Geom of two spheres: Ig2_Sphere_Sphere_L3Geom's update, plus the relative rotation phi.
#pragma once
#include <pkg/dem/localframe/Ig2_Sphere_Sphere_L3Geom.hpp>

namespace yade {

class Ig2_Sphere_Sphere_L6Geom : public Ig2_Sphere_Sphere_L3Geom {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: L6Geom of two spheres, updated as by Ig2_Sphere_Sphere_L3Geom, and phi += T_mid·Δt(ω2 - ω1) (T_mid: the "
            "mid-step trsf).";
    template <class V> void visit(V& v) { Ig2_Sphere_Sphere_L3Geom::visit(v); }
    std::string producedType() const override { return "L6Geom"; }

protected:
    bool makesL6() const override { return true; }
};

} // namespace yade
