// yade.pack.SpherePack: the geometric packing of pkg/dem/SpherePack, with Yade's argument names.
// toSimulation is added in Python (py/yade/pack.py).
#include <pkg/dem/SpherePack.hpp>
#include <py/wrapper/SpherePackWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

namespace {
    py::tuple item(const SpherePack::Sph& s) { return py::make_tuple(s.c, s.r); }

    py::list toList(const SpherePack& p) {
        py::list l;
        for (const auto& s : p.pack) l.append(item(s));
        return l;
    }

    // Replaces the spheres by [(center, radius), ...].
    void fromList(SpherePack& p, const py::iterable& spheres) {
        SpherePack loaded;
        int        i = 0;
        for (py::handle h : spheres) {
            const py::sequence s = py::reinterpret_borrow<py::object>(h);
            if (py::len(s) != 2) throw py::value_error("SpherePack: item " + std::to_string(i) + " must be a (center, radius) pair");
            loaded.add(s[0].cast<Vector3r>(), s[1].cast<Real>());
            i++;
        }
        p.pack = std::move(loaded.pack);
    }

    // Iterator over (center, radius) tuples; keeps the packing alive.
    struct Iterator {
        const SpherePack* pack;
        std::size_t       i = 0;
    };

    void translateFileError(std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SpherePack::FileError& e) {
            // OSError(errno, message, file): Python picks the subclass, FileNotFoundError for ENOENT.
            PyErr_SetObject(PyExc_OSError, py::make_tuple(e.err, e.what(), e.file).ptr());
        }
    }
} // namespace

void bindSpherePack(py::module_& m) {
    py::register_exception_translator(&translateFileError);
    py::class_<Iterator>(m, "_SpherePackIterator")
            .def("__iter__", [](Iterator& it) -> Iterator& { return it; })
            .def("__next__", [](Iterator& it) {
                if (it.i >= it.pack->size()) throw py::stop_iteration();
                return item(it.pack->pack[it.i++]);
            });

    py::class_<SpherePack>(m, "SpherePack", "Set of spheres (center, radius) without any simulation data; loose random packings with makeCloud.")
            .def(py::init<>())
            .def(py::init([](const py::iterable& l) {
                SpherePack p;
                fromList(p, l);
                return p;
            }),
                    py::arg("list"), "Packing from [((cx,cy,cz),r), ...]")
            .def("makeCloud", &SpherePack::makeCloud, py::arg("minCorner"), py::arg("maxCorner"), py::arg("rMean") = -1., py::arg("rRelFuzz") = 0.,
                    py::arg("num") = -1, py::arg("periodic") = false, py::arg("porosity") = 0.65, py::arg("psdSizes") = std::vector<Real>(),
                    py::arg("psdCumm") = std::vector<Real>(), py::arg("distributeMass") = false, py::arg("seed") = -1,
                    "Random loose cloud of non-overlapping spheres in the box [minCorner, maxCorner], appended to the packing; returns "
                    "the number of spheres in the packing. Radii: uniform in rMean·(1±rRelFuzz); or, with rMean<0 and num, rMean "
                    "derived from the box volume, num and porosity (porosity raised until num spheres fit); or from psdSizes "
                    "(diameters) and psdCumm (cumulative fractions, of mass if distributeMass). With num the radii are "
                    "deterministic quantiles, placed largest first; without it, random until a sphere cannot be placed in 1000 "
                    "tries. periodic: spheres may cross the box faces (overlaps checked through the periodic images), cellSize "
                    "is set. seed<0: random seed.")
            .def("add", &SpherePack::add, py::arg("center"), py::arg("radius"), "Append one sphere")
            .def("aabb", [](const SpherePack& p) { auto b = p.aabb(); return py::make_tuple(b.first, b.second); },
                    "(min, max) corners of the box around the spheres, radii included")
            .def("dim", &SpherePack::dim, "Size of aabb()")
            .def("center", &SpherePack::center, "Middle of aabb()")
            .def("relDensity", &SpherePack::relDensity, "Volume of the spheres over the volume of aabb()")
            .def("translate", &SpherePack::translate, py::arg("shift"), "Move all spheres by shift")
            .def("scale", &SpherePack::scale, py::arg("scale"), "Scale positions (about center()), radii and cellSize")
            .def("psd", [](const SpherePack& p, int bins, bool mass) { auto r = p.psd(bins, mass); return py::make_tuple(r.first, r.second); },
                    py::arg("bins") = 50, py::arg("mass") = true,
                    "Particle size distribution: (diameters, cumulative fractions), bins+1 values each; fractions of mass (volume) "
                    "or of number")
            .def("save", &SpherePack::save, py::arg("fileName"), "Write as text: 'x y z r' per line (after '##PERIODIC:: sx sy sz' if periodic)")
            .def("load", &SpherePack::load, py::arg("fileName"), "Replace the spheres by those of a file written by save() (or by Yade)")
            .def("toList", &toList, "[(center, radius), ...]")
            .def("fromList", &fromList, py::arg("list"), "Replace the spheres by [(center, radius), ...]")
            .def_readwrite("cellSize", &SpherePack::cellSize, "Size of the periodic cell; zero if not periodic")
            .def_property_readonly("isPeriodic", &SpherePack::isPeriodic, "Whether cellSize is set")
            .def_readonly("appliedPsdScaling", &SpherePack::appliedPsdScaling, "Factor applied to psdSizes by the last makeCloud with psd and num")
            .def("__len__", &SpherePack::size)
            .def("__iter__", [](const SpherePack& p) { return Iterator { &p }; }, py::keep_alive<0, 1>())
            .def("__getitem__", [](const SpherePack& p, py::ssize_t i) {
                const auto n = static_cast<py::ssize_t>(p.size());
                if (i < 0) i += n;
                if (i < 0 || i >= n) throw py::index_error("SpherePack index out of range");
                return item(p.pack[i]);
            })
            .def("__repr__", [](const SpherePack& p) { return "<SpherePack with " + std::to_string(p.size()) + " spheres>"; });
}

} // namespace yade
