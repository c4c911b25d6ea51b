// Convex polyhedra as plain data, written here (no CGAL): the convex hull of a set of points, the
// clipping of a polyhedron by half-spaces (the intersection of two convex polyhedra), volume, centroid
// and inertia. Used by Polyhedra and its Ig2 functors; it knows nothing of bodies or scenes.
#pragma once
#include <lib/base/Math.hpp>
#include <vector>

namespace yade {
namespace polyhedron {

// A face: its vertices in counter-clockwise order seen from outside, and which solid it comes from
// (the index of the polyhedron whose surface it lies on: 0 or 1, for the contact normal).
struct Face {
    std::vector<Vector3r> pts;
    int origin = 0;
};
using Faces = std::vector<Face>;

// A plane of a convex polyhedron: the points x inside satisfy normal·x <= offset.
struct Plane {
    Vector3r normal = Vector3r::Zero();
    Real offset = 0;
};

// The convex hull of the points: the indices of the hull's vertices among them, and for each face the
// indices of its vertices, counter-clockwise seen from outside. Throws std::invalid_argument when the
// points span no volume (fewer than 4 points, all coplanar, non-finite).
struct Hull {
    std::vector<int> vertices;
    std::vector<std::vector<int>> faces;
};
Hull convexHull(const std::vector<Vector3r>& points);

// Volume, centroid and inertia tensor (about the centroid, unit density) of a closed polygon soup.
struct MassProperties {
    Real volume = 0;
    Vector3r centroid = Vector3r::Zero();
    Matrix3r inertia = Matrix3r::Zero();
};
MassProperties massProperties(const Faces& faces);

// The part of the solid bounded by faces on the inner side of the plane (normal·x <= offset); the cut
// adds a face of the given origin. Empty when nothing is left.
Faces clip(const Faces& faces, const Plane& plane, int origin);

// Area vector (area × outward unit normal) of a planar polygon listed counter-clockwise.
Vector3r areaVector(const std::vector<Vector3r>& pts);

} // namespace polyhedron
} // namespace yade
