#include <core/Scene.hpp>
#include <pkg/dem/polyhedra/Ig2_Polyhedra_Polyhedra_PolyhedraGeom.hpp>
#include <pkg/dem/polyhedra/PolyhedraOverlap.hpp>

namespace yade {

bool Ig2_Polyhedra_Polyhedra_PolyhedraGeom::go(const Polyhedra& p1, const Polyhedra& p2, const State& s1, const State& s2,
        const Vector3r& shift2, bool, Interaction& I) {
    if (!p1.initialized || !p2.initialized) return false; // (Bo1_Polyhedra_Aabb initializes them)
    // in a frame centered at body 1, for precision far from the origin
    const Vector3r d = s2.pos() + shift2 - s1.pos();
    if (d.norm() > p1.radius + p2.radius) return false;
    polyhedron::Faces overlap = p1.facesAt(Vector3r::Zero(), s1.ori(), 0);
    const Matrix3r R2 = s2.ori().toRotationMatrix();
    for (const auto& pl : p2.planes) {
        const Vector3r n = R2 * pl.normal;
        overlap = polyhedron::clip(overlap, {n, pl.offset + n.dot(d)}, 1);
        if (overlap.empty()) return false;
    }
    return setPolyhedraGeom(overlap, s1.pos(), overlapNormal(overlap, d), s1, s2, shift2, scene->dt, I);
}

} // namespace yade
