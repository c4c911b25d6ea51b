#pragma once
#include <core/Omega.hpp>
#include <pybind11/pybind11.h>

namespace yade {
Omega& omega(); // the one controller behind Python's O
// Real interactions of a body that is in the current scene.
pybind11::list bodyInteractions(const Body& b);
// Binds Omega (as the object O) and the container proxies O.bodies, O.interactions, ...
void bindOmega(pybind11::module_& m);
// Makes labeled engines and functors reachable by name from scripts (builtins namespace).
void injectLabels(const std::vector<std::shared_ptr<Engine>>& engines);
} // namespace yade
