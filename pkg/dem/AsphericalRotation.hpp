// The rotation of an aspherical body over one step (3.5.2): the three schemes NewtonIntegrator.rotAlgorithm
// chooses from, each a plain function of one body's orientation, spin or angular momentum, torque and
// principal moments of inertia. The damping of the torque and the bookkeeping stay in NewtonIntegrator.cpp.
#pragma once
#include <lib/base/Math.hpp>
#include <cmath>
#include <stdexcept>
#include <string>

namespace yade {
namespace aspherical {

    // NewtonIntegrator.rotAlgorithm: its values, in the order of the enumeration.
    enum class Scheme : unsigned char { spiral, omelyan, fincham };
    inline const char* const schemeNames[] = {"delValle2023", "Omelyan1998", "Fincham1992"};
    inline Scheme schemeOf(const std::string& name) {
        for (int k = 0; k < 3; ++k)
            if (name == schemeNames[k]) return Scheme(k);
        throw std::invalid_argument("NewtonIntegrator.rotAlgorithm: '" + name
                + "' is not a rotation scheme; use 'Fincham1992' (the default, as the reference 2023.02a), 'delValle2023' (SPIRAL) or 'Omelyan1998'");
    }

    // What a scheme gives after a step: the new orientation, the new (mid-step) spin and angular momentum
    // in the global frame, and the rotational kinetic energy at the step's time (on-step, for O.energy).
    struct Turn {
        Quaternionr ori;
        Vector3r angVel, angMom;
        Real kinetic;
    };

    // sin(x)/x and cos(x) for x = angle/2. Rotations per step are small: for x below 1e-2 the Taylor
    // series to x⁶ and x⁸ (truncation below 1e-21 relative) replaces the library calls (within an ulp).
    inline void sincCosHalf(Real angle, Real& sinc, Real& c) {
        const Real x = 0.5 * angle, x2 = x * x;
        if (x2 < 1e-4) {
            sinc = 1 - x2 * (1. / 6) * (1 - x2 * (1. / 20) * (1 - x2 * (1. / 42)));
            c = 1 - x2 * 0.5 * (1 - x2 * (1. / 12) * (1 - x2 * (1. / 30) * (1 - x2 * (1. / 56))));
        } else {
            sinc = std::sin(x) / x;
            c = std::cos(x);
        }
    }

    // Euler's equations (3.5.10) in the body's principal frame: the angular acceleration of the spin w
    // under the torque t, I the principal moments of inertia.
    inline Vector3r eulerAccel(const Vector3r& w, const Vector3r& t, const Vector3r& I) {
        return Vector3r((t[0] - (I[2] - I[1]) * w[1] * w[2]) / I[0], (t[1] - (I[0] - I[2]) * w[2] * w[0]) / I[1],
                (t[2] - (I[1] - I[0]) * w[0] * w[1]) / I[2]);
    }

    inline Vector3r bodyMomentum(const Vector3r& w, const Vector3r& I) { return I.cwiseProduct(w); }
    inline Real kineticOf(const Vector3r& w, const Vector3r& I) { return 0.5 * w.dot(I.cwiseProduct(w)); }

    // The derivative of the orientation q for the spin w in the body's frame, q̇ = ½ q·(0, w) (3.5.2, the
    // matrix form of the manual), each component summed from left to right.
    inline Quaternionr dotQ(const Vector3r& w, const Quaternionr& q) {
        return Quaternionr((-q.x() * w[0] - q.y() * w[1] - q.z() * w[2]) / 2, (q.w() * w[0] - q.z() * w[1] + q.y() * w[2]) / 2,
                (q.z() * w[0] + q.w() * w[1] - q.x() * w[2]) / 2, (-q.y() * w[0] + q.x() * w[1] + q.w() * w[2]) / 2);
    }
    inline Quaternionr plus(const Quaternionr& a, Real k, const Quaternionr& b) { // a + k·b, coefficient by coefficient
        return Quaternionr(a.w() + k * b.w(), a.x() + k * b.x(), a.y() + k * b.y(), a.z() + k * b.z());
    }

