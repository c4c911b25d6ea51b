// Ig2 functors compute the contact geometry (IGeom) of two shapes; IGeomDispatcher picks one
// per pair of shape types, swapping the pair when only (Shape2, Shape1) is handled.
#pragma once
#include <core/Dispatcher.hpp>
#include <core/Interaction.hpp>

namespace yade {

class IGeomFunctor : public Functor {
public:
    template <class V> void visit(V& v) { Functor::visit(v); }
    // Returns whether the shapes are in contact (always true with force=true for an existing
    // contact); creates or updates I.geom. shift2 is the periodic shift added to body 2.
    virtual bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2,
            bool force, Interaction& I);
    // A promise that lets the interaction loop skip a potential pair without calling go():
    // two spheres farther apart than this factor × (r1 + r2), or a sphere whose center is farther
    // than this factor × r from a facet's plane, are not in contact (negative: no such promise).
    virtual Real quickRejectFactor() const { return -1; }
};

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
        return table.get(a.getClassIndex(), b.getClassIndex(), functors, "Shape", "Shape", true);
    }

private:
    DispatchTable2D<IGeomFunctor> table;
};

} // namespace yade
