// The split of body ids between threads: n ids in consecutive ranges, the first n % parts of them
// one longer (as OpenMP's static schedule in GCC's libgomp). O.forces (each thread adds in place
// to its own range), the integrator and the interaction loop's assignment of pairs use it, so
// that each thread mostly reads and writes the entries it wrote itself.
#pragma once
#include <algorithm>
#include <utility>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

// [begin, end) of part `part` of `parts`.
inline std::pair<long, long> threadRange(long n, long part, long parts) {
    const long q = n / parts, r = n % parts, begin = part * q + std::min(part, r);
    return {begin, begin + q + (part < r ? 1 : 0)};
}

// The range of the calling thread in the current parallel region (everything outside one).
inline std::pair<long, long> myThreadRange(long n) {
#ifdef _OPENMP
    return threadRange(n, omp_get_thread_num(), omp_get_num_threads());
#else
    return {0, n};
#endif
}

// The part whose range holds id.
inline int threadOwning(long id, long n, long parts) {
    const long q = n / parts, r = n % parts, cut = r * (q + 1);
    return (int)(id < cut ? id / (q + 1) : r + (q > 0 ? (id - cut) / q : 0));
}

} // namespace yade
