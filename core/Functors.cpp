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
void IGeomFunctor::goBatch(const BodyColumns&, Contact* c, size_t n, char* result) {
    const BodyContainer& bodies = scene->bodies;
    for (size_t j = 0; j < n; ++j) {
        Interaction& i = c[j].interaction();
        const Body& b1 = *bodies[i.id1];
        const Body& b2 = *bodies[i.id2];
        result[j] = go(*b1.shape, *b2.shape, *b1.state, *b2.state, Vector3r::Zero(), false, i);
        if (i.geom.get() != c[j].geom) c[j].setGeom(i.geom); // (a new one: the record's too)
    }
}

void IGeomFunctor::goBatchWithLaw(const BodyColumns&, Contact*, size_t, LawFunctor& law, char*) {
    throw std::logic_error(getClassName() + " has no fused pass with " + law.getClassName());
}

void LawFunctor::goBatch(const Contact* c, size_t n, char* keep) {
    for (size_t j = 0; j < n; ++j) keep[j] = go(*c[j].geom, *c[j].phys, c[j].interaction());
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
