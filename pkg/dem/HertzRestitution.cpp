// In the units where the overlap u, time and mass are scaled by the impact (u* = (m v0²/k_no)^(2/5)),
// the impact is  s'' = -s^(3/2) - 2β·sqrt(3/2)·s^(1/4)·s',  s(0) = 0, s'(0) = 1, whatever the
// masses, moduli and velocity: e depends on β alone. It is integrated here (RK4) and inverted by
// bisection, once per distinct value (a small cache per thread).
#include <array>
#include <cmath>
#include <pkg/dem/HertzRestitution.hpp>
#include <stdexcept>
#include <string>

namespace yade {

namespace {
struct Accel {
    Real c;
    Real operator()(Real s, Real v) const {
        if (s <= 0) return 0;
        const Real q = std::sqrt(s);
        return -s * q - c * std::sqrt(q) * v;
    }
};
} // namespace

Real hertzRestitution(Real beta) {
    if (!(beta >= 0) || !std::isfinite(beta)) throw std::invalid_argument("hertzRestitution: the damping ratio must be finite and >= 0");
    const Accel a{2 * beta * std::sqrt(1.5)};
    const Real h = 1e-3;
    Real s = 0, v = 1;
    for (int step = 0; step < 10000000; ++step) {
        const Real k1s = v, k1v = a(s, v);
        const Real k2s = v + 0.5 * h * k1v, k2v = a(s + 0.5 * h * k1s, v + 0.5 * h * k1v);
        const Real k3s = v + 0.5 * h * k2v, k3v = a(s + 0.5 * h * k2s, v + 0.5 * h * k2v);
        const Real k4s = v + h * k3v, k4v = a(s + h * k3s, v + h * k3v);
        const Real s2 = s + h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s), v2 = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        // the rebound ends where the net force would pull the bodies together, or at zero overlap
        if (v2 < 0 && (s2 <= 0 || a(s2, v2) >= 0)) return -v2;
        if (v2 >= 0 && v2 < 1e-12 && a(s2, v2) >= 0) return 0; // stopped inside the contact (overdamped)
        s = s2;
        v = v2;
    }
    return 0;
}

Real hertzDampingRatio(Real e) {
    if (!(e > 0 && e <= 1)) throw std::invalid_argument("restitution coefficient must be in (0, 1], got " + std::to_string(e));
    if (e == 1) return 0;
    thread_local std::array<std::pair<Real, Real>, 8> cache{};
    thread_local size_t next = 0;
    for (const auto& c : cache)
        if (c.first == e) return c.second;
    Real lo = 0, hi = 1;
    while (hertzRestitution(hi) > e) hi *= 2; // e falls with β
    for (int i = 0; i < 50; ++i) {
        const Real mid = 0.5 * (lo + hi);
        (hertzRestitution(mid) > e ? lo : hi) = mid;
    }
    const Real beta = 0.5 * (lo + hi);
    cache[next++ % cache.size()] = {e, beta};
    return beta;
}

} // namespace yade
