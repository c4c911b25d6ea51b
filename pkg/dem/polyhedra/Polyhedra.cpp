#include <pkg/dem/polyhedra/Polyhedra.hpp>
#include <Eigen/Eigenvalues>
#include <ctime>
#include <mutex>
#include <random>

namespace yade {

Polyhedra::Polyhedra() : seed((int)std::time(nullptr)) {}

void Polyhedra::postLoad() {
    if (v.empty()) {
        initialized = false;
        return;
    }
    initialize();
}

void Polyhedra::randomVertices() {
    // Points on the surface of the box of half-sizes size/2 in random directions, then a random turn of them all.
    std::mt19937 gen((unsigned)seed);
    std::normal_distribution<Real> normal(0, 1);
    v.clear();
    for (int i = 0; i < 24; ++i) {
        const Vector3r d(normal(gen), normal(gen), normal(gen));
        const Real t = 1 / (2 * d.cwiseAbs().cwiseQuotient(size).maxCoeff());
        v.push_back(t * d);
    }
    const Quaternionr turn = Quaternionr(normal(gen), normal(gen), normal(gen), normal(gen)).normalized();
    for (auto& x : v) x = turn * x;
}

void Polyhedra::initialize() {
    if (initialized && !v.empty() && v == madeV) return; // (keeps centroid and orientation of the vertices first given)
    if (v.empty()) randomVertices();
    const polyhedron::Hull hull = polyhedron::convexHull(v);
    std::vector<Vector3r> pts;
    for (int i : hull.vertices) pts.push_back(v[i]);
    polyhedron::Faces soup;
    for (const auto& f : hull.faces) {
        polyhedron::Face face;
        for (int i : f) face.pts.push_back(pts[i]);
        soup.push_back(face);
    }
    const polyhedron::MassProperties m = polyhedron::massProperties(soup);
    if (!(m.volume > 0)) throw std::invalid_argument("a polyhedron needs at least 4 non-coplanar vertices (these span no volume)");
    // Principal axes: kept as they are when the tensor is already diagonal (a box keeps its x, y, z in that order).
    Matrix3r R = Matrix3r::Identity();
    const Matrix3r off = m.inertia - Matrix3r(m.inertia.diagonal().asDiagonal());
    if (off.cwiseAbs().maxCoeff() > 1e-12 * m.inertia.trace()) {
        Eigen::SelfAdjointEigenSolver<Matrix3r> eig(m.inertia);
        R = eig.eigenvectors();
        if (R.determinant() < 0) R.col(2) = -R.col(2);
    }
    // vertices already centered (e.g. loaded from a file) are kept to the bit
    Real size = 0;
    for (const auto& p : pts) size = std::max(size, p.norm());
    centroid = m.centroid.norm() <= 1e-13 * size ? Vector3r::Zero() : m.centroid;
    orientation = Quaternionr(R);
    orientation.normalize();
    v.clear();
    radius = 0;
    for (const auto& p : pts) {
        v.push_back(R.transpose() * (p - centroid));
        radius = std::max(radius, v.back().norm());
    }
    faces = hull.faces;
    planes.clear();
    for (const auto& f : faces) {
        std::vector<Vector3r> poly;
        for (int i : f) poly.push_back(v[i]);
        const Vector3r n = polyhedron::areaVector(poly).normalized();
        planes.push_back({n, n.dot(poly[0])});
    }
    volume = m.volume;
    inertia = (R.transpose() * m.inertia * R).diagonal();
    madeV = v;
    initialized = true;
}

void Polyhedra::ensureInitialized() const {
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    if (!initialized) const_cast<Polyhedra*>(this)->initialize(); // (derived data, made once, under the lock)
}

polyhedron::Faces Polyhedra::facesAt(const Vector3r& pos, const Quaternionr& ori, int origin) const {
    const Matrix3r R = ori.toRotationMatrix();
    std::vector<Vector3r> p;
    p.reserve(v.size());
    for (const auto& x : v) p.push_back(pos + R * x);
    polyhedron::Faces out(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
        out[i].origin = origin;
        for (int k : faces[i]) out[i].pts.push_back(p[k]);
    }
    return out;
}

} // namespace yade
