// Contact laws written once (doc/contact-laws.md, "Kernels"): an Ig2 functor's geometry and a Law2
// functor's physics are each a kernel, a member template on the number type T (lib/base/Lanes.hpp),
// and every path instantiates the same kernels:
//   - the general path: LawKernelFunctor::go() runs the law's kernel on one contact (T = Real)
//     after the Ig2 functor's go() (which runs the geometry kernel on one contact);
//   - the fast pass (KernelPass): for existing contacts of one (Ig2, Law2) pair, the geometry and the
//     law of two contacts at a time (T = Two), an odd last one with T = Real.
// Both give the same bits by construction. Registering a Law2 class derived from LawKernelFunctor
// (its YADE_CLASS line in classes.def) makes its pass with every geometry kernel of its IGeom class
// (GeomKernels); the interaction loop finds it with KernelPasses::find().
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <core/Scene.hpp>
#include <lib/base/Lanes.hpp>
#include <type_traits>
#include <typeindex>

namespace yade {

// The two bodies of the contacts of each lane, read from the columns when asked.
// In a periodic scene, for pairs through the cell's faces, body 2 is its image (Contact::shift): the one
// contact `image` says, or in a fast pass lanes[0] (shift2) and lanes[1] (shiftVel2) of each lane.
template <class T> struct ContactBodies {
    const BodyColumns& b;
    LaneIds<T> id1, id2;
    const ContactShift* image = nullptr;
    const Vec3<T>* lanes = nullptr;
    YADE_KERNEL Vec3<T> pos1() const { return gather<T>(b.store.pos, id1); }
    YADE_KERNEL Vec3<T> pos2() const {
        if constexpr (std::is_same<T, Real>::value)
            if (image) return gather<T>(b.store.pos, id2) + vec3(image->shift2);
        if (lanes) return gather<T>(b.store.pos, id2) + lanes[0];
        return gather<T>(b.store.pos, id2);
    }
    YADE_KERNEL Vec3<T> vel1() const { return gather<T>(b.store.vel, id1); }
    YADE_KERNEL Vec3<T> vel2() const {
        if constexpr (std::is_same<T, Real>::value)
            if (image) return gather<T>(b.store.vel, id2) + vec3(image->shiftVel2);
        if (lanes) return gather<T>(b.store.vel, id2) + lanes[1];
        return gather<T>(b.store.vel, id2);
    }
    YADE_KERNEL Vec3<T> angVel1() const { return gather<T>(b.store.angVel, id1); }
    YADE_KERNEL Vec3<T> angVel2() const { return gather<T>(b.store.angVel, id2); }
    YADE_KERNEL PairMotion<T> motion() const { return {pos1(), pos2(), vel1(), vel2(), angVel1(), angVel2()}; }
    // a value made lane by lane by a scalar function of the two ids
    template <class F> T perPair(F f) const {
        return eachLane<T>([&](int i) { return f(id1.i[i], id2.i[i]); });
    }
};

// The motion of two bodies a one-contact functor is given.
inline PairMotion<Real> motionOf(const Kinematics& a, const Kinematics& b) {
    return {vec3(a.pos), vec3(b.pos), vec3(a.vel), vec3(b.vel), vec3(a.angVel), vec3(b.angVel)};
}

// What a law's kernel returns: the force on body 1 (body 2 gets its opposite) and the torques on
// both, added where `apply` is set.
template <class T> struct ContactForce {
    Vec3<T> f1, t1, t2;
    MaskOf<T> apply;
};

// The energy terms of O.energy (when O.trackEnergy), added lane by lane in lane order.
template <class T> struct LaneEnergy {
    EnergyTracker* tracker; // null: energy not tracked
    const bool* live;
    void add(int id, T value, MaskOf<T> where) const {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i] && lane(where, i)) tracker->add(id, lane(value, i));
    }
};

