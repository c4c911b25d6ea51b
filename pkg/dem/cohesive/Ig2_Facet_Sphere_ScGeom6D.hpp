// Contact of a facet and a sphere with six degrees of freedom: Ig2_Facet_Sphere_ScGeom's geometry (the
// facet seen as a sphere of twice the sphere's radius), and the relative rotation of the two bodies since
// the contact began (ScGeom6D: twist and bending).
#pragma once
#include <pkg/dem/Ig2_Facet_Sphere_ScGeom.hpp>
#include <pkg/dem/cohesive/ScGeom6D.hpp>

namespace yade {

class Ig2_Facet_Sphere_ScGeom6D : public Ig2_Facet_Sphere_ScGeom {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: ScGeom6D of a Facet and a Sphere, Ig2_Facet_Sphere_ScGeom's geometry (contact with the face, an edge or a "
            "vertex) and the relative rotation of the facet and the sphere since the contact began, twist and bending.";
    template <class V> void visit(V& v) { Ig2_Facet_Sphere_ScGeom::visit(v); }
    std::string producedType() const override { return registeredName<ScGeom6D>(); }
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force, Interaction& I) override;
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;

private:
    bool contact6D(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
};

} // namespace yade
