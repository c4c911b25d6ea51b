#include <core/Scene.hpp>
#include <pkg/dem/polyhedra/Ig2_Wall_Polyhedra_PolyhedraGeom.hpp>
#include <pkg/dem/polyhedra/PolyhedraOverlap.hpp>

namespace yade {

bool Ig2_Wall_Polyhedra_PolyhedraGeom::go(const Wall& w, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2,
        bool, Interaction& I) {
    if (!p.initialized) return false;
    const Vector3r center = s2.pos() + shift2;
    const Real gap = center[w.axis] - s1.pos()[w.axis]; // the polyhedron's center from the wall's plane
    const Real side = w.sense != 0 ? Real(w.sense) : (gap >= 0 ? 1 : -1);
    if (side * gap > p.radius) return false;
    Vector3r n = Vector3r::Zero();
    n[w.axis] = side;
    // in a frame centered at the polyhedron: keep side·x[axis] <= side·(wall - center)
    polyhedron::Faces overlap = polyhedron::clip(p.facesAt(Vector3r::Zero(), s2.ori(), 1), {n, -side * gap}, 0);
    if (overlap.empty()) return false;
    return setPolyhedraGeom(overlap, center, n, s1, s2, shift2, scene->dt, I);
}

} // namespace yade
