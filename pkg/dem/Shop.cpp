#include <pkg/common/ElastMat.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pkg/dem/Shop.hpp>
#include <stdexcept>

namespace yade {

static const Sphere* sphereOf(const Body& b) { return dynamic_cast<const Sphere*>(b.shape.get()); }

Real Shop::PWaveTimeStep(const Scene& scene) {
    Real dt = Inf;
    for (const auto& b : scene.bodies) {
        if (!b || !b->shape || !b->material) continue;
        const auto* s = sphereOf(*b);
        const auto* m = dynamic_cast<const ElastMat*>(b->material.get());
        if (!s || !m) continue;
        // The density seen by the dynamics is the body's mass over its volume.
        const Real volume = 4.0 / 3.0 * Mathr_PI * std::pow(s->radius, 3);
        const Real density = b->state->mass() > 0 ? b->state->mass() / volume : m->density;
        dt = std::min(dt, s->radius / std::sqrt(m->young / density));
    }
    if (!std::isfinite(dt)) throw std::runtime_error("PWaveTimeStep: no sphere with an elastic material (ElastMat) in the scene");
    return dt;
}

Real Shop::unbalancedForce(Scene& scene, bool useMaxForce) {
    Vector3r gravity = Vector3r::Zero();
    for (const auto& e : scene.getEngines())
        if (auto* newton = dynamic_cast<NewtonIntegrator*>(e.get())) gravity = newton->gravity;
    scene.forces.sync();
    Real sumF = 0, maxF = 0;
    long nBodies = 0;
    for (const auto& b : scene.bodies) {
        if (!b || !b->isDynamic()) continue;
        const Real f = (scene.forces.getForce(b->id) + b->state->mass() * gravity).norm();
        maxF = std::max(maxF, f);
        sumF += f;
        ++nBodies;
    }
    Real sumContact = 0;
    long nContacts = 0;
    for (size_t k = 0; k < scene.interactions.size(); ++k) {
        if (!scene.interactions.isReal(k)) continue;
        if (const auto* p = dynamic_cast<const NormShearPhys*>(scene.interactions.phys(k))) {
            sumContact += (p->normalForce + p->shearForce).norm();
            ++nContacts;
        }
    }
    const Real meanContact = sumContact / nContacts;
    return (useMaxForce ? maxF : sumF / nBodies) / meanContact;
}

Real Shop::kineticEnergy(const Scene& scene, long* maxId) {
    Real e = 0, largest = -1;
    if (maxId) *maxId = -1;
    for (const auto& b : scene.bodies) {
        if (!b || !b->isDynamic()) continue;
        const State& s = *b->state;
        const Matrix3r R = s.ori().toRotationMatrix();
        const Matrix3r I = R * s.inertia().asDiagonal() * R.transpose(); // inertia in the global frame
        // (in a periodic cell, the velocity's fluctuation about the homogeneous field velGrad·x)
        const Vector3r v = scene.isPeriodic ? Vector3r(s.vel() - scene.cell->velGrad * s.pos()) : s.vel();
        const Real eb = 0.5 * s.mass() * v.squaredNorm() + 0.5 * s.angVel().dot(I * s.angVel());
        e += eb;
        if (maxId && eb > largest) {
            largest = eb;
            *maxId = b->id;
        }
    }
    return e;
}

std::pair<Vector3r, Vector3r> Shop::aabbExtremaOfSpheres(const Scene& scene, bool centers) {
    Vector3r lo = Vector3r::Constant(Inf), hi = Vector3r::Constant(-Inf);
    for (const auto& b : scene.bodies) {
        if (!b) continue;
        const Sphere* s = sphereOf(*b);
        if (!s) continue;
        const Vector3r r = Vector3r::Constant(centers ? 0 : s->radius);
        lo = lo.cwiseMin(b->state->pos() - r);
        hi = hi.cwiseMax(b->state->pos() + r);
    }
    return {lo, hi};
}

Real Shop::spheresVolume(const Scene& scene, int mask) {
    Real v = 0;
    for (const auto& b : scene.bodies) {
        if (!b || (mask > 0 && !(b->mask & mask))) continue;
        if (const Sphere* s = sphereOf(*b)) v += 4.0 / 3.0 * Mathr_PI * std::pow(s->radius, 3);
    }
    return v;
}

std::vector<int> Shop::coordinations(const Scene& scene, const Vector3r& lo, const Vector3r& hi) {
    std::vector<int> counts;
    for (const auto& b : scene.bodies) {
        if (!b) continue;
        const Vector3r& p = b->state->pos();
        if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
        int n = 0;
        for (const auto& I : scene.interactions.withBody(b->id)) n += I->isReal();
        counts.push_back(n);
    }
    return counts;
}

Shop::SphereColumns Shop::sphereColumns(const Scene& scene, int mask) {
    SphereColumns c;
    for (const auto& b : scene.bodies) {
        if (!b) continue;
        const Sphere* s = sphereOf(*b);
        if (!s || (mask != -1 && (b->mask & mask) == 0)) continue;
        c.ids.push_back(b->id);
        c.pos.push_back(b->state->pos());
        c.radius.push_back(s->radius);
        c.matIds.push_back(b->material ? b->material->id : -1);
    }
    return c;
}

Real Shop::spheresMass(const Scene& scene, int mask) {
    Real m = 0;
    for (const auto& b : scene.bodies)
        if (b && sphereOf(*b) && (mask == 0 || mask == -1 || (b->mask & mask) != 0)) m += b->state->mass();
    return m;
}

} // namespace yade
