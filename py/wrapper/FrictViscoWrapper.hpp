#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of Law2_ScGeom_FrictViscoPhys_CundallStrackVisco (its energies).
void bindFrictVisco(pybind11::module_& m);
} // namespace yade
