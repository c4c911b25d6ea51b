// Contact of two spheres with six degrees of freedom: Ig2_Sphere_Sphere_ScGeom's geometry, and the
// relative rotation of the spheres since the contact began (ScGeom6D: twist and bending).
#pragma once
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/cohesive/ScGeom6D.hpp>

namespace yade {

class Ig2_Sphere_Sphere_ScGeom6D : public Ig2_Sphere_Sphere_ScGeom {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: ScGeom6D of two spheres, Ig2_Sphere_Sphere_ScGeom's geometry (3.3.1, 3.3.2) and the relative rotation since the "
            "contact began, twist about the normal and bending perpendicular to it. interactionDetectionFactor > 1 (with "
            "Bo1_Sphere_Aabb.aabbEnlargeFactor) makes contacts of spheres that are apart, e.g. for cohesive packings.";
    bool updateRotations = true, creep = false;
    template <class V> void visit(V& v) {
        Ig2_Sphere_Sphere_ScGeom::visit(v);
        v.attr("updateRotations", updateRotations, "Compute twist and bending at every step (false: they keep their last values, for laws "
                                                   "that need no moments)");
        v.attr("creep", creep, "Take the rotational creep ScGeom6D.twistCreep out of the relative rotation");
    }
    std::string producedType() const override { return registeredName<ScGeom6D>(); }
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force, Interaction& I) override;
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;

private:
    bool contact6D(Real r1, Real r2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
};

} // namespace yade
