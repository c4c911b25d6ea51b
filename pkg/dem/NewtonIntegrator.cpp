#include <core/Scene.hpp>
#include <lib/base/Lanes.hpp>
#include <lib/base/ThreadRange.hpp>
#include <pkg/common/Clump.hpp>
#include <pkg/dem/CriticalTimeStep.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pkg/dem/AsphericalRotation.hpp>
#include <lib/base/Logging.hpp>
#include <cstdint>
#include <cstring>
#include <string>
#include <pkg/dem/ScGeom.hpp>
#include <sstream>
#include <thread>

namespace yade {

// Acceleration of a force or torque on the free degrees of freedom; blocked ones get zero.
static inline Vector3r accelOf(const Vector3r& f, const Vector3r& m, int blocked, int firstBit) {
    Vector3r a = f.cwiseQuotient(m);
    if (blocked)
        for (int i = 0; i < 3; ++i)
            if (blocked & (1 << (firstBit + i))) a[i] = 0;
    return a;
}

// sin(x)/x and cos(x) for x = angle/2 (AsphericalRotation.hpp). The coefficients are products by constants,
// not quotients, and the caller needs sin(x)/x, not sin(x) (then divided by |ω|): the divisions in a chain
// made the integrator wait on them.
using aspherical::sincCosHalf;

static constexpr int allRotations = State::DOF_RX | State::DOF_RY | State::DOF_RZ;

// The spherical rotation update (3.5.9) of one body (T = Real) or of two consecutive ones (T = Two,
// lib/base/Lanes.hpp: the same bits): each turned by angVel·dt about angVel; a body that does not
// spin keeps its orientation.
template <class T> YADE_KERNEL void turnStep(const BodyStore::Columns& h, long id, Real dt) {
    constexpr int lanes = lanesOf<T>;
    LaneIds<T> ids;
    for (int i = 0; i < lanes; ++i) ids.i[i] = id + i;
    const Vec3<T> w = gather<T>(h.angVel, ids);
    const T angle = norm(w) * T(dt);
    bool small = true; // (every lane in the range of sincCosHalf's series: the usual case)
    for (int i = 0; i < lanes; ++i) small &= 0.25 * lane(angle, i) * lane(angle, i) < 1e-4;
    T sincHalf, cosHalf;
    if (small) {
        const T x = T(0.5) * angle, x2 = x * x;
        sincHalf = T(1.0) - x2 * T(1. / 6) * (T(1.0) - x2 * T(1. / 20) * (T(1.0) - x2 * T(1. / 42)));
        cosHalf = T(1.0) - x2 * T(0.5) * (T(1.0) - x2 * T(1. / 12) * (T(1.0) - x2 * T(1. / 30) * (T(1.0) - x2 * T(1. / 56))));
    } else {
        Real s[lanes], c[lanes];
        for (int i = 0; i < lanes; ++i) sincCosHalf(lane(angle, i), s[i], c[i]);
        sincHalf = eachLane<T>([&](int i) { return s[i]; });
        cosHalf = eachLane<T>([&](int i) { return c[i]; });
    }
    const T k = sincHalf * T(0.5 * dt); // sin(angle/2) / |ω|, angle = |ω|·dt
    // (cosHalf, k·ω) * ori, in the order of Eigen's product of two quaternions (its SSE2 form)
    const T ax = k * w.x, ay = k * w.y, az = k * w.z, aw = cosHalf;
    const T bx = eachLane<T>([&](int i) { return h.ori[id + i].x(); }), by = eachLane<T>([&](int i) { return h.ori[id + i].y(); });
    const T bz = eachLane<T>([&](int i) { return h.ori[id + i].z(); }), bw = eachLane<T>([&](int i) { return h.ori[id + i].w(); });
    const T qx = (aw * bx + ay * bz) - (az * by - ax * bw), qy = (aw * by + ay * bw) + (az * bx - ax * bz);
    const T qz = (aw * bz - ay * bx) + (az * bw + ax * by), qw = (aw * bw - ay * by) - (az * bz + ax * bx);
    // back to unit length: |q|² = 1 + e, e of the order of the rounding after a step, and then
    // 1/sqrt(1 + e) = (3 - |q|²)/2 + O(e²) in double precision (an ori set far from unit length from
    // Python gets the exact division)
    const T n2 = (qx * qx + qz * qz) + (qy * qy + qw * qw);
    const T factor = eachLane<T>([&](int i) {
        const Real m = lane(n2, i);
        return std::abs(m - 1) < 1e-8 ? 0.5 * (3 - m) : 1 / std::sqrt(m);
    });
    const T x = qx * factor, y = qy * factor, z = qz * factor, wq = qw * factor;
    for (int i = 0; i < lanes; ++i)
        if (lane(angle, i) != 0) h.ori[id + i] = Quaternionr(lane(wq, i), lane(x, i), lane(y, i), lane(z, i));
}

// The rotation update of bodies b0 .. b1-1 whose spins[id] is set (1: turnStep; 2: a body whose
// rotations are all blocked, turned by the reference's formula). In a loop of its own, after the one
// that updates the velocities: each turn waits for its spin, and in one loop with the rest a body's
// whole update was one chain of dependent operations the processor could not overlap with the next
// body's (this loop is short: several bodies are in flight at once, two in each turnStep).
static void turnSpheres(const BodyStore::Columns& h, const char* spins, long b0, long b1, Real dt) {
    for (long id = b0; id < b1;) {
        if (id + 1 < b1 && spins[id] == 1 && spins[id + 1] == 1) {
            turnStep<Two>(h, id, dt);
            id += 2;
            continue;
        }
        if (spins[id] == 1) turnStep<Real>(h, id, dt);
        else if (spins[id] == 2) { // a body turned by an engine (facets of a drum): the turn as the reference computes it
            const Vector3r& angVel = h.angVel[id];
            const Real w = angVel.norm(), angle = w * dt;
            if (angle != 0) h.ori[id] = (Quaternionr(AngleAxisr(angle, angVel / w)) * h.ori[id]).normalized();
        }
        ++id;
    }
}

// Whether the principal moments differ (by their bits: one test for the spheres, instead of three
// floating-point comparisons in the integrator's loop).
static inline bool unequalMoments(const Vector3r& I) {
    uint64_t a, b, c;
    std::memcpy(&a, &I[0], sizeof a);
    std::memcpy(&b, &I[1], sizeof b);
    std::memcpy(&c, &I[2], sizeof c);
    return ((a ^ b) | (b ^ c)) != 0;
}

// One step of an aspherical body's rotation by the chosen scheme (AsphericalRotation.hpp), out of the
// integrator's loop (few bodies take it): the new orientation, spin and angular momentum, the rotational
// kinetic energy on-step and the power of the damping torque (for O.energy). The damping (3.5.12) acts on
// the torque in the global frame, by the sign of each component of torque·spin, the spin being the last
// step's (dampSpin: the stored State.angVel), as in the reference. lambda: the damping (0: none).
struct AsphericalTurn {
    aspherical::Turn turn;
    Real dampingPower;
};
static __attribute__((noinline)) AsphericalTurn turnAspherical(aspherical::Scheme scheme, bool normalize, const Quaternionr& q,
        const Vector3r& angVel, const Vector3r& angMom, const Vector3r& dampSpin, const Vector3r& torque, const Vector3r& I, Real dt,
        Real lambda) {
    Vector3r damped = torque;
    if (lambda != 0) NewtonIntegrator::damp(damped, dampSpin, 0, lambda); // (the sign of each component of torque·spin)
    AsphericalTurn t;
    switch (scheme) {
        case aspherical::Scheme::fincham: t.turn = aspherical::fincham(q, angMom, damped, I, dt); break;
        case aspherical::Scheme::omelyan: t.turn = aspherical::omelyan(q, angVel, damped, I, dt, normalize); break;
        default: t.turn = aspherical::spiral(q, angVel, damped, I, dt, normalize);
    }
    t.dampingPower = (damped - torque).dot(0.5 * (angVel + t.turn.angVel));
    return t;
}

// Gravity without the blocked translations.
static inline Vector3r freeGravity(const Vector3r& g, int blocked) {
    Vector3r a = g;
    if (blocked)
        for (int i = 0; i < 3; ++i)
            if (blocked & (1 << i)) a[i] = 0;
    return a;
}

// The constants of a step: the engine's attributes and the scene's columns. The functions below
// work on a local copy: through references, every bool or char store made the compiler reload
// each base pointer.
struct IntegratorStep {
    Scene* scene;
    Real dt, lambda; // lambda: the damping
    Vector3r g;
    bool gravityDamped, aspherical, energy, split;
    aspherical::Scheme rotScheme; // NewtonIntegrator.rotAlgorithm
    bool normalizeOri;            // whether SPIRAL and Omelyan normalize the orientation in this step (normalizeEvery)
    int moveMask;
    BodyStore::Columns h;
    const Vector3r* F;         // the force and torque totals
    const Vector3r* T;
    char* spins;               // NewtonIntegrator::spinning
    const Vector3r* reference; // the skin's reference positions (MotionRecord::Write), or null
    // A periodic cell whose homogeneous field the bodies follow (Cell.homoDeform 1, 2 or 3): the
    // change of velGrad since the last step, the last step's velGrad, and whether the convective
    // term (2, 3) is added.
    bool periodic, homo, convective;
    Matrix3r dVelGrad, prevVelGrad;
    Vector3r dSpin; // the change of the field's spin (the axial vector of velGrad's skew part)
};

// A body's energy terms in a step, or their sums over bodies (kin: all the kinetic energy, or its
// translational part with kinSplit).
struct BodyEnergy {
    Real grav = 0, kin = 0, kinRot = 0, damp = 0;
};

// What an aspherical body's step adds to the new state. (The new state is kept in locals, not in one
// record: the compiler kept such a record in memory, 15 instructions more per body.)
struct AsphericalUpdate {
    Quaternionr ori; // (when turned)
    bool turned = false;
    Vector3r* angMom = nullptr; // (its State.angMom, and the new value)
    Vector3r newAngMom = Vector3r::Zero();
    Vector3r dampSpin = Vector3r::Zero(); // the stored spin, whose sign the damping reads
};

// Translation (3.5.1): the acceleration of the gathered force on the free translations, with gravity
// (damped with it when dampGravity) and the damping (3.5.12); undamped: the same before damping.
// (vel: the velocity the damping's sign reads; in a periodic cell, the fluctuation about the homogeneous field)
static inline Vector3r linearAccel(const IntegratorStep& st, const Vector3r& force, Real mass, int blocked, bool damped,
        const Vector3r& vel, const Vector3r& gFree, Vector3r& undamped) {
    Vector3r accel = accelOf(force, Vector3r::Constant(mass), blocked, 0);
    if (st.gravityDamped) accel += gFree;
    undamped = accel;
    if (damped) NewtonIntegrator::damp(accel, vel, st.dt, st.lambda);
    if (!st.gravityDamped) accel += gFree;
    return accel;
}

// Energy terms of a body's step (on-step velocities v_n = v_{n-1/2} + a·dt/2, consistent with
// positions x_n): the work of gravity over the move x_{n-1} -> x_n, the kinetic energy (one term, or
// translational and rotational with kinSplit), the work of the damping. vel, angVel: before the step.
static inline void energyOfSphere(const IntegratorStep& st, Real mass, const Vector3r& inertia, const Vector3r& gFree, const Vector3r& vel,
        const Vector3r& accel, const Vector3r& undamped, const Vector3r& angVel, const Vector3r& angAccel, const Vector3r& angUndamped, BodyEnergy& e) {
    const Vector3r v = vel + 0.5 * st.dt * accel, w = angVel + 0.5 * st.dt * angAccel;
    e.grav = -mass * gFree.dot(vel) * st.dt;
    if (st.split) {
        e.kin = 0.5 * mass * v.squaredNorm();
        e.kinRot = 0.5 * w.dot(inertia.cwiseProduct(w));
    } else
        e.kin = 0.5 * mass * v.squaredNorm() + 0.5 * w.dot(inertia.cwiseProduct(w));
    e.damp = -st.dt * (mass * (accel - undamped).dot(v) + (angAccel - angUndamped).dot(inertia.cwiseProduct(w)));
}

static inline void energyOfAspherical(const IntegratorStep& st, Real mass, const Vector3r& gFree, const Vector3r& vel, const Vector3r& accel,
        const Vector3r& undamped, const AsphericalTurn& t, BodyEnergy& e) {
    const Vector3r v = vel + 0.5 * st.dt * accel;
    e.grav = -mass * gFree.dot(vel) * st.dt;
    const Real trans = 0.5 * mass * v.squaredNorm();
    if (st.split) {
        e.kin = trans;
        e.kinRot = t.turn.kinetic;
    } else
        e.kin = trans + t.turn.kinetic;
    e.damp = -st.dt * (mass * (accel - undamped).dot(v) + t.dampingPower);
}

// Rotation of a sphere (or of any body with exactAsphericalRot off): the new spin from the torque on
// the free rotations, damped as the translation; the orientation is turned by turnSpheres. A still
// body (no spin, no torque) keeps angAccel = 0 (skipped: most bodies before their first contact).
static inline void rotateSphere(const IntegratorStep& st, long id, Real mass, const Vector3r& inertia, int blocked, bool damped, bool still,
        const Vector3r& gFree, const Vector3r& vel, const Vector3r& accel, const Vector3r& undamped, Vector3r& angVel, BodyEnergy& e) {
    Vector3r angAccel = still ? Vector3r::Zero() : accelOf(st.T[id], inertia, blocked, 3);
    const Vector3r angUndamped = angAccel;
    if (damped && !still) NewtonIntegrator::damp(angAccel, angVel, st.dt, st.lambda); // the same for rotations
    if (st.energy) energyOfSphere(st, mass, inertia, gFree, vel, accel, undamped, angVel, angAccel, angUndamped, e);
    angVel += st.dt * angAccel;
}

// Unequal principal moments and free rotations: Euler's equations in the body's frame (3.5.2) by the scheme
// NewtonIntegrator.rotAlgorithm chooses. Fincham's (the default) is driven by the angular momentum
// State.angMom (global frame), as in the reference: the spin is found from it (a spin set alone is
// overwritten); SPIRAL and Omelyan are driven by the spin State.angVel, angMom following it.
static inline bool isAspherical(const IntegratorStep& st, const Vector3r& inertia, int blocked) {
    return __builtin_expect(unequalMoments(inertia), 0) && st.aspherical && !(blocked & allRotations) && (inertia.array() > 0).all();
}

// (The spin found from the momentum is the body's spin at the step's time; the damping reads the stored one, as
// the reference does: a body given only angMom is not damped in its first step.)
static inline void spinFromMomentum(const IntegratorStep& st, long id, const Vector3r& inertia, Vector3r& angVel, AsphericalUpdate& a) {
    a.angMom = &(*st.scene).bodies[id]->state->angMom;
    a.dampSpin = angVel;
    if (st.rotScheme != aspherical::Scheme::fincham) return;
    const Quaternionr& q = st.h.ori[id];
    angVel = q * (q.conjugate() * *a.angMom).cwiseQuotient(inertia);
}

static inline void rotateAspherical(const IntegratorStep& st, long id, Real mass, const Vector3r& inertia, bool damped, const Vector3r& gFree,
        const Vector3r& vel, const Vector3r& accel, const Vector3r& undamped, Vector3r& angVel, BodyEnergy& e, AsphericalUpdate& a) {
    const AsphericalTurn t = turnAspherical(st.rotScheme, st.normalizeOri, st.h.ori[id], angVel, *a.angMom, a.dampSpin, st.T[id], inertia,
            st.dt, damped ? st.lambda : 0);
    a.ori = t.turn.ori;
    a.turned = true;
    a.newAngMom = t.turn.angMom;
    if (!std::isfinite(a.ori.coeffs().sum())) e.kinRot = NaN; // (caught by the guard)
    if (st.energy) energyOfAspherical(st, mass, gFree, vel, accel, undamped, t, e);
    angVel = t.turn.angVel;
}

// m·v, each row's terms summed left to right (as Eigen's product of a 3×3 matrix sums them), for one
// body (T = Real) or two: the periodic steps take it in every path, which then give the same bits
template <class T> YADE_KERNEL Vec3<T> matVec(const Matrix3r& m, const Vec3<T>& v) {
    return {(T(m(0, 0)) * v.x + T(m(0, 1)) * v.y) + T(m(0, 2)) * v.z, (T(m(1, 0)) * v.x + T(m(1, 1)) * v.y) + T(m(1, 2)) * v.z,
            (T(m(2, 0)) * v.x + T(m(2, 1)) * v.y) + T(m(2, 2)) * v.z};
}
static inline Vector3r mulRows(const Matrix3r& m, const Vector3r& v) { return eigen(matVec<Real>(m, vec3(v))); }

// The homogeneous field of a periodic cell (3.6.1, Cell.homoDeform): the new velocity with the field's
// convective acceleration velGrad·v (2, 3: the last step's velGrad, v before the step, v(t - Δt/2)),
// then the change of velGrad since the last step times the position before the step.
static inline void homogeneousField(const IntegratorStep& st, const Vector3r& pos, const Vector3r& accel, Vector3r& vel) {
    vel = st.convective ? Vector3r(vel + st.dt * (accel + mulRows(st.prevVelGrad, vel))) : Vector3r(vel + st.dt * accel);
    vel = vel + mulRows(st.dVelGrad, pos);
}
static inline void homogeneousSpin(const IntegratorStep& st, Vector3r& angVel) { angVel += st.dSpin; }

// A dynamic body's new velocity and spin (and an aspherical body's orientation) with its energy terms;
// Periodic: the damping reads the fluctuation of the velocity about the cell's homogeneous field, and
// bodies follow the field where Cell.homoDeform says so (homogeneousField).
template <bool Periodic>
static inline void accelerate(const IntegratorStep& st, long id, int blocked, Real mass, const Vector3r& inertia, Vector3r& vel, Vector3r& angVel,
        BodyEnergy& e, AsphericalUpdate& a, const Vector3r& pos) {
    const Vector3r fluct = Periodic ? Vector3r(vel - mulRows(st.prevVelGrad, pos)) : vel;
    const bool damped = st.lambda != 0 && st.h.isDamped[id];
    const Vector3r gFree = freeGravity(st.g, blocked);
    Vector3r undamped;
    const Vector3r accel = linearAccel(st, st.F[id], mass, blocked, damped, fluct, gFree, undamped);
    const bool asphericalBody = isAspherical(st, inertia, blocked);
    if (__builtin_expect(asphericalBody, 0)) spinFromMomentum(st, id, inertia, angVel, a);
    const bool still = (angVel.array() == 0).all() && (st.T[id].array() == 0).all() && (inertia.array() > 0).all();
    if (asphericalBody && !still)
        rotateAspherical(st, id, mass, inertia, damped, gFree, fluct, accel, undamped, angVel, e, a);
    else
        rotateSphere(st, id, mass, inertia, blocked, damped, still, gFree, fluct, accel, undamped, angVel, e);
    if (Periodic && st.homo) homogeneousField(st, pos, accel, vel);
    else vel += st.dt * accel;
}

// The stability guard: whether the new state is finite and the orientation a non-zero quaternion (an
// ori written into a view or an array is checked here: NaN or zero). The terms are summed as a tree,
// not one after the other: the branch waits for the sum, and a chain of twelve additions held every
// body's update back. (|angVel|² is finite where the turn's angle |angVel|·dt is.)
static inline bool finiteState(const Vector3r& pos, const Vector3r& vel, const Vector3r& angVel, const BodyEnergy& e, const Quaternionr& ori) {
    const Real spin2 = angVel.squaredNorm(), oriNorm2 = ori.coeffs().squaredNorm();
    const Real energies = (e.kin + e.kinRot) + (e.damp + e.grav);
    return std::isfinite(((pos[0] + pos[1]) + (pos[2] + vel[0])) + ((vel[1] + vel[2]) + (spin2 + oriNorm2)) + energies) && oriNorm2 > 0;
}

// One body's step: its new state, the guard, then its entries written (false: not finite, the last
// state kept). Holes and bodies outside the mask are not moved. st.spins[id] says whether
// turnSpheres turns it; its energy terms are added to sum (any: some were) and its squared velocity
// to maxV2.
static inline bool integrateBody(const IntegratorStep& st, long id, BodyEnergy& sum, bool& any, Real& maxV2) {
    const BodyStore::Columns& h = st.h;
    st.spins[id] = false;
    if (!h.exists[id]) { // (the State of a body is a view of its entries in these columns)
        return true;
    }
    Vector3r& statePos = h.pos[id];
    if (st.moveMask != -1 && !(h.mask[id] & st.moveMask)) return true; // bodies outside the mask are not moved
    const int blocked = h.blockedDOFsMask[id];
    if (__builtin_expect(blocked & State::clumpedBit, 0)) return true; // a clump member: moved with its clump (Clump::moveMembers)
    const bool dynamic = blocked != State::DOF_ALL;
    Vector3r vel = h.vel[id], angVel = h.angVel[id];
    BodyEnergy e; // (added once the new state is known finite)
    AsphericalUpdate a;
    if (dynamic) {
        if (__builtin_expect(st.periodic, 0)) {
            accelerate<true>(st, id, blocked, h.mass[id], h.inertia[id], vel, angVel, e, a, statePos);
            if (st.homo) homogeneousSpin(st, angVel);
        }
        else accelerate<false>(st, id, blocked, h.mass[id], h.inertia[id], vel, angVel, e, a, statePos);
    }
    const Vector3r pos = statePos + vel * st.dt;
    if (!finiteState(pos, vel, angVel, e, h.ori[id])) return false;
    h.vel[id] = vel;
    h.angVel[id] = angVel;
    if (a.angMom) *a.angMom = a.newAngMom; // (zero for a still body)
    statePos = pos;
    if (st.energy && dynamic) { // summed in registers, added to O.energy once per thread or per chunk
        sum.grav += e.grav;
        sum.kin += e.kin;
        sum.kinRot += e.kinRot;
        sum.damp += e.damp;
        any = true;
    }
    maxV2 = std::max(maxV2, vel.squaredNorm());
    if (__builtin_expect(a.turned, 0)) // an aspherical body: its new orientation (normalized as its scheme says: normalizeEvery)
        h.ori[id] = a.ori;
    else // (turned by turnSpheres: 1, or 2 for a body whose rotations are all blocked: it turns only as an engine prescribes)
        st.spins[id] = (blocked & allRotations) == allRotations ? 2 : 1;
    return true;
}

// A free sphere's step (no blocked DOF, equal principal moments; without energy tracking or mask):
// integrateBody's arithmetic in the same order, without the tests that cannot apply, written once
// for one body (T = Real) and for two consecutive ones (T = Two, one in each lane: lib/base/Lanes.hpp),
// which give the same bits. Returns false, having written nothing, if a lane's new state is not finite
// (integrateBody then takes the bodies one by one and reports it).
static inline bool isFreeSphere(const BodyStore::Columns& h, long id) {
    return h.exists[id] && h.blockedDOFsMask[id] == 0 && !unequalMoments(h.inertia[id]);
}
// (3.5.12) lane by lane, as NewtonIntegrator::damp: a·(1 - λ·sign(a·(v + a·dt/2))), sign(NaN) = 0
template <class T> YADE_KERNEL T dampLane(T a, T v, T halfDt, T lambda) {
    const T p = a * (v + halfDt * a);
    const T sign = select(greater(p, T(0.0)), T(1.0), select(greater(T(0.0), p), T(-1.0), T(0.0)));
    return a * (T(1.0) - lambda * sign);
}
template <class T> YADE_KERNEL Vec3<T> dampVec(const Vec3<T>& a, const Vec3<T>& v, T halfDt, T lambda) {
    return {dampLane(a.x, v.x, halfDt, lambda), dampLane(a.y, v.y, halfDt, lambda), dampLane(a.z, v.z, halfDt, lambda)};
}
// Periodic: in a periodic cell (integrateBody's periodic arithmetic: the damping of the fluctuation,
// homogeneousField, homogeneousSpin).
template <class T, bool Periodic = false> YADE_KERNEL bool freeSpheresStep(const IntegratorStep& st, long id, Real& maxV2) {
    constexpr int lanes = lanesOf<T>;
    const BodyStore::Columns& h = st.h;
    LaneIds<T> ids;
    for (int i = 0; i < lanes; ++i) ids.i[i] = id + i;
    const T dt(st.dt), halfDt(0.5 * st.dt), lambda(st.lambda), zero(0.0);
    const MaskOf<T> damped = greater(eachLane<T>([&](int i) { return st.lambda != 0 && h.isDamped[id + i] ? 1.0 : 0.0; }), zero);
    const Vec3<T> g{T(st.g[0]), T(st.g[1]), T(st.g[2])};
    Vec3<T> vel = gather<T>(h.vel, ids), angVel = gather<T>(h.angVel, ids);
    // translation (linearAccel with nothing blocked)
    Vec3<T> accel = gather<T>(st.F, ids) / gather(h.mass, ids);
    if (st.gravityDamped) accel = accel + g;
    Vec3<T> pos0;
    if constexpr (Periodic) {
        pos0 = gather<T>(h.pos, ids);
        accel = select(damped, dampVec(accel, vel - matVec(st.prevVelGrad, pos0), halfDt, lambda), accel);
    } else
        accel = select(damped, dampVec(accel, vel, halfDt, lambda), accel);
    if (!st.gravityDamped) accel = accel + g;
    // rotation (rotateSphere): a still body (no spin, no torque) keeps a zero acceleration, undamped
    const Vec3<T> torque = gather<T>(st.T, ids), inertia = gather<T>(h.inertia, ids);
    const MaskOf<T> still = equal(angVel.x, zero) & equal(angVel.y, zero) & equal(angVel.z, zero) & equal(torque.x, zero)
            & equal(torque.y, zero) & equal(torque.z, zero) & greater(inertia.x, zero) & greater(inertia.y, zero) & greater(inertia.z, zero);
    Vec3<T> angAccel = select(still, Vec3<T>::zero(), Vec3<T>(torque.x / inertia.x, torque.y / inertia.y, torque.z / inertia.z));
    angAccel = select(damped & !still, dampVec(angAccel, angVel, halfDt, lambda), angAccel);
    angVel = angVel + dt * angAccel;
    if constexpr (Periodic) {
        if (st.homo) {
            vel = st.convective ? vel + dt * (accel + matVec(st.prevVelGrad, vel)) : vel + dt * accel;
            vel = vel + matVec(st.dVelGrad, pos0);
            angVel = angVel + Vec3<T>{T(st.dSpin[0]), T(st.dSpin[1]), T(st.dSpin[2])};
        } else
            vel = vel + dt * accel;
    } else
        vel = vel + dt * accel;
    const Vec3<T> pos = gather<T>(h.pos, ids) + vel * dt;
    for (int i = 0; i < lanes; ++i)
        if (!finiteState(pos.lane(i), vel.lane(i), angVel.lane(i), BodyEnergy(), h.ori[id + i])) return false;
    for (int i = 0; i < lanes; ++i) {
        h.vel[id + i] = vel.lane(i);
        h.angVel[id + i] = angVel.lane(i);
        h.pos[id + i] = pos.lane(i);
        maxV2 = std::max(maxV2, h.vel[id + i].squaredNorm());
        st.spins[id + i] = (h.angVel[id + i].array() != 0).any(); // (no spin: turnStep would leave it as it is)
    }
    return true;
}

// The skin's displacement (doc/performance.md, "The skin of the fast path"): the largest squared
// distance of bodies b0 .. b1-1 from their reference positions, into m (just written: in cache;
// holes and bodies other than spheres: their reference is NaN, ignored).
static inline void maxMovedSince(const IntegratorStep& st, long b0, long b1, Real& m) {
    for (long id = b0; id < b1; ++id) m = std::max(m, (st.h.pos[id] - st.reference[id]).squaredNorm());
}

// Bodies b0 .. b1-1 without energy tracking or mask: free spheres by their own step, two at a time;
// returns the largest id of a body whose new state is not finite (-1: none).
template <bool Periodic> static inline long freeSpheres(const IntegratorStep& st, long b0, long b1, BodyEnergy& sum, bool& any, Real& maxV2) {
    long diverged = -1;
    for (long id = b0; id < b1;) {
        if (id + 1 < b1 && isFreeSphere(st.h, id) && isFreeSphere(st.h, id + 1) && freeSpheresStep<Two, Periodic>(st, id, maxV2)) {
            id += 2;
            continue;
        }
        if (!(isFreeSphere(st.h, id) && freeSpheresStep<Real, Periodic>(st, id, maxV2)) && !integrateBody(st, id, sum, any, maxV2))
            diverged = std::max(diverged, id);
        ++id;
    }
    return diverged;
}

// Bodies lo .. hi-1, their energy terms into sums (each body's new state does not depend on the
// thread that computes it), a block of bodies at a time: the second loop (turnSpheres) finds their
// spins and orientations in cache.
void NewtonIntegrator::integrateRange(const IntegratorStep& step, long lo, long hi, EnergySums& sums, Extremes& x) {
    const IntegratorStep st = step; // (in registers: see IntegratorStep)
    BodyEnergy sum{sums.grav, sums.kin, sums.kinRot, sums.damp};
    bool any = sums.any;
    Real maxV2 = x.maxV2, maxMoved2 = x.maxMoved2;
    long diverged = x.diverged;
    const bool lean = !st.energy && st.moveMask == -1;
    for (long b0 = lo; b0 < hi; b0 += chunkBodies) {
        const long b1 = std::min(hi, b0 + chunkBodies);
        if (lean && st.periodic)
            diverged = std::max(diverged, freeSpheres<true>(st, b0, b1, sum, any, maxV2));
        else if (lean)
            diverged = std::max(diverged, freeSpheres<false>(st, b0, b1, sum, any, maxV2));
        else
            for (long id = b0; id < b1; ++id)
                if (!integrateBody(st, id, sum, any, maxV2)) diverged = std::max(diverged, id);
        turnSpheres(st.h, st.spins, b0, b1, st.dt);
        if (st.reference) maxMovedSince(st, b0, b1, maxMoved2);
    }
    sums.grav = sum.grav;
    sums.kin = sum.kin;
    sums.kinRot = sum.kinRot;
    sums.damp = sum.damp;
    sums.any = any;
    x.maxV2 = maxV2;
    x.maxMoved2 = maxMoved2;
    x.diverged = diverged;
}

// The calling thread's share: the bodies of its range (the same split as O.forces and
// InteractionLoop). With several threads, a thread that is done helps with the others' last bodies
// (on shared machines a core is often slower than the other for a while): its own chunks from the
// front, then the others' last ones (ChunkQueue.hpp), the energy terms per chunk (summed in order
// by addChunkEnergies). The queues were filled before the parallel region (prepareStealing): a
// thread that starts late (its core busy with another process) finds its chunks taken, and no
// thread waits for another to start.
void NewtonIntegrator::integrateShare(const IntegratorStep& st, long n, int threads, const EnergyTerms& ids, Extremes& x) {
    EnergySums mySums; // this thread's energy terms (without work stealing)
    const int team = omp_get_num_threads();
    if (threads == 1 || team != threads) { // (fewer threads came: each its range, the chunks' sums left at zero)
        const auto range = myThreadRange(n);
        integrateRange(st, range.first, range.second, mySums, x);
    } else {
        const int me = omp_get_thread_num();
        for (int k = 0; k < team; ++k) { // own chunks from the front, then the others' from the back
            const int t = (me + k) % team;
            ChunkQueue& q = *queues[t];
            const auto r = threadRange(n, t, team);
            unsigned c;
            while (t == me ? q.takeFront(c) : q.takeBack(c))
                integrateRange(st, r.first + (long)c * chunkBodies, std::min(r.second, r.first + ((long)c + 1) * chunkBodies), chunkSums[t][c], x);
        }
    }
    if (mySums.any) addEnergy(*st.scene, mySums, ids);
}

// Before the parallel region: each thread's range cut into chunks, all published.
void NewtonIntegrator::prepareStealing(int threads, long n) {
    while ((int)queues.size() < threads) queues.emplace_back(new ChunkQueue);
    chunkSums.resize(threads);
    for (int t = 0; t < threads; ++t) {
        const auto r = threadRange(n, t, threads);
        const unsigned chunks = (unsigned)((r.second - r.first + chunkBodies - 1) / chunkBodies);
        chunkSums[t].assign(chunks, EnergySums());
        queues[t]->reset(chunks);
    }
}

// With work stealing: the energy terms per range, chunk by chunk in order: the same sums whoever computed each chunk.
void NewtonIntegrator::addChunkEnergies(Scene& s, int threads, const EnergyTerms& ids) const {
    for (int t = 0; t < threads; ++t) {
        EnergySums range;
        for (const EnergySums& e : chunkSums[t]) {
            range.grav += e.grav;
            range.kin += e.kin;
            range.kinRot += e.kinRot;
            range.damp += e.damp;
            range.any |= e.any;
        }
        if (range.any) addEnergy(s, range, ids);
    }
}

void NewtonIntegrator::addEnergy(Scene& s, const EnergySums& e, const EnergyTerms& id) const {
    s.energy.add(id.grav, e.grav); // (a term appears once something was added to it, as in Yade)
    s.energy.add(id.kin, e.kin);
    if (id.kinRot >= 0) s.energy.add(id.kinRot, e.kinRot);
    if (damping != 0) s.energy.add(id.damp, e.damp);
}

// The totals of the forces (the threads' few remote contributions added), and the warning when
// no ForceResetter ran in this step.
void NewtonIntegrator::gatherForces(Scene& s) {
    s.forces.sync();
    if (warnNoForceReset && s.forces.lastReset != s.iter && warnedNoReset != s.iter - 1) // (once for a run of such steps)
        logWarning("NewtonIntegrator: O.forces last reset in step " + std::to_string(s.forces.lastReset) + ", while the current step is "
                + std::to_string(s.iter) + ". Did you forget to include ForceResetter in O.engines? (NewtonIntegrator.warnNoForceReset=False silences this)");
    if (s.forces.lastReset != s.iter) warnedNoReset = s.iter;
}

NewtonIntegrator::EnergyTerms NewtonIntegrator::energyTerms(Scene& s) const {
    EnergyTerms ids;
    if (!s.trackEnergy) return ids;
    const bool split = kinSplit;
    ids.kin = s.energy.term(split ? "kinTrans" : "kinetic", false);
    if (split) ids.kinRot = s.energy.term("kinRot", false);
    ids.grav = s.energy.term("gravWork", true);
    ids.damp = s.energy.term("nonviscDamp", true);
    return ids;
}

// The step's constants, with the skin's reference positions (MotionRecord::beginWrite), and the
// spin flags sized to the bodies.
IntegratorStep NewtonIntegrator::prepareStep(Scene& s, const MotionRecord::Write& motion) {
    spinning.resize(s.bodies.size());
    IntegratorStep st;
    st.scene = &s;
    st.dt = s.dt;
    st.lambda = damping;
    st.g = gravity;
    st.gravityDamped = dampGravity;
    st.aspherical = exactAsphericalRot;
    st.rotScheme = aspherical::schemeOf(rotAlgorithm);
    st.normalizeOri = normalizeEvery > 0 && s.iter % normalizeEvery == 0;
    st.energy = s.trackEnergy;
    st.split = st.energy && kinSplit;
    st.moveMask = mask;
    st.h = s.bodies.hot().columns();
    st.F = s.forces.forceData();
    st.T = s.forces.torqueData();
    st.spins = spinning.data();
    st.reference = motion.reference;
    Cell& cell = *s.cell;
    if (s.isPeriodic) cell.takeNextVelGrad();
    st.periodic = s.isPeriodic;
    st.homo = s.isPeriodic && cell.homoDeform >= Cell::homoVel;
    st.convective = cell.homoDeform >= Cell::homoVel2nd;
    st.dVelGrad = cell.velGrad - cell.prevVelGrad;
    st.prevVelGrad = cell.prevVelGrad;
    const Matrix3r dW = st.dVelGrad - st.dVelGrad.transpose(); // (twice the change of the spin tensor)
    st.dSpin = 0.5 * Vector3r(dW(2, 1), dW(0, 2), dW(1, 0));
    return st;
}

void NewtonIntegrator::action() {
    Scene& s = *scene;
    gatherForces(s);
    const bool clumps = !s.bodies.clumps.empty();
    if (clumps) Clump::sumForces(s);
    const EnergyTerms ids = energyTerms(s);
    // Before moving anything: the time step against the contacts' critical step: all contacts periodically and when O.dt
    // changed, otherwise the bodies of the contacts made in this step (cheap: against their stiffness sums kept since).
    CriticalStep crit;
    const bool full = stabilityCheckPeriod > 0 && (s.iter % stabilityCheckPeriod == 0 || s.dt != lastCheckedDt);
    if (stabilityCheckPeriod > 0) lastCheckedDt = s.dt;
    if (full) crit = criticalTimeStep(s, true, stiffnessTrans, stiffnessRot);
    else if (stabilityCheckPeriod > 0 && !s.newContacts.empty()) crit = criticalStepOfNewContacts(s, s.newContacts, stiffnessTrans, stiffnessRot);
    const long n = (long)s.bodies.size();
    const MotionRecord::Write motion = s.motion.beginWrite(n); // (the skin protocol: core/MotionRecord.hpp)
    const IntegratorStep st = prepareStep(s, motion);
    const int threads = s.threads(); // (the scene's count, which its force and energy buffers are made for; Omega sets OpenMP's to it)
    const bool steal = threads > 1;
    if (steal) prepareStealing(threads, n);
    Real maxV2 = 0, maxMoved2 = 0;
    long diverged = -1;
#pragma omp parallel num_threads(threads) reduction(max : maxV2, maxMoved2, diverged)
    {
        Extremes mine;
        if (!(st.dt > crit.dt)) integrateShare(st, n, threads, ids, mine); // (the same answer in every thread)
        maxV2 = std::max(maxV2, mine.maxV2);
        maxMoved2 = std::max(maxMoved2, mine.maxMoved2);
        diverged = std::max(diverged, mine.diverged);
    }
    if (steal && st.energy) addChunkEnergies(s, threads, ids);
    if (st.dt > crit.dt) throw StabilityError(diagnose(s, crit.body, "the time step is above the critical one"));
    if (clumps) Clump::moveMembers(s, st.reference, maxV2, maxMoved2);
    s.motion.publish(motion, maxV2, st.dt, maxMoved2);
    maxVelocitySq = maxV2;
    if (diverged >= 0) throw StabilityError(diagnose(s, (Body::id_t)diverged, "its new position or velocity is not finite, or its orientation is not a finite non-zero quaternion"));
}

void NewtonIntegrator::postLoad() { aspherical::schemeOf(rotAlgorithm); }

std::string NewtonIntegrator::diagnose(const Scene& s, Body::id_t id, const std::string& what) const {
    const CriticalStep crit = criticalTimeStep(s);
    std::ostringstream os;
    os.precision(3);
    os << "Simulation unstable at step " << s.iter << ", body #" << id << ": " << what << ". Likely cause: ";
    Real maxOverlap = 0;
    std::string spin; // what in its contacts can make its spin explode (IPhys::diagnoseSpin; of the last such contact)
    for (const auto& partner : s.interactions.partnersOf(id)) {
        if (const auto* g = dynamic_cast<const ScGeom*>(s.interactions.geom(partner.k)))
            maxOverlap = std::max(maxOverlap, g->penetrationDepth / std::max(std::min(g->refR1 > 0 ? g->refR1 : g->refR2, g->refR2), Real(1e-300)));
        if (const IPhys* p = s.interactions.phys(partner.k)) {
            std::string why = p->diagnoseSpin();
            if (!why.empty()) spin = std::move(why);
        }
    }
    const BodyHot state = s.bodies.hot().get((size_t)id);
    const int xyz = State::DOF_X | State::DOF_Y | State::DOF_Z;
    if (!(state.mass > 0) && (state.blockedDOFsMask & xyz) != xyz)
        os << "its mass is " << state.mass << " (a material of density 0?) while its translations are free: "
           << "give it a density, or block it (fixed=True, as walls of density 0 are in Yade's scripts)";
    else if (std::isfinite(crit.dt) && s.dt > crit.dt)
        os << "O.dt=" << s.dt << " exceeds the critical step " << crit.dt << " of body #" << crit.body
           << "'s contacts (stiffness-based, 3.5.18); use a smaller O.dt (e.g. O.dt=" << 0.5 * crit.dt
           << ") or a GlobalStiffnessTimeStepper";
    else if (maxOverlap > 0.5)
        os << "an overlap of " << 100 * maxOverlap << "% of the radius: the bodies were placed overlapping or the loading is too fast";
    else if (!spin.empty())
        os << spin;
    else
        os << "none of the usual ones (time step below the critical " << crit.dt
           << ", overlaps moderate): check forces added from Python and prescribed velocities";
    return os.str();
}

} // namespace yade
