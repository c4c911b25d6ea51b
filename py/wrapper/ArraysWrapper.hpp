// NumPy views of the bodies' columns and arrays of the real contacts.
#pragma once
#include <pybind11/pybind11.h>

namespace yade {
void bindArrays(pybind11::module_& m);
}
