// What the 3D view draws, gathered in one call per frame (yade._yade._displayFrame).
#pragma once
#include <pybind11/pybind11.h>

namespace yade {
void bindDisplay(pybind11::module_& m);
} // namespace yade
