// Contact of a facet and a polyhedron: the part of the polyhedron behind the facet, within the triangle's prism.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>
#include <pkg/dem/polyhedra/PolyhedraGeom.hpp>

namespace yade {

class Ig2_Facet_Polyhedra_PolyhedraGeom : public IGeomFunctorOf<Facet, Polyhedra, PolyhedraGeom> {
public:
    static constexpr const char* classDoc = "Create/update the geometry of the contact of a Facet and a Polyhedra: the part of the polyhedron behind the facet's plane (the side away from the polyhedron's center) and within the prism of the triangle; the normal is the facet's, towards the polyhedron.";
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Facet& f, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2, bool force, Interaction& I) override;
};

} // namespace yade
