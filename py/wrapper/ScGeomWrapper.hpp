#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of ScGeom: the incident velocity of an interaction (incidentVel) and the
// relative spin (relAngVel), as the reference's.
void bindScGeom(pybind11::module_& m);
} // namespace yade
