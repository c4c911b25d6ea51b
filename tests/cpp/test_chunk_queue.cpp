// ChunkQueue: the owner takes chunks from the front, others from the back; every chunk is taken
// exactly once, the others' chunks are a suffix, and done flags publish their results.
#include <atomic>
#include <gtest/gtest.h>
#include <lib/base/ChunkQueue.hpp>
#include <thread>
#include <vector>

using namespace yade;

TEST(ChunkQueue, OwnerAloneTakesEveryChunkInOrder) {
    ChunkQueue q;
    q.reset(5);
    EXPECT_TRUE(q.published());
    unsigned c, expected = 0;
    while (q.takeFront(c)) EXPECT_EQ(c, expected++);
    EXPECT_EQ(expected, 5u);
    EXPECT_EQ(q.stolenFrom(), 5u);
    unsigned none;
    EXPECT_FALSE(q.takeBack(none));
    q.reset(0);
    EXPECT_FALSE(q.takeFront(none));
    EXPECT_EQ(q.stolenFrom(), 0u);
}

TEST(ChunkQueue, ConcurrentTakersGetDisjointChunksAndTheOthersASuffix) {
    for (int round = 0; round < 200; ++round) {
        const unsigned n = 1 + round % 40;
        ChunkQueue q;
        q.reset(n);
        std::vector<std::atomic<int>> takenBy(n);
        for (auto& t : takenBy) t.store(0);
        std::vector<unsigned> ownerOrder;
        std::thread thief([&] {
            unsigned c;
            while (q.takeBack(c)) {
                takenBy[c].fetch_add(2);
                q.markDone(c);
            }
        });
        unsigned c;
        while (q.takeFront(c)) {
            takenBy[c].fetch_add(1);
            ownerOrder.push_back(c);
        }
        const unsigned from = q.stolenFrom();
        for (unsigned k = from; k < n; ++k) q.waitDone(k); // (returns once the thief marked them)
        thief.join();
        ASSERT_EQ(ownerOrder.size(), (size_t)from);
        for (unsigned k = 0; k < n; ++k) {
            EXPECT_EQ(takenBy[k].load(), k < from ? 1 : 2) << "chunk " << k << " of " << n; // exactly once each
            if (k < from) {
                EXPECT_EQ(ownerOrder[k], k);
            }
        }
    }
}
