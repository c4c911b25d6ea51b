// L3Geom of a facet and a sphere (contact with the face, an edge or a vertex).
#pragma once
#include <pkg/dem/localframe/Ig2_Sphere_Sphere_L3Geom.hpp>

namespace yade {

class Ig2_Facet_Sphere_L3Geom : public Ig2_Sphere_Sphere_L3Geom {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: L3Geom of a Facet and a Sphere, updated as by Ig2_Sphere_Sphere_L3Geom (whose attributes it uses). The normal "
            "goes from the facet's nearest point (on the face, an edge or a vertex) to the sphere's centre, the contact point is that "
            "nearest point, u_x = distance - r; the facet counts as a radius of 0.";
    template <class V> void visit(V& v) { Ig2_Sphere_Sphere_L3Geom::visit(v); }
    std::vector<std::string> argTypes() const override { return {"Facet", "Sphere"}; }
    bool goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c) override;
};

} // namespace yade
