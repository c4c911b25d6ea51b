#include <core/Omega.hpp>
#include <lib/base/ThreadPinning.hpp>
#include <cstdio>
#include <stdexcept>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

Omega::Omega() {
    scenes[0] = std::make_shared<Scene>();
    scenes[1] = std::make_shared<Scene>();
}

Omega::~Omega() {
    stopRequested = true;
    {
        std::lock_guard<std::mutex> lock(mutex);
        shutdown = true;
    }
    wake.notify_all();
    if (loopThread.joinable()) loopThread.join();
}

// One thread runs every O.run() of the session: OpenMP keeps one team of threads for it (a new
// thread per run would leave the previous team spinning on the cores).
void Omega::worker() {
    for (;;) {
        {
            std::unique_lock<std::mutex> lock(mutex);
            wake.wait(lock, [this] { return startRequested || shutdown; });
            if (shutdown) return;
            startRequested = false;
        }
        loop();
        {
            std::lock_guard<std::mutex> lock(mutex);
            running = false;
        }
        stopped.notify_all();
    }
}

void Omega::requireStopped(const char* what) const {
    if (running) throw std::runtime_error(std::string(what) + " is not possible while the simulation is running (call O.pause() first)");
}

void Omega::loop() {
    Scene& s = scene();
#ifdef _OPENMP
    omp_set_num_threads(s.threads()); // (each thread has its own count: setNumThreads set the caller's)
#endif
    pinLoopThreads(s.threads());
    endedByRequest = false;
    bool reachedEnd = false;
    try {
        while (!stopRequested) {
            s.moveToNextTimeStep();
            noteStepDone();
            if (s.iter == s.stopAtIter) {
                s.stopAtIter = -1; // reached: a later O.run() runs until paused
                reachedEnd = true;
            }
            if (s.stopAtTime > 0 && s.time >= s.stopAtTime) {
                s.stopAtTime = -1; // (as stopAtIter)
                reachedEnd = true;
            }
            if (reachedEnd) break;
        }
        endedByRequest = !reachedEnd && stopRequested.load();
    } catch (...) {
        error = std::current_exception();
        const std::string where = (s.failedEngine.empty() ? std::string() : "in " + s.failedEngine + " ") + "at iteration " + std::to_string(s.iter);
        {
            std::lock_guard<std::mutex> lock(mutex);
            errorSource = where;
        }
        if (!quiet) std::fprintf(stderr, "Simulation stopped by an exception %s; O.wait() re-raises it.\n", where.c_str());
    }
}

std::string Omega::lastErrorSource() const {
    std::lock_guard<std::mutex> lock(mutex);
    return errorSource;
}

void Omega::run(long long nSteps, bool quietError) {
    if (running) return;
    joinLoop();
    Scene& s = scene();
    if (nSteps > 0) s.stopAtIter = s.iter + nSteps;
    error = nullptr;
    {
        std::lock_guard<std::mutex> lock(mutex);
        errorSource.clear();
    }
    quiet = quietError;
    stopRequested = false;
    if (!loopThread.joinable()) {
        loopThread = std::thread([this] { worker(); });
        loopThreadId = loopThread.get_id();
    }
    {
        std::lock_guard<std::mutex> lock(mutex);
        running = true;
        startRequested = true;
    }
    wake.notify_one();
}

void Omega::joinLoop() { // waits until the current run has ended
    if (inLoopThread()) return;
    std::unique_lock<std::mutex> lock(mutex);
    stopped.wait(lock, [this] { return !running; });
}

void Omega::pause() {
    ++pauseCalls;
    stopRequested = true;
    if (!inLoopThread()) joinLoop();
}

void Omega::loopWaitsForGui(bool waits) {
    std::lock_guard<std::mutex> lock(mutex);
    guiAwaited = waits;
}

bool Omega::interrupt(bool yieldToLoop) {
    if (!running) return false;
    const bool askedBefore = stopRequested;
    const long long calls = pauseCalls;
    if (yieldToLoop && !inLoopThread()) {
        ++pauseCalls;
        stopRequested = true;
        std::unique_lock<std::mutex> lock(mutex);
        while (!stopped.wait_for(lock, std::chrono::milliseconds(20), [this] { return !running; }))
            // the loop thread cannot reach the end of its step while it waits (it sets guiAwaited back
            // under this mutex), so taking the request back here is safe; not when the script asked too
            if (guiAwaited && !askedBefore && pauseCalls == calls + 1) {
                stopRequested = false;
                return false;
            }
    } else {
        pause();
    }
    // not to be resumed when the script asked for the stop too (O.pause() in a PyRunner while the view
    // held the run between two steps): one pause call more than this one's
    return !askedBefore && pauseCalls == calls + 1 && endedByRequest && !error;
}

void Omega::wait() {
    if (inLoopThread()) throw std::runtime_error("O.wait() cannot be called from inside the simulation loop");
    joinLoop();
    if (error) {
        std::exception_ptr e = error;
        error = nullptr;
        std::rethrow_exception(e);
    }
}

bool Omega::waitFor(std::chrono::milliseconds timeout) {
    if (inLoopThread()) throw std::runtime_error("O.wait() cannot be called from inside the simulation loop");
    std::unique_lock<std::mutex> lock(mutex);
    return stopped.wait_for(lock, timeout, [this] { return !running; });
}

void Omega::step() {
    if (inLoopThread()) throw std::runtime_error("O.step() cannot be called from inside the simulation loop");
    requireStopped("O.step()");
    joinLoop();
    Scene& s = scene();
    const long long iter = s.iter;
    if (s.subStepping) s.moveToNextSubStep();
    else s.moveToNextTimeStep();
    if (s.iter != iter) noteStepDone();
}

void Omega::noteStepDone() {
    const auto now = std::chrono::steady_clock::now();
    std::lock_guard<std::mutex> lock(speedMutex);
    const double dt = std::chrono::duration<double>(now - lastStepEnd).count();
    rates[nextRate] = anyStepEnd && dt > 0 ? 1 / dt : 0;
    nextRate = (nextRate + 1) % speedSamples;
    lastStepEnd = now;
    anyStepEnd = true;
}

double Omega::speed() const {
    std::lock_guard<std::mutex> lock(speedMutex);
    double sum = 0;
    for (double r : rates) sum += r;
    return sum / speedSamples;
}

void Omega::reset() {
    if (inLoopThread()) throw std::runtime_error("O.reset() cannot be called from inside the simulation loop");
    pause();
    scenes[current]->dropViews();
    scenes[current] = std::make_shared<Scene>();
}

void Omega::resetAll() {
    if (inLoopThread()) throw std::runtime_error("O.resetAllScenes() cannot be called from inside the simulation loop");
    pause();
    for (auto& s : scenes) {
        s->dropViews();
        s = std::make_shared<Scene>();
    }
}

void Omega::setScene(std::shared_ptr<Scene> s) {
    if (inLoopThread()) throw std::runtime_error("a scene cannot be loaded from inside the simulation loop");
    pause();
    if (s != scenes[current]) scenes[current]->dropViews();
    scenes[current] = std::move(s);
}

void Omega::switchWorld() {
    if (running) throw std::runtime_error("Please stop the simulation first, e.g. O.pause()."); // (the reference's words)
    joinLoop();
    current = 1 - current;
}

} // namespace yade
