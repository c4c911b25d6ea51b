#include <core/Scene.hpp>
#include <pkg/common/PyRunner.hpp>
#include <pkg/dem/PeriIsoCompressor.hpp>
#include <pkg/dem/Shop.hpp>
#include <cmath>

namespace yade {

// As for PeriTriaxController, the law was found by running the reference (Yade 2023.02a) on fixed
// configurations (doc/periodic.md, tests/reference/peri_controllers.py).

void PeriIsoCompressor::action() {
    Scene& s = *scene;
    if (!s.isPeriodic) throw std::runtime_error("PeriIsoCompressor: being used on a non-periodic simulation (it controls O.cell: set O.periodic=True)");
    if (state < 0) throw std::invalid_argument("PeriIsoCompressor.state must not be negative, got " + std::to_string(state));
    if ((size_t)state >= stresses.size()) return;
    const Real goal = stresses[state];
    if (!(goal < 0) || !std::isfinite(goal))
        throw std::invalid_argument("PeriIsoCompressor.stresses must be finite and negative (compression), got " + std::to_string(goal) + " at index " + std::to_string(state));
    if (globalUpdateInt < 1) throw std::invalid_argument("PeriIsoCompressor.globalUpdateInt must be at least 1, got " + std::to_string(globalUpdateInt));
    if (!(s.dt > 0)) throw std::runtime_error("PeriIsoCompressor needs a positive O.dt");
    if (charLen < 0 || maxSpan < 0) {
        Real first = -1, largest = 0;
        for (const auto& b : s.bodies) {
            if (!b || !b->bound) continue;
            const Vector3r d = b->bound->max - b->bound->min;
            if (!d.allFinite()) continue;
            if (first < 0) first = d.mean();
            largest = std::max(largest, d.maxCoeff());
        }
        if (charLen < 0) charLen = first;
        if (maxSpan < 0) maxSpan = largest;
        if (charLen < 0) throw std::runtime_error("PeriIsoCompressor: no body has a bound to take charLen from (set charLen)");
    }
    Cell& cell = *s.cell;
    const Vector3r size = cell.size();
    if (size.minCoeff() < 2.1 * maxSpan)
        throw std::runtime_error("Minimum cell size is smaller than 2.1*span_of_the_biggest_body! (periodic collider requirement): the smallest edge is "
                + std::to_string(size.minCoeff()) + ", maxSpan " + std::to_string(maxSpan));
    const Vector3r area(size[1] * size[2], size[0] * size[2], size[0] * size[1]);

    // the normal stresses, from the magnitudes of the contact forces' components, and the mean stiffness
    Vector3r sumF = Vector3r::Zero();
    Real sumK = 0;
    long n = 0;
    Shop::forEachContactForce(s, [&](const Vector3r& f, const Vector3r&, const Vector3r&, const NormShearPhys& phys) {
        sumF += f.cwiseAbs();
        sumK += (phys.kn + 2 * phys.ks) / 3;
        ++n;
    });
    const Real K = n > 0 ? sumK / n : 0;
    sigma = -sumF.cwiseQuotient(area);

    // Δl: how much the cell's edge should grow (the reference's gain of 1e-4 on the stiffness estimate),
    // at most maxDispl on any edge
    const Real dt = s.dt, maxDispl = 1e-2 * charLen;
    auto growth = [&](Real stressError, Real a) { return K > 0 ? stressError * a * 1e-4 / K : (stressError == 0 ? 0 : std::copysign(Inf, stressError)); };
    if (keepProportions) {
        Real strainInc = growth(goal - sigma.mean(), area.mean()) / size.mean();
        if (std::abs(strainInc) * size.maxCoeff() > maxDispl) strainInc = std::copysign(maxDispl / size.maxCoeff(), strainInc);
        for (int i = 0; i < 3; ++i) cell.velGrad(i, i) = strainInc / dt;
        sigma += Vector3r::Constant(K * strainInc * size.mean());
    } else {
        for (int i = 0; i < 3; ++i) {
            Real grow = growth(goal - sigma[i], area[i]);
            if (std::abs(grow) > maxDispl) grow = std::copysign(maxDispl, grow);
            cell.velGrad(i, i) = grow / (size[i] * dt);
            sigma[i] += K * grow;
        }
    }

    // the stress is reached when it is within 0.5 % (the mean with keepProportions, else along every axis)
    // and the unbalanced force is below maxUnbalanced; that force is computed only every globalUpdateInt
    // steps, the last value (-1: none yet) counting in between
    const Real tol = 5e-3 * std::abs(goal);
    if (keepProportions ? std::abs(sigma.mean() - goal) > tol : (sigma.array() - goal).abs().maxCoeff() > tol) return;
    if (s.iter % globalUpdateInt == 0) currUnbalanced = Shop::unbalancedForce(s, false);
    if (currUnbalanced > maxUnbalanced) return;
    ++state;
    if ((size_t)state >= stresses.size() && !doneHook.empty()) PyRunner::runCommand(doneHook, "PeriIsoCompressor.doneHook");
}

} // namespace yade
