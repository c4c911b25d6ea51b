// What the three Ig2 functors of polyhedra share: a PolyhedraGeom made from an overlap given as polygons.
#pragma once
#include <core/Interaction.hpp>
#include <core/State.hpp>
#include <pkg/dem/polyhedra/ConvexPolyhedron.hpp>

namespace yade {

// Creates or updates I.geom (a PolyhedraGeom) from the overlap's faces, given relative to `origin` (a point near
// them, for precision), and the normal from body 1 to body 2; body 2 is at its position + shift2. Returns false
// (no contact) when the overlap has no volume.
bool setPolyhedraGeom(const polyhedron::Faces& overlap, const Vector3r& origin, const Vector3r& normal, const State& s1, const State& s2,
        const Vector3r& shift2, Real dt, Interaction& I);

// The overlap normal from the faces of origin 0 (body 1's surface): their area vectors' sum, normalized; `fallback`
// when they cancel (one body inside the other).
Vector3r overlapNormal(const polyhedron::Faces& overlap, const Vector3r& fallback);

} // namespace yade
