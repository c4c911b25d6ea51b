// ContactPool: records constructed in place, compact after removals (the last record fills the
// hole), ended contacts removed by InteractionContainer::sweep with their pairs relinked, and a
// view object following its record and keeping its last values when the contact ends.
#include <core/InteractionContainer.hpp>
#include <gtest/gtest.h>
#include <pkg/RegisterClasses.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>

using namespace yade;

namespace {
const ClassInfo& info(const std::type_info& t) { return ClassRegistry::instance().get(t); }

ScGeom geomWithDepth(Real d) {
    ScGeom g;
    g.penetrationDepth = d;
    return g;
}
} // namespace

TEST(ContactPool, RecordsAreCompactAfterRemovalsAndKeepTheirValues) {
    registerAllClasses();
    ContactPool pool(info(typeid(ScGeom)), info(typeid(FrictPhys)));
    FrictPhys p;
    for (int i = 0; i < 5; ++i) {
        p.kn = 100 + i;
        const size_t slot = pool.append(ContactPool::Header{i, i + 1, (uint32_t)i, 0, 7}, geomWithDepth(0.1 * i), p);
        EXPECT_EQ(slot, (size_t)i);
    }
    EXPECT_EQ(pool.size(), 5u);
    EXPECT_EQ(pool.stride % alignof(ScGeom), 0u);
    // the record of slot 1 leaves: the last one (slot 4) moves into it
    EXPECT_TRUE(pool.removeAt(1));
    EXPECT_EQ(pool.size(), 4u);
    EXPECT_EQ(pool.header(1).k, 4u);
    EXPECT_EQ(pool.header(1).id1, 4);
    EXPECT_DOUBLE_EQ(static_cast<ScGeom*>(pool.geom(1))->penetrationDepth, 0.4);
    EXPECT_DOUBLE_EQ(static_cast<FrictPhys*>(pool.phys(1))->kn, 104);
    EXPECT_EQ(pool.geom(1)->getClassIndex(), ScGeom::classIndexStatic()); // (a live object of its class)
    EXPECT_FALSE(pool.removeAt(3)); // the last one: nothing moves
    EXPECT_EQ(pool.size(), 3u);
}

TEST(ContactPool, EndedContactsLeaveAtTheSweepAndViewsFollowTheirRecord) {
    registerAllClasses();
    InteractionContainer intrs;
    for (int i = 0; i < 6; ++i) intrs.insertPotential(i, i + 1);
    intrs.prepareRecords();
    for (size_t k = 0; k < 6; ++k) {
        auto g = std::make_shared<ScGeom>(geomWithDepth(0.01 * (double)k));
        auto p = std::make_shared<FrictPhys>();
        intrs.makeContact(k, g, p, 3);
    }
    EXPECT_EQ(intrs.countReal(), 6u);
    // Python holds the object of pair 5 and its geometry (a view of the record)
    auto I = intrs[5];
    auto view = I->geom;
    EXPECT_NE(view->viewTarget(), nullptr);
    EXPECT_EQ(intrs.iterMadeReal(5), 3);
    // pairs 0 and 1 end in the loop; their records leave at the sweep and pair 5's record moves
    intrs.endContact(0);
    intrs.endContact(1);
    EXPECT_FALSE(intrs.isReal(0));
    intrs.sweep();
    EXPECT_EQ(intrs.pools[0]->size(), 4u);
    for (size_t k = 2; k < 6; ++k) {
        ASSERT_TRUE(intrs.isReal(k));
        EXPECT_DOUBLE_EQ(static_cast<ScGeom*>(intrs.geom(k))->penetrationDepth, 0.01 * (double)k);
        EXPECT_EQ(intrs.pool(intrs.contactOf[k]).header(InteractionContainer::slotOf(intrs.contactOf[k])).k, k);
    }
    EXPECT_EQ(view->viewTarget(), intrs.geom(5)); // the view followed its record
    static_cast<ScGeom*>(intrs.geom(5))->penetrationDepth = 0.5;
    intrs.endContact(5);
    intrs.sweep();
    EXPECT_EQ(view->viewTarget(), nullptr); // detached, with the last values
    EXPECT_DOUBLE_EQ(std::static_pointer_cast<ScGeom>(view)->penetrationDepth, 0.5);
    EXPECT_FALSE(I->isReal()); // the held object was reset
}

