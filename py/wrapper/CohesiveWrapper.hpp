#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of Law2_ScGeom6D_CohFrictPhys_CohesionMoment (its energies).
void bindCohesive(pybind11::module_& m);
} // namespace yade
