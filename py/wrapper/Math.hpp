// Python bindings of Yade's math types (the "minieigen" API: Vector2, Vector2i, Vector3, Vector3i,
// Vector6, Matrix3, Quaternion). The types are bound as classes (not numpy conversions), and any
// sequence of the right shape (tuple, list, numpy array) is implicitly accepted wherever C++ takes one.
#pragma once
#include <pybind11/pybind11.h>

namespace yade {
void registerMath(pybind11::module_& m);
} // namespace yade
