// Exact contact of two spheres (3.3.1): overlap, normal, contact point, then the shear update.
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Ig2_Sphere_Sphere_ScGeom : public IGeomFunctorBatched<Ig2_Sphere_Sphere_ScGeom, Sphere, Sphere, ScGeom> {
public:
    static constexpr const char* classDoc = "Ig2 functor: exact contact of two spheres (3.3.1), overlap, normal and contact point, then the shear update (3.3.2).";
    Real interactionDetectionFactor = 1;
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("interactionDetectionFactor", interactionDetectionFactor,
                "A contact starts when the distance is below this factor times r1+r2 (3.3.1)", Attr::positive);
    }
    bool go(const Sphere& s1, const Sphere& s2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
            Contact& contact);
    // The batch reads the radii from BodyColumns (contiguous) instead of the shapes.
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;
    bool go(Real r1, Real r2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
    Real quickRejectFactor() const override { return interactionDetectionFactor; }

    // The geometry kernel (core/ContactKernel.hpp): spheres of radii r1, r2, body 2 shifted by shift2;
    // oldNormal is the contact's normal at the last step (unused for a new contact).
    template <class T>
    YADE_KERNEL ScGeom::Values<T> kernel(T r1, T r2, const PairMotion<T>& m, const Vec3<T>& shift2, const Vec3<T>& oldNormal, bool isNew, T dt) const {
        ScGeom::Values<T> g;
        const Vec3<T> centres = (m.pos2 + shift2) - m.pos1;
        const T dist = norm(centres);
        g.normal = centres / dist;
        g.penetrationDepth = (r1 + r2) - dist;
        g.contactPoint = m.pos1 + (r1 - T(0.5) * g.penetrationDepth) * g.normal;
        g.refR1 = r1;
        g.refR2 = r2;
        g.precompute(oldNormal, isNew, m, dt, true, shift2);
        return g;
    }
    // an existing contact's geometry (KernelPass), written into its record
    template <class T> YADE_KERNEL ScGeom::Values<T> batchKernel(const ContactBodies<T>& b, Rows<ScGeom, T>& rows, Real dt) const {
        const ScGeom::Values<T> g = kernel<T>(gather(b.b.radius, b.id1), gather(b.b.radius, b.id2), b.motion(), Vec3<T>::zero(),
                rows.get(&ScGeom::normal), false, T(dt));
        g.store(rows);
        return g;
    }
};

} // namespace yade
