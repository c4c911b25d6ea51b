// Contact of a wall and a polyhedron: the part of the polyhedron behind the wall's plane.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>
#include <pkg/dem/polyhedra/PolyhedraGeom.hpp>

namespace yade {

class Ig2_Wall_Polyhedra_PolyhedraGeom : public IGeomFunctorOf<Wall, Polyhedra, PolyhedraGeom> {
public:
    static constexpr const char* classDoc = "Create/update the geometry of the contact of a Wall and a Polyhedra: the part of the polyhedron behind the wall (on the side away from its center, or the side opposite Wall.sense); the normal is the wall's, towards the polyhedron.";
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Wall& w, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2, bool force, Interaction& I) override;
};

} // namespace yade