    // The products below are written out so that their sums go in one fixed order, whatever Eigen
    // vectorizes (the Fincham scheme then gives the reference's bits): m·v with each row summed as
    // a0 + (a1 + a2); q turning v by v + 2w(u×v) + u×2(u×v), u = vec(q) (q need not be of unit length:
    // the reference turns the new spin by the orientation before its normalization); q scaled to unit
    // length with |q|² summed as (x² + y²) + (z² + w²).
    inline Vector3r mulRows(const Matrix3r& m, const Vector3r& v) {
        return Vector3r(m(0, 0) * v[0] + (m(0, 1) * v[1] + m(0, 2) * v[2]), m(1, 0) * v[0] + (m(1, 1) * v[1] + m(1, 2) * v[2]),
                m(2, 0) * v[0] + (m(2, 1) * v[1] + m(2, 2) * v[2]));
    }
    inline Vector3r crossOf(const Vector3r& a, const Vector3r& b) {
        return Vector3r(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
    }
    inline Vector3r turn(const Quaternionr& q, const Vector3r& v) {
        const Vector3r u(q.x(), q.y(), q.z());
        Vector3r uv = crossOf(u, v);
        uv = uv + uv;
        const Vector3r uuv = crossOf(u, uv);
        return Vector3r(v[0] + q.w() * uv[0] + uuv[0], v[1] + q.w() * uv[1] + uuv[1], v[2] + q.w() * uv[2] + uuv[2]);
    }
    inline Quaternionr unit(const Quaternionr& q) {
        const Real n = std::sqrt((q.x() * q.x() + q.y() * q.y()) + (q.z() * q.z() + q.w() * q.w()));
        return Quaternionr(q.w() / n, q.x() / n, q.y() / n, q.z() / n);
    }

    // Vectors between the global and the body's frames by an orientation q that is not normalized in every
    // step (normalizeEvery), n2 = |q|²: v ↦ q·v·q⁻¹ = v + (2/n2)·(w·(u×v) + u×(u×v)), u = vec(q). (Eigen's q*v
    // assumes |q| = 1: for |q|² = n2 it gives (1 - n2)·v + n2·(q·v·q⁻¹), an error of the order of |q|² - 1 in
    // each step, which grew to 1e-9 in 20000 steps.)
    inline Vector3r turnBy(const Quaternionr& q, Real n2, const Vector3r& v) {
        const Vector3r u = q.vec(), uv = u.cross(v);
        return v + (2 / n2) * (q.w() * uv + u.cross(uv));
    }
    inline Vector3r toBody(const Quaternionr& q, Real n2, const Vector3r& v) { return turnBy(q.conjugate(), n2, v); }
    inline Vector3r toGlobal(const Quaternionr& q, Real n2, const Vector3r& v) { return turnBy(q, n2, v); }

    // SPIRAL (3.5.2, [delValle2023]): the spin in the body's frame w (the last step's, at the current
    // orientation q) advanced by three estimates of Euler's equations with the torque t (body frame)
    // held over the step; then q turned by the new spin in the body's frame, q·(cos θ, ŵ sin θ), θ =
    // |w|·dt/2, which keeps |q|: normalized only when asked (NewtonIntegrator.normalizeEvery).
    inline Turn spiral(const Quaternionr& q, const Vector3r& angVel, const Vector3r& torque, const Vector3r& I, Real dt, bool normalize) {
        const Real n2 = q.squaredNorm();
        const Vector3r before = toBody(q, n2, angVel), t = toBody(q, n2, torque);
        const Vector3r k1 = dt * eulerAccel(before, t, I);
        const Vector3r k2 = dt * eulerAccel(before + k1, t, I);
        const Vector3r k3 = dt * eulerAccel(before + 0.25 * (k1 + k2), t, I);
        const Vector3r w = before + (k1 + k2 + 4 * k3) / 6;
        Real sincHalf, cosHalf;
        sincCosHalf(w.norm() * dt, sincHalf, cosHalf);
        const Real k = sincHalf * (0.5 * dt);
        Turn r;
        r.ori = q * Quaternionr(cosHalf, k * w[0], k * w[1], k * w[2]);
        Real n2new = n2; // (|q| is kept)
        if (normalize) {
            r.ori.normalize();
            n2new = 1;
        }
        r.angVel = toGlobal(r.ori, n2new, w);
        r.angMom = toGlobal(r.ori, n2new, bodyMomentum(w, I));
        r.kinetic = kineticOf(0.5 * (before + w), I);
        return r;
    }

    // Omelyan (3.5.2, [Omelyan1998]): the new spin in the body's frame solves the implicit leapfrog
    // w⁺ = w⁻ + dt·I⁻¹(t - (I_k - I_j)·(w⁻_j w⁻_k + w⁺_j w⁺_k)/2) (i, j, k cyclic), by fixed-point iteration
    // (a contraction of ratio about dt·|w|·|ΔI|/I: a few iterations); the orientation is turned by its
    // Cayley form q⁺ = ((1 - a)·q + dt·q̇)/(1 + a), a = dt²|w⁺|²/16, q̇ = ½ q·(0, w⁺), which keeps |q|.
    inline Turn omelyan(const Quaternionr& q, const Vector3r& angVel, const Vector3r& torque, const Vector3r& I, Real dt, bool normalize) {
        const Real n2 = q.squaredNorm();
        const Vector3r before = toBody(q, n2, angVel), t = toBody(q, n2, torque);
        const Vector3r d(I[2] - I[1], I[0] - I[2], I[1] - I[0]), h = dt * I.cwiseInverse();
        const Vector3r old(before[1] * before[2], before[2] * before[0], before[0] * before[1]);
        Vector3r w = before;
        for (int it = 0; it < 50; ++it) {
            const Vector3r now(w[1] * w[2], w[2] * w[0], w[0] * w[1]);
            const Vector3r next = before + h.cwiseProduct(t - 0.5 * d.cwiseProduct(old + now));
            const bool done = (next - w).cwiseAbs().maxCoeff() <= 4 * std::numeric_limits<Real>::epsilon() * next.cwiseAbs().maxCoeff();
            w = next;
            if (done) break;
        }
        const Real a = dt * dt * w.squaredNorm() / 16;
        const Quaternionr dq = dotQ(w, q);
        Turn r;
        const Real c = 1 - a, n = 1 + a;
        r.ori = Quaternionr((c * q.w() + dt * dq.w()) / n, (c * q.x() + dt * dq.x()) / n, (c * q.y() + dt * dq.y()) / n, (c * q.z() + dt * dq.z()) / n);
        Real n2new = n2; // (|q| is kept)
        if (normalize) {
            r.ori.normalize();
            n2new = 1;
        }
        r.angVel = toGlobal(r.ori, n2new, w);
        r.angMom = toGlobal(r.ori, n2new, bodyMomentum(w, I));
        r.kinetic = kineticOf(0.5 * (before + w), I);
        return r;
    }

    // Fincham (3.5.2, [Fincham1992], [Allen1989]), the scheme of the reference 2023.02a, in its order of
    // operations (its bits): the state is the angular momentum L (global frame); with A the rotation to
    // the body's frame at the current orientation q,
    //   L° = L + T·dt/2, w° = I⁻¹·A·L°   (on-step),  L⁺ = L + T·dt, w⁺ = I⁻¹·A·L⁺   (mid-step),
    //   q½ = q + q̇(w°, q)·dt/2,  q⁺ = q + q̇(w⁺, q½)·dt,
    // the new spin is w⁺ turned by q⁺ before it is normalized (every step: the scheme does not keep |q|).
    inline Turn fincham(const Quaternionr& q, const Vector3r& angMom, const Vector3r& torque, const Vector3r& I, Real dt) {
        const Matrix3r A = q.conjugate().toRotationMatrix();
        const Vector3r onStep = angMom + 0.5 * dt * torque;
        const Vector3r wOn = mulRows(A, onStep).cwiseQuotient(I);
        const Quaternionr half = plus(q, 0.5 * dt, dotQ(wOn, q));
        Turn r;
        r.angMom = angMom + dt * torque;
        const Vector3r w = mulRows(A, r.angMom).cwiseQuotient(I);
        const Quaternionr next = plus(q, dt, dotQ(w, half));
        r.angVel = turn(next, w);
        r.ori = unit(next);
        r.kinetic = kineticOf(wOn, I);
        return r;
    }

} // namespace aspherical
} // namespace yade
