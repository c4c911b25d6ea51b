// Class indices for dispatch: every Shape, Material, Bound, IGeom and IPhys class gets a small
// integer, assigned when the class is registered; dispatchers are tables indexed by it.
#pragma once
#include <type_traits>

// In the root of a family (Shape, Material, ...).
#define YADE_INDEXABLE_ROOT(Klass)                                     \
    using IndexableRoot = Klass;                                       \
    using IndexedClass = Klass;                                        \
    static int& classIndexStatic() {                                   \
        static int index = -1;                                         \
        return index;                                                  \
    }                                                                  \
    virtual int getClassIndex() const { return classIndexStatic(); }

// In every class derived from such a root.
#define YADE_INDEXABLE(Klass)                                          \
    using IndexedClass = Klass;                                        \
    static int& classIndexStatic() {                                   \
        static int index = -1;                                         \
        return index;                                                  \
    }                                                                  \
    int getClassIndex() const override { return classIndexStatic(); }

namespace yade {
template <class T, class = void> struct IsIndexable { static constexpr bool value = false; };
template <class T> struct IsIndexable<T, std::void_t<typename T::IndexableRoot>> { static constexpr bool value = true; };
} // namespace yade