TEST(ContactPool, OrderingFollowsTheListsAndKeepsEachContactsValues) {
    registerAllClasses();
    InteractionContainer intrs;
    for (int i = 0; i < 8; ++i) intrs.insertPotential(i, i + 1);
    intrs.prepareRecords();
    for (size_t k = 0; k < 8; ++k) intrs.makeContact(k, std::make_shared<ScGeom>(geomWithDepth(0.01 * (double)k)), std::make_shared<FrictPhys>(), 1);
    auto I = intrs[2];
    auto view = I->geom;
    // two thread lists: the odd pairs, then the even ones, each backwards
    intrs.orderPools({{7, 5, 3, 1}, {6, 4, 2, 0}});
    const ContactPool& P = *intrs.pools[0];
    const std::vector<uint32_t> expected{7, 5, 3, 1, 6, 4, 2, 0};
    for (size_t slot = 0; slot < P.size(); ++slot) {
        EXPECT_EQ(P.header(slot).k, expected[slot]);
        EXPECT_EQ(InteractionContainer::slotOf(intrs.contactOf[expected[slot]]), slot);
        EXPECT_DOUBLE_EQ(static_cast<ScGeom*>(P.geom(slot))->penetrationDepth, 0.01 * expected[slot]);
    }
    EXPECT_EQ(view->viewTarget(), intrs.geom(2)); // the view followed
    EXPECT_EQ(P.appendsSinceOrder, 0u);
    EXPECT_EQ(P.movesSinceOrder, 0u);
}

TEST(ContactPool, NeedsOrderAfterManyAppendsOrWhenALargePoolDrifted) {
    registerAllClasses();
    ContactPool pool(info(typeid(ScGeom)), info(typeid(FrictPhys)));
    const FrictPhys p;
    const ScGeom g;
    auto identity = [&pool] {
        std::vector<uint32_t> to(pool.size());
        for (size_t s = 0; s < to.size(); ++s) to[s] = (uint32_t)s;
        pool.permute(to);
    };
    for (int i = 0; i < 1000; ++i) pool.append(ContactPool::Header{i, i + 1, (uint32_t)i, 0, 0}, g, p);
    EXPECT_FALSE(pool.needsOrder()); // (small pools: not worth it)
    for (int i = 1000; i < 2000; ++i) pool.append(ContactPool::Header{i, i + 1, (uint32_t)i, 0, 0}, g, p);
    EXPECT_TRUE(pool.needsOrder()); // many appended since the last order
    identity();
    EXPECT_FALSE(pool.needsOrder());
    EXPECT_EQ(pool.appendsSinceOrder + pool.movesSinceOrder, 0u);
    // a pool beyond 8 MB in order, then records moved into the slots of removed ones
    const size_t large = (size_t(9) << 20) / pool.stride; // (above 8 MB also after the removals)
    for (size_t i = pool.size(); i < large; ++i) pool.append(ContactPool::Header{(int)i, (int)i + 1, (uint32_t)i, 0, 0}, g, p);
    identity();
    size_t moved = 0;
    for (size_t s = 0; 16 * moved <= large - moved; s += 2) moved += pool.removeAt(s);
    EXPECT_EQ(pool.movesSinceOrder, moved);
    EXPECT_TRUE(pool.needsOrder()); // one record in 16 out of place
    identity();
    EXPECT_FALSE(pool.needsOrder());
    pool.removeAt(0); // one more moved: far from one in 16
    EXPECT_FALSE(pool.needsOrder());
}
