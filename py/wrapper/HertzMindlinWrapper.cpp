#include <core/Omega.hpp>
#include <lib/base/Logging.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_Mindlin.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <py/wrapper/HertzMindlinWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>

namespace py = pybind11;

namespace yade {

template <class T> static py::class_<T, Serializable, std::shared_ptr<T>> boundClass() {
    return py::reinterpret_borrow<py::class_<T, Serializable, std::shared_ptr<T>>>(py::type::handle_of<T>());
}

void bindHertzMindlin(py::module_&) {
    py::reinterpret_borrow<py::class_<MatchMaker>>(py::type::handle_of<MatchMaker>())
            .def("__call__", [](const MatchMaker& m, int id1, int id2, Real v1, Real v2) { return m(id1, id2, v1, v2); }, py::arg("id1"),
                    py::arg("id2"), py::arg("val1") = NaN, py::arg("val2") = NaN,
                    "The value for materials id1, id2: from matches, else algo applied to val1 and val2 (the materials' own values)")
            .def("computeFallback", &MatchMaker::computeFallback, py::arg("val1"), py::arg("val2"), "algo applied to val1 and val2");

    using Law = Law2_ScGeom_MindlinPhys_Mindlin;
    const char* deprecated = "Law2_ScGeom_MindlinPhys_Mindlin.preventGranularRatcheting is deprecated, use Law2_ScGeom_MindlinPhys_Mindlin.nothing "
                             "instead. (this value is no longer used, don't define it.)";
    py::reinterpret_borrow<py::class_<Law>>(py::type::handle_of<Law>())
            .def("normElastEnergy", [](const Law&) { return Law::normElastEnergy(omega().scene()); },
                    "Normal elastic energy of the Hertz-Mindlin contacts: the sum of 2/5·kno·u^(5/2) [J]")
            .def("ratioSlidingContacts", [](const Law&) { return Law::ratioSlidingContacts(omega().scene()); },
                    "Fraction of the Hertz-Mindlin contacts that slide")
            .def("contactsAdhesive", [](const Law&) { return Law::contactsAdhesive(omega().scene()); },
                    "Number of Hertz-Mindlin contacts whose normal force pulls (adhesion)")
            .def_property("preventGranularRatcheting",
                    [deprecated](const Law& l) {
                        logWarning(deprecated);
                        return l.nothing;
                    },
                    [deprecated](Law& l, bool v) {
                        logWarning(deprecated);
                        l.nothing = v;
                    },
                    "Deprecated: no longer used (an alias of nothing)");
}

} // namespace yade
