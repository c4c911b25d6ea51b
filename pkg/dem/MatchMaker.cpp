#include <cmath>
#include <pkg/dem/MatchMaker.hpp>
#include <stdexcept>

namespace yade {

namespace {
enum class Algo { Val, Avg, Min, Max, HarmAvg };
Algo parseAlgo(const std::string& a) {
    if (a == "val") return Algo::Val;
    if (a == "avg") return Algo::Avg;
    if (a == "min") return Algo::Min;
    if (a == "max") return Algo::Max;
    if (a == "harmAvg") return Algo::HarmAvg;
    throw std::invalid_argument("MatchMaker: algo '" + a + "' not recognized (possible values: val, avg, min, max, harmAvg)");
}
} // namespace

void MatchMaker::postLoad() { parseAlgo(algo); }

Real MatchMaker::computeFallback(Real v1, Real v2) const {
    switch (parseAlgo(algo)) {
        case Algo::Val: return val;
        case Algo::Avg: return 0.5 * (v1 + v2);
        case Algo::Min: return std::min(v1, v2);
        case Algo::Max: return std::max(v1, v2);
        case Algo::HarmAvg: return 2 * v1 * v2 / (v1 + v2);
    }
    return NaN;
}

Real MatchMaker::operator()(int id1, int id2, Real v1, Real v2) const {
    for (const Vector3r& m : matches) {
        const int a = (int)m[0], b = (int)m[1];
        if ((a == id1 && b == id2) || (a == id2 && b == id1)) return m[2];
    }
    if (algo != "val" && (std::isnan(v1) || std::isnan(v2)))
        throw std::invalid_argument("MatchMaker: no match for (" + std::to_string(id1) + "," + std::to_string(id2) +
                "), and values required for algo computation '" + algo + "' not specified.");
    return computeFallback(v1, v2);
}

std::shared_ptr<MatchMaker> MatchMaker::constant(Real v) {
    auto m = std::make_shared<MatchMaker>();
    m->algo = "val";
    m->val = v;
    return m;
}

} // namespace yade
