// Geometry of a contact with six degrees of freedom: ScGeom (normal, shear) and the relative
// rotation of the two bodies since the contact began, split into twist (about the normal) and
// bending (perpendicular to it).
#pragma once
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class ScGeom6D : public ScGeom {
public:
    static constexpr const char* classDoc =
            "Contact geometry with 6 degrees of freedom (normal, 2 shear, twist, 2 bending): ScGeom's incremental shear, and the relative "
            "rotation of the bodies since the contact began (initialOrientation1, initialOrientation2), as twist (about the normal) and "
            "bending (a rotation vector perpendicular to it).";
    Quaternionr initialOrientation1 = Quaternionr::Identity(), initialOrientation2 = Quaternionr::Identity(),
                twistCreep = Quaternionr::Identity();
    Real twist = 0;
    Vector3r bending = Vector3r::Zero();
    template <class V> void visit(V& v) {
        ScGeom::visit(v);
        v.attr("initialOrientation1", initialOrientation1, "Orientation of body 1 when the contact began (or became cohesive)");
        v.attr("initialOrientation2", initialOrientation2, "Orientation of body 2 when the contact began (or became cohesive)");
        v.attr("twistCreep", twistCreep, "Rotational creep taken out of the relative rotation (Ig2_Sphere_Sphere_ScGeom6D.creep)");
        v.attr("twist", twist, "Relative rotation about the normal since the contact began (elastic twist angle) [rad]");
        v.attr("bending", bending, "Relative rotation perpendicular to the normal since the contact began, as a rotation vector "
                                   "(axis·angle) [rad]");
    }
    // The rotations start from the bodies' orientations now: twist and bending are zero.
    void initRotations(const Quaternionr& ori1, const Quaternionr& ori2);
    // twist and bending from the bodies' orientations now (and the creep, with `creep`).
    void precomputeRotations(const Quaternionr& ori1, const Quaternionr& ori2, bool creep);
    YADE_INDEXABLE(ScGeom6D)
};

} // namespace yade
