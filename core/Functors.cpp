// Default bodies of the functor entry points: reached only when a base functor is called.
#include <core/BoundDispatcher.hpp>
#include <core/IGeomDispatcher.hpp>
#include <core/IPhysDispatcher.hpp>
#include <core/LawDispatcher.hpp>
#include <core/Scene.hpp>
#include <stdexcept>

namespace yade {

static std::runtime_error notImplemented(const Functor& f) {
    return std::runtime_error(f.getClassName() + ".go is not implemented (use a concrete functor)");
}
void BoundFunctor::go(const Shape&, std::shared_ptr<Bound>&, const State&, const Body&) { throw notImplemented(*this); }
bool IGeomFunctor::go(const Shape&, const Shape&, const State&, const State&, const Vector3r&, bool, Interaction&) {
    throw notImplemented(*this);
}
void IPhysFunctor::go(const std::shared_ptr<Material>&, const std::shared_ptr<Material>&, Interaction&) {
    throw notImplemented(*this);
}
bool LawFunctor::go(IGeom&, IPhys&, Interaction&) { throw notImplemented(*this); }

// The adapters from the batched forms to the one-contact ones (functors written in that form).
// The Interaction a one-contact functor gets: the contact's own object when it has one (a
// Contact made from an Interaction), else a stand-in per thread whose geom and phys are the
// contact's objects (not owned: they live in a pool record or in the Contact).
namespace {
struct StandIn {
    Interaction& I;
    bool own;
    explicit StandIn(const Contact& c) : I(c.I ? *c.I : spare()), own(!c.I) {
        if (!own) return;
        I.id1 = c.id1;
        I.id2 = c.id2;
        I.geom = std::shared_ptr<IGeom>(std::shared_ptr<IGeom>(), c.geom);
        I.phys = std::shared_ptr<IPhys>(std::shared_ptr<IPhys>(), c.phys);
    }
    ~StandIn() {
        if (!own) return;
        I.geom.reset();
        I.phys.reset();
    }
    static Interaction& spare() {
        thread_local Interaction i;
        return i;
    }
};
} // namespace

void IGeomFunctor::goBatch(const BodyColumns&, Contact* c, size_t n, char* result) {
    const BodyContainer& bodies = scene->bodies;
    for (size_t j = 0; j < n; ++j) {
        StandIn s(c[j]);
        const Body& b1 = *bodies[c[j].id1];
        const Body& b2 = *bodies[c[j].id2];
        result[j] = go(*b1.shape, *b2.shape, *b1.state, *b2.state, c[j].shift ? c[j].shift->shift2 : Vector3r::Zero(), false, s.I); // (periodic: the functor adds the shift)
        if (s.own && s.I.geom.get() != c[j].geom) c[j].setGeom(s.I.geom); // (a new one)
        else if (!s.own) c[j].geom = s.I.geom.get();
    }
}

void LawFunctor::goBatch(const Contact* c, size_t n, char* keep) {
    for (size_t j = 0; j < n; ++j) {
        StandIn s(c[j]);
        keep[j] = go(*c[j].geom, *c[j].phys, s.I);
    }
}

void BoundDispatcher::action() {
    for (const auto& b : scene->bodies) {
        if (!b || !b->shape) continue;
        if (BoundFunctor* f = getFunctor(*b->shape)) {
            f->scene = scene;
            f->go(*b->shape, b->bound, *b->state, *b);
        }
    }
}

} // namespace yade
