// Contact of two convex polyhedra: the volume of their intersection (body 1 clipped by the planes of body 2's faces).
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>
#include <pkg/dem/polyhedra/PolyhedraGeom.hpp>

namespace yade {

class Ig2_Polyhedra_Polyhedra_PolyhedraGeom : public IGeomFunctorOf<Polyhedra, Polyhedra, PolyhedraGeom> {
public:
    static constexpr const char* classDoc = "Create/update the geometry of the contact of 2 Polyhedra: the volume and centroid of their intersection, the normal from the faces of the intersection that lie on body 1's surface.";
    Real interactionDetectionFactor = 1;
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("interactionDetectionFactor", interactionDetectionFactor, "Kept for scripts (see Ig2_Sphere_Sphere_ScGeom.interactionDetectionFactor); a contact exists here only while the polyhedra overlap");
    }
    bool go(const Polyhedra& p1, const Polyhedra& p2, const State& s1, const State& s2, const Vector3r& shift2, bool force, Interaction& I) override;
};

} // namespace yade
