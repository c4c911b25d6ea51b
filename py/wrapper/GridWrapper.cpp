#include <core/Omega.hpp>
#include <pkg/dem/grid/GridConnection.hpp>
#include <pkg/dem/grid/GridNode.hpp>
#include <pybind11/stl.h>
#include <py/wrapper/GridWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <stdexcept>

namespace py = pybind11;

namespace yade {

void bindGrid(py::module_&) {
    py::reinterpret_borrow<py::class_<GridNode>>(py::type::handle_of<GridNode>())
            .def("addConnection",
                    [](GridNode& n, const std::shared_ptr<Body>& b) {
                        if (!b || !b->shape || !dynamic_cast<GridConnection*>(b->shape.get()))
                            throw py::type_error("GridNode.addConnection: the body must have a GridConnection shape");
                        n.ConnList.push_back(b);
                    },
                    py::arg("body"), "Adds a GridConnection body to the connections of this node")
            .def("getConnections",
                    [](const GridNode& n) {
                        std::vector<std::shared_ptr<Body>> out;
                        for (const auto& w : n.ConnList)
                            if (auto b = w.lock()) out.push_back(b);
                        return out;
                    },
                    "The GridConnection bodies of this node (those still alive)");
    py::reinterpret_borrow<py::class_<GridConnection>>(py::type::handle_of<GridConnection>())
            .def("getLength", [](const GridConnection& c) { return c.getLength(omega().scene()); },
                    "Distance between the two nodes now (in O.bodies) [m]");
}

} // namespace yade
