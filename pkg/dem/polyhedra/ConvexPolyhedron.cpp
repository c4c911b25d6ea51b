#include <pkg/dem/polyhedra/ConvexPolyhedron.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace yade {
namespace polyhedron {

namespace {

// Largest distance of the points from their mean: the length that scales the tolerances.
Real extent(const std::vector<Vector3r>& p, Vector3r& mean) {
    mean = Vector3r::Zero();
    for (const auto& x : p) mean += x;
    mean /= Real(p.size());
    Real r = 0;
    for (const auto& x : p) r = std::max(r, (x - mean).norm());
    return r;
}

// The points (lying in a plane of normal n, in convex position) ordered counter-clockwise around n.
template <class Key> void orderAround(std::vector<Key>& keys, const std::vector<Vector3r>& pts, const Vector3r& n) {
    Vector3r c = Vector3r::Zero();
    for (const auto& p : pts) c += p;
    c /= Real(pts.size());
    const Vector3r u = (std::abs(n[0]) < 0.9 ? Vector3r::UnitX() : Vector3r::UnitY()).cross(n).normalized();
    const Vector3r w = n.cross(u);
    std::vector<std::pair<Real, Key>> a;
    for (size_t i = 0; i < pts.size(); ++i) a.push_back({std::atan2((pts[i] - c).dot(w), (pts[i] - c).dot(u)), keys[i]});
    std::sort(a.begin(), a.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (size_t i = 0; i < a.size(); ++i) keys[i] = a[i].second;
}

} // namespace

Hull convexHull(const std::vector<Vector3r>& points) {
    if (points.size() < 4)
        throw std::invalid_argument("a polyhedron needs at least 4 non-coplanar vertices, got " + std::to_string(points.size()));
    for (const auto& p : points)
        if (!p.allFinite()) throw std::invalid_argument("a polyhedron's vertices must be finite numbers");
    Vector3r mean;
    const Real scale = extent(points, mean);
    const Real eps = 1e-9 * scale;
    std::vector<int> ids; // the points without duplicates
    for (int i = 0; i < (int)points.size(); ++i) {
        bool dup = false;
        for (int j : ids) dup = dup || (points[i] - points[j]).norm() <= eps;
        if (!dup) ids.push_back(i);
    }
    // Every plane through three points that leaves all points on one side carries a face (the points are few: at most a
    // hundred or so, and this runs once per shape).
    std::vector<Plane> planes;
    Hull hull;
    const size_t n = ids.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                const Vector3r& a = points[ids[i]];
                Vector3r nrm = (points[ids[j]] - a).cross(points[ids[k]] - a);
                if (!(nrm.norm() > 1e-12 * scale * scale)) continue;
                nrm.normalize();
                Real d = nrm.dot(a);
                int above = 0, below = 0;
                for (int id : ids) {
                    const Real s = nrm.dot(points[id]) - d;
                    above += s > eps;
                    below += s < -eps;
                }
                if ((above && below) || (!above && !below)) continue;
                if (above) nrm = -nrm, d = -d;
                bool known = false;
                for (const auto& p : planes) known = known || (p.normal.dot(nrm) > 1 - 1e-9 && std::abs(p.offset - d) <= eps);
                if (known) continue;
                planes.push_back({nrm, d});
                std::vector<int> face;
                std::vector<Vector3r> pts;
                for (int id : ids)
                    if (std::abs(nrm.dot(points[id]) - d) <= eps) face.push_back(id), pts.push_back(points[id]);
                orderAround(face, pts, nrm);
                hull.faces.push_back(face);
            }
    if (hull.faces.size() < 4) throw std::invalid_argument("a polyhedron needs at least 4 non-coplanar vertices (these span no volume)");
    // index the hull's vertices from 0
    std::vector<int> index(points.size(), -1);
    for (auto& f : hull.faces)
        for (int& id : f) {
            if (index[id] < 0) {
                index[id] = (int)hull.vertices.size();
                hull.vertices.push_back(id);
            }
            id = index[id];
        }
    return hull;
}

Vector3r areaVector(const std::vector<Vector3r>& pts) {
    Vector3r s = Vector3r::Zero();
    for (size_t i = 1; i + 1 < pts.size(); ++i) s += (pts[i] - pts[0]).cross(pts[i + 1] - pts[0]);
    return 0.5 * s;
}

MassProperties massProperties(const Faces& faces) {
    MassProperties m;
    if (faces.empty()) return m;
    const Vector3r r = faces[0].pts[0]; // tetrahedra from this point to each triangle of the surface
    Matrix3r C = Matrix3r::Zero();       // ∫ x xᵀ dV about r
    Vector3r first = Vector3r::Zero();   // ∫ x dV about r
    for (const auto& f : faces)
        for (size_t i = 1; i + 1 < f.pts.size(); ++i) {
            const Vector3r a = f.pts[0] - r, b = f.pts[i] - r, c = f.pts[i + 1] - r;
            const Real v = a.dot(b.cross(c)) / 6;
            const Vector3r s = a + b + c;
            m.volume += v;
            first += v * s / 4;
            C += v / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
        }
    if (!(m.volume > 0)) return MassProperties{};
    const Vector3r g = first / m.volume;
    m.centroid = r + g;
    const Matrix3r Cc = C - m.volume * g * g.transpose();
    m.inertia = Cc.trace() * Matrix3r::Identity() - Cc;
    return m;
}

Faces clip(const Faces& faces, const Plane& plane, int origin) {
    Real scale = std::abs(plane.offset);
    for (const auto& f : faces)
        for (const auto& p : f.pts) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    const Real eps = 1e-12 * scale;
    Faces out;
    std::vector<Vector3r> cap; // the points of the cut plane: the cap's vertices
    bool cut = false;
    for (const auto& f : faces) {
        const size_t n = f.pts.size();
        std::vector<Real> s(n);
        bool anyOut = false, anyIn = false;
        for (size_t i = 0; i < n; ++i) {
            s[i] = plane.normal.dot(f.pts[i]) - plane.offset;
            anyOut = anyOut || s[i] > eps;
            anyIn = anyIn || s[i] < -eps;
        }
        cut = cut || anyOut;
        if (!anyOut) { // wholly inside (or on the plane)
            out.push_back(f);
            for (size_t i = 0; i < n; ++i)
                if (s[i] >= -eps) cap.push_back(f.pts[i]);
            continue;
        }
        if (!anyIn) continue; // wholly outside
        Face kept{{}, f.origin};
        for (size_t i = 0; i < n; ++i) {
            const size_t j = (i + 1) % n;
            if (s[i] <= eps) kept.pts.push_back(f.pts[i]);
            if (s[i] >= -eps && s[i] <= eps) cap.push_back(f.pts[i]);
            if ((s[i] < -eps && s[j] > eps) || (s[i] > eps && s[j] < -eps)) {
                const Vector3r x = f.pts[i] + (f.pts[j] - f.pts[i]) * (s[i] / (s[i] - s[j]));
                kept.pts.push_back(x);
                cap.push_back(x);
            }
        }
        if (kept.pts.size() >= 3) out.push_back(std::move(kept));
    }
    if (!cut || out.empty()) return out;
    std::vector<Vector3r> pts; // the cap's points without duplicates
    for (const auto& p : cap) {
        bool dup = false;
        for (const auto& q : pts) dup = dup || (p - q).norm() <= 1e3 * eps;
        if (!dup) pts.push_back(p);
    }
    if (pts.size() < 3) return out;
    std::vector<int> order(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) order[i] = (int)i;
    orderAround(order, pts, plane.normal);
    Face capFace{{}, origin};
    for (int i : order) capFace.pts.push_back(pts[i]);
    out.push_back(std::move(capFace));
    return out;
}

} // namespace polyhedron
} // namespace yade
