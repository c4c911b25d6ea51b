#include <core/Scene.hpp>
#include <pkg/dem/polyhedra/Ig2_Facet_Polyhedra_PolyhedraGeom.hpp>
#include <pkg/dem/polyhedra/PolyhedraOverlap.hpp>

namespace yade {

bool Ig2_Facet_Polyhedra_PolyhedraGeom::go(const Facet& f, const Polyhedra& p, const State& s1, const State& s2, const Vector3r& shift2,
        bool, Interaction& I) {
    if (!p.initialized || !(f.area > 0)) return false;
    const Vector3r center = s2.pos() + shift2;
    const Matrix3r R = s1.ori().toRotationMatrix();
    const Vector3r fc = s1.pos() - center; // the facet's position, in a frame centered at the polyhedron
    const Real gap = -(R * f.normal).dot(fc);
    if (std::abs(gap) > p.radius) return false;
    const Vector3r n = (gap >= 0 ? 1 : -1) * (R * f.normal); // from the facet towards the polyhedron
    polyhedron::Faces overlap = polyhedron::clip(p.facesAt(Vector3r::Zero(), s2.ori(), 1), {n, n.dot(fc)}, 0);
    for (int i = 0; i < 3 && !overlap.empty(); ++i) { // the prism of the triangle: its edges' outward normals
        const Vector3r e = R * f.ne[i];
        overlap = polyhedron::clip(overlap, {e, e.dot(fc + R * f.vertices[i])}, 0);
    }
    if (overlap.empty()) return false;
    return setPolyhedraGeom(overlap, center, n, s1, s2, shift2, scene->dt, I);
}

} // namespace yade
