#include <core/Omega.hpp>
#include <pkg/dem/concrete/CpmPhys.hpp>
#include <pkg/dem/concrete/Law2_ScGeom_CpmPhys_Cpm.hpp>
#include <py/wrapper/CpmWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>

namespace py = pybind11;

namespace yade {

void bindCpm(py::module_&) {
    py::reinterpret_borrow<py::class_<Material>>(py::type::handle_of<Material>())
            .def("newAssocState", [](const Material& m) { return m.newAssocState(); },
                    "A new State of the class that bodies of this material need (CpmMat: CpmState); utils.sphere and the other "
                    "body constructors call it");
    py::reinterpret_borrow<py::class_<CpmPhys>>(py::type::handle_of<CpmPhys>())
            .def_static("funcG", &CpmPhys::funcG, py::arg("kappaD"), py::arg("epsCrackOnset"), py::arg("epsFracture"),
                    py::arg("neverDamage") = false, py::arg("damLaw") = 1,
                    "Damage law: omega for the largest strain kappaD; 0 up to epsCrackOnset (and always with neverDamage), then "
                    "1 - (ε0/κ)·exp(-(κ-ε0)/εf) (damLaw 1) or (1 - ε0/κ)·εf/(εf - ε0) (damLaw 0, linear softening)")
            .def_static("funcGInv", &CpmPhys::funcGInv, py::arg("omega"), py::arg("epsCrackOnset"), py::arg("epsFracture"),
                    py::arg("neverDamage") = false, py::arg("damLaw") = 1,
                    "Inverse of funcG: the kappaD of damage omega (RuntimeError for omega >= 1 with the exponential law)")
            .def("setDamage", &CpmPhys::setDamage, py::arg("omega"), "Sets omega and the kappaD that gives it (funcGInv)");
    using Law = Law2_ScGeom_CpmPhys_Cpm;
    py::reinterpret_borrow<py::class_<Law>>(py::type::handle_of<Law>())
            .def("elasticEnergy", [](const Law&) { return Law::elasticEnergy(omega().scene()); },
                    "Total elastic energy of the CpmPhys contacts: the sum of (|normalForce|²/kn + |shearForce|²/ks)/2 [J]")
            .def("yieldSigmaTMagnitude", [](const Law&, Real sigmaN, Real omega, Real undamagedCohesion, Real tanFrictionAngle) {
                return Law::yieldSigmaTMagnitude(sigmaN, omega, undamagedCohesion, tanFrictionAngle);
            }, py::arg("sigmaN"), py::arg("omega"), py::arg("undamagedCohesion"), py::arg("tanFrictionAngle"),
                    "Radius of the yield surface the law uses, max(0, undamagedCohesion·(1 - omega) - sigmaN·tanFrictionAngle) [Pa] "
                    "(the reference's build, without the full model, raises RuntimeError here)");
}

} // namespace yade
