#include <core/Cell.hpp>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

namespace yade {

static std::string show(const Matrix3r& m) {
    std::ostringstream os;
    os.precision(6);
    os << "Matrix3(";
    for (int i = 0; i < 9; ++i) os << (i ? "," : "") << m(i / 3, i % 3);
    os << ")";
    return os.str();
}

// Refused: what is not finite, and a cell whose edges span no volume or are left-handed (hSize's
// determinant not positive): wrapping and the collider's cell coordinates need an invertible,
// right-handed base.
static void checkCell(const Matrix3r& h, const char* what) {
    if (!h.allFinite()) throw std::invalid_argument(std::string(what) + " must be finite, got " + show(h));
    // (RuntimeError in Python, as the reference's)
    const Real det = h.determinant(), scale = h.colwise().norm().prod();
    if (!(det > 1e-12 * scale) || !(scale > 0))
        throw std::runtime_error(std::string(what) + (det < 0 && det < -1e-12 * scale ? " is inverted (negative volume, left-handed edges): " : " is degenerate (zero volume): ")
                + show(h) + "; the columns are the cell's edges and must span a right-handed parallelepiped");
}

void Cell::check() const {
    checkCell(hSize, "Cell.hSize");
    if (!velGrad.allFinite() || !nextVelGrad.allFinite()) throw std::invalid_argument("Cell.velGrad must be finite");
}

void Cell::setHSize(const Matrix3r& m) {
    checkCell(m, "Cell.hSize");
    hSize = refHSize = prevHSize = m;
}

void Cell::setBox(const Vector3r& s) {
    if (!s.allFinite() || !(s.minCoeff() > 0))
        throw std::invalid_argument("Cell.setBox: the sizes must be positive and finite");
    setHSize(s.asDiagonal());
    trsf = Matrix3r::Identity();
}

void Cell::setVelGrad(const Matrix3r& m) {
    if (!m.allFinite()) throw std::invalid_argument("Cell.velGrad must be finite, got " + show(m));
    nextVelGrad = m;
    velGradChanged = true;
}

Vector3r Cell::wrap(const Vector3r& p, Vector3i& period) const {
    const Vector3r s = fractional(p);
    Vector3r w;
    for (int i = 0; i < 3; ++i) {
        const Real f = std::floor(s[i]);
        period[i] = (int)f;
        w[i] = s[i] - f;
    }
    return hSize * w;
}

Vector3r Cell::wrap(const Vector3r& p) const {
    Vector3i period;
    return wrap(p, period);
}

Vector3r Cell::wrapPt(const Vector3r& p) const {
    const Vector3r s = size();
    Vector3r w;
    for (int i = 0; i < 3; ++i) w[i] = p[i] - s[i] * std::floor(p[i] / s[i]);
    return w;
}

void Cell::integrate(Real dt) {
    prevHSize = hSize;
    const Matrix3r inc = dt * velGrad;
    trsf += inc * trsf;
    hSize += inc * hSize;
    prevVelGrad = velGrad;
}

void Cell::takeNextVelGrad() {
    if (!velGradChanged) return;
    velGrad = nextVelGrad;
    velGradChanged = false;
}

std::pair<Matrix3r, Matrix3r> Cell::polarDecomposition() const {
    // U = sqrt(FᵀF) from the eigen decomposition of the symmetric C = FᵀF; R = F·U⁻¹; V = R·U·Rᵀ.
    Eigen::SelfAdjointEigenSolver<Matrix3r> es(rightCauchyGreen());
    const Matrix3r U = es.eigenvectors() * es.eigenvalues().cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
    const Matrix3r R = trsf * U.inverse();
    return {R, U};
    // (the left stretch V = R·U·Rᵀ: Cell.getLeftStretch)
}

} // namespace yade
