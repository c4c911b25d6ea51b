// NumPy arrays over the engine's columns (O.bodies.arrays()) and over the real contacts
// (O.interactions.arrays()), for post-processing without a Python loop over bodies.
#include <core/Omega.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <lib/base/ViewRegistry.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <py/wrapper/ArraysWrapper.hpp>
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <algorithm>
#include <atomic>
#include <mutex>

namespace py = pybind11;

namespace yade {

Omega& omega();

namespace {

// The arrays of one call of O.bodies.arrays() or O.interactions.arrays(): what they point into
// (kept alive as long as one of them lives), and each array, so that they can be made read-only
// when what they show moves or is dropped (the registry of the store or of the contacts calls
// stale(), from the thread that made the change, maybe without the GIL: it only clears a flag
// bit in each array's header and sets `isStale`).
// A writable view of the positions also tells the engine that they may change behind its back
// (BodyStore::writableViews) until it goes or is stale, and then that they may have changed (a
// write through a temporary array, as `numpy.asarray(O.bodies.arrays().pos)[1, 0] = x`, is over
// before the next step).
class ArraySet final : public ViewRegistry::Client {
public:
    // One array: its base (a capsule that owns this link), so that its end is known.
    struct Link {
        std::shared_ptr<ArraySet> set;
        PyObject* array = nullptr;   // (not owned: it owns this link)
        BodyStore* writer = nullptr; // counted in writer->writableViews (while not stale)
    };
    ArraySet(std::shared_ptr<ViewRegistry> r, std::vector<std::shared_ptr<const void>> k) : registry(std::move(r)), keep(std::move(k)) {}
    ~ArraySet() override { registry->remove(this); }
    // Starts being told (before its arrays are made: an array made after a change is read-only).
    void listen() { registry->add(this); }
    void stale() override {
        std::lock_guard<std::mutex> lock(mutex);
        isStale = true;
        for (Link* l : links) {
            readOnly(l->array);
            release(*l);
        }
    }
    // An n × columns array (columns = 0: a vector) of `dtype` over `first`, `stride` bytes from
    // one row to the next and `itemStride` between columns; `writer`: the store whose positions
    // it shows (the pos view).
    py::array make(const py::dtype& dtype, const void* first, size_t n, size_t columns, size_t stride, size_t itemStride, bool writable,
            const std::shared_ptr<ArraySet>& self, BodyStore* writer = nullptr) {
        std::vector<py::ssize_t> shape{(py::ssize_t)n}, strides{(py::ssize_t)stride};
        if (columns) {
            shape.push_back((py::ssize_t)columns);
            strides.push_back((py::ssize_t)itemStride);
        }
        auto* link = new Link{self, nullptr, nullptr};
        const py::capsule base(link, [](void* p) { forget(static_cast<Link*>(p)); });
        py::array a(dtype, shape, strides, first, base);
        if (!writable) readOnly(a.ptr());
        std::lock_guard<std::mutex> lock(mutex);
        link->array = a.ptr();
        if (isStale) readOnly(a.ptr());
        else if (writer && writable) {
            link->writer = writer;
            ++writer->writableViews;
        }
        links.push_back(link);
        return a;
    }
    std::atomic<bool> isStale{false};

private:
    std::shared_ptr<ViewRegistry> registry;
    std::vector<std::shared_ptr<const void>> keep;
    std::mutex mutex; // links, and the arrays' flags
    std::vector<Link*> links;
    static void readOnly(PyObject* a) { py::detail::array_proxy(a)->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_; }
    static void release(Link& l) {
        if (!l.writer) return;
        noteExternalWrite();
        --l.writer->writableViews;
        l.writer = nullptr;
    }
    static void forget(Link* l) { // (its array is going)
        {
            ArraySet& s = *l->set;
            std::lock_guard<std::mutex> lock(s.mutex);
            s.links.erase(std::find(s.links.begin(), s.links.end(), l));
            release(*l);
        }
        delete l; // (may end the set)
    }
};

struct BodyArrays {
    py::dict arrays;
    std::shared_ptr<ArraySet> set;
};

BodyArrays bodyArrays() {
    std::shared_ptr<Scene> s = omega().scenePtr();
    const std::shared_ptr<BodyStore>& store = s->bodies.hotStore();
    BodyStore& st = *store;
    const size_t n = s->bodies.size();
    s->forces.resize(n);
    s->forces.sync(); // (the totals of the last step, including what other threads added)
    // sphere radii, refreshed here from the shapes
    st.radius.resize(n, NaN);
    for (size_t id = 0; id < n; ++id) {
        const Body* b = s->bodies[(Body::id_t)id].get();
        const Sphere* sphere = b ? dynamic_cast<const Sphere*>(b->shape.get()) : nullptr;
        st.radius[id] = sphere ? sphere->radius : NaN;
    }
    // (the scene's ForceContainer holds the force and torque columns)
    BodyArrays r{py::dict(), std::make_shared<ArraySet>(std::shared_ptr<ViewRegistry>(store, &st.views), std::vector<std::shared_ptr<const void>>{s, store})};
    ArraySet& set = *r.set;
    set.listen();
    const py::dtype real = py::dtype::of<Real>();
    auto vectors = [&](const auto* data, bool writable, BodyStore* writer = nullptr) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(data)>>;
        constexpr size_t columns = sizeof(T) / sizeof(Real);
        return set.make(real, data, n, columns, sizeof(T), sizeof(Real), writable, r.set, writer);
    };
    r.arrays["pos"] = vectors(st.pos.data(), true, &st);
    r.arrays["vel"] = vectors(st.vel.data(), true);
    r.arrays["angVel"] = vectors(st.angVel.data(), true);
    r.arrays["ori"] = vectors(st.ori.data(), true);
    r.arrays["mass"] = set.make(real, st.mass.data(), n, 0, sizeof(Real), 0, true, r.set);
    r.arrays["inertia"] = vectors(st.inertia.data(), true);
    r.arrays["force"] = vectors(s->forces.forceData(), false); // (read-only views)
    r.arrays["torque"] = vectors(s->forces.torqueData(), false);
    r.arrays["radius"] = set.make(real, st.radius.data(), n, 0, sizeof(Real), 0, false, r.set);
    r.arrays["exists"] = set.make(py::dtype::of<bool>(), st.exists.data(), n, 0, sizeof(bool), 0, false, r.set);
    return r;
}

// A periodic scene's cellDist of contacts (entries k of the container), as an n×3 int array (a copy).
static py::array_t<int> cellDists(const InteractionContainer& intrs, const std::vector<size_t>& entries) {
    py::array_t<int> a({(py::ssize_t)entries.size(), (py::ssize_t)3});
    auto m = a.mutable_unchecked<2>();
    for (size_t i = 0; i < entries.size(); ++i)
        for (int c = 0; c < 3; ++c) m(i, c) = intrs.cellDist[entries[i]][c];
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

// The real contacts whose geometry is a ScGeom and physics a NormShearPhys (the others are left
// out), as a ContactArrays (a dict) of read-only arrays (and, in a periodic scene, cellDist: a
// copy taken now). When they are all of one kind (one
// ContactPool), views of the pool's records (row stride = the record's size); else copies.
py::object interactionArrays(const py::object& contactArraysClass) {
    Scene& s = omega().scene();
    const InteractionContainer& intrs = s.interactions;
    std::shared_ptr<ContactPool> pool; // the one pool with contacts, if one
    size_t pools = 0;
    for (size_t p = 0; p < intrs.poolCount(); ++p)
        if (intrs.pools[p]->size() > 0) {
            pool = intrs.pools[p];
            ++pools;
        }
    const ContactPool* only = pool.get();
    const ScGeom* g0 = only ? dynamic_cast<const ScGeom*>(only->geom(0)) : nullptr;
    const NormShearPhys* p0 = only ? dynamic_cast<const NormShearPhys*>(only->phys(0)) : nullptr;
    const bool views = pools == 1 && g0 && p0 && intrs.countReal() == only->size();
    auto set = std::make_shared<ArraySet>(intrs.views, std::vector<std::shared_ptr<const void>>{pool});
    py::object d = contactArraysClass();
    d.attr("_views") = py::cast(set);
    set->listen();
    if (views) {
        const size_t n = only->size(), stride = only->stride;
        const ContactPool::Header& h = only->header(0);
        const py::dtype real = py::dtype::of<Real>(), ints = py::dtype::of<int>();
        d["id1"] = set->make(ints, &h.id1, n, 0, stride, 0, false, set);
        d["id2"] = set->make(ints, &h.id2, n, 0, stride, 0, false, set);
        d["normalForce"] = set->make(real, p0->normalForce.data(), n, 3, stride, sizeof(Real), false, set);
        d["shearForce"] = set->make(real, p0->shearForce.data(), n, 3, stride, sizeof(Real), false, set);
        d["normal"] = set->make(real, g0->normal.data(), n, 3, stride, sizeof(Real), false, set);
        d["contactPoint"] = set->make(real, g0->contactPoint.data(), n, 3, stride, sizeof(Real), false, set);
        d["penetrationDepth"] = set->make(real, &g0->penetrationDepth, n, 0, stride, 0, false, set);
        d["refR1"] = set->make(real, &g0->refR1, n, 0, stride, 0, false, set);
        d["refR2"] = set->make(real, &g0->refR2, n, 0, stride, 0, false, set);
        if (intrs.periodic) {
            std::vector<size_t> entries(n);
            for (size_t i = 0; i < n; ++i) entries[i] = only->header(i).k;
            d["cellDist"] = cellDists(intrs, entries);
        }
        return d;
    }
    std::vector<int> id1, id2;
    std::vector<Vector3r> fn, fs, normal, point;
    std::vector<Real> depth, refR1, refR2;
    std::vector<size_t> entries;
    for (size_t k = 0; k < intrs.size(); ++k) {
        if (!intrs.isReal(k)) continue;
        const auto* g = dynamic_cast<const ScGeom*>(intrs.geom(k));
        const auto* p = dynamic_cast<const NormShearPhys*>(intrs.phys(k));
        if (!g || !p) continue;
        id1.push_back(intrs.pairIds[2 * k]);
        id2.push_back(intrs.pairIds[2 * k + 1]);
        fn.push_back(p->normalForce);
        fs.push_back(p->shearForce);
        normal.push_back(g->normal);
        point.push_back(g->contactPoint);
        depth.push_back(g->penetrationDepth);
        refR1.push_back(g->refR1);
        refR2.push_back(g->refR2);
        entries.push_back(k);
    }
    auto vectors = [](const std::vector<Vector3r>& v) {
        py::array_t<Real> a({(py::ssize_t)v.size(), (py::ssize_t)3});
        auto m = a.mutable_unchecked<2>();
        for (size_t i = 0; i < v.size(); ++i)
            for (int c = 0; c < 3; ++c) m(i, c) = v[i][c];
        return a;
    };
    d["id1"] = py::array_t<int>((py::ssize_t)id1.size(), id1.data());
    d["id2"] = py::array_t<int>((py::ssize_t)id2.size(), id2.data());
    d["normalForce"] = vectors(fn);
    d["shearForce"] = vectors(fs);
    d["normal"] = vectors(normal);
    d["contactPoint"] = vectors(point);
    d["penetrationDepth"] = py::array_t<Real>((py::ssize_t)depth.size(), depth.data());
    d["refR1"] = py::array_t<Real>((py::ssize_t)refR1.size(), refR1.data());
    d["refR2"] = py::array_t<Real>((py::ssize_t)refR2.size(), refR2.data());
    if (intrs.periodic) d["cellDist"] = cellDists(intrs, entries);
    for (const auto& item : py::reinterpret_borrow<py::dict>(d)) // (read-only as the views, though nobody reads them after)
        py::detail::array_proxy(item.second.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return d;
}

} // namespace

void bindArrays(py::module_& m) {
    py::class_<ArraySet, std::shared_ptr<ArraySet>>(m, "_ArrayViews", "What a set of arrays from O.bodies.arrays() or O.interactions.arrays() points into.")
            .def_property_readonly("stale", [](const ArraySet& s) { return s.isStale.load(); });
    py::class_<BodyArrays>(m, "BodyArrays", R"(NumPy views of the bodies' state, indexed by body id (from O.bodies.arrays()).

Attributes (arrays of float64 unless said): pos, vel, angVel, inertia (N×3), ori (N×4: x, y, z, w),
mass (N), force, torque (N×3, read-only: the totals of the last step), radius (N, read-only, NaN
for bodies that are not spheres), exists (N, bool, read-only: False for erased ids).

These are views, not copies: they read and write the engine's own columns. Writing pos, vel,
angVel, ori, mass or inertia changes the simulation (values are not checked: keep them finite).
A view covers the N bodies there were when it was taken. When the set of bodies changes (a body
appended or erased, O.bodies.clear()) or the scene is dropped (O.reset(), O.load()), the arrays
become stale: `stale` is True and every one of them is read-only (a write raises ValueError:
assignment destination is read-only); take new ones. A stale array can still be read: it stays
valid memory as long as it lives, and shows the columns it was taken from (after O.reset() the
last values of the old scene). Arrays made from one before it became stale (a slice, a reshape)
are not told: take slices of fresh arrays. radius is refreshed from the shapes when the view is
taken. While a view of pos is alive and not stale the engine does not rely on positions it
cached.)")
            .def_property_readonly("stale", [](const BodyArrays& a) { return a.set->isStale.load(); },
                    "True once the set of bodies changed or the scene was dropped: the arrays are then read-only; take new ones")
            .def("__getattr__", [](BodyArrays& a, const std::string& name) -> py::object {
                if (!a.arrays.contains(name)) throw py::attribute_error("BodyArrays has no array '" + name + "' (have: " + std::string(py::str(py::list(a.arrays.attr("keys")()))) + ")");
                return a.arrays[name.c_str()];
            })
            .def("keys", [](BodyArrays& a) { return py::list(a.arrays.attr("keys")()); })
            .def("__dir__", [](BodyArrays& a) { return py::list(a.arrays.attr("keys")()); });
    // What O.interactions.arrays() returns: a dict with a `stale` property.
    py::exec(R"(
class ContactArrays(dict):
    """The real contacts as read-only NumPy arrays, by name (from O.interactions.arrays()): a dict
with a `stale` property."""
    __slots__ = ("_views",)

    @property
    def stale(self):
        """True once the set of contacts changed (a contact made or ended, an erase, O.reset()):
views then show other contacts in their rows, or none; take new arrays."""
        return self._views.stale
)",
            m.attr("__dict__"));
    const py::object contactArraysClass = m.attr("ContactArrays");
    // as methods of O.bodies and O.interactions (bound by bindOmega)
    py::object bodiesClass = m.attr("BodyContainer"), interactionsClass = m.attr("InteractionContainer");
    py::setattr(bodiesClass, "arrays",
            py::cpp_function([](py::object) { return bodyArrays(); }, py::is_method(bodiesClass), py::name("arrays"),
                    "NumPy views of the bodies' state (a BodyArrays: pos, vel, angVel, ori, mass, inertia, force, torque, radius, exists). "
                    "They become stale (BodyArrays.stale, every array read-only: a write raises ValueError) when a body is appended or "
                    "erased or the scene is dropped (O.reset(), O.load()); a stale array can still be read. See help(BodyArrays)."));
    py::setattr(interactionsClass, "arrays",
            py::cpp_function([contactArraysClass](py::object) { return interactionArrays(contactArraysClass); }, py::is_method(interactionsClass), py::name("arrays"),
                    "The real contacts (ScGeom + NormShearPhys) as a ContactArrays (a dict) of read-only NumPy arrays: id1, id2, normalForce, "
                    "shearForce, normal, contactPoint, penetrationDepth, refR1, refR2, and in a periodic scene cellDist (row i is one contact; forces are those on body 2). When all real "
                    "contacts are of one kind (one IGeom and one IPhys class: the usual case), these are views of the engine's contact "
                    "records, not copies: they show the current values until the set of contacts changes (a contact made or ended, "
                    "usually at the next step; an erase; O.reset()): then the dict's `stale` is True, and rows may show other contacts "
                    "or records no longer used (reading stays valid memory as long as they live); take new ones after each step. With "
                    "several kinds of contacts they are copies taken now (`stale` tells the same)."));
}

} // namespace yade
