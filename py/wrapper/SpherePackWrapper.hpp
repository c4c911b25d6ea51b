#pragma once
#include <pybind11/pybind11.h>
namespace yade {
void bindSpherePack(pybind11::module_& m); // SpherePack (yade.pack.SpherePack)
} // namespace yade
