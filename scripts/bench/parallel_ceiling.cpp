// What T threads give on this machine right now to a loop that needs nothing but the CPUs: no
// shared data, no serial part, perfectly balanced. A "step" is two OpenMP parallel loops over
// 5 000 items (about the size and the number of parallel regions of a benchmark step), timed with
// 1 thread and with T threads alternately; printed: one line
//     ceiling threads=T one_thread_steps_per_s=<a> threads_steps_per_s=<b> ratio=<b/a>
// The benchmark harness (run_bench.py) runs it between its repeats: on a shared virtual machine
// this ratio moves as much as the engine's own 2-thread / 1-thread ratio does.
//     parallel_ceiling [T=2] [steps=400] [rounds=3]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

static double seconds(std::vector<double>& data, int threads, int steps) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    const long n = (long)data.size() / 4;
    const auto t0 = std::chrono::steady_clock::now();
    for (int step = 0; step < steps; ++step)
        for (int region = 0; region < 2; ++region) {
#pragma omp parallel for schedule(static)
            for (long k = 0; k < n; ++k) {
                double* p = &data[4 * k];
                for (int q = 0; q < 40; ++q) p[0] = p[0] * 0.999999 + p[1] * 1e-7; // (a dependent chain: CPU-bound)
            }
        }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int main(int argc, char** argv) {
    const int threads = argc > 1 ? std::atoi(argv[1]) : 2;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 400;
    const int rounds = argc > 3 ? std::atoi(argv[3]) : 3;
    if (threads < 1 || steps < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: parallel_ceiling [threads>=1] [steps>=1] [rounds>=1]\n");
        return 2;
    }
    std::vector<double> data(4 * 5000, 1.0);
    seconds(data, threads, steps / 4 + 1); // (threads started, caches warm)
    double one = 0, many = 0;
    for (int r = 0; r < rounds; ++r) {
        one += seconds(data, 1, steps);
        many += seconds(data, threads, steps);
    }
    std::printf("ceiling threads=%d one_thread_steps_per_s=%.1f threads_steps_per_s=%.1f ratio=%.3f\n", threads,
            rounds * steps / one, rounds * steps / many, one / many);
    return data[0] < 0; // (keeps the work)
}
