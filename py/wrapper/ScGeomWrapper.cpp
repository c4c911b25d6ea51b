#include <core/Omega.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <py/wrapper/ScGeomWrapper.hpp>

namespace py = pybind11;

namespace yade {

void bindScGeom(py::module_&) {
    py::reinterpret_borrow<py::class_<ScGeom, Serializable, std::shared_ptr<ScGeom>>>(py::type::handle_of<ScGeom>())
            .def("incidentVel", [](const ScGeom& g, const Interaction& i, bool avoidGranularRatcheting) {
                const Scene& s = omega().scene();
                if (!s.bodies.exists(i.id1) || !s.bodies.exists(i.id2)) throw py::value_error("the interaction's bodies do not exist (any more)");
                Vector3r shift2 = Vector3r::Zero(), shiftVel2 = Vector3r::Zero();
                if (s.isPeriodic) {
                    const Vector3r c = i.cellDist.cast<Real>();
                    shift2 = s.cell->hSize * c;
                    shiftVel2 = s.cell->prevVelGrad * (s.cell->prevHSize * c);
                }
                return g.incidentVel(s.bodies[i.id1]->state->kinematics(), s.bodies[i.id2]->state->kinematics(), shift2, shiftVel2, avoidGranularRatcheting);
            }, py::arg("i"), py::arg("avoidGranularRatcheting") = true,
                    "Relative velocity of body 2 at the contact of interaction i (normal and shear parts; in a periodic scene body 2's image, "
                    "moving with the homogeneous field): with avoidGranularRatcheting, of points at the reference radii, else of the bodies' "
                    "material points at the contact point")
            .def("relAngVel", [](const ScGeom&, const Interaction& i) {
                const Scene& s = omega().scene();
                if (!s.bodies.exists(i.id1) || !s.bodies.exists(i.id2)) throw py::value_error("the interaction's bodies do not exist (any more)");
                return Vector3r(s.bodies[i.id2]->state->angVel() - s.bodies[i.id1]->state->angVel());
            }, py::arg("i"), "Relative angular velocity of the bodies of interaction i (body 2's less body 1's)");
}

} // namespace yade
