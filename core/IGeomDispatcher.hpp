// Ig2 functors compute the contact geometry (IGeom) of two shapes; IGeomDispatcher picks one
// per pair of shape types, swapping the pair when only (Shape2, Shape1) is handled.
#pragma once
#include <core/Dispatcher.hpp>
#include <core/Interaction.hpp>
#include <core/LawDispatcher.hpp>

namespace yade {

// What a batch of contacts reads about the bodies, indexed by id: the store's columns, their
// shapes (null: none, or a hole) and the radii of spheres (NaN for other shapes).
struct BodyColumns {
    BodyStore::Columns store;
    const Shape* const* shape = nullptr;
    const Real* radius = nullptr;
};

class IGeomFunctor : public Functor {
public:
    static constexpr const char* classDoc = "Ig2 functor: computes the contact geometry (IGeom) of two shapes, or says there is no contact.";
    template <class V> void visit(V& v) { Functor::visit(v); }
    // Returns whether the shapes are in contact (always true with force=true for an existing
    // contact); creates or updates I.geom. shift2 is the periodic shift added to body 2.
    virtual bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2,
            bool force, Interaction& I);
    // A promise that lets the interaction loop skip a potential pair without calling go():
    // two spheres farther apart than this factor × (r1 + r2), or a sphere whose center is farther
    // than this factor × r from a facet's plane, are not in contact (negative: no such promise).
    virtual Real quickRejectFactor() const { return -1; }
    // The batched form: the geometry of the potential or real interactions c[0] .. c[n-1], all
    // of one pair of shape types taken in this functor's order; result[j] is go()'s answer for
    // c[j] (whose geom is set when the functor made one); in a periodic scene body 2 is the image the
    // contact says (Contact::shift). The default calls go() once per
    // contact (an adapter for functors written in the one-contact form); the library's functors
    // derive from IGeomFunctorBatched.
    virtual void goBatch(const BodyColumns& bodies, Contact* c, size_t n, char* result);
};

// A library Ig2 functor: Derived has a non-virtual
//   bool go(const S1&, const S2&, const Kinematics&, const Kinematics&, const Vector3r& shift2, bool force, Contact&)
// that reads the bodies' columns; goBatch() calls it in a loop with no virtual call per contact
// (Derived may replace goBatch, e.g. to read radii from BodyColumns instead of the shapes).
template <class Derived, class S1, class S2, class G> class IGeomFunctorBatched : public IGeomFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<S1>(), registeredName<S2>()}; }
    std::string producedType() const override { return registeredName<G>(); }
    // (not final: a subclass making another IGeom class, e.g. Ig2_Sphere_Sphere_ScGeom6D, replaces it)
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
            Interaction& I) override {
        Contact c(I);
        return self().Derived::go(static_cast<const S1&>(s1), static_cast<const S2&>(s2), st1.kinematics(), st2.kinematics(), shift2, force, c);
    }
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override {
        Derived& d = self();
        const BodyStore::Columns cols = b.store; // (locals: the char stores to result may alias anything in memory)
        const Shape* const* shape = b.shape;
        for (size_t j = 0; j < n; ++j) {
            Contact& x = c[j];
            if (__builtin_expect(x.shift != nullptr, 0)) {
                const Kinematics k2 = cols.kinematics(x.id2);
                const Vector3r pos2 = k2.pos + x.shift->shift2, vel2 = k2.vel + x.shift->shiftVel2;
                result[j] = d.Derived::go(static_cast<const S1&>(*shape[x.id1]), static_cast<const S2&>(*shape[x.id2]), cols.kinematics(x.id1),
                        Kinematics{pos2, vel2, k2.angVel, k2.ori}, Vector3r::Zero(), false, x);
            } else
                result[j] = d.Derived::go(static_cast<const S1&>(*shape[x.id1]), static_cast<const S2&>(*shape[x.id2]), cols.kinematics(x.id1),
                        cols.kinematics(x.id2), Vector3r::Zero(), false, x);
        }
    }

private:
    Derived& self() { return static_cast<Derived&>(*this); }
};

// A functor in the one-contact form (a user's own C++ functor): the typed go() is called once
// per contact through IGeomFunctor::goBatch, the adapter.
template <class S1, class S2, class G> class IGeomFunctorOf : public IGeomFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<S1>(), registeredName<S2>()}; }
    std::string producedType() const override { return registeredName<G>(); }
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
            Interaction& I) final {
        return go(static_cast<const S1&>(s1), static_cast<const S2&>(s2), st1, st2, shift2, force, I);
    }
    virtual bool go(const S1& s1, const S2& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
            Interaction& I) = 0;
};

class IGeomDispatcher : public Dispatcher {
public:
    static constexpr const char* classDoc = "Dispatcher of Ig2 functors: picks one per pair of Shape classes (swapping the pair when only the reverse order is handled).";
    std::vector<std::shared_ptr<IGeomFunctor>> functors;
    template <class V> void visit(V& v) {
        Dispatcher::visit(v);
        v.attr("functors", functors, "Ig2 functors, one per pair of shape types");
    }
    std::vector<std::shared_ptr<Functor>> functorsBase() const override { return {functors.begin(), functors.end()}; }
    void postLoad() override { table.invalidate(); }
    // Resolves all type pairs now (before a parallel loop reads the table); true if it had to.
    bool prepareTable() {
        if (table.isFilled()) return false;
        table.fill(functors, "Shape", "Shape", true);
        return true;
    }
    const DispatchTable2D<IGeomFunctor>::Entry& getFunctor(const Shape& a, const Shape& b) {
        return getFunctor(a.getClassIndex(), b.getClassIndex());
    }
    // By class indices (Shape::getClassIndex()), for loops that keep them in a column.
    const DispatchTable2D<IGeomFunctor>::Entry& getFunctor(int index1, int index2) {
        return table.get(index1, index2, functors, "Shape", "Shape", true);
    }

private:
    DispatchTable2D<IGeomFunctor> table;
};

} // namespace yade
