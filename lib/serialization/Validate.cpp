#include <lib/serialization/Validate.hpp>
#include <cmath>
#include <cstdio>

namespace yade {

std::string Validate::fmt(Real x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

static bool sameValue(Real a, Real b) { return a == b || (std::isnan(a) && std::isnan(b)); }

void Validate::checkFlags(const AttrInfo& a, const Real* x, const Real* dflt, int n, const std::string& where) {
    for (int i = 0; i < n; ++i) {
        if (dflt && sameValue(x[i], dflt[i])) continue;
        const bool fin = std::isfinite(x[i]);
        const char* problem = nullptr;
        if (a.has(Attr::positive) && !(fin && x[i] > 0)) problem = " must be positive and finite";
        else if (a.has(Attr::nonNegative) && !(fin && x[i] >= 0)) problem = " must be non-negative and finite";
        else if (a.has(Attr::finite) && !fin) problem = " must be finite";
        if (problem) throw FormatError(where + problem + ", found " + fmt(x[i]));
    }
}

bool Validate::validUtf8(const std::string& s) {
    const auto* p = reinterpret_cast<const unsigned char*>(s.data());
    const auto* end = p + s.size();
    while (p < end) {
        const unsigned c = *p++;
        int more;
        unsigned lo = 0x80, hi = 0xbf; // the range of the first continuation byte
        if (c < 0x80) continue;
        else if (c >= 0xc2 && c <= 0xdf) more = 1;
        else if (c >= 0xe0 && c <= 0xef) {
            more = 2;
            if (c == 0xe0) lo = 0xa0;      // (overlong)
            else if (c == 0xed) hi = 0x9f; // (surrogates)
        } else if (c >= 0xf0 && c <= 0xf4) {
            more = 3;
            if (c == 0xf0) lo = 0x90;      // (overlong)
            else if (c == 0xf4) hi = 0x8f; // (above U+10FFFF)
        } else return false;
        if (end - p < more || *p < lo || *p > hi) return false;
        for (++p, --more; more > 0; --more, ++p)
            if (*p < 0x80 || *p > 0xbf) return false;
    }
    return true;
}

const std::string& Validate::utf8(const std::string& s, const std::string& where) {
    if (!validUtf8(s)) throw FormatError(where + ": a string that is not valid UTF-8 ('" + s.substr(0, 40) + "')");
    return s;
}

void Validate::checkQuaternion(const Real* q, const std::string& where) {
    const Real n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(std::isfinite(n) && n > 0)) throw FormatError(where + " must be a finite non-zero quaternion");
}

} // namespace yade
