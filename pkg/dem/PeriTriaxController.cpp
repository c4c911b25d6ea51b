#include <core/Scene.hpp>
#include <pkg/common/PyRunner.hpp>
#include <pkg/dem/PeriTriaxController.hpp>
#include <pkg/dem/Shop.hpp>
#include <cmath>
#include <sstream>

namespace yade {

// The law below was found by running the reference (Yade 2023.02a) on fixed configurations and
// comparing step by step (tests/reference/peri_controllers.py, doc/periodic.md); it is not derived.

static std::string show(const Vector3r& v) {
    std::ostringstream os;
    os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    return os.str();
}

static Real sign(Real x) { return Real((x > 0) - (x < 0)); }

// The largest extent of the bodies' bounds along each axis (zero where no body has a bound yet).
static Vector3r largestBound(const Scene& s) {
    Vector3r span = Vector3r::Zero();
    for (const auto& b : s.bodies) {
        if (!b || !b->bound) continue;
        const Vector3r d = b->bound->max - b->bound->min;
        if (d.allFinite()) span = span.cwiseMax(d);
    }
    return span;
}

void PeriTriaxController::updateStressAndStiffness() {
    Scene& s = *scene;
    Matrix3r sum = Matrix3r::Zero();
    Vector3r kSum = Vector3r::Zero();
    long n = 0;
    Shop::forEachContactForce(s, [&](const Vector3r& f, const Vector3r& l, const Vector3r& normal, const NormShearPhys& phys) {
        sum += f * l.transpose();
        const Vector3r a = normal.cwiseAbs();
        kSum += a * phys.kn + (Vector3r::Ones() - a) * phys.ks;
        ++n;
    });
    stressTensor = -sum / s.cell->volume(); // (compression negative)
    stress = stressTensor.diagonal();
    if (!dynCell) stiff = n > 0 ? Vector3r(kSum / Real(n)) : Vector3r::Zero();
}

void PeriTriaxController::action() {
    Scene& s = *scene;
    if (!s.isPeriodic) throw std::runtime_error("PeriTriaxController run on aperiodic simulation (it controls O.cell: set O.periodic=True).");
    if (!goal.allFinite()) throw std::invalid_argument("PeriTriaxController.goal must be finite, got " + show(goal));
    if (!maxStrainRate.allFinite() || maxStrainRate.minCoeff() < 0)
        throw std::invalid_argument("PeriTriaxController.maxStrainRate must be finite and non-negative, got " + show(maxStrainRate));
    if (globUpdate < 1) throw std::invalid_argument("PeriTriaxController.globUpdate must be at least 1, got " + std::to_string(globUpdate));
    if (!(s.dt > 0)) throw std::runtime_error("PeriTriaxController needs a positive O.dt");
    Cell& cell = *s.cell;
    const Vector3r size = cell.size();
    const Vector3r area(size[1] * size[2], size[0] * size[2], size[0] * size[1]);
    if (maxBodySpan[0] <= 0) maxBodySpan = largestBound(s);
    for (int i = 0; i < 3; ++i)
        if (size[i] < 2.1 * maxBodySpan[i])
            throw std::runtime_error("Minimum cell size is smaller than 2.1*maxBodySpan (periodic collider requirement): the cell's size is " + show(size)
                    + ", maxBodySpan " + show(maxBodySpan));
    if (dynCell) {
        if (std::isnan(mass)) { // (the reference's default: the mass of all bodies)
            mass = 0;
            for (const auto& b : s.bodies)
                if (b) mass += b->state->mass();
        }
        if (!(mass > 0) || !std::isfinite(mass))
            throw std::invalid_argument("PeriTriaxController.mass must be positive and finite with dynCell=True (NaN: the bodies' total mass), got " + std::to_string(mass));
    }
    // Stress and strain are taken from the contacts and the cell every globUpdate steps, and at every
    // step while there is no stiffness to predict them with (no contacts yet, or dynCell, which does
    // not compute it); the unbalanced force only every globUpdate steps.
    const bool update = s.iter % globUpdate == 0, measure = update || !(stiff.minCoeff() > 0);
    if (measure) updateStressAndStiffness();

    const Real dt = s.dt, volume = cell.volume();
    for (int i = 0; i < 3; ++i) {
        const Real F = cell.trsf(i, i);
        if (measure) strain[i] = std::log(F); // (in between, the strain follows the rates set)
        const bool stressAxis = stressMask & (1 << i);
        Real rate;
        if (stressAxis && dynCell) {
            // the cell as a mass pushed by (goal - stress), the push damped while it moves towards the goal
            const Real d = goal[i] - stress[i];
            rate = prevGrow[i] + (1 - growDamping * sign(prevGrow[i] * d)) * dt * d / mass;
        } else {
            // the rate that would reach the goal in one step: from the stiffness (stress), or exactly (strain)
            Real reach;
            if (stressAxis) {
                const Real d = goal[i] - stress[i];
                reach = stiff[i] > 0 ? d * area[i] / (stiff[i] * dt) : (d == 0 ? 0 : std::copysign(Inf, d));
            } else
                reach = (std::exp(goal[i] - strain[i]) - 1) / dt;
            // ... of which only a part, plus most of the last step's rate (the reference's damping)
            rate = dynCell || std::isinf(reach) ? reach : (1 - growDamping) * reach + 0.8 * prevGrow[i];
        }
        if (std::abs(rate) > maxStrainRate[i]) rate = std::copysign(maxStrainRate[i], rate);
        prevGrow[i] = strainRate[i] = rate;
        cell.velGrad(i, i) = rate;
        // until the next update, the stress follows the cell's strain through the stiffness
        if (stiff[i] > 0) stress[i] += stiff[i] * rate * dt / volume;
        strain[i] += rate * dt;
    }
    // work of the stress on the cell's deformation, the velocity gradient taken as the mean of the last
    // step's and this one's
    const Real work = 0.5 * dt * volume * (stressTensor * (cell.prevVelGrad + cell.velGrad)).trace();
    externalWork += work;
    if (s.trackEnergy) s.energy.add(s.energy.term("velGradWork", true), -work);

    bool allOk = true;
    for (int i = 0; i < 3; ++i) {
        if (stressMask & (1 << i)) {
            const Real d = std::abs(stress[i] - goal[i]);
            if (!(d <= absStressTol) || (goal[i] != 0 && !(d / std::abs(goal[i]) <= relStressTol))) allOk = false;
        } else { // (the strain is prescribed exactly: the tolerance is for rounding)
            const Real d = std::abs(strain[i] - goal[i]);
            if (!(d <= 1e-6) || (goal[i] != 0 && !(d / std::abs(goal[i]) <= 1e-6))) allOk = false;
        }
    }
    if (!allOk) return;
    if (update) currUnbalanced = Shop::unbalancedForce(s, false);
    if (currUnbalanced < maxUnbalanced && !doneHook.empty()) PyRunner::runCommand(doneHook, "PeriTriaxController.doneHook");
}

} // namespace yade
