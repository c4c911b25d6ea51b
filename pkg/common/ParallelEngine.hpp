// Groups of engines that the reference may run at the same time (ParallelEngine([e1, [e2, e3]])):
// here the groups run one after the other, in order, and each group's engines in order; a result
// that depended on the order of independent groups would differ between the reference's runs too.
#pragma once
#include <core/Engine.hpp>
#include <memory>
#include <vector>

namespace yade {

class ParallelEngine : public Engine {
public:
    static constexpr const char* classDoc =
            "Groups of engines that do not depend on each other (slaves): ParallelEngine([e1, [e2, e3]]) is two groups, e1 alone "
            "and e2 followed by e3. The reference may run the groups concurrently; here they run one after the other, in order.";
    // slaves, stored flat: the engines of all groups in order, and each group's length
    std::vector<std::shared_ptr<Engine>> members;
    std::vector<int> groupSizes;
    template <class V> void visit(V& v) {
        Engine::visit(v);
        v.attr("members", members, "The engines of all groups, in order (Python: slaves)", Attr::hidden);
        v.attr("groupSizes", groupSizes, "The number of engines of each group (Python: slaves)", Attr::hidden);
    }
    // Replaces the groups (each a list of engines, possibly empty); throws std::invalid_argument on None.
    void setSlaves(const std::vector<std::vector<std::shared_ptr<Engine>>>& groups);
    std::vector<std::vector<std::shared_ptr<Engine>>> slaves() const;
    void action() override;
    // Whether `e` is one of the slaves, or a slave of a ParallelEngine among them (at any depth).
    bool holds(const Engine* e) const;

private:
    bool running = false; // set during action(): a cycle read from a file is reported, not recursed into
};

} // namespace yade
