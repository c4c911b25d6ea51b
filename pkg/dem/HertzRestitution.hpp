// The damping ratio β of a Hertzian contact with viscous damping c = 2β·sqrt(m·k_t), k_t the
// tangent stiffness (3/2)·k_no·u^(1/2), that gives the restitution coefficient e in a normal
// impact, the contact ending when the total normal force falls to zero (no attraction).
#pragma once
#include <lib/base/Math.hpp>

namespace yade {

// e in (0, 1]: β >= 0 (0 for e = 1); std::invalid_argument otherwise.
Real hertzDampingRatio(Real restitution);
// The inverse: the restitution coefficient of damping ratio β >= 0.
Real hertzRestitution(Real dampingRatio);

} // namespace yade