// A Law2 functor whose physics is a kernel. Derived provides
//   template <class T> ContactForce<T> kernel(const typename G::template Values<T>& geom, Rows<P, T>& phys,
//           const ContactBodies<T>& bodies, const LaneEnergy<T>& energy) const;  (a contact's forces)
//   bool separated(P& phys) const;  (the bodies separated: whether the contact stays)
// and gets go() and goBatch() (one contact at a time) from it. A law whose kernel also acts on a
// contact kept after its bodies separated (a viscous force) says so with computesApart().
template <class Derived, class G, class P> class LawKernelFunctor : public LawFunctor {
public:
    using GeomType = G;
    using PhysType = P;
    using KernelOf = Derived;
    bool computesApart() const { return false; }
    std::vector<std::string> argTypes() const override { return {registeredName<G>(), registeredName<P>()}; }
    bool go(IGeom& geom, IPhys& phys, Interaction& I) final {
        const BodyColumns cols{scene->bodies.hot().columns(), nullptr, nullptr};
        return one(static_cast<G&>(geom), static_cast<P&>(phys), I.id1, I.id2, cols);
    }
    void goBatch(const Contact* c, size_t n, char* keep) final {
        const BodyColumns cols{scene->bodies.hot().columns(), nullptr, nullptr};
        for (size_t j = 0; j < n; ++j)
            keep[j] = one(static_cast<G&>(*c[j].geom), static_cast<P&>(*c[j].phys), c[j].id1, c[j].id2, cols, c[j].shift);
    }

private:
    bool one(G& geom, P& phys, Body::id_t id1, Body::id_t id2, const BodyColumns& cols, const ContactShift* image = nullptr) {
        Derived& law = static_cast<Derived&>(*this);
        const auto values = G::template Values<Real>::of(geom);
        if (values.apart()) {
            const bool keep = law.separated(phys);
            if (!keep || !law.computesApart()) return keep;
        }
        const bool live[1] = {true};
        Rows<P, Real> rows{{&phys}, {true}};
        const ContactBodies<Real> bodies{cols, {{id1}}, {{id2}}, image};
        const LaneEnergy<Real> energy{scene->trackEnergy ? &scene->energy : nullptr, live};
        const ContactForce<Real> f = law.template kernel<Real>(values, rows, bodies, energy);
        if (f.apply) scene->forces.addContact(id1, id2, eigen(f.f1), eigen(f.t1), eigen(f.t2));
        return true;
    }
};

// The fast passes, by (Ig2 class, Law2 class).
class KernelPasses {
public:
    // The geometry then the forces of existing contacts c[0] .. c[n-1] (real, of the Ig2 functor's
    // shape types in its order, whose Law2 functor is `law`); keep[j] is the law's answer for c[j].
    using Pass = void (*)(IGeomFunctor& geom, LawFunctor& law, const BodyColumns& bodies, Contact* c, size_t n, char* keep);
    static bool add(std::type_index geom, std::type_index law, Pass pass);
    // The pass of exactly these classes (a subclass may compute otherwise), or null.
    static Pass find(const IGeomFunctor& geom, const LawFunctor& law);
};

// What the passes read a few contacts ahead.
constexpr size_t kernelLookahead = 8;
inline void prefetchLines(const void* p, int lines) {
    for (int l = 0; l < lines; ++l) __builtin_prefetch(static_cast<const char*>(p) + 64 * l);
}

