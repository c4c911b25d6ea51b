// Reading and writing declared attributes from Python, driven by the AttrInfo table.
#pragma once
#include <lib/factory/ClassRegistry.hpp>
#include <pybind11/pybind11.h>

namespace yade {

const ClassInfo& classInfoOf(const Serializable& s);
// Value of an attribute: numbers and strings by value, vectors and matrices as views that
// write through (kept alive by `owner`), objects as their Python wrappers.
pybind11::object getAttr(Serializable& s, const AttrInfo& a, pybind11::handle owner);
// Sets an attribute with type and value checks (TypeError / ValueError naming it).
void setAttr(Serializable& s, const AttrInfo& a, pybind11::handle value);
// Defines the Python properties of the attributes a class declares itself.
void defineAttrProperties(pybind11::handle cls, const ClassInfo& info);
// dict() of all visible attributes.
pybind11::dict attrDict(Serializable& s, pybind11::handle owner);

} // namespace yade
