#include <core/Scene.hpp>
#include <pkg/common/ParallelEngine.hpp>
#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace yade {

void ParallelEngine::setSlaves(const std::vector<std::vector<std::shared_ptr<Engine>>>& groups) {
    std::vector<std::shared_ptr<Engine>> flat;
    std::vector<int> sizes;
    for (size_t g = 0; g < groups.size(); ++g) {
        for (const auto& e : groups[g]) {
            if (!e) throw std::invalid_argument("ParallelEngine.slaves: group " + std::to_string(g) + " holds None, not an engine");
            if (e.get() == this) throw std::invalid_argument("ParallelEngine.slaves: a ParallelEngine cannot be its own slave");
            const auto* pe = dynamic_cast<const ParallelEngine*>(e.get());
            if (pe && pe->holds(this))
                throw std::invalid_argument("ParallelEngine.slaves: a ParallelEngine cannot be its own slave (here through the slaves of " +
                                            (pe->label.empty() ? std::string("another ParallelEngine") : pe->label) + ")");
            flat.push_back(e);
        }
        sizes.push_back((int)groups[g].size());
    }
    members = std::move(flat);
    groupSizes = std::move(sizes);
}

std::vector<std::vector<std::shared_ptr<Engine>>> ParallelEngine::slaves() const {
    std::vector<std::vector<std::shared_ptr<Engine>>> groups;
    size_t next = 0;
    for (const int size : groupSizes) {
        if (size < 0 || next + size > members.size()) break; // (inconsistent: reported by action())
        groups.emplace_back(members.begin() + next, members.begin() + next + size);
        next += size;
    }
    return groups;
}

bool ParallelEngine::holds(const Engine* e) const {
    // iterative, with a visited set: a cycle read from a file must not make this recurse forever
    std::vector<const ParallelEngine*> todo{this}, seen;
    while (!todo.empty()) {
        const ParallelEngine* pe = todo.back();
        todo.pop_back();
        if (std::find(seen.begin(), seen.end(), pe) != seen.end()) continue;
        seen.push_back(pe);
        for (const auto& m : pe->members) {
            if (m.get() == e) return true;
            if (const auto* sub = dynamic_cast<const ParallelEngine*>(m.get())) todo.push_back(sub);
        }
    }
    return false;
}

void ParallelEngine::action() {
    if (running) throw std::runtime_error("ParallelEngine: it is among its own slaves (a cycle of ParallelEngines)");
    struct Running { // cleared however action() ends
        bool& flag;
        explicit Running(bool& f) : flag(f) { flag = true; }
        ~Running() { flag = false; }
    } guard(running);
    const long total = std::accumulate(groupSizes.begin(), groupSizes.end(), 0L);
    if (total != (long)members.size() || std::any_of(groupSizes.begin(), groupSizes.end(), [](int s) { return s < 0; }))
        throw std::runtime_error("ParallelEngine: the groups' sizes do not match its engines (a corrupt saved simulation?)");
    for (const auto& e : members) {
        if (!e) throw std::runtime_error("ParallelEngine: None in its slaves");
        scene->runEngine(*e);
    }
}

} // namespace yade
