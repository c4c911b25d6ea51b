#pragma once
#include <pybind11/pybind11.h>

namespace yade {
// Hand-written members of Polyhedra (GetVolume, GetSurfaces...) and of Law2_PolyhedraGeom_PolyhedraPhys_Volumetric
// (its energies), and the C++ functions of yade._polyhedra_utils.
void bindPolyhedra(pybind11::module_& m);
} // namespace yade
