// What the 3D view draws (py/yade/qt/drawing.py), gathered in C++ in one pass per frame: each body's drawing
// functor (chosen by its shape's class, as a dispatcher chooses) and the numbers it hands over (a sphere's
// radius, a facet's corners in world coordinates...), beside the positions, orientations and colors; the
// contacts' ids and normal forces and the cell. Copies, so that the view never holds what a running simulation
// changes; a run in the background is paused at the end of its step meanwhile, unless the caller says the loop
// is already waiting for it (a SnapshotEngine's frame).
#include <core/Bound.hpp>
#include <core/Scene.hpp>
#include <map>
#include <pkg/common/GlFunctors.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <py/wrapper/DisplayWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <set>
#include <typeindex>
#include <unordered_map>

namespace py = pybind11;

namespace yade {

// The drawing functor of each shape class, chosen as a dispatcher chooses: the registered GlShapeFunctor whose
// `bases` name the class, else the one of its nearest base class; none (-1) when no functor draws it.
class ShapeDrawers {
public:
    std::vector<std::shared_ptr<GlShapeFunctor>> functors; // a drawer's number is its index here
    std::vector<std::string> names;
    ShapeDrawers() {
        const ClassRegistry& r = ClassRegistry::instance();
        for (const ClassInfo* c : r.all()) {
            if (c->name == "GlShapeFunctor" || !r.isSubclass(c->name, "GlShapeFunctor")) continue;
            auto f = std::dynamic_pointer_cast<GlShapeFunctor>(c->factory());
            if (!f || f->argTypes().empty()) continue;
            drawerOfClass[f->argTypes()[0]] = (int)functors.size();
            functors.push_back(f);
            names.push_back(c->name);
        }
    }
    int drawerOf(const Shape& s) {
        auto cached = byType.find(typeid(s));
        if (cached != byType.end()) return cached->second;
        const ClassRegistry& r = ClassRegistry::instance();
        int d = -1;
        for (const ClassInfo* c = &r.get(typeid(s)); c && d < 0; c = c->baseName.empty() ? nullptr : r.find(c->baseName)) {
            auto it = drawerOfClass.find(c->name);
            if (it != drawerOfClass.end()) d = it->second;
        }
        return byType[typeid(s)] = d;
    }

private:
    std::map<std::string, int> drawerOfClass;
    std::unordered_map<std::type_index, int> byType;
};

static ShapeDrawers& shapeDrawers() {
    static ShapeDrawers d; // (made at the first frame: every class is registered by then)
    return d;
}

template <class T> static py::array_t<T> array(std::vector<py::ssize_t> shape) { return py::array_t<T>(shape); }

static py::object displayFrame(bool pauseRun, bool contacts, bool pairs) {
    std::unique_ptr<BetweenSteps> between;
    if (pauseRun) between = std::make_unique<BetweenSteps>(/*yieldToLoop*/ true);
    if (between && !between->held()) return py::none(); // the loop waits for the GUI: no frame this time
    const Scene& s = omega().scene();
    const BodyContainer& bodies = s.bodies;
    const py::ssize_t n = (py::ssize_t)bodies.size();
    auto drawer = array<short>({n});
    auto pos = array<double>({n, 3}), rot = array<double>({n, 3, 3}), size = array<double>({n, 3});
    auto color = array<float>({n, 3});
    auto boundMin = array<double>({n, 3}), boundMax = array<double>({n, 3});
    auto bmin = boundMin.mutable_unchecked<2>(), bmax = boundMax.mutable_unchecked<2>();
    auto wire = array<bool>({n}), highlight = array<bool>({n});
    auto mask = array<int>({n});
    auto k = drawer.mutable_unchecked<1>();
    auto p = pos.mutable_unchecked<2>(), sz = size.mutable_unchecked<2>();
    auto r = rot.mutable_unchecked<3>();
    auto c = color.mutable_unchecked<2>();
    auto w = wire.mutable_unchecked<1>(), h = highlight.mutable_unchecked<1>();
    auto m = mask.mutable_unchecked<1>();
    ShapeDrawers& drawers = shapeDrawers();
    std::vector<int> triangleBody;
    std::vector<Vector3r> triangles;
    std::set<std::string> undrawn;
    for (py::ssize_t i = 0; i < n; ++i) {
        const Body* b = bodies[(int)i].get();
        const Shape* shape = b ? b->shape.get() : nullptr;
        k(i) = -1;
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
        if (b->isClump()) { // drawn as its members
            k(i) = -2;
            continue;
        }
        k(i) = drawers.drawerOf(*shape);
        if (k(i) < 0) {
            undrawn.insert(shape->getClassName());
            continue;
        }
        DisplayItem item;
        item.triangles = &triangles;
        const size_t before = triangles.size();
        drawers.functors[k(i)]->gather(*shape, *b->state, item);
        for (size_t t = before; t < triangles.size(); t += 3) triangleBody.push_back((int)i);
        for (int a = 0; a < 3; ++a) sz(i, a) = item.size[a];
    }
    py::dict d;
    d["drawer"] = drawer;
    d["drawers"] = drawers.names;
    d["undrawn"] = undrawn;
    d["pos"] = pos;
    d["rot"] = rot;
    d["size"] = size;
    d["color"] = color;
    d["wire"] = wire;
    d["highlight"] = highlight;
    d["mask"] = mask;
    d["boundMin"] = boundMin;
    d["boundMax"] = boundMax;
    const py::ssize_t nt = (py::ssize_t)triangleBody.size();
    d["triangleBody"] = py::array_t<int>({nt}, triangleBody.data());
    auto corners = array<double>({nt, 3, 3});
    auto cc = corners.mutable_unchecked<3>();
    for (py::ssize_t t = 0; t < nt; ++t)
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) cc(t, v, a) = triangles[3 * t + v][a];
    d["triangleCorners"] = corners;
    // contacts: the real ones with a normal force (force chains), and every pair (OpenGLRenderer.intrAllWire)
    const InteractionContainer& intrs = s.interactions;
    std::vector<int> ids, pairIds;
    std::vector<double> fn;
    for (size_t e = 0; (contacts || pairs) && e < intrs.size(); ++e) {
        const int id1 = intrs.pairIds[2 * e], id2 = intrs.pairIds[2 * e + 1];
        if (pairs) pairIds.insert(pairIds.end(), {id1, id2});
        if (!contacts || !intrs.isReal(e)) continue;
        const auto* np = dynamic_cast<const NormPhys*>(intrs.phys(e));
        const auto* g = dynamic_cast<const ScGeom*>(intrs.geom(e));
        if (!np) continue;
        ids.insert(ids.end(), {id1, id2});
        // signed: normalForce·normal, positive in compression (Gl1_NormPhys.signFilter filters on its sign)
        fn.push_back(g ? np->normalForce.dot(g->normal) : np->normalForce.norm());
    }
    d["contactIds"] = py::array_t<int>({(py::ssize_t)fn.size(), (py::ssize_t)2}, ids.data());
    d["contactFn"] = py::array_t<double>({(py::ssize_t)fn.size()}, fn.data());
    d["pairIds"] = py::array_t<int>({(py::ssize_t)pairIds.size() / 2, (py::ssize_t)2}, pairIds.data());
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
    m.def("_displayFrame", &displayFrame, py::arg("pauseRun") = true, py::arg("contacts") = true, py::arg("pairs") = true,
          "What the 3D view draws, as a dict of NumPy copies: per body its drawer (an index into drawers, the names of the "
          "GlShapeFunctor classes; -1: no shape or no functor draws it, -2: a clump, drawn as its members), pos, rot (3×3), "
          "size (what the functor gathered: a sphere's radius, a box's half-extents, a wall's axis and sense), color, wire, "
          "highlight, mask, boundMin and boundMax (NaN without a bound); undrawn (the shape classes no functor draws); "
          "triangleBody and triangleCorners (world coordinates: facets); contactIds and contactFn (signed normal "
          "force normalForce·normal, positive in compression); pairIds (every pair); cellHSize (None when not periodic); "
          "iter; time. pauseRun: stop a background run at the end of its step meanwhile (for as long as the copy takes; None "
          "instead of a frame when the run's thread waits for the GUI meanwhile: a PyRunner's makeVideo); "
          "contacts, pairs: gather those (else the arrays are empty: a frame that draws no contact pauses the run less).");
}

} // namespace yade
