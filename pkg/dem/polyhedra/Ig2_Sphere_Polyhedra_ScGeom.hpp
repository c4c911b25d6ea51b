// Contact of a sphere and a polyhedron: with the closest point of the polyhedron's surface (a face, an edge or a vertex).
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>

namespace yade {

class Ig2_Sphere_Polyhedra_ScGeom : public IGeomFunctorOf<Sphere, Polyhedra, ScGeom> {
public:
    static constexpr const char* classDoc = "Create/update the ScGeom of a Sphere (body 1) and a Polyhedra (body 2): the contact is with the closest point of the polyhedron's surface, the normal from the sphere's center towards it, refR1 = refR2 = the sphere's radius.";
    Real edgeCoeff = 1, vertexCoeff = 1;
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("edgeCoeff", edgeCoeff, "Kept for scripts (the reference's; its default 1 changes nothing); not used here");
        v.attr("vertexCoeff", vertexCoeff, "Kept for scripts (the reference's; its default 1 changes nothing); not used here");
    }
    bool go(const Sphere& s, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2, bool force, Interaction& I) override;
};

} // namespace yade
