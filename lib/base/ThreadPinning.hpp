// Pinning of the simulation's OpenMP threads to CPUs.
#pragma once

namespace yade {

// Called by the simulation loop's thread before each run. With several threads (and at most as
// many as the CPUs the process may use), OpenMP thread i is pinned to the i-th of those CPUs: on
// the virtual machines we measured, the scheduler otherwise moved the threads between CPUs and
// the caches they had warmed were lost (5000-sphere deposition, 2 threads: 2770 -> 3460 iter/s,
// per-thread loop times within 1-10 % instead of 15-40 %). Nothing is pinned when the user chose a
// binding (OMP_PROC_BIND, OMP_PLACES or GOMP_CPU_AFFINITY set) or YADE_NO_PINNING is set; with one
// thread the loop's thread gets back every CPU the process had. Other threads (Python's, those the
// user starts from the script) are never touched; a process or thread started from a PyRunner
// (which runs in the loop's thread) inherits the loop thread's single CPU.
void pinLoopThreads(int threads);

} // namespace yade
