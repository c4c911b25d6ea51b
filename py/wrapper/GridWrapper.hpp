#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of GridNode (its list of connections) and GridConnection (its length).
void bindGrid(pybind11::module_& m);
} // namespace yade