// The pass of one (Ig2, Law2) pair. Ig2 provides
//   template <class T> typename G::template Values<T> batchKernel(const ContactBodies<T>&, Rows<G, T>& geom, Real dt) const;
// (an existing contact's geometry, written into its record).
template <class Ig2, class Law> struct KernelPass {
    using G = typename Law::GeomType;
    using P = typename Law::PhysType;
    static void run(IGeomFunctor& geomFunctor, LawFunctor& lawFunctor, const BodyColumns& b, Contact* c, size_t n, char* keep) {
        const Ig2& ig2 = static_cast<const Ig2&>(geomFunctor);
        Law& law = static_cast<Law&>(lawFunctor);
        Scene& s = *law.scene;
        Vector3r* const force = s.forces.inPlaceForces(); // (one thread: adds in place, as addContact would)
        Vector3r* const torque = s.forces.inPlaceTorques();
        if (__builtin_expect(s.isPeriodic, 0)) steps<true>(ig2, law, s, b, c, n, keep, force, torque);
        else steps<false>(ig2, law, s, b, c, n, keep, force, torque);
        if (force && n) s.forces.markAdded();
    }

private:
    // Periodic: the contacts may include pairs through the cell's faces (Contact::shift)
    template <bool Periodic>
    static void steps(const Ig2& ig2, Law& law, Scene& s, const BodyColumns& b, Contact* c, size_t n, char* keep, Vector3r* force, Vector3r* torque) {
        size_t j = 0;
        for (; j + 1 < n; j += 2) {
            for (size_t ahead = j + kernelLookahead; ahead < std::min(n, j + kernelLookahead + 2); ++ahead) prefetch(c[ahead], b);
            if (Periodic && (c[j].shift || c[j + 1].shift)) step<Two, true>(ig2, law, s, b, c + j, keep + j, force, torque);
            else step<Two>(ig2, law, s, b, c + j, keep + j, force, torque);
        }
        if (Periodic && j < n && c[j].shift) step<Real, true>(ig2, law, s, b, c + j, keep + j, force, torque);
        else if (j < n) step<Real>(ig2, law, s, b, c + j, keep + j, force, torque);
    }
    static void prefetch(const Contact& x, const BodyColumns& b) {
        prefetchLines(x.geom, (int)std::min<size_t>(4, (sizeof(G) + 63) / 64));
        prefetchLines(x.phys, (int)std::min<size_t>(6, (sizeof(P) + 63) / 64));
        for (const Body::id_t id : {x.id1, x.id2}) {
            __builtin_prefetch(&b.store.pos[id]);
            __builtin_prefetch(&b.store.vel[id]);
            __builtin_prefetch(&b.store.angVel[id]);
        }
    }
    // Shifted: a periodic scene's pairs through the cell's faces among them (Contact::shift; a lane
    // without one gets a zero shift)
    template <class T, bool Shifted = false>
    YADE_KERNEL static void step(const Ig2& ig2, Law& law, Scene& s, const BodyColumns& b, Contact* c, char* keep, Vector3r* force, Vector3r* torque) {
        constexpr int lanes = lanesOf<T>;
        ContactBodies<T> bodies{b, {}, {}};
        Vec3<T> images[2];
        if constexpr (Shifted) {
            for (int w = 0; w < 2; ++w) {
                auto part = [&](int axis) {
                    return eachLane<T>([&](int i) { return c[i].shift ? (w ? c[i].shift->shiftVel2 : c[i].shift->shift2)[axis] : Real(0); });
                };
                images[w] = Vec3<T>{part(0), part(1), part(2)};
            }
            bodies.lanes = images;
        }
        Rows<G, T> geom;
        Rows<P, T> phys;
        for (int i = 0; i < lanes; ++i) {
            bodies.id1.i[i] = c[i].id1;
            bodies.id2.i[i] = c[i].id2;
            geom.p[i] = static_cast<G*>(c[i].geom);
            geom.live[i] = true;
            phys.p[i] = static_cast<P*>(c[i].phys);
        }
        const auto values = ig2.template batchKernel<T>(bodies, geom, s.dt);
        const MaskOf<T> apart = values.apart();
        for (int i = 0; i < lanes; ++i) {
            phys.live[i] = !lane(apart, i);
            if (!phys.live[i]) phys.live[i] = (keep[i] = law.separated(*phys.p[i])) && law.computesApart();
        }
        if (!phys.anyLive()) return;
        const LaneEnergy<T> energy{s.trackEnergy ? &s.energy : nullptr, phys.live};
        const ContactForce<T> f = law.template kernel<T>(values, phys, bodies, energy);
        for (int i = 0; i < lanes; ++i) { // lane by lane, in order: as one contact at a time
            if (!phys.live[i]) continue;
            keep[i] = true;
            if (!lane(f.apply, i)) continue;
            const Vector3r F = f.f1.lane(i), T1 = f.t1.lane(i), T2 = f.t2.lane(i);
            const Body::id_t id1 = c[i].id1, id2 = c[i].id2;
            if (force) {
                force[id1] += F;
                torque[id1] += T1;
                force[id2] -= F;
                torque[id2] += T2;
            } else
                s.forces.addContact(id1, id2, F, T1, T2);
        }
    }
};

// The geometry kernels of an IGeom class (specialized where they are listed, e.g.
// pkg/dem/ScGeomKernels.hpp): GeomKernels<G>::List is a KernelList of Ig2 classes.
template <class... Ig2> struct KernelList {};
template <class G> struct GeomKernels {
    using List = KernelList<>;
};

template <class Law, class... Ig2> void registerKernelPasses(KernelList<Ig2...>) {
    (KernelPasses::add(typeid(Ig2), typeid(Law), &KernelPass<Ig2, Law>::run), ...);
}
// Called for every registered class (pkg/RegisterClasses.cpp): a Law2 functor written as a kernel
// gets its pass with every geometry kernel of its IGeom class, and nothing else has to be said.
template <class C, class = void> struct IsLawKernel : std::false_type {};
template <class C> struct IsLawKernel<C, std::void_t<typename C::KernelOf>> : std::is_same<typename C::KernelOf, C> {};
template <class Class> void registerKernelPassesOf() {
    if constexpr (IsLawKernel<Class>::value)
        registerKernelPasses<Class>(typename GeomKernels<typename Class::GeomType>::List{});
}

} // namespace yade
