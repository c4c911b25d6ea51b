// The interaction loop's batched dispatch: a user's functors written in the one-contact form
// (IGeomFunctorOf, LawFunctorOf) run through the adapters and give the same forces, bit for bit, as
// the library's batched functors; State objects are views of the body store.
#include <core/Scene.hpp>
#include <gtest/gtest.h>
#include <pkg/RegisterClasses.hpp>
#include <pkg/common/ForceResetter.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/common/InteractionLoop.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/Ip2_FrictMat_FrictMat_FrictPhys.hpp>
#include <pkg/dem/Law2_ScGeom_FrictPhys_CundallStrack.hpp>

using namespace yade;

namespace {
// The one-contact form, delegating to the library's functors one contact at a time.
class OldIg2 : public IGeomFunctorOf<Sphere, Sphere, ScGeom> {
public:
    Ig2_Sphere_Sphere_ScGeom inner;
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Sphere& s1, const Sphere& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
            Interaction& I) override {
        ++calls;
        inner.scene = scene;
        return static_cast<IGeomFunctor&>(inner).go(s1, s2, st1, st2, shift2, force, I);
    }
    int calls = 0;
};
class OldLaw : public LawFunctorOf<ScGeom, FrictPhys> {
public:
    Law2_ScGeom_FrictPhys_CundallStrack inner;
    template <class V> void visit(V& v) { LawFunctor::visit(v); }
    bool go(ScGeom& g, FrictPhys& p, Interaction& I) override {
        ++calls;
        inner.scene = scene;
        return static_cast<LawFunctor&>(inner).go(g, p, I);
    }
    int calls = 0;
};

void registerTestClasses() {
    registerAllClasses();
    static bool done = false;
    if (done) return;
    done = true;
    ClassRegistry::instance().add<OldIg2, IGeomFunctor>("OldIg2");
    ClassRegistry::instance().add<OldLaw, LawFunctor>("OldLaw");
}

// A row of overlapping spheres with some velocities and spins; returns the forces after `steps` loop passes.
std::vector<Vector3r> forcesAfter(std::shared_ptr<IGeomFunctor> ig2, std::shared_ptr<LawFunctor> law, int steps) {
    Scene s;
    s.setThreads(1);
    auto mat = std::make_shared<FrictMat>();
    mat->young = 1e7;
    for (int i = 0; i < 6; ++i) {
        auto b = std::make_shared<Body>();
        auto sh = std::make_shared<Sphere>();
        sh->radius = 0.01;
        b->shape = sh;
        b->material = mat;
        b->state->pos() = Vector3r(0.0195 * i, 0.001 * (i % 2), 0);
        b->state->vel() = Vector3r(0.01 * i, 0, -0.02 * (i % 3));
        b->state->angVel() = Vector3r(1, -2, 0.5 * i);
        s.appendBody(b);
    }
    for (int i = 0; i + 1 < 6; ++i) s.interactions.insert(std::make_shared<Interaction>(i, i + 1));
    auto loop = std::make_shared<InteractionLoop>();
    loop->geomDispatcher->functors = {ig2};
    loop->physDispatcher->functors = {std::make_shared<Ip2_FrictMat_FrictMat_FrictPhys>()};
    loop->lawDispatcher->functors = {law};
    loop->scene = &s;
    s.forces.resize(s.bodies.size());
    std::vector<Vector3r> f;
    for (int k = 0; k < steps; ++k) {
        s.forces.reset();
        loop->action();
        for (size_t id = 0; id < s.bodies.size(); ++id) s.bodies.hot().pos[id] += 1e-6 * s.bodies.hot().vel[id]; // (a move between passes)
        ++s.iter;
    }
    s.forces.sync();
    for (size_t id = 0; id < s.bodies.size(); ++id) {
        f.push_back(s.forces.getForce((int)id));
        f.push_back(s.forces.getTorque((int)id));
    }
    return f;
}
} // namespace

TEST(BatchedDispatch, OneContactFunctorsRunThroughTheAdaptersWithTheSameForces) {
    registerTestClasses();
    auto oldIg2 = std::make_shared<OldIg2>();
    auto oldLaw = std::make_shared<OldLaw>();
    const auto batched = forcesAfter(std::make_shared<Ig2_Sphere_Sphere_ScGeom>(), std::make_shared<Law2_ScGeom_FrictPhys_CundallStrack>(), 5);
    const auto adapted = forcesAfter(oldIg2, oldLaw, 5);
    EXPECT_EQ(oldIg2->calls, 5 * 5); // every pair at every pass, one call each (no quick reject: OldIg2 makes no promise)
    EXPECT_GE(oldLaw->calls, 20);    // every live contact at every pass (one pair separates on the way)
    EXPECT_LE(oldLaw->calls, 25);
    ASSERT_EQ(batched.size(), adapted.size());
    Real largest = 0;
    for (size_t i = 0; i < batched.size(); ++i) {
        EXPECT_EQ(batched[i], adapted[i]) << "entry " << i;
        largest = std::max(largest, batched[i].norm());
    }
    EXPECT_GT(largest, 1.0); // (the contacts do push)
}

TEST(BodyStore, StateIsAViewWhileItsBodyIsInTheScene) {
    registerTestClasses();
    Scene s;
    auto b = std::make_shared<Body>();
    b->state->pos() = Vector3r(1, 2, 3);
    s.appendBody(b);
    EXPECT_EQ(s.bodies.hot().pos[0], Vector3r(1, 2, 3));
    s.bodies.hot().vel[0] = Vector3r(4, 5, 6);
    EXPECT_EQ(b->state->vel(), Vector3r(4, 5, 6));
    const AttrInfo* pos = ClassRegistry::instance().get(typeid(State)).findAttr("pos");
    *static_cast<Vector3r*>(pos->address(*b->state)) = Vector3r(7, 8, 9); // as Python and the loader write it
    EXPECT_EQ(s.bodies.hot().pos[0], Vector3r(7, 8, 9));
    auto st = b->state;
    s.eraseBody(0);
    EXPECT_FALSE(s.bodies.hot().exists[0]);
    EXPECT_EQ(st->pos(), Vector3r(7, 8, 9)); // its own copy again
    EXPECT_EQ(st->vel(), Vector3r(4, 5, 6));
}
