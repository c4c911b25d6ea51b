#pragma once
#include <pybind11/pybind11.h>
namespace yade {
void bindShop(pybind11::module_& m); // utils functions implemented in C++
} // namespace yade
