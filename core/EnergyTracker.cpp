#include <core/EnergyTracker.hpp>
#include <algorithm>

namespace yade {

int EnergyTracker::term(const std::string& name, bool isCumulative) {
    auto it = index.find(name);
    if (it != index.end()) return it->second;
    const int id = (int)termNames.size();
    index[name] = id;
    termNames.push_back(name);
    termValues.push_back(0);
    cumulative.push_back(isCumulative);
    touched.push_back(0);
    for (auto& t : perThread) t.push_back(0);
    for (auto& t : touchedThread) t.push_back(0);
    return id;
}

void EnergyTracker::setThreads(int n) {
    sync();
    perThread.assign(n > 0 ? n : 1, std::vector<Real>(termNames.size(), 0));
    touchedThread.assign(perThread.size(), std::vector<char>(termNames.size(), 0));
    // room for many terms: the threads' slots then lie in separate cache lines (no false sharing)
    for (auto& t : perThread) t.reserve(std::max<size_t>(64, termNames.size()));
    for (auto& t : touchedThread) t.reserve(std::max<size_t>(512, termNames.size()));
    captureTo.assign(perThread.size(), CaptureSlot());
}

void EnergyTracker::capture(std::vector<Captured>* into) {
#ifdef _OPENMP
    captureTo[omp_get_thread_num()].into = into;
#else
    captureTo[0].into = into;
#endif
}

void EnergyTracker::applyCaptured(const std::vector<Captured>& list) {
    for (const Captured& c : list) add(c.id, c.value);
}

void EnergyTracker::sync() {
    for (size_t th = 0; th < perThread.size(); ++th)
        for (size_t i = 0; i < termValues.size(); ++i) {
            termValues[i] += perThread[th][i];
            perThread[th][i] = 0;
            touched[i] |= touchedThread[th][i];
            touchedThread[th][i] = 0;
        }
}

std::vector<std::string> EnergyTracker::names() {
    sync();
    std::vector<std::string> r;
    for (size_t i = 0; i < termNames.size(); ++i)
        if (touched[i]) r.push_back(termNames[i]);
    return r;
}

std::vector<Real> EnergyTracker::values() {
    sync();
    std::vector<Real> r;
    for (size_t i = 0; i < termValues.size(); ++i)
        if (touched[i]) r.push_back(termValues[i]);
    return r;
}

std::vector<bool> EnergyTracker::cumulativeFlags() {
    sync();
    std::vector<bool> r;
    for (size_t i = 0; i < termValues.size(); ++i)
        if (touched[i]) r.push_back(cumulative[i]);
    return r;
}

void EnergyTracker::resetInstantaneous() {
    sync();
    for (size_t i = 0; i < termValues.size(); ++i)
        if (!cumulative[i]) termValues[i] = 0;
}

void EnergyTracker::clear() {
    termNames.clear();
    termValues.clear();
    cumulative.clear();
    touched.clear();
    index.clear();
    for (auto& t : perThread) t.clear();
    for (auto& t : touchedThread) t.clear();
}

Real EnergyTracker::total() {
    sync();
    Real s = 0;
    for (Real v : termValues) s += v;
    return s;
}

void EnergyTracker::set(const std::string& name, Real value, bool isCumulative) {
    const int id = term(name, isCumulative);
    sync();
    termValues[id] = value;
    touched[id] = 1;
}

} // namespace yade
