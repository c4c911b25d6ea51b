#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of Cell: hSize and velGrad assigned with their side effects, the derived
// quantities (size, volume, shear transformations) and the strain measures of trsf.
void bindCell(pybind11::module_& m);
} // namespace yade
