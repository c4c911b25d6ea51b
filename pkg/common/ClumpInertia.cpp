#include <pkg/common/ClumpInertia.hpp>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yade {

// The inertia tensor of a point mass m at d from the axes' origin: m (|d|² E - d dᵀ).
static Matrix3r pointInertia(Real m, const Vector3r& d) { return m * (d.squaredNorm() * Matrix3r::Identity() - d * d.transpose()); }

MassProperties summedMassProperties(const std::vector<ClumpPart>& parts) {
    MassProperties p;
    Vector3r moment = Vector3r::Zero();
    for (const ClumpPart& b : parts) {
        p.mass += b.mass;
        moment += b.mass * b.pos;
    }
    p.centroid = p.mass > 0 ? Vector3r(moment / p.mass) : Vector3r::Zero();
    for (const ClumpPart& b : parts) {
        const Matrix3r R = b.ori.toRotationMatrix();
        p.inertia += R * b.inertia.asDiagonal() * R.transpose() + pointInertia(b.mass, b.pos - p.centroid);
    }
    return p;
}

MassProperties gridMassProperties(const std::vector<ClumpPart>& parts, int n) {
    if (n <= 0) throw std::invalid_argument("discretization must be positive, got " + std::to_string(n));
    Vector3r lo = Vector3r::Constant(Inf), hi = Vector3r::Constant(-Inf);
    for (const ClumpPart& b : parts) {
        if (!(b.radius > 0)) throw std::invalid_argument("discretization integrates the mass over member spheres: every member must be a Sphere");
        lo = lo.cwiseMin(b.pos - Vector3r::Constant(b.radius));
        hi = hi.cwiseMax(b.pos + Vector3r::Constant(b.radius));
    }
    const Real h = (hi - lo).minCoeff() / n;
    const Real density = parts.front().density;
    if (!(density > 0)) throw std::invalid_argument("discretization needs the first member's material density, got " + std::to_string(density));
    const Real cellMass = density * h * h * h;
    // first the cells inside (their count and first moment), then their inertia about the centroid
    std::vector<Vector3r> inside;
    Vector3i cells;
    for (int k = 0; k < 3; ++k) cells[k] = (int)std::ceil((hi[k] - lo[k]) / h - 0.5); // centres below hi
    for (int i = 0; i < cells[0]; ++i)
        for (int j = 0; j < cells[1]; ++j)
            for (int k = 0; k < cells[2]; ++k) {
                const Vector3r c = lo + h * Vector3r(i + 0.5, j + 0.5, k + 0.5);
                for (const ClumpPart& b : parts)
                    if ((c - b.pos).squaredNorm() < b.radius * b.radius) {
                        inside.push_back(c);
                        break;
                    }
            }
    MassProperties p;
    if (inside.empty()) throw std::invalid_argument("discretization " + std::to_string(n) + " is too coarse: no cell centre lies inside the members");
    Vector3r sum = Vector3r::Zero();
    for (const Vector3r& c : inside) sum += c;
    p.mass = cellMass * (Real)inside.size();
    p.centroid = sum / (Real)inside.size();
    for (const Vector3r& c : inside) p.inertia += pointInertia(cellMass, c - p.centroid);
    p.inertia += p.mass * h * h / 6 * Matrix3r::Identity(); // the cells' own inertia (cubes)
    return p;
}

PrincipalAxes principalAxes(const Matrix3r& inertia) {
    Eigen::SelfAdjointEigenSolver<Matrix3r> eig(0.5 * (inertia + inertia.transpose()));
    Matrix3r R = eig.eigenvectors();
    if (R.determinant() < 0) R.col(2) = -R.col(2);
    PrincipalAxes a;
    a.moments = eig.eigenvalues();
    a.ori = Quaternionr(R).normalized();
    return a;
}

} // namespace yade
