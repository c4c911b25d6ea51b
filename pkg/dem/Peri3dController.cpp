#include <core/Scene.hpp>
#include <pkg/common/PyRunner.hpp>
#include <pkg/dem/Peri3dController.hpp>
#include <pkg/dem/Shop.hpp>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <sstream>

namespace yade {

// The law below was found by running the reference (Yade 2023.02a) on fixed configurations and
// comparing step by step (tests/reference/peri3d.py, doc/periodic.md); it is not derived.

namespace {

// Voigt order: xx, yy, zz, yz, zx, xy
constexpr int voigtRow[6] = {0, 1, 2, 1, 0, 0}, voigtCol[6] = {0, 1, 2, 2, 2, 1};

std::string show(const Vector6r& v) {
    std::ostringstream os;
    os << "(";
    for (int i = 0; i < 6; ++i) os << (i ? ", " : "") << v[i];
    return os.str() + ")";
}

// The first-step compliance of an isotropic packing (tensorial shear strain: (1+ν)/E).
Real compliance(int i, int j, Real E, Real nu) {
    if (i < 3 && j < 3) return i == j ? 1 / E : -nu / E;
    return i == j ? (1 + nu) / E : 0;
}

} // namespace

Vector6r Peri3dController::measureStress() const {
    const Scene& s = *scene;
    Matrix3r sum = Matrix3r::Zero();
    Shop::forEachContactForce(s, [&](const Vector3r& f, const Vector3r& l, const Vector3r&, const NormShearPhys&) { sum += f * l.transpose(); });
    const Matrix3r t = -sum / s.cell->volume(); // (compression negative)
    Vector6r r;
    for (int i = 0; i < 6; ++i) r[i] = (t(voigtRow[i], voigtCol[i]) + t(voigtCol[i], voigtRow[i])) / 2; // (the symmetric part)
    return r;
}

void Peri3dController::action() {
    Scene& s = *scene;
    if (!s.isPeriodic) throw std::runtime_error("Peri3dController run on aperiodic simulation (it controls O.cell: set O.periodic=True).");
    if (!goal.allFinite()) throw std::invalid_argument("Peri3dController.goal must be finite, got " + show(goal));
    if (nSteps < 1) throw std::invalid_argument("Peri3dController.nSteps must be at least 1, got " + std::to_string(nSteps));
    if (!(s.dt > 0)) throw std::runtime_error("Peri3dController needs a positive O.dt");
    if (!(youngEstimation != 0) || !std::isfinite(youngEstimation) || !std::isfinite(poissonEstimation) || !std::isfinite(mod))
        throw std::invalid_argument("Peri3dController: youngEstimation must be finite and non-zero, poissonEstimation and mod finite");
    if (!(maxStrainRate >= 0)) throw std::invalid_argument("Peri3dController.maxStrainRate must be non-negative, got " + std::to_string(maxStrainRate));
    const std::vector<Vector2r>* paths[6] = {&xxPath, &yyPath, &zzPath, &yzPath, &zxPath, &xyPath};
    static const char* pathNames[6] = {"xxPath", "yyPath", "zzPath", "yzPath", "zxPath", "xyPath"};
    for (int i = 0; i < 6; ++i) {
        const auto& p = *paths[i];
        if (p.empty()) throw std::invalid_argument(std::string("Peri3dController.") + pathNames[i] + " must have at least one point");
        for (size_t k = 0; k < p.size(); ++k) {
            if (!p[k].allFinite()) throw std::invalid_argument(std::string("Peri3dController.") + pathNames[i] + " must be finite");
            if (!(p[k][0] > (k ? p[k - 1][0] : 0)))
                throw std::invalid_argument(std::string("Peri3dController.") + pathNames[i] + ": the times must be positive and increasing");
        }
        if (p.back()[1] == 0 && goal[i] != 0)
            throw std::invalid_argument(std::string("Peri3dController.") + pathNames[i] + ": the value of the last point must not be 0 (the others are relative to it)");
    }
    Cell& cell = *s.cell;
    const Real dt = s.dt;
    if (!cell.trsf.allFinite() || !(std::abs(cell.trsf.determinant()) > 0))
        throw std::runtime_error("Peri3dController: O.cell.trsf must be finite and invertible (the velocity gradient is computed from its inverse)");

    // which components are stresses, which strains
    lenPe = lenPs = 0;
    pe = ps = Vector6i::Zero();
    for (int i = 0; i < 6; ++i) {
        if (stressMask & (1 << i)) {
            ps[lenPs++] = i;
            stressGoal[i] = goal[i], strainGoal[i] = 0;
        } else {
            pe[lenPe++] = i;
            strainGoal[i] = goal[i], stressGoal[i] = 0;
        }
        pathSizes[i] = int(paths[i]->size());
    }
    stress = measureStress();
    const bool first = progress <= 0;

    // the segment of each path: the next one once the progress so far reaches its end (one segment a
    // step, as the reference); past the last point (pathsCounter >= pathSizes, counting on every
    // step) the last rate goes on
    for (int i = 0; i < 6; ++i) {
        const auto& p = *paths[i];
        const int n = int(p.size());
        int& k = pathsCounter[i];
        if (k < 0) k = 0;
        const Real tEnd = p.back()[0];
        if (progress >= p[std::min(k, n - 1)][0] / tEnd && k < std::numeric_limits<int>::max()) ++k;
        if (k >= n) continue;
        const Vector2r from = k ? p[k - 1] : Vector2r::Zero();
        const Real dValue = goal[i] == 0 ? 0 : goal[i] * (p[k][1] - from[1]) / p.back()[1];
        const Real rate = dValue / ((p[k][0] - from[0]) / tEnd * nSteps * dt);
        if (stressMask & (1 << i)) stressRate[i] = rate;
        else strainRate[i] = rate;
    }
    for (int k = 0; k < lenPs; ++k) stressIdeal[ps[k]] += stressRate[ps[k]] * dt;
    // the strain attribute takes the new rates of the strain components, the last of the stress ones
    strain += dt * strainRate;

    // the stress components' strain rates: the first step from the estimated compliance (doubled
    // unless every component is a stress, as the reference), then the predictor
    const Vector6r stressError = stress - stressIdeal;
    if (first) {
        const Real factor = lenPe == 0 ? 1 : 2;
        for (int a = 0; a < lenPs; ++a) {
            Real r = 0;
            for (int b = 0; b < lenPs; ++b) r += compliance(ps[a], ps[b], youngEstimation, poissonEstimation) * stressRate[ps[b]];
            strainRate[ps[a]] = factor * r;
        }
    } else {
        const Real step = strainRate.cwiseAbs().maxCoeff() * mod;
        for (int a = 0; a < lenPs; ++a) {
            const int i = ps[a];
            const Real predicted = 2 * stressError[i] - prevStressError[i];
            strainRate[i] += predicted > 0 ? -step : step;
        }
    }
    prevStressError = stressError;
    // too fast: every rate scaled down together, the largest to maxStrainRate
    // (and the progress slowed as much: stressIdeal and the strain attribute are not)
    const Real fastest = strainRate.cwiseAbs().maxCoeff();
    Real slowDown = 1;
    if (fastest > maxStrainRate) {
        slowDown = maxStrainRate / fastest;
        strainRate *= slowDown;
    }

    // the next transformation: the strain increment, turned into the cell's axes, added to the stretch
    // (T = U·P from the singular value decomposition T = W·Σ·Vᵀ: U = W·Vᵀ, P = V·Σ·Vᵀ; it follows the
    // reference's velGrad more closely, to rounding, than Cell::polarDecomposition's eigen solver)
    const Eigen::JacobiSVD<Matrix3r> svd(cell.trsf, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Matrix3r U = svd.matrixU() * svd.matrixV().transpose();
    const Matrix3r P = svd.matrixV() * svd.singularValues().asDiagonal() * svd.matrixV().transpose();
    Matrix3r dEps;
    for (int i = 0; i < 6; ++i) {
        const Real e = dt * strainRate[i] * (i < 3 ? 1 : Real(.5)); // (engineering shear strain: γ = 2ε)
        dEps(voigtRow[i], voigtCol[i]) = dEps(voigtCol[i], voigtRow[i]) = e;
    }
    const Matrix3r next = U * (P + U.transpose() * dEps * U);
    const Matrix3r velGrad = (next * cell.trsf.inverse() - Matrix3r::Identity()) / dt;
    if (!velGrad.allFinite())
        throw std::runtime_error("Peri3dController: the velocity gradient is not finite (strain rates " + show(strainRate) + "; lower maxStrainRate or goal)");
    cell.velGrad = velGrad;

    progress += slowDown / nSteps;
    if (progress >= 1 || strain.cwiseAbs().maxCoeff() >= maxStrain) {
        if (doneHook.empty()) dead = true;
        else PyRunner::runCommand(doneHook, "Peri3dController.doneHook");
    }
}

} // namespace yade
