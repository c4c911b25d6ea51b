// A convex polyhedron (Eliáš 2014): the convex hull of its vertices v, given in the body's frame, where Initialize()
// puts the centroid at the origin and the principal axes of inertia along x, y, z. Without vertices, Initialize() makes
// a random one from seed and size.
#pragma once
#include <core/Shape.hpp>
#include <pkg/dem/polyhedra/ConvexPolyhedron.hpp>

namespace yade {

class Polyhedra : public Shape {
public:
    static constexpr const char* classDoc = "Polyhedral (convex) geometry: the convex hull of the vertices v, in the body's frame (centroid at the origin, principal axes along x, y, z once initialized); without vertices, Initialize() makes a random polyhedron from seed and size.";
    std::vector<Vector3r> v;
    int seed = 0;
    Vector3r size = Vector3r(1, 1, 1);
    // Derived by Initialize(), not saved (made again from v on load).
    std::vector<std::vector<int>> faces;         // vertex indices, counter-clockwise seen from outside
    std::vector<polyhedron::Plane> planes;       // one per face, in the body's frame
    Real volume = NaN, radius = NaN;             // radius: the largest distance of a vertex from the origin
    Vector3r inertia = Vector3r::Constant(NaN);  // principal moments of inertia per unit density
    Vector3r centroid = Vector3r::Zero();        // where the centroid of the vertices as given was
    Quaternionr orientation = Quaternionr::Identity(); // the turn from the principal frame to the vertices as given
    bool initialized = false;
    std::vector<Vector3r> madeV; // v as initialize() left it: setting v to the same again changes nothing
    Polyhedra();
    template <class V> void visit(V& v_) {
        Shape::visit(v_);
        v_.attr("v", v, "Polyhedron vertices in local coordinate system [m]; Initialize() moves them so that the centroid is at the origin and the principal axes along x, y, z", Attr::finite);
        v_.attr("seed", seed, "Seed for the random vertices made by Initialize() when v is empty (default: the time)");
        v_.attr("size", size, "Size of the grain in meters - x,y,z - of a random polyhedron (when v is empty), before its random rotation", Attr::positive);
    }
    // With vertices: makes the derived data now (std::invalid_argument for fewer than 4 non-coplanar ones).
    void postLoad() override;
    // Makes the derived data: the hull of v (or of random vertices when v is empty), centered and turned to its axes.
    void initialize();
    // Initializes on first use (Bo1 functors, Python methods); safe to call from several threads.
    void ensureInitialized() const;
    // The faces as polygons in a frame where the body's origin is at `pos` and turned by `ori`.
    polyhedron::Faces facesAt(const Vector3r& pos, const Quaternionr& ori, int origin) const;
    YADE_INDEXABLE(Polyhedra)

private:
    void randomVertices();
};

} // namespace yade
