#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Binds every registered class (from the classes.def lists) into the module.
void bindAllClasses(pybind11::module_& m);
} // namespace yade
