// Python methods and computed properties of the triaxial set-up (pkg/dem/triaxial).
#pragma once
#include <pybind11/pybind11.h>

namespace yade {
void bindTriaxial(pybind11::module_& m);
}
