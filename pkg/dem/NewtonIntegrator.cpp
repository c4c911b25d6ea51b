#include <core/Scene.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>

namespace yade {

static inline Real sign(Real x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

// (3.5.12): each component of the acceleration is reduced when it increases the on-step
// velocity estimate v + a·dt/2, and increased when it decreases it.
void NewtonIntegrator::dampTranslation(Vector3r& accel, const Vector3r& vel, Real dt) const {
    for (int i = 0; i < 3; ++i) accel[i] *= 1 - damping * sign(accel[i] * (vel[i] + 0.5 * dt * accel[i]));
}

// The same for rotations, with the mid-step angular velocity.
void NewtonIntegrator::dampRotation(Vector3r& angAccel, const Vector3r& angVel) const {
    for (int i = 0; i < 3; ++i) angAccel[i] *= 1 - damping * sign(angAccel[i] * angVel[i]);
}

// Acceleration of a force or torque on the free degrees of freedom; blocked ones get zero.
static inline Vector3r accelOf(const Vector3r& f, const Vector3r& m, int blocked, int firstBit) {
    Vector3r a = f.cwiseQuotient(m);
    if (blocked)
        for (int i = 0; i < 3; ++i)
            if (blocked & (1 << (firstBit + i))) a[i] = 0;
    return a;
}

void NewtonIntegrator::action() {
    Scene& s = *scene;
    const Real dt = s.dt;
    s.forces.sync();
    const bool energy = s.trackEnergy;
    int kinId = -1, gravId = -1, dampId = -1;
    if (energy) {
        kinId = s.energy.term("kinetic", false);
        gravId = s.energy.term("gravWork", true);
        dampId = s.energy.term("nonviscDamp", true);
    }
    const long n = (long)s.bodies.size();
    Real maxV2 = 0;
#pragma omp parallel for schedule(static) reduction(max : maxV2)
    for (long id = 0; id < n; ++id) {
        const auto& b = s.bodies[(Body::id_t)id];
        if (!b) continue;
        if (mask != -1 && !(b->mask & mask)) continue; // bodies outside the mask are not moved
        State& st = *b->state;
        if (b->isDynamic()) {
            Vector3r accel = accelOf(s.forces.getForce((int)id), Vector3r::Constant(st.mass), st.blockedDOFsMask, 0);
            const Vector3r g = accelOf(gravity, Vector3r::Ones(), st.blockedDOFsMask, 0);
            if (dampGravity) accel += g;
            const Vector3r undamped = accel;
            if (damping != 0 && st.isDamped) dampTranslation(accel, st.vel, dt);
            if (!dampGravity) accel += g;
            Vector3r angAccel = accelOf(s.forces.getTorque((int)id), st.inertia, st.blockedDOFsMask, 3);
            const Vector3r angUndamped = angAccel;
            if (damping != 0 && st.isDamped) dampRotation(angAccel, st.angVel);
            if (energy) { // (on-step velocities v_n = v_{n-1/2} + a·dt/2, consistent with positions x_n)
                if (gravity != Vector3r::Zero()) s.energy.add(gravId, -st.mass * g.dot(st.vel) * dt); // the move x_{n-1} -> x_n
                const Vector3r v = st.vel + 0.5 * dt * accel, w = st.angVel + 0.5 * dt * angAccel;
                s.energy.add(kinId, 0.5 * st.mass * v.squaredNorm() + 0.5 * w.dot(st.inertia.cwiseProduct(w)));
                if (damping != 0) s.energy.add(dampId, -dt * (st.mass * (accel - undamped).dot(v) + (angAccel - angUndamped).dot(st.inertia.cwiseProduct(w))));
            }
            st.vel += dt * accel;
            st.angVel += dt * angAccel;
        }
        maxV2 = std::max(maxV2, st.vel.squaredNorm());
        st.pos += st.vel * dt;
        const Real angle = st.angVel.norm() * dt;
        if (angle != 0) { // spherical rotation update (3.5.9): rotate by angVel·dt
            st.ori = Quaternionr(AngleAxisr(angle, st.angVel / st.angVel.norm())) * st.ori;
            st.ori.normalize();
        }
    }
    maxVelocitySq = maxV2;
}

} // namespace yade
