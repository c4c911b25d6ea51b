// Contact of a facet and a sphere: with the face, an edge or a vertex.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Ig2_Facet_Sphere_ScGeom : public IGeomFunctorBatched<Ig2_Facet_Sphere_ScGeom, Facet, Sphere, ScGeom> {
public:
    static constexpr const char* classDoc = "Ig2 functor: ScGeom of a Facet and a Sphere, the contact being with the face, an edge or a vertex.";
    Real shrinkFactor = 0;
    bool hertzian = false;
    static constexpr Real hertzianFacetRadius = 1e5; // [m], as the reference: R* = r·1e5/(r+1e5)
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("hertzian", hertzian, "Give the facet a very large radius (1e5 m) instead of twice the sphere's, so that a Hertzian law sees a sphere on a plane (effective radius r)");
        v.attr("shrinkFactor", shrinkFactor, "Shrink the facet's edges inwards by this fraction of the sphere radius", Attr::nonNegative);
    }
    bool go(const Facet& f, const Sphere& s, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
            Contact& contact);
    // The batch reads the spheres' radii from BodyColumns (contiguous) instead of their shapes.
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;
    bool go(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
    Real quickRejectFactor() const override { return 1; } // go() returns false when the plane is out of reach
};

} // namespace yade
