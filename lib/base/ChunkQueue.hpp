// The chunks of one thread's share of a parallel loop, for deterministic work stealing: the
// owning thread takes chunks from the front, other threads that have finished their own take
// what is left from the back. The chunks a thread did not take are then a suffix
// [stolenFrom(), count()), and each is marked done() by whoever computed it; the owner can wait
// for them and use their results in chunk order, so that the outcome does not depend on who
// computed what.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>

namespace yade {

class ChunkQueue {
public:
    // A new round of n chunks, none taken (by the owner, or by any thread before the parallel region).
    void reset(unsigned n) {
        if (n > capacity) {
            doneFlags.reset(new std::atomic<char>[n]);
            capacity = n;
        }
        for (unsigned c = 0; c < n; ++c) doneFlags[c].store(0, std::memory_order_relaxed);
        chunks = n;
        span.store(pack(0, n), std::memory_order_relaxed);
        ready.store(true, std::memory_order_release);
    }
    void unpublish() { ready.store(false, std::memory_order_relaxed); } // (before the parallel region)
    bool published() const { return ready.load(std::memory_order_acquire); }
    unsigned count() const { return chunks; }
    // The next chunk from the front (owner) or from the back (others); false when none is left.
    bool takeFront(unsigned& chunk) { return take(chunk, true); }
    bool takeBack(unsigned& chunk) { return take(chunk, false); }
    // After takeFront() failed: the first chunk that others took.
    unsigned stolenFrom() const { return (unsigned)(span.load(std::memory_order_acquire) >> 32); }
    void markDone(unsigned chunk) { doneFlags[chunk].store(1, std::memory_order_release); }
    void waitDone(unsigned chunk) const {
        while (!doneFlags[chunk].load(std::memory_order_acquire)) std::this_thread::yield();
    }

private:
    static uint64_t pack(uint64_t front, uint64_t back) { return (front << 32) | back; }
    bool take(unsigned& chunk, bool front) {
        uint64_t v = span.load(std::memory_order_acquire);
        for (;;) {
            const uint64_t f = v >> 32, b = v & 0xffffffffu;
            if (f >= b) return false;
            const uint64_t next = front ? pack(f + 1, b) : pack(f, b - 1);
            if (span.compare_exchange_weak(v, next, std::memory_order_acq_rel)) {
                chunk = (unsigned)(front ? f : b - 1);
                return true;
            }
        }
    }
    alignas(64) std::atomic<uint64_t> span{0}; // front << 32 | back: chunks [front, back) not taken
    std::atomic<bool> ready{false};
    std::unique_ptr<std::atomic<char>[]> doneFlags;
    unsigned chunks = 0, capacity = 0;
};

} // namespace yade
