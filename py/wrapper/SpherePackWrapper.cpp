// yade.pack.SpherePack: the geometric packing of pkg/dem/SpherePack, with Yade's argument names. Iteration
// gives (center, radius) pairs; indexing and toList add the clump id of clump members, as in the reference.
// toSimulation is added in Python (py/yade/pack.py).
#include <py/wrapper/OmegaWrapper.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/SpherePack.hpp>
#include <py/wrapper/SpherePackWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

namespace {
    // (center, radius), or (center, radius, clumpId) for a clump member, as the reference gives them.
    py::tuple item(const SpherePack::Sph& s) { return s.clumpId >= 0 ? py::make_tuple(s.c, s.r, s.clumpId) : py::make_tuple(s.c, s.r); }

    py::list toList(const SpherePack& p) {
        py::list l;
        for (const auto& s : p.pack) l.append(item(s));
        return l;
    }

    // Replaces the spheres by [(center, radius), ...]; an item may add a clump id (negative: none).
    void fromList(SpherePack& p, const py::iterable& spheres) {
        SpherePack loaded;
        int        i = 0;
        for (py::handle h : spheres) {
            const py::sequence s = py::reinterpret_borrow<py::object>(h);
            if (py::len(s) != 2 && py::len(s) != 3)
                throw py::value_error("SpherePack: item " + std::to_string(i) + " must be a (center, radius) or (center, radius, clumpId) tuple");
            loaded.add(s[0].cast<Vector3r>(), s[1].cast<Real>());
            if (py::len(s) == 3) loaded.pack.back().clumpId = std::max(-1, s[2].cast<int>());
            i++;
        }
        p.pack = std::move(loaded.pack);
    }

    std::string typeName(py::handle h) { return py::str(py::type::of(h).attr("__name__")); }

    // The templates of makeClumpCloud: a list of SpherePack, as the reference takes them.
    std::vector<SpherePack> clumpTemplates(const py::object& clumps) {
        if (py::isinstance<SpherePack>(clumps) || py::isinstance<py::str>(clumps) || !py::isinstance<py::sequence>(clumps))
            throw py::type_error("SpherePack.makeClumpCloud: clumps must be a list of SpherePack (one per kind of clump), got " + typeName(clumps));
        std::vector<SpherePack> out;
        int                     i = 0;
        for (py::handle h : clumps) {
            if (!py::isinstance<SpherePack>(h))
                throw py::type_error("SpherePack.makeClumpCloud: clumps[" + std::to_string(i)
                        + "] must be a SpherePack of the member spheres (centers relative to the clump), got " + typeName(h)
                        + " (from a utils.clumpTemplate t: SpherePack(list(zip(t.relPositions, t.relRadii))))");
            out.push_back(h.cast<const SpherePack&>());
            i++;
        }
        return out;
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

    // The spheres of the current scene (a periodic one: centres wrapped into the cell, and its size).
    void fromSimulation(SpherePack& p) {
        const Scene& scene = omega().scene();
        p.pack.clear();
        p.cellSize = scene.isPeriodic ? scene.cell->size() : Vector3r::Zero();
        for (const auto& b : scene.bodies) {
            const Sphere* s = b ? dynamic_cast<const Sphere*>(b->shape.get()) : nullptr;
            if (!s) continue;
            const Vector3r c = scene.isPeriodic ? scene.cell->wrapPt(b->state->pos()) : Vector3r(b->state->pos());
            p.pack.push_back(SpherePack::Sph { c, s->radius, -1 });
        }
    }
} // namespace

void bindSpherePack(py::module_& m) {
    py::register_exception_translator(&translateFileError);
    py::class_<Iterator>(m, "_SpherePackIterator")
            .def("__iter__", [](Iterator& it) -> Iterator& { return it; })
            .def("__next__", [](Iterator& it) {
                if (it.i >= it.pack->size()) throw py::stop_iteration();
                const auto& s = it.pack->pack[it.i++];
                return py::make_tuple(s.c, s.r); // (no clump id, as in the reference)
            });

    py::class_<SpherePack>(m, "SpherePack", "Set of spheres (center, radius) without any simulation data; loose random packings with makeCloud.")
            .def(py::init<>())
            .def(py::init([](const py::iterable& l) {
                SpherePack p;
                fromList(p, l);
                return p;
            }),
                    py::arg("list"), "Packing from [((cx,cy,cz),r), ...]; an item ((cx,cy,cz),r,clumpId) is a clump member")
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
            .def("makeClumpCloud",
                    [](SpherePack& p, const Vector3r& lo, const Vector3r& hi, const py::object& clumps, bool periodic, int num, long seed) {
                        return p.makeClumpCloud(lo, hi, clumpTemplates(clumps), periodic, num, seed);
                    },
                    py::arg("minCorner"), py::arg("maxCorner"), py::arg("clumps"), py::arg("periodic") = false, py::arg("num") = -1,
                    py::arg("seed") = -1,
                    "Random loose cloud of non-overlapping clumps in the box [minCorner, maxCorner], appended to the packing; "
                    "returns the number of clumps placed. clumps: a list of SpherePack, each the member spheres of one kind of "
                    "clump in its own frame, e.g. [SpherePack([((0,0,0),1e-2),((1e-2,0,0),1e-2)])]; each clump takes one at "
                    "random, then a random position and orientation (at most 200 tries). The members carry their clump id "
                    "(toList, getClumps, save) and toSimulation makes them clumps. periodic, num, seed: as in makeCloud "
                    "(num<0: as many as fit).")
            .def("getClumps", [](const SpherePack& p) { auto c = p.getClumps(); return py::make_tuple(py::cast(c.first), py::cast(c.second)); },
                    "(standalones, [clump1, clump2, ...]): the indices of the spheres in no clump, and of the members of each "
                    "clump, by increasing clump id")
            .def("hasClumps", &SpherePack::hasClumps, "Whether some sphere belongs to a clump")
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
            .def("save", &SpherePack::save, py::arg("fileName"), "Write as text: 'x y z r' per line, 'x y z r clumpId' (-1: no clump) if the packing has clumps, after "
                    "'##PERIODIC:: sx sy sz' if periodic")
            .def("load", &SpherePack::load, py::arg("fileName"), "Replace the spheres by those of a file written by save() (or by Yade)")
            .def("cellRepeat", &SpherePack::cellRepeat, py::arg("count"),
                    "Repeat the periodic packing count[i] times along axis i; cellSize grows accordingly (non-periodic: RuntimeError)")
            .def("cellFill", &SpherePack::cellFill, py::arg("size"),
                    "Repeat the periodic packing (cellRepeat) the fewest times that make cellSize at least size on every axis "
                    "(non-periodic: RuntimeError)")
            .def("fromSimulation", &fromSimulation,
                    "Replace the spheres by the spherical bodies of the current scene (O.bodies, by id); a periodic scene "
                    "also sets cellSize, and the centres are wrapped into the cell")
            .def("toList", &toList, "[(center, radius), ...], (center, radius, clumpId) for clump members")
            .def("fromList", &fromList, py::arg("list"), "Replace the spheres by [(center, radius), ...]; an item (center, radius, clumpId) is a clump member")
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
