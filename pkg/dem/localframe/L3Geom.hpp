// Contact geometry in local coordinates (the reference's L3Geom): a local frame (trsf, whose first row
// is the normal, positioned at contactPoint) and the relative displacement u in that frame: one normal
// and two shear components, u0 being the displacement's zero.
#pragma once
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class L3Geom : public GenericSpheresContact {
public:
    static constexpr const char* classDoc =
            "Geometry of contact given in local coordinates with 3 degrees of freedom: normal and two in the shear plane. trsf turns "
            "global vectors into local ones (its first row is the normal); the displacement is u - u0.";
    Vector3r u = Vector3r::Zero(), u0 = Vector3r::Zero(), F = Vector3r::Zero();
    Matrix3r trsf = Matrix3r::Identity();
    template <class V> void visit(V& v) {
        GenericSpheresContact::visit(v);
        v.attr("u", u, "Displacement components, in local coordinates (x: normal, negative in compression; y, z: shear) [m]");
        v.attr("u0", u0, "Zero displacement value, always subtracted from u: set by the Ig2 functor (distFactor < 0: the initial "
                         "distance) and by the law (plastic slip). Increment it, never set it [m]");
        v.attr("trsf", trsf, "Transformation (rotation) from global to local coordinates; its first row is the normal (the origin is "
                             "contactPoint)");
        v.attr("F", F, "Force applied by the law, in local coordinates (Law2_L3Geom_FrictPhys_ElPerfPl) [N]");
    }
    YADE_INDEXABLE(L3Geom)
};

} // namespace yade
