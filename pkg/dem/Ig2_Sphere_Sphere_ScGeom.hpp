// Exact contact of two spheres (3.3.1): overlap, normal, contact point, then the shear update.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Law2_ScGeom_MindlinPhys_Mindlin;

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
    // With Law2_ScGeom_FrictPhys_CundallStrack or Law2_ScGeom_MindlinPhys_Mindlin: both in one pass,
    // the same arithmetic (IGeomFunctor::goBatchWithLaw; Ig2_Sphere_Sphere_ScGeom_CundallStrack.cpp,
    // Ig2_Sphere_Sphere_ScGeom_Mindlin.cpp).
    bool fusesWith(const LawFunctor& law) const override;
    void goBatchWithLaw(const BodyColumns& b, Contact* c, size_t n, LawFunctor& law, char* keep) override;
    Real quickRejectFactor() const override { return interactionDetectionFactor; }

private:
    void goBatchWithMindlin(const BodyColumns& b, Contact* c, size_t n, Law2_ScGeom_MindlinPhys_Mindlin& law, char* keep);
};

} // namespace yade
