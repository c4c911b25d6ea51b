#include <core/Scene.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <pkg/common/Box.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/triaxial/TriaxialStressController.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace yade {

// The control laws below were found by running the reference (Yade 2023.02a) on fixed packings and
// comparing step by step (doc/triaxial.md); the velocities match it to rounding.

static const char* wallName[6] = {"wall_left_id", "wall_right_id", "wall_bottom_id", "wall_top_id", "wall_back_id", "wall_front_id"};

int TriaxialStressController::wallId(int w) const {
    const int ids[6] = {wall_left_id, wall_right_id, wall_bottom_id, wall_top_id, wall_back_id, wall_front_id};
    return ids[w];
}

bool TriaxialStressController::wallActivated(int w) const {
    const bool on[6] = {wall_left_activated, wall_right_activated, wall_bottom_activated, wall_top_activated, wall_back_activated, wall_front_activated};
    return on[w];
}

Vector3r TriaxialStressController::normal(int w) {
    Vector3r n = Vector3r::Zero();
    n[w / 2] = (w % 2 == 0) ? 1 : -1;
    return n;
}

Real TriaxialStressController::solidVolume(const Scene& s) {
    Real v = 0;
    for (const auto& b : s.bodies) {
        if (!b || !(b->isDynamic() || b->clumpId >= 0)) continue;
        if (const auto* sphere = dynamic_cast<const Sphere*>(b->shape.get())) v += 4. / 3. * M_PI * std::pow(sphere->radius, 3);
    }
    return v;
}

Vector3r TriaxialStressController::strainRate() const {
    Vector3r rate = Vector3r::Zero();
    if (!scene) return rate;
    const Real size[3] = {width, height, depth};
    for (int i = 0; i < 3; ++i) {
        const int lo = wallId(2 * i), hi = wallId(2 * i + 1);
        if (!scene->bodies.exists(lo) || !scene->bodies.exists(hi) || !(size[i] > 0)) continue;
        rate[i] = (scene->bodies[hi]->state->vel()[i] - scene->bodies[lo]->state->vel()[i]) / size[i];
    }
    return rate;
}

void TriaxialStressController::checkAndInit() {
    Scene& s = *scene;
    if (computeStressStrainInterval < 1 || stiffnessUpdateInterval < 1 || radiusControlInterval < 1)
        throw std::invalid_argument(getClassName() + ": computeStressStrainInterval, stiffnessUpdateInterval and radiusControlInterval must be at least 1");
    for (Real x : {goal1, goal2, goal3, stressDamping, strainDamping, max_vel, maxMultiplier, finalMaxMultiplier})
        if (!std::isfinite(x)) throw std::invalid_argument(getClassName() + ": goal1..3, stressDamping, strainDamping, max_vel and the multipliers must be finite");
    if (max_vel < 0) throw std::invalid_argument(getClassName() + ".max_vel must be non-negative, got " + std::to_string(max_vel));
    if (!(s.dt > 0)) throw std::runtime_error(getClassName() + " needs a positive O.dt");
    for (int w = 0; w < 6; ++w) {
        const int id = wallId(w);
        if (!s.bodies.exists(id))
            throw std::runtime_error(getClassName() + "." + wallName[w] + " = " + std::to_string(id) + " is not a body of the scene (the six walls, e.g. utils.aabbWalls, must exist)");
    }
    for (int w = 0; w < 6; ++w)
        for (int u = w + 1; u < 6; ++u)
            if (wallId(w) == wallId(u)) throw std::invalid_argument(getClassName() + ": " + wallName[w] + " and " + wallName[u] + " are the same body " + std::to_string(wallId(w)));
    if (initialized) return;
    if (thickness < 0) {
        const auto* box = dynamic_cast<const Box*>(s.bodies[wall_bottom_id]->shape.get());
        thickness = box ? 2 * box->extents[1] : 0;
    }
    particlesVolume = solidVolume(s);
    updateDimensions();
    if (width0 <= 0) width0 = width;
    if (height0 <= 0) height0 = height;
    if (depth0 <= 0) depth0 = depth;
    initialized = true;
}

void TriaxialStressController::updateDimensions() {
    const Scene& s = *scene;
    auto coord = [&](int w) { return s.bodies[wallId(w)]->state->pos()[w / 2]; };
    width = coord(right) - coord(left) - thickness;
    height = coord(top) - coord(bottom) - thickness;
    depth = coord(front) - coord(back) - thickness;
    if (!(width > 0 && height > 0 && depth > 0) || !std::isfinite(width * height * depth))
        throw std::runtime_error(getClassName() + ": the box between the walls has size " + std::to_string(width) + " x " + std::to_string(height) + " x "
                + std::to_string(depth) + " (each wall_*_id must name the wall on its side: left/right along x, bottom/top along y, back/front along z, and thickness must be below the gaps)");
    boxVolume = width * height * depth;
    porosity = 1 - particlesVolume / boxVolume;
    const Real mean = (width + height + depth) / 3;
    if (mean > 0) maxVel = Vector3r(width, height, depth) * (max_vel / mean);
}

void TriaxialStressController::updateStiffness() {
    const Scene& s = *scene;
    for (int w = 0; w < 6; ++w) {
        stiffness[w] = 0;
        for (const auto& p : s.interactions.partnersOf(wallId(w))) {
            if (!s.interactions.isReal(p.k)) continue;
            if (const auto* phys = dynamic_cast<const NormPhys*>(s.interactions.phys(p.k))) stiffness[w] += phys->kn;
        }
    }
}

