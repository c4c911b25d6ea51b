#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of the concrete particle model's classes (pkg/dem/concrete) and
// Material.newAssocState.
void bindCpm(pybind11::module_& m);
} // namespace yade
