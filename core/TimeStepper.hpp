// The base class of engines that set O.dt themselves (GlobalStiffnessTimeStepper): whether they do
// (active, also switched by O.dynDt and by a negative O.dt) and how often.
#pragma once
#include <core/Engine.hpp>

namespace yade {

class TimeStepper : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Base class of the engines that set O.dt (GlobalStiffnessTimeStepper): active, and every timeStepUpdateInterval steps. "
                                            "O.dt < 0 or O.dynDt = True activates the first one in O.engines.";
    bool active = true;
    int timeStepUpdateInterval = 1;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("active", active, "Whether O.dt is changed");
        v.attr("timeStepUpdateInterval", timeStepUpdateInterval, "Update O.dt every this many steps", Attr::positive);
    }
    bool isActivated() override;
    void action() override; // (the base class computes no step: an error)
};

} // namespace yade
