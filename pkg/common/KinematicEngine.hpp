// Prescribed motion of the bodies in `ids`: each step their velocities are set to zero, then
// apply() adds the prescribed linear and angular velocities; NewtonIntegrator then moves them
// (non-dynamic bodies by their velocity alone).
#pragma once
#include <core/Engine.hpp>
#include <vector>

namespace yade {

class KinematicEngine : public PartialEngine {
public:
    static constexpr const char* classDoc = "Base of the engines that prescribe the motion of the bodies in ids: every step their vel and angVel are reset to zero, then the engine adds its own velocities (so that engines combined with + add up).";
    template <class V> void visit(V& v) { PartialEngine::visit(v); }
    void action() override;
    // Adds this engine's velocities to those of `bodyIds` (already checked and reset by the caller).
    virtual void apply(const std::vector<int>& bodyIds) { (void)bodyIds; }
    // Throws std::out_of_range naming `who` if an id is not a body of the scene.
    static void checkIds(const Scene& s, const std::vector<int>& bodyIds, const std::string& who);
    // Sets vel and angVel of the bodies to zero.
    static void resetVelocities(Scene& s, const std::vector<int>& bodyIds);
};

} // namespace yade
