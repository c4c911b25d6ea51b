// A growable array whose elements never move: the whole capacity is reserved as address space
// once (untouched pages cost no memory), so a pointer or a Python view into it stays valid as
// long as the array lives, however many elements are appended later. Contiguous, so that hot
// loops and NumPy views read it as a plain array. For trivially copyable records only.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <new>
#include <stdexcept>
#include <string>
#include <sys/mman.h>
#include <type_traits>

namespace yade {

template <class T> class StableArray {
    static_assert(std::is_trivially_destructible_v<T>, "StableArray holds plain records (never destroyed one by one)");

public:
    // The address space is reserved inaccessible and made writable as the array grows, so that
    // only what is used counts against the system's memory commitment.
    // Each array starts a different number of cache lines into its first page: arrays that all
    // start on a page boundary map entry i of every column to the same cache set, and a loop over
    // a dozen columns then evicts its own lines (the caches have 8 to 16 ways).
    // Where the address space is limited (ulimit -v), the reservation is halved until it fits.
    explicit StableArray(size_t maxElements) : capacity(maxElements) {
        static std::atomic<unsigned> arrays{0};
        offset = 64 * ((arrays++ * 23) % 64);
        void* p = MAP_FAILED;
        for (; capacity >= 4096; capacity /= 2) {
            p = mmap(nullptr, bytes() + offset, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
            if (p != MAP_FAILED) break;
        }
        if (p == MAP_FAILED) throw std::bad_alloc();
        base = static_cast<char*>(p);
        items = reinterpret_cast<T*>(base + offset);
    }
    ~StableArray() { munmap(base, bytes() + offset); }
    StableArray(const StableArray&) = delete;
    StableArray& operator=(const StableArray&) = delete;

    size_t size() const { return count; }
    size_t maxSize() const { return capacity; }
    T* data() { return items; }
    const T* data() const { return items; }
    T& operator[](size_t i) { return items[i]; }
    const T& operator[](size_t i) const { return items[i]; }
    // New elements get `fill`; shrinking keeps the memory (the addresses stay valid).
    void resize(size_t n, const T& fill = T()) {
        if (n > capacity) throw std::length_error("more than " + std::to_string(capacity) + " entries (the address space reserved for them)");
        if (offset + n * sizeof(T) > usable) { // in steps of 1 MiB
            const size_t want = std::min(bytes() + offset, (offset + n * sizeof(T) + step - 1) / step * step);
            if (mprotect(base, want, PROT_READ | PROT_WRITE) != 0) throw std::bad_alloc();
            usable = want;
        }
        for (size_t i = count; i < n; ++i) new (items + i) T(fill);
        count = n;
    }
    void push_back(const T& x) {
        resize(count + 1, x);
    }

private:
    size_t bytes() const { return capacity * sizeof(T); }
    char* base = nullptr; // the mapping
    size_t offset = 0;    // where items start in it
    T* items = nullptr;
    size_t count = 0, capacity;
    size_t usable = 0; // bytes of the mapping made writable
    static constexpr size_t step = size_t(1) << 20;
};

} // namespace yade
