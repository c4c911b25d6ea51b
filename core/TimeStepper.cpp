#include <core/Scene.hpp>
#include <core/TimeStepper.hpp>
#include <stdexcept>

namespace yade {

bool TimeStepper::isActivated() { return active && scene->iter % timeStepUpdateInterval == 0; }

// (the reference's base class aborts the process here)
void TimeStepper::action() {
    throw std::runtime_error("TimeStepper is the base class of the time steppers and computes no time step: use GlobalStiffnessTimeStepper");
}

} // namespace yade
