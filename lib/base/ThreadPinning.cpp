#include <lib/base/ThreadPinning.hpp>
#include <cstdlib>
#include <vector>
#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

void pinLoopThreads(int threads) {
#if defined(__linux__) && defined(_OPENMP)
    // the CPUs the process may use, read once before anything is pinned (the loop's thread inherits them)
    static cpu_set_t allowed;
    static std::vector<int> cpus;
    static bool pinned = false;
    if (cpus.empty()) {
        CPU_ZERO(&allowed);
        if (sched_getaffinity(0, sizeof(allowed), &allowed) != 0) return;
        for (int c = 0; c < CPU_SETSIZE; ++c)
            if (CPU_ISSET(c, &allowed)) cpus.push_back(c);
        if (cpus.empty()) return;
    }
    const bool userChose = std::getenv("OMP_PROC_BIND") || std::getenv("OMP_PLACES") || std::getenv("GOMP_CPU_AFFINITY")
            || std::getenv("YADE_NO_PINNING");
    const bool pin = threads > 1 && (size_t)threads <= cpus.size() && !userChose;
    if (!pin && !pinned) return;
#pragma omp parallel num_threads(pin ? threads : 1)
    {
        cpu_set_t set = allowed;
        if (pin) {
            CPU_ZERO(&set);
            CPU_SET(cpus[(size_t)omp_get_thread_num() % cpus.size()], &set);
        }
        pthread_setaffinity_np(pthread_self(), sizeof(set), &set); // (a refusal leaves the thread as it was)
    }
    pinned = pin;
#else
    (void)threads;
#endif
}

} // namespace yade
