// Adds a constant force to the bodies in ids every step.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class ForceEngine : public PartialEngine {
public:
    static constexpr const char* classDoc = "Adds the constant force `force` to each body in ids every step (acceleration force/mass on a free body).";
    Vector3r force = Vector3r::Zero();
    template <class V> void visit(V& v) {
        PartialEngine::visit(v);
        v.attr("force", force, "Force added to each body [N]", Attr::finite);
    }
    void action() override;
};

} // namespace yade