void TriaxialStressController::computeStressStrain() {
    Scene& s = *scene;
    const Real area[3] = {height * depth, width * depth, width * height};
    meanStress = 0;
    for (int w = 0; w < 6; ++w) {
        // the force the packing puts on the wall, outwards positive: compression is a negative stress
        stress[w] = s.forces.getForce(wallId(w)) * ((w % 2 == 0) ? 1. : -1.) / area[w / 2];
        meanStress += stress[w][w / 2] / 6;
    }
    strain = Vector3r(std::log(width / width0), std::log(height / height0), std::log(depth / depth0));
    volumetricStrain = strain.sum();
}

void TriaxialStressController::controlExternalStress(int w, Real goalStress) {
    Scene& s = *scene;
    const int axis = w / 2;
    const Real area[3] = {height * depth, width * depth, width * height};
    const Vector3r n = normal(w);
    // the wall's move that would cancel the force error, from the stiffness of its contacts, at most max_vel_i dt
    const Real error = s.forces.getForce(wallId(w)).dot(n) - goalStress * area[axis];
    const Real limit = maxVel[axis] * s.dt;
    Real move;
    if (stiffness[w] > 0) {
        move = error / stiffness[w];
        if (std::abs(move) > limit) move = std::copysign(limit, move);
    } else
        move = limit * Real((error > 0) - (error < 0));
    Vector3r& vel = s.bodies[wallId(w)]->state->vel();
    const Real vn = vel.dot(n);
    vel += (0.8 * vn + (1 - stressDamping) * move / s.dt - vn) * n;
}

void TriaxialStressController::controlStrainRate(int w, Real rate) {
    Scene& s = *scene;
    const Real size[3] = {width, height, depth};
    const Vector3r target = -0.5 * rate * size[w / 2] * normal(w);
    Vector3r& vel = s.bodies[wallId(w)]->state->vel();
    vel = strainDamping * vel + (1 - strainDamping) * target;
}

void TriaxialStressController::growParticles(Real multiplier) {
    Scene& s = *scene;
    const Real m3 = multiplier * multiplier * multiplier, m5 = m3 * multiplier * multiplier;
    for (const auto& b : s.bodies) {
        if (!b || !b->isDynamic()) continue;
        auto* sphere = dynamic_cast<Sphere*>(b->shape.get());
        if (!sphere) continue;
        sphere->radius *= multiplier;
        b->state->mass() *= m3;
        b->state->inertia() *= m5;
    }
    // the contacts follow, as in the reference: their radii and stiffnesses (linear in the radii) scale too
    const InteractionContainer& I = s.interactions;
    auto grows = [&](Body::id_t id) {
        const auto& b = s.bodies[id];
        return b && b->isDynamic() && dynamic_cast<const Sphere*>(b->shape.get());
    };
    std::vector<char> done(I.size(), 0);
    for (const auto& b : s.bodies) {
        if (!b || !grows(b->id)) continue;
        for (const auto& p : I.partnersOf(b->id)) {
            if (p.k >= done.size() || done[p.k] || !I.isReal(p.k)) continue;
            done[p.k] = 1;
            if (auto* phys = dynamic_cast<NormShearPhys*>(I.phys(p.k))) {
                phys->kn *= multiplier;
                phys->ks *= multiplier;
            }
            if (auto* geom = dynamic_cast<GenericSpheresContact*>(I.geom(p.k))) { // (the radius of a grown sphere only)
                const Body::id_t id1 = I.pairIds[2 * p.k], id2 = I.pairIds[2 * p.k + 1];
                if (grows(id1)) geom->refR1 *= multiplier;
                if (grows(id2)) geom->refR2 *= multiplier;
            }
        }
    }
    particlesVolume *= m3;
    noteExternalWrite(); // (the shapes changed: the loop's and the collider's caches are rebuilt)
}

void TriaxialStressController::controlInternalStress() {
    const Real goalMean = (goal1 + goal2 + goal3) / 3;
    if (goalMean == 0) throw std::invalid_argument(getClassName() + ": internalCompaction needs a non-zero mean of goal1, goal2, goal3 (a stress)");
    // once the mean stress has passed the goal, the finer multiplier only
    if (std::abs(meanStress) >= std::abs(goalMean) && meanStress * goalMean > 0) finalStage = true;
    const Real factor = (finalStage ? finalMaxMultiplier : maxMultiplier) - 1;
    const Real multiplier = 1 + factor * (goalMean - meanStress) / goalMean;
    previousMultiplier = multiplier;
    previousStress = meanStress;
    growParticles(multiplier);
}

void TriaxialStressController::measure() {
    Scene& s = *scene;
    checkAndInit();
    if (updatePorosity) {
        particlesVolume = solidVolume(s);
        updatePorosity = false;
    }
    updateDimensions();
    if (s.iter % stiffnessUpdateInterval == 0 || s.iter == 0) updateStiffness();
    if (s.iter % computeStressStrainInterval == 0) computeStressStrain();
}

void TriaxialStressController::control() {
    Scene& s = *scene;
    if (internalCompaction) {
        if (s.iter % radiusControlInterval == 0) controlInternalStress();
    } else {
        for (int axis = 0; axis < 3; ++axis)
            for (int w = 2 * axis; w < 2 * axis + 2; ++w) {
                if (!wallActivated(w)) continue;
                if (stressMask & (1 << axis)) controlExternalStress(w, goal(axis));
                else controlStrainRate(w, goal(axis));
            }
    }
    Real work = 0;
    for (int w = 0; w < 6; ++w) work += s.forces.getForce(wallId(w)).dot(s.bodies[wallId(w)]->state->vel());
    externalWork += work * s.dt;
}

void TriaxialStressController::action() {
    measure();
    control();
}

} // namespace yade
