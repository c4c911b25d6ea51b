#pragma once
#include <pybind11/pybind11.h>
namespace yade {
// Hand-written members of MatchMaker (calling it) and Law2_ScGeom_MindlinPhys_Mindlin (its
// summaries over the contacts, the deprecated preventGranularRatcheting).
void bindHertzMindlin(pybind11::module_& m);
} // namespace yade
