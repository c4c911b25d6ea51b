#include <core/Cell.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <lib/base/Logging.hpp>
#include <py/wrapper/CellWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

void bindCell(py::module_&) {
    auto axial = [](const Matrix3r& w) { return Vector3r(w(2, 1), w(0, 2), w(1, 0)); };
    py::reinterpret_borrow<py::class_<Cell, Serializable, std::shared_ptr<Cell>>>(py::type::handle_of<Cell>())
            .def_property("hSize", [](const Cell& c) { return c.hSize; },
                    [](Cell& c, const Matrix3r& m) {
                        c.setHSize(m);
                        noteExternalWrite();
                    },
                    "Base vectors of the cell, in columns (H of 3.6); assigning it sets refHSize too (trsf and velGrad are kept). A degenerate or inverted cell is refused (default: Matrix3(1,0,0, 0,1,0, 0,0,1))")
            .def_property("velGrad", [](const Cell& c) { return c.velGrad; }, [](Cell& c, const Matrix3r& m) { c.setVelGrad(m); },
                    "Velocity gradient ∇v of the homogeneous field (3.6.1); an assigned value takes effect at the next step (nextVelGrad until then) (default: Matrix3(0,0,0, 0,0,0, 0,0,0))")
            .def_property_readonly("size", &Cell::size, "Lengths of the cell's edges (column norms of hSize)")
            .def_property("refSize", [](const Cell& c) { return c.size(); },
                    [](Cell& c, const Vector3r& s) {
                        logWarning("Setting Cell.refSize is deprecated, use Cell.setBox(...) instead.");
                        c.setBox(s);
                        noteExternalWrite();
                    },
                    "Lengths of the cell's edges; assigning it is setBox (deprecated)")
            .def_property_readonly("volume", &Cell::volume, "Volume of the cell (det hSize)")
            .def_property_readonly("hSize0", [](const Cell& c) { return Matrix3r(c.trsf.inverse() * c.hSize); },
                    "The cell before the deformation trsf: trsf⁻¹·hSize")
            .def_property_readonly("shearTrsf", &Cell::shearTrsf, "hSize with unit columns: the cell's shear and rotation")
            .def_property_readonly("unshearTrsf", &Cell::unshearTrsf, "Inverse of shearTrsf")
            .def("shearPt", &Cell::shearPt, py::arg("pt"), "shearTrsf·pt")
            .def("unshearPt", &Cell::unshearPt, py::arg("pt"), "unshearTrsf·pt")
            .def("wrap", [](const Cell& c, const Vector3r& p) { return c.wrap(p); }, py::arg("pt"),
                    "The image of pt inside the cell (moved by whole cells along its edges)")
            .def("wrapPt", &Cell::wrapPt, py::arg("pt"), "pt wrapped in the axis-aligned box [0, size) (the cell without its shear)")
            .def("setBox", [](Cell& c, const Vector3r& s) { c.setBox(s); noteExternalWrite(); }, py::arg("size"),
                    "An axis-aligned cell of these edge lengths; trsf is reset to identity")
            .def("setBox", [](Cell& c, Real x, Real y, Real z) { c.setBox(Vector3r(x, y, z)); noteExternalWrite(); }, py::arg("x"), py::arg("y"), py::arg("z"),
                    "An axis-aligned cell of these edge lengths; trsf is reset to identity")
            .def("getDefGrad", [](const Cell& c) { return c.trsf; }, "Deformation gradient F (trsf)")
            .def("getSmallStrain", &Cell::smallStrain, "Small strain ½(F + Fᵀ) - I")
            .def("getRCauchyGreenDef", &Cell::rightCauchyGreen, "Right Cauchy-Green tensor FᵀF")
            .def("getLCauchyGreenDef", &Cell::leftCauchyGreen, "Left Cauchy-Green tensor FFᵀ")
            .def("getLagrangianStrain", &Cell::lagrangianStrain, "Green-Lagrange strain ½(FᵀF - I)")
            .def("getEulerianAlmansiStrain", &Cell::eulerianAlmansiStrain, "Euler-Almansi strain ½(I - (FFᵀ)⁻¹)")
            .def("getPolarDecOfDefGrad", [](const Cell& c) {
                const auto ru = c.polarDecomposition();
                return py::make_tuple(ru.first, ru.second);
            }, "Polar decomposition of F = R·U: (R, U), the rotation and the stretch U = (FᵀF)^½")
            .def("getRotation", [](const Cell& c) { return c.polarDecomposition().first; }, "Rotation R of the polar decomposition of F")
            // (the reference's names, followed here: 'right' the stretch applied after the rotation)
            .def("getRightStretch", [](const Cell& c) {
                const auto ru = c.polarDecomposition();
                return Matrix3r(ru.first * ru.second * ru.first.transpose());
            }, "The stretch V of F = V·R, (FFᵀ)^½ (named as in the reference)")
            .def("getLeftStretch", [](const Cell& c) { return c.polarDecomposition().second; }, "The stretch U of F = R·U, (FᵀF)^½ (named as in the reference)")
            .def("getSpin", [axial](const Cell& c) { return axial(c.spin()); }, "Axial vector of the spin ½(∇v - ∇vᵀ)");
}

} // namespace yade
