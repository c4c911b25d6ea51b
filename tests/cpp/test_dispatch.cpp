// Dispatch tables: class indices, lookup falling back to base classes, symmetric swap.
#include <core/BoundDispatcher.hpp>
#include <core/IGeomDispatcher.hpp>
#include <gtest/gtest.h>
#include <pkg/RegisterClasses.hpp>
#include <pkg/common/Bo1_Sphere_Aabb.hpp>
#include <pkg/common/FrictMat.hpp>

using namespace yade;

namespace {
class SubSphere : public Sphere {
public:
    template <class V> void visit(V& v) { Sphere::visit(v); }
    YADE_INDEXABLE(SubSphere)
};
class TestIg2_Sphere_Shape : public IGeomFunctorOf<Sphere, Shape, IGeom> {
public:
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Sphere&, const Shape&, const State&, const State&, const Vector3r&, bool, Interaction&) override { return true; }
};

void registerTestClasses() {
    registerAllClasses();
    static bool done = false;
    if (done) return;
    done = true;
    ClassRegistry::instance().add<SubSphere, Sphere>("SubSphere");
    ClassRegistry::instance().add<TestIg2_Sphere_Shape, IGeomFunctor>("TestIg2_Sphere_Shape");
}
} // namespace

TEST(ClassIndex, EachShapeClassHasItsOwnIndexAndParent) {
    registerTestClasses();
    auto& reg = ClassRegistry::instance();
    EXPECT_EQ(Shape::classIndexStatic(), 0);
    EXPECT_GT(Sphere::classIndexStatic(), 0);
    EXPECT_NE(SubSphere::classIndexStatic(), Sphere::classIndexStatic());
    EXPECT_EQ(reg.parentIndex("Shape", SubSphere::classIndexStatic()), Sphere::classIndexStatic());
    EXPECT_EQ(reg.parentIndex("Shape", Sphere::classIndexStatic()), Shape::classIndexStatic());
    EXPECT_EQ(reg.parentIndex("Shape", Shape::classIndexStatic()), -1);
    SubSphere s;
    const Shape& asShape = s;
    EXPECT_EQ(asShape.getClassIndex(), SubSphere::classIndexStatic());
}

TEST(BoundDispatcher, FallsBackToBaseClassFunctor) {
    registerTestClasses();
    BoundDispatcher d;
    auto bo1 = std::make_shared<Bo1_Sphere_Aabb>();
    d.functors = {bo1};
    EXPECT_EQ(d.getFunctor(Sphere()), bo1.get());
    EXPECT_EQ(d.getFunctor(SubSphere()), bo1.get()); // SubSphere -> Sphere
    EXPECT_EQ(d.getFunctor(Shape()), nullptr);       // nothing handles the base class
}

TEST(BoundDispatcher, ComputesSphereAabb) {
    registerTestClasses();
    BoundDispatcher d;
    d.functors = {std::make_shared<Bo1_Sphere_Aabb>()};
    Body b;
    auto s = std::make_shared<Sphere>();
    s->radius = 0.5;
    b.shape = s;
    b.state->pos() = Vector3r(1, 2, 3);
    d.getFunctor(*s)->go(*s, b.bound, *b.state, b);
    ASSERT_TRUE(b.bound);
    EXPECT_EQ(b.bound->min, Vector3r(0.5, 1.5, 2.5));
    EXPECT_EQ(b.bound->max, Vector3r(1.5, 2.5, 3.5));
}

TEST(IGeomDispatcher, SymmetricLookupWithBaseFallbackAndSwap) {
    registerTestClasses();
    IGeomDispatcher d;
    auto f = std::make_shared<TestIg2_Sphere_Shape>();
    d.functors = {f};
    Sphere sp;
    SubSphere sub;
    Shape base;
    auto e1 = d.getFunctor(sub, sp); // (SubSphere,Sphere) -> (Sphere,Shape) directly
    EXPECT_EQ(e1.functor, f.get());
    EXPECT_FALSE(e1.swap);
    auto e2 = d.getFunctor(base, sp); // only (Sphere,Shape) exists: swapped
    EXPECT_EQ(e2.functor, f.get());
    EXPECT_TRUE(e2.swap);
    auto e3 = d.getFunctor(base, base);
    EXPECT_EQ(e3.functor, nullptr);
    d.functors.clear();
    d.postLoad(); // the table is rebuilt after the functors change
    EXPECT_EQ(d.getFunctor(sub, sp).functor, nullptr);
}

TEST(ClassRegistry, AttributesAreDeclaredOnceAndInherited) {
    registerTestClasses();
    const ClassInfo* fm = ClassRegistry::instance().find("FrictMat");
    ASSERT_NE(fm, nullptr);
    std::vector<std::string> names;
    for (const auto& a : fm->attrs) names.push_back(a.name);
    EXPECT_EQ(names, (std::vector<std::string>{"id", "label", "density", "young", "poisson", "frictionAngle"}));
    EXPECT_EQ(fm->ownAttrsBegin, 5u);
    auto obj = ClassRegistry::instance().create("FrictMat");
    const AttrInfo* young = fm->findAttr("young");
    *static_cast<Real*>(young->address(*obj)) = 3e9;
    EXPECT_EQ(std::dynamic_pointer_cast<FrictMat>(obj)->young, 3e9);
    EXPECT_TRUE(ClassRegistry::instance().isSubclass("FrictMat", "Material"));
    EXPECT_FALSE(ClassRegistry::instance().isSubclass("Material", "FrictMat"));
}
