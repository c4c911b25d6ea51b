// Geometry of a contact between two spheres (or a sphere and a plane/facet/box), with the
// incremental shear update of (3.3.2).
#pragma once
#include <core/IGeom.hpp>
#include <core/State.hpp>

namespace yade {

// Contact of two bodies that are spheres at least locally: normal, contact point and radii.
class GenericSpheresContact : public IGeom {
public:
    static constexpr const char* classDoc = "Contact geometry shared by sphere-like contacts: normal and the two radii refR1, refR2.";
    Vector3r normal = Vector3r::Zero();       // unit vector from body 1 towards body 2
    Vector3r contactPoint = Vector3r::Zero(); // middle of the overlap zone (3.3.4)
    Real refR1 = 0, refR2 = 0;                // reference radii (0 or less for a flat boundary)
    template <class V> void visit(V& v) {
        IGeom::visit(v);
        v.attr("normal", normal, "Unit contact normal, from body 1 towards body 2");
        v.attr("contactPoint", contactPoint, "Contact point, in the middle of the overlap (3.3.4) [m]");
        v.attr("refR1", refR1, "Reference radius of body 1 [m]");
        v.attr("refR2", refR2, "Reference radius of body 2 [m]");
    }
    YADE_INDEXABLE(GenericSpheresContact)
};

class ScGeom : public GenericSpheresContact {
public:
    static constexpr const char* classDoc = "Contact geometry of two spheres (or a sphere and a wall/facet/box): penetrationDepth, normal, contactPoint and the incremental shear (3.3.2).";
    Real penetrationDepth = NaN;
    Vector3r shearInc = Vector3r::Zero(); // shear displacement increment of this step (3.3.6)
    // Rotation of the contact plane since the last step: tilt (normal_old × normal_new) and
    // twist (half step of the mean spin about the normal), applied to shear vectors by rotate().
    Vector3r orthonormalAxis = Vector3r::Zero(), twistAxis = Vector3r::Zero();
    template <class V> void visit(V& v) {
        GenericSpheresContact::visit(v);
        v.attr("penetrationDepth", penetrationDepth, "Overlap of the two bodies (negative: gap) [m]");
        v.attr("shearInc", shearInc, "Shear displacement increment in the last step [m]");
        v.attr("orthonormalAxis", orthonormalAxis, "Tilt of the contact plane in the last step", Attr::hidden);
        v.attr("twistAxis", twistAxis, "Twist of the contact plane in the last step", Attr::hidden);
    }
    // Updates normal, the plane rotation and shearInc for the current step (3.3.2); refR1,
    // refR2, penetrationDepth and contactPoint must be set before. With avoidRatcheting (two
    // spheres), the relative velocity is that of points at the reference radii; otherwise that of
    // the bodies' material points at the contact point.
    void precompute(const Kinematics& s1, const Kinematics& s2, Real dt, const Vector3r& currentNormal, bool isNew,
            const Vector3r& shift2, bool avoidRatcheting);
    // Rotates a shear vector (force or displacement) with the contact plane: (3.3.2) step 1.
    Vector3r& rotate(Vector3r& shear) const { return shear = rotated(shear); }
    // The same on a value (kept in registers: a vector updated in memory component by component
    // made the next whole-vector read wait for the stores).
    Vector3r rotated(const Vector3r& shear) const { return minusCross(minusCross(shear, orthonormalAxis), twistAxis); }
    static Vector3r minusCross(const Vector3r& v, const Vector3r& a) { // v - v × a
        return Vector3r(v[0] - (v[1] * a[2] - v[2] * a[1]), v[1] - (v[2] * a[0] - v[0] * a[2]), v[2] - (v[0] * a[1] - v[1] * a[0]));
    }
    YADE_INDEXABLE(ScGeom)
};

} // namespace yade
