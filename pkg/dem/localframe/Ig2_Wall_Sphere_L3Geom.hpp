// L3Geom of an axis-aligned wall and a sphere.
#pragma once
#include <pkg/dem/localframe/Ig2_Sphere_Sphere_L3Geom.hpp>

namespace yade {

class Ig2_Wall_Sphere_L3Geom : public Ig2_Sphere_Sphere_L3Geom {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: L3Geom of a Wall and a Sphere, updated as by Ig2_Sphere_Sphere_L3Geom (whose attributes it uses). The normal is "
            "the wall's axis, towards the sphere (or the wall's sense), the contact point the sphere's centre projected on the wall, "
            "u_x = |distance| - r; the wall counts as a radius of 0.";
    template <class V> void visit(V& v) { Ig2_Sphere_Sphere_L3Geom::visit(v); }
    std::vector<std::string> argTypes() const override { return {"Wall", "Sphere"}; }
    bool goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c) override;
};

} // namespace yade
