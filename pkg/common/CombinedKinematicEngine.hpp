// Several kinematic engines acting together on the same bodies (built by `engine1 + engine2`):
// the velocities are reset once, then each engine of comb adds its own.
#pragma once
#include <pkg/common/KinematicEngine.hpp>
#include <memory>

namespace yade {

class CombinedKinematicEngine : public PartialEngine {
public:
    static constexpr const char* classDoc = "Kinematic engines of comb acting together on the bodies of ids (those of the first engine when built with +): velocities are reset once, then each engine, in order, adds its own.";
    std::vector<std::shared_ptr<KinematicEngine>> comb;
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("comb", comb, "The combined kinematic engines, applied in this order (their own ids are not used)");
    }
    void action() override;
};

} // namespace yade
