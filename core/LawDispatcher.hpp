// Law2 functors (constitutive laws) turn IGeom + IPhys into forces; LawDispatcher picks one
// per (IGeom type, IPhys type).
#pragma once
#include <core/Dispatcher.hpp>
#include <core/Interaction.hpp>

namespace yade {

class LawFunctor : public Functor {
public:
    static constexpr const char* classDoc = "Law2 functor (constitutive law): turns a contact's IGeom and IPhys into forces and torques on its two bodies.";
    template <class V> void visit(V& v) { Functor::visit(v); }
    // Applies forces on both bodies; returns false when the interaction must be removed.
    virtual bool go(IGeom& geom, IPhys& phys, Interaction& I);
    // The batched form: forces of the real contacts c[0] .. c[n-1], all of this functor's
    // (IGeom, IPhys) types, in this order; keep[j] is go()'s answer for c[j]. The default calls
    // go() once per contact (an adapter for the one-contact form); the library's functors
    // derive from LawFunctorBatched.
    virtual void goBatch(const Contact* c, size_t n, char* keep);
};

// A library Law2 functor: Derived has a non-virtual bool go(G&, P&, const Contact&), called in a
// loop by goBatch() with no virtual call per contact.
template <class Derived, class G, class P> class LawFunctorBatched : public LawFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<G>(), registeredName<P>()}; }
    bool go(IGeom& geom, IPhys& phys, Interaction& I) final {
        return self().Derived::go(static_cast<G&>(geom), static_cast<P&>(phys), Contact(&I, &geom, &phys, I.id1, I.id2));
    }
    void goBatch(const Contact* c, size_t n, char* keep) final {
        Derived& d = self();
        for (size_t j = 0; j < n; ++j) keep[j] = d.Derived::go(static_cast<G&>(*c[j].geom), static_cast<P&>(*c[j].phys), c[j]);
    }

private:
    Derived& self() { return static_cast<Derived&>(*this); }
};

// A functor in the one-contact form (a user's own C++ functor), called once per contact through
// LawFunctor::goBatch, the adapter.
template <class G, class P> class LawFunctorOf : public LawFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<G>(), registeredName<P>()}; }
    bool go(IGeom& geom, IPhys& phys, Interaction& I) final { return go(static_cast<G&>(geom), static_cast<P&>(phys), I); }
    virtual bool go(G& geom, P& phys, Interaction& I) = 0;
};

class LawDispatcher : public Dispatcher {
public:
    static constexpr const char* classDoc = "Dispatcher of Law2 functors: picks one per (IGeom class, IPhys class) pair.";
    std::vector<std::shared_ptr<LawFunctor>> functors;
    template <class V> void visit(V& v) {
        Dispatcher::visit(v);
        v.attr("functors", functors, "Law2 functors, one per (IGeom, IPhys) pair");
    }
    std::vector<std::shared_ptr<Functor>> functorsBase() const override { return {functors.begin(), functors.end()}; }
    void postLoad() override { table.invalidate(); }
    // Resolves all type pairs now (before a parallel loop reads the table); true if it had to.
    bool prepareTable() {
        if (table.isFilled()) return false;
        table.fill(functors, "IGeom", "IPhys", false);
        return true;
    }
    const DispatchTable2D<LawFunctor>::Entry& getFunctor(const IGeom& g, const IPhys& p) {
        return table.get(g.getClassIndex(), p.getClassIndex(), functors, "IGeom", "IPhys", false);
    }
    long long tableGeneration() const { return table.generation(); }

private:
    DispatchTable2D<LawFunctor> table;
};

} // namespace yade
