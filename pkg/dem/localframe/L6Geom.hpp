// Contact geometry in local coordinates with rotations (the reference's L6Geom): L3Geom plus the
// relative rotation phi in the local frame (x: twist, y and z: bending), phi0 its zero.
#pragma once
#include <pkg/dem/localframe/L3Geom.hpp>

namespace yade {

class L6Geom : public L3Geom {
public:
    static constexpr const char* classDoc =
            "Geometry of contact in local coordinates with 6 degrees of freedom: L3Geom and the relative rotation phi (x: twist about "
            "the normal, y and z: bending); the rotation is phi - phi0.";
    Vector3r phi = Vector3r::Zero(), phi0 = Vector3r::Zero();
    template <class V> void visit(V& v) {
        L3Geom::visit(v);
        v.attr("phi", phi, "Rotation components, in local coordinates (x: twist, y, z: bending) [rad]");
        v.attr("phi0", phi0, "Zero rotation, always subtracted from phi (see L3Geom.u0) [rad]");
    }
    YADE_INDEXABLE(L6Geom)
};

} // namespace yade
