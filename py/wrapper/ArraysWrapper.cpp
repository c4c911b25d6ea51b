// NumPy arrays over the engine's columns (O.bodies.arrays()) and over the real contacts
// (O.interactions.arrays()), for post-processing without a Python loop over bodies.
#include <core/Omega.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <py/wrapper/ArraysWrapper.hpp>
#include <pybind11/numpy.h>

namespace py = pybind11;

namespace yade {

Omega& omega();

namespace {

// Keeps what a view points into alive as long as the NumPy array lives; a writable view of the
// positions also tells the engine that they may change behind its back (BodyStore::writableViews),
// and when it goes that they may have changed (a write through a temporary array, as
// `numpy.asarray(O.bodies.arrays().pos)[1, 0] = x`, is over before the next step).
struct ViewOwner {
    std::shared_ptr<Scene> scene; // (its ForceContainer holds the force and torque columns)
    std::shared_ptr<BodyStore> store;
    bool countsAsWriter = false;
    ~ViewOwner() {
        if (!countsAsWriter) return;
        noteExternalWrite();
        --store->writableViews;
    }
};

py::capsule ownerOf(const std::shared_ptr<Scene>& s, bool writesPositions) {
    auto* o = new ViewOwner{s, s->bodies.hotStore(), writesPositions};
    if (writesPositions) ++o->store->writableViews;
    return py::capsule(o, [](void* p) { delete static_cast<ViewOwner*>(p); });
}

// An n × columns array of doubles (columns = 0: a vector) over `data`, `stride` bytes per row.
template <class T> py::array view(T* data, size_t n, size_t columns, bool writable, const py::capsule& owner) {
    std::vector<py::ssize_t> shape{(py::ssize_t)n}, strides{(py::ssize_t)sizeof(T)};
    if (columns) {
        shape.push_back((py::ssize_t)columns);
        strides.push_back((py::ssize_t)(sizeof(T) / columns));
    }
    using Scalar = std::conditional_t<std::is_same_v<T, int> || std::is_same_v<T, bool>, T, Real>;
    py::array a(py::dtype::of<Scalar>(), shape, strides, reinterpret_cast<Scalar*>(data), owner);
    if (!writable) py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

struct BodyArrays {
    py::dict arrays;
};

BodyArrays bodyArrays() {
    std::shared_ptr<Scene> s = omega().scenePtr();
    BodyStore& st = s->bodies.hot();
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
    const py::capsule readOnly = ownerOf(s, false), writes = ownerOf(s, true);
    BodyArrays r;
    r.arrays["pos"] = view(st.pos.data(), n, 3, true, writes);
    r.arrays["vel"] = view(st.vel.data(), n, 3, true, readOnly);
    r.arrays["angVel"] = view(st.angVel.data(), n, 3, true, readOnly);
    r.arrays["ori"] = view(st.ori.data(), n, 4, true, readOnly);
    r.arrays["mass"] = view(st.mass.data(), n, 0, true, readOnly);
    r.arrays["inertia"] = view(st.inertia.data(), n, 3, true, readOnly);
    r.arrays["force"] = view(const_cast<Vector3r*>(s->forces.forceData()), n, 3, false, readOnly); // (read-only views)
    r.arrays["torque"] = view(const_cast<Vector3r*>(s->forces.torqueData()), n, 3, false, readOnly);
    r.arrays["radius"] = view(st.radius.data(), n, 0, false, readOnly);
    r.arrays["exists"] = view(st.exists.data(), n, 0, false, readOnly);
    return r;
}

// An n × columns array of doubles (columns = 0: a vector) or a vector of ints, `stride` bytes
// from one row to the next, over a pool's records (read-only).
py::array rowsOf(const void* first, size_t n, size_t columns, size_t stride, bool ints, const py::capsule& owner) {
    std::vector<py::ssize_t> shape{(py::ssize_t)n}, strides{(py::ssize_t)stride};
    if (columns) {
        shape.push_back((py::ssize_t)columns);
        strides.push_back((py::ssize_t)sizeof(Real));
    }
    py::array a(ints ? py::dtype::of<int>() : py::dtype::of<Real>(), shape, strides, first, owner);
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

// The real contacts whose geometry is a ScGeom and physics a NormShearPhys (the others are left
// out). When they are all of one kind (one ContactPool), views of the pool's records; else copies.
py::dict interactionArrays() {
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
    py::dict d;
    if (pools == 1 && g0 && p0 && intrs.countReal() == only->size()) { // views
        const py::capsule owner(new std::shared_ptr<ContactPool>(pool), [](void* p) { delete static_cast<std::shared_ptr<ContactPool>*>(p); });
        const size_t n = only->size(), stride = only->stride;
        const ContactPool::Header& h = only->header(0);
        d["id1"] = rowsOf(&h.id1, n, 0, stride, true, owner);
        d["id2"] = rowsOf(&h.id2, n, 0, stride, true, owner);
        d["normalForce"] = rowsOf(p0->normalForce.data(), n, 3, stride, false, owner);
        d["shearForce"] = rowsOf(p0->shearForce.data(), n, 3, stride, false, owner);
        d["normal"] = rowsOf(g0->normal.data(), n, 3, stride, false, owner);
        d["contactPoint"] = rowsOf(g0->contactPoint.data(), n, 3, stride, false, owner);
        d["penetrationDepth"] = rowsOf(&g0->penetrationDepth, n, 0, stride, false, owner);
        return d;
    }
    std::vector<int> id1, id2;
    std::vector<Vector3r> fn, fs, normal, point;
    std::vector<Real> depth;
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
    return d;
}

} // namespace

void bindArrays(py::module_& m) {
    py::class_<BodyArrays>(m, "BodyArrays", R"(NumPy views of the bodies' state, indexed by body id (from O.bodies.arrays()).

Attributes (arrays of float64 unless said): pos, vel, angVel, inertia (N×3), ori (N×4: x, y, z, w),
mass (N), force, torque (N×3, read-only: the totals of the last step), radius (N, read-only, NaN
for bodies that are not spheres), exists (N, bool, read-only: False for erased ids).

These are views, not copies: they read and write the engine's own columns. Writing pos, vel,
angVel, ori, mass or inertia changes the simulation (values are not checked: keep them finite).
A view covers the N bodies there were when it was taken and stays valid memory as long as it
lives, also after O.reset(); bodies appended later are not in it (take a new one), an erased
body's rows keep their last values with exists False. radius is refreshed from the shapes when
the view is taken. While a view of pos is alive the engine does not rely on positions it cached.)")
            .def("__getattr__", [](BodyArrays& a, const std::string& name) -> py::object {
                if (!a.arrays.contains(name)) throw py::attribute_error("BodyArrays has no array '" + name + "' (have: " + std::string(py::str(py::list(a.arrays.attr("keys")()))) + ")");
                return a.arrays[name.c_str()];
            })
            .def("keys", [](BodyArrays& a) { return py::list(a.arrays.attr("keys")()); })
            .def("__dir__", [](BodyArrays& a) { return py::list(a.arrays.attr("keys")()); });
    // as methods of O.bodies and O.interactions (bound by bindOmega)
    py::object bodiesClass = m.attr("BodyContainer"), interactionsClass = m.attr("InteractionContainer");
    py::setattr(bodiesClass, "arrays",
            py::cpp_function([](py::object) { return bodyArrays(); }, py::is_method(bodiesClass), py::name("arrays"),
                    "NumPy views of the bodies' state (a BodyArrays: pos, vel, angVel, ori, mass, inertia, force, torque, radius, exists); see help(BodyArrays) for how long they stay valid"));
    py::setattr(interactionsClass, "arrays",
            py::cpp_function([](py::object) { return interactionArrays(); }, py::is_method(interactionsClass), py::name("arrays"),
                    "The real contacts (ScGeom + NormShearPhys) as a dict of read-only NumPy arrays: id1, id2, normalForce, shearForce, "
                    "normal, contactPoint, penetrationDepth (row i is one contact; forces are those on body 2). When all real contacts are "
                    "of one kind (one IGeom and one IPhys class: the usual case), these are views of the engine's contact records, "
                    "not copies: they show the current values until the set of contacts changes (the next step, or an insert or erase: "
                    "contacts that end are replaced by others in their rows, new ones are not in the view), and stay valid memory as long "
                    "as they live; take new ones after each step. With several kinds of contacts they are copies taken now."));
}

} // namespace yade
