// Zeroes the per-step forces and torques at the start of each step (1.2.1).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class ForceResetter : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Engine that zeroes the forces and torques of O.forces at the start of each step (1.2.1).";
    template <class V> void visit(V& v) { GlobalEngine::visit(v); }
    void action() override;
};

} // namespace yade
