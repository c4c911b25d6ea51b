// Piecewise-linear interpolation in a table of (time, value) points, as the interpolating engines use
// it: the first value before the first time, the last after the last; with wrap, time is taken
// modulo the table's span (last - first) first, so the table repeats from its first point.
#pragma once
#include <lib/base/Math.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace yade {

// Throws std::invalid_argument naming `who` for an empty table, tables of different lengths or times
// that decrease.
template <class T>
T interpolateInTime(Real t, const std::vector<Real>& times, const std::vector<T>& values, bool wrap, const std::string& who) {
    if (times.empty() || times.size() != values.size())
        throw std::invalid_argument(who + ": times and its values must be non-empty and of the same length (" + std::to_string(times.size())
                + " and " + std::to_string(values.size()) + ")");
    for (size_t i = 1; i < times.size(); ++i)
        if (!(times[i] >= times[i - 1])) throw std::invalid_argument(who + ": times must not decrease (times[" + std::to_string(i) + "])");
    const Real first = times.front(), span = times.back() - first;
    if (wrap && span > 0) {
        t = std::fmod(t - first, span);
        if (t < 0) t += span;
        t += first;
    }
    if (t <= first) return values.front();
    if (t >= times.back()) return values.back();
    size_t i = 1;
    while (times[i] < t) ++i; // times[i-1] < t <= times[i]
    const Real w = (t - times[i - 1]) / (times[i] - times[i - 1]);
    return values[i - 1] + w * (values[i] - values[i - 1]);
}

} // namespace yade
