// Dispatchers pick a functor by the class indices of its arguments (1.2.1). The choice for a
// pair of indices is looked up once (falling back to base classes) and kept in a table.
#pragma once
#include <core/Engine.hpp>
#include <core/Functor.hpp>
#include <atomic>

namespace yade {

class Dispatcher : public Engine {
public:
    static constexpr const char* classDoc = "Engine that picks a functor by the classes of its arguments (1.2.1), falling back to base classes.";
    template <class V> void visit(V& v) { Engine::visit(v); }
    // Functors as the base type, for label lookup and chain checks.
    virtual std::vector<std::shared_ptr<Functor>> functorsBase() const { return {}; }
    // Each rebuild of a table gets a new generation number; interactions cache functors with it.
    static long long newGeneration() {
        static std::atomic<long long> counter{0};
        return ++counter;
    }
};

// Index of the class named `name` in `family`, or throws naming both.
int familyIndexOf(const std::string& family, const std::string& name);
// Chain of indices from a class up to its family root.
std::vector<int> classChain(const std::string& family, int index);

// Dispatch on one argument (Bo1 functors).
template <class F> class DispatchTable1D {
public:
    void invalidate() { table.clear(); }
    // Resolves every class of the family now, so that get() only reads (parallel loops).
    void fill(const std::vector<std::shared_ptr<F>>& functors, const char* family) {
        if (table.empty()) table.assign(ClassRegistry::instance().familySize(family), unresolved());
        for (int i = 0; i < (int)table.size(); ++i) get(i, functors, family);
    }
    // (family names as C strings: the look-up runs per body or contact, a std::string per call costs)
    F* get(int index, const std::vector<std::shared_ptr<F>>& functors, const char* family) {
        if (table.empty()) table.assign(ClassRegistry::instance().familySize(family), unresolved());
        if (index < 0 || index >= (int)table.size()) return nullptr;
        F*& slot = table[index];
        if (slot == unresolved()) slot = resolve(index, functors, family);
        return slot;
    }

private:
    static F* unresolved() { return reinterpret_cast<F*>(std::uintptr_t(1)); }
    std::vector<F*> table;
    static F* resolve(int index, const std::vector<std::shared_ptr<F>>& functors, const std::string& family) {
        for (int c : classChain(family, index))
            for (const auto& f : functors)
                if (f && familyIndexOf(family, f->argTypes().at(0)) == c) return f.get();
        return nullptr;
    }
};

// Dispatch on two arguments (Ig2, Ip2, Law2 functors); `symmetric` allows a functor for (B,A)
// to serve (A,B) with its arguments swapped.
template <class F> class DispatchTable2D {
public:
    struct Entry {
        F* functor = nullptr;
        bool swap = false;
        bool resolved = false;
    };
    void invalidate() { table.clear(); }
    bool isFilled() const { return !table.empty(); }
    // Unique to each filling of each table (for caches of the functors it chose).
    long long generation() const { return filled; }
    // Resolves every pair at once, so that get() only reads (safe from several threads).
    void fill(const std::vector<std::shared_ptr<F>>& functors, const char* family1, const char* family2, bool symmetric) {
        table.clear();
        filled = Dispatcher::newGeneration();
        for (int i = 0; i < ClassRegistry::instance().familySize(family1); ++i)
            for (int j = 0; j < ClassRegistry::instance().familySize(family2); ++j) get(i, j, functors, family1, family2, symmetric);
    }
    // (family names as C strings: the look-up runs per contact, a std::string per call costs)
    const Entry& get(int i1, int i2, const std::vector<std::shared_ptr<F>>& functors, const char* family1, const char* family2,
            bool symmetric) {
        static const Entry noneEntry{nullptr, false, true};
        if (table.empty()) {
            filled = Dispatcher::newGeneration();
            n1 = ClassRegistry::instance().familySize(family1);
            n2 = ClassRegistry::instance().familySize(family2);
            table.assign((size_t)n1 * n2, Entry());
        }
        if (i1 < 0 || i2 < 0 || i1 >= n1 || i2 >= n2) return noneEntry;
        Entry& e = table[(size_t)i1 * n2 + i2];
        if (!e.resolved) e = resolve(i1, i2, functors, family1, family2, symmetric);
        return e;
    }

private:
    std::vector<Entry> table;
    int n1 = 0, n2 = 0;
    long long filled = -1;
    static Entry resolve(int i1, int i2, const std::vector<std::shared_ptr<F>>& functors, const std::string& family1,
            const std::string& family2, bool symmetric) {
        const auto chain1 = classChain(family1, i1), chain2 = classChain(family2, i2);
        for (int c1 : chain1)
            for (int c2 : chain2)
                for (const auto& f : functors) {
                    if (!f) continue;
                    const auto types = f->argTypes();
                    const int a = familyIndexOf(family1, types.at(0)), b = familyIndexOf(family2, types.at(1));
                    if (a == c1 && b == c2) return Entry{f.get(), false, true};
                    if (symmetric && a == c2 && b == c1) return Entry{f.get(), true, true};
                }
        return Entry{nullptr, false, true};
    }
};

} // namespace yade
