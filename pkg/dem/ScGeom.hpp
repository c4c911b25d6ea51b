// Geometry of a contact between two spheres (or a sphere and a plane/facet/box), with the
// incremental shear update of (3.3.2).
#pragma once
#include <core/IGeom.hpp>
#include <core/State.hpp>
#include <lib/base/Lanes.hpp>

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
    // refR2, penetrationDepth and contactPoint must be set before (Values::precompute, one contact).
    void precompute(const Kinematics& s1, const Kinematics& s2, Real dt, const Vector3r& currentNormal, bool isNew,
            const Vector3r& shift2, bool avoidRatcheting);
    // The relative velocity of body 2 at the contact (whole, not only its shear part), body 2 being its
    // image at pos + shift2 moving at vel + shiftVel2 in a periodic scene: with avoidRatcheting, of points
    // at the reference radii along the normal (the translation scaled by (r1+r2)/distance), otherwise of
    // the bodies' material points at the contact point.
    Vector3r incidentVel(const Kinematics& s1, const Kinematics& s2, const Vector3r& shift2, const Vector3r& shiftVel2, bool avoidRatcheting) const;
    // Rotates a shear vector (force or displacement) with the contact plane: (3.3.2) step 1.
    Vector3r& rotate(Vector3r& shear) const { return shear = rotated(shear); }
    Vector3r rotated(const Vector3r& shear) const {
        return eigen(Values<Real>::minusCross(Values<Real>::minusCross(vec3(shear), vec3(orthonormalAxis)), vec3(twistAxis)));
    }
    // What the kernels (core/ContactKernel.hpp) read and write of a ScGeom, as values of T: one
    // contact's (T = Real) or two contacts' (T = Two).
    template <class T> struct Values {
        Vec3<T> normal, contactPoint, shearInc, orthonormalAxis, twistAxis;
        T penetrationDepth, refR1, refR2;
        YADE_KERNEL static Values of(const ScGeom& g) {
            return Values{vec3(g.normal), vec3(g.contactPoint), vec3(g.shearInc), vec3(g.orthonormalAxis), vec3(g.twistAxis),
                    g.penetrationDepth, g.refR1, g.refR2};
        }
        YADE_KERNEL void store(Rows<ScGeom, T>& g) const {
            g.put(&ScGeom::penetrationDepth, penetrationDepth);
            g.put(&ScGeom::contactPoint, contactPoint);
            g.put(&ScGeom::refR1, refR1);
            g.put(&ScGeom::refR2, refR2);
            g.put(&ScGeom::orthonormalAxis, orthonormalAxis);
            g.put(&ScGeom::twistAxis, twistAxis);
            g.put(&ScGeom::normal, normal);
            g.put(&ScGeom::shearInc, shearInc);
        }
        void store(ScGeom& g) const {
            Rows<ScGeom, Real> rows{{&g}, {true}};
            store(rows);
        }
        // the bodies separated (the laws' test)
        YADE_KERNEL MaskOf<T> apart() const { return greater(T(0.0), penetrationDepth); }
        // a shear vector (force or displacement) turned with the contact plane: (3.3.2) step 1
        YADE_KERNEL Vec3<T> rotated(const Vec3<T>& v) const { return minusCross(minusCross(v, orthonormalAxis), twistAxis); }
        YADE_KERNEL static Vec3<T> minusCross(const Vec3<T>& v, const Vec3<T>& a) { // v - v × a
            return {v.x - (v.y * a.z - v.z * a.y), v.y - (v.z * a.x - v.x * a.z), v.z - (v.x * a.y - v.y * a.x)};
        }
        // With `normal` now the current normal (refR1, refR2, penetrationDepth and contactPoint set):
        // the rotation of the contact plane since the last step and the shear increment (3.3.2). With
        // avoidRatcheting (two spheres) the relative velocity is that of points at the reference radii;
        // otherwise that of the bodies' material points at the contact point.
        YADE_KERNEL void precompute(const Vec3<T>& oldNormal, bool isNew, const PairMotion<T>& m, T dt, bool avoidRatcheting, const Vec3<T>& shift2) {
            const Vec3<T> n = normal;
            if (isNew) {
                orthonormalAxis = twistAxis = Vec3<T>::zero();
            } else {
                orthonormalAxis = cross(oldNormal, n);                                              // tilt
                twistAxis = (dt * T(0.5) * dot(oldNormal, m.angVel1 + m.angVel2)) * oldNormal; // twist
            }
            Vec3<T> relVel;
            if (avoidRatcheting) {
                // as if the spheres kept their reference radii (no granular ratcheting): lever arms
                // refR1, refR2, and the translational part scaled by (r1+r2)/distance accordingly
                const T r1 = refR1, r2 = refR2;
                const Vec3<T> c1x = r1 * n, c2x = (-r2) * n;
                const T alpha = (r1 + r2) / (r1 + r2 - penetrationDepth);
                relVel = ((m.vel2 - m.vel1) * alpha + cross(m.angVel2, c2x)) - cross(m.angVel1, c1x);
            } else {
                const Vec3<T> c1x = contactPoint - m.pos1, c2x = contactPoint - (m.pos2 + shift2);
                relVel = (m.vel2 + cross(m.angVel2, c2x)) - (m.vel1 + cross(m.angVel1, c1x));
            }
            relVel = relVel - dot(n, relVel) * n; // shear part only
            shearInc = relVel * dt;
        }
    };
    YADE_INDEXABLE(ScGeom)
};

} // namespace yade
