// What the 3D view draws (py/yade/qt/drawing.py), gathered in C++ in one pass per frame: the shapes'
// kinds, colors and sizes beside the positions and orientations, the facets' corners in world
// coordinates, the contacts' ids and normal forces and the cell. Copies, so that the view never holds
// what a running simulation changes; a run in the background is paused at the end of its step meanwhile,
// unless the caller says the loop is already waiting for it (a SnapshotEngine's frame).
#include <core/Bound.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Box.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <py/wrapper/DisplayWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <pybind11/numpy.h>

namespace py = pybind11;

namespace yade {

// Body kinds as the view knows them (drawing.py: KIND_*).
enum DisplayKind : signed char { noShape = 0, sphereKind = 1, facetKind = 2, wallKind = 3, boxKind = 4, clumpKind = 5, otherKind = 6 };

template <class T> static py::array_t<T> array(std::vector<py::ssize_t> shape) { return py::array_t<T>(shape); }

static py::dict displayFrame(bool pauseRun) {
    std::unique_ptr<BetweenSteps> between;
    if (pauseRun) between = std::make_unique<BetweenSteps>();
    const Scene& s = omega().scene();
    const BodyContainer& bodies = s.bodies;
    const py::ssize_t n = (py::ssize_t)bodies.size();
    auto kind = array<signed char>({n});
    auto pos = array<double>({n, 3}), rot = array<double>({n, 3, 3}), size = array<double>({n, 3});
    auto color = array<float>({n, 3});
    auto boundMin = array<double>({n, 3}), boundMax = array<double>({n, 3});
    auto bmin = boundMin.mutable_unchecked<2>(), bmax = boundMax.mutable_unchecked<2>();
    auto wire = array<bool>({n}), highlight = array<bool>({n});
    auto mask = array<int>({n});
    auto k = kind.mutable_unchecked<1>();
    auto p = pos.mutable_unchecked<2>(), sz = size.mutable_unchecked<2>();
    auto r = rot.mutable_unchecked<3>();
    auto c = color.mutable_unchecked<2>();
    auto w = wire.mutable_unchecked<1>(), h = highlight.mutable_unchecked<1>();
    auto m = mask.mutable_unchecked<1>();
    std::vector<int> facetBody;
    std::vector<double> facetCorners;
    for (py::ssize_t i = 0; i < n; ++i) {
        const Body* b = bodies[(int)i].get();
        const Shape* shape = b ? b->shape.get() : nullptr;
        k(i) = noShape;
        for (int a = 0; a < 3; ++a) p(i, a) = sz(i, a) = c(i, a) = 0;
        for (int a = 0; a < 3; ++a) bmin(i, a) = bmax(i, a) = b && b->bound ? 0 : NaN;
        if (b && b->bound)
            for (int a = 0; a < 3; ++a) {
                bmin(i, a) = b->bound->min[a];
                bmax(i, a) = b->bound->max[a];
            }
        for (int a = 0; a < 3; ++a)
            for (int e = 0; e < 3; ++e) r(i, a, e) = a == e;
        w(i) = h(i) = false;
        m(i) = b ? b->mask : 0;
        if (!b || !shape) continue;
        const Vector3r x = b->state->pos();
        const Matrix3r R = b->state->ori().toRotationMatrix();
        for (int a = 0; a < 3; ++a) {
            p(i, a) = x[a];
            c(i, a) = (float)shape->color[a];
            for (int e = 0; e < 3; ++e) r(i, a, e) = R(a, e);
        }
        w(i) = shape->wire;
        h(i) = shape->highlight;
        if (const auto* sp = dynamic_cast<const Sphere*>(shape)) {
            k(i) = sphereKind;
            sz(i, 0) = sp->radius;
        } else if (const auto* f = dynamic_cast<const Facet*>(shape)) {
            k(i) = facetKind;
            facetBody.push_back((int)i);
            for (const Vector3r& v : f->vertices) {
                const Vector3r world = x + R * v;
                facetCorners.insert(facetCorners.end(), {world[0], world[1], world[2]});
            }
        } else if (const auto* wl = dynamic_cast<const Wall*>(shape)) {
            k(i) = wallKind;
            sz(i, 0) = wl->axis;
            sz(i, 1) = wl->sense;
        } else if (const auto* bx = dynamic_cast<const Box*>(shape)) {
            k(i) = boxKind;
            for (int a = 0; a < 3; ++a) sz(i, a) = bx->extents[a];
        } else {
            k(i) = shape->asClump() ? clumpKind : otherKind;
        }
    }
    py::dict d;
    d["kind"] = kind;
    d["pos"] = pos;
    d["rot"] = rot;
    d["size"] = size;
    d["color"] = color;
    d["wire"] = wire;
    d["highlight"] = highlight;
    d["mask"] = mask;
    d["boundMin"] = boundMin;
    d["boundMax"] = boundMax;
    const py::ssize_t nf = (py::ssize_t)facetBody.size();
    d["facetBody"] = py::array_t<int>({nf}, facetBody.data());
    d["facetCorners"] = py::array_t<double>({nf, (py::ssize_t)3, (py::ssize_t)3}, facetCorners.data());
    // contacts: the real ones with a normal force (force chains), and every pair (OpenGLRenderer.intrAllWire)
    const InteractionContainer& intrs = s.interactions;
    std::vector<int> ids, pairs;
    std::vector<double> fn;
    for (size_t e = 0; e < intrs.size(); ++e) {
        const int id1 = intrs.pairIds[2 * e], id2 = intrs.pairIds[2 * e + 1];
        pairs.insert(pairs.end(), {id1, id2});
        if (!intrs.isReal(e)) continue;
        const auto* np = dynamic_cast<const NormPhys*>(intrs.phys(e));
        const auto* g = dynamic_cast<const ScGeom*>(intrs.geom(e));
        if (!np) continue;
        ids.insert(ids.end(), {id1, id2});
        // signed: normalForce·normal, positive in compression (Gl1_NormPhys.signFilter filters on its sign)
        fn.push_back(g ? np->normalForce.dot(g->normal) : np->normalForce.norm());
    }
    d["contactIds"] = py::array_t<int>({(py::ssize_t)fn.size(), (py::ssize_t)2}, ids.data());
    d["contactFn"] = py::array_t<double>({(py::ssize_t)fn.size()}, fn.data());
    d["pairIds"] = py::array_t<int>({(py::ssize_t)pairs.size() / 2, (py::ssize_t)2}, pairs.data());
    if (s.isPeriodic) {
        auto H = array<double>({3, 3});
        auto hh = H.mutable_unchecked<2>();
        for (int a = 0; a < 3; ++a)
            for (int e = 0; e < 3; ++e) hh(a, e) = s.cell->hSize(a, e);
        d["cellHSize"] = H;
    } else {
        d["cellHSize"] = py::none();
    }
    d["iter"] = s.iter;
    d["time"] = s.time;
    return d;
}

void bindDisplay(py::module_& m) {
    m.def("_displayFrame", &displayFrame, py::arg("pauseRun") = true,
          "What the 3D view draws, as a dict of NumPy copies: per body kind (0 none, 1 sphere, 2 facet, 3 wall, 4 box, "
          "5 clump, 6 other), pos, rot (3×3), size (radius; box half-extents; wall axis and sense), color, wire, "
          "highlight, mask, boundMin and boundMax (NaN without a bound); facetBody and facetCorners (world coordinates); contactIds and contactFn (signed normal "
          "force normalForce·normal, positive in compression); pairIds (every pair); cellHSize (None when not periodic); iter; time. "
          "pauseRun: stop a background run at the end of its step meanwhile.");
}

} // namespace yade
