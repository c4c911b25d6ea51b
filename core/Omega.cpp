#include <core/Omega.hpp>
#include <cstdio>
#include <stdexcept>

namespace yade {

Omega::Omega() {
    scenes[0] = std::make_shared<Scene>();
    scenes[1] = std::make_shared<Scene>();
}

Omega::~Omega() {
    stopRequested = true;
    if (loopThread.joinable()) loopThread.join();
}

void Omega::requireStopped(const char* what) const {
    if (running) throw std::runtime_error(std::string(what) + " is not possible while the simulation is running (call O.pause() first)");
}

void Omega::loop() {
    Scene& s = scene();
    endedByRequest = false;
    bool reachedEnd = false;
    try {
        while (!stopRequested) {
            s.moveToNextTimeStep();
            if (s.iter == s.stopAtIter) {
                s.stopAtIter = -1; // reached: a later O.run() runs until paused
                reachedEnd = true;
                break;
            }
        }
        endedByRequest = !reachedEnd && stopRequested.load();
    } catch (...) {
        error = std::current_exception();
        if (!quiet) std::fprintf(stderr, "Simulation stopped at iteration %lld by an exception; O.wait() re-raises it.\n", s.iter);
    }
    running = false;
}

void Omega::run(long long nSteps, bool quietError) {
    if (running) return;
    joinLoop();
    Scene& s = scene();
    if (nSteps > 0) s.stopAtIter = s.iter + nSteps;
    error = nullptr;
    quiet = quietError;
    stopRequested = false;
    running = true;
    loopThread = std::thread([this] { loop(); });
    loopThreadId = loopThread.get_id();
}

void Omega::joinLoop() {
    if (loopThread.joinable() && !inLoopThread()) loopThread.join();
}

void Omega::pause() {
    stopRequested = true;
    if (!inLoopThread()) joinLoop();
}

bool Omega::interrupt() {
    if (!running) return false;
    pause();
    return endedByRequest && !error;
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

void Omega::step() {
    if (inLoopThread()) throw std::runtime_error("O.step() cannot be called from inside the simulation loop");
    requireStopped("O.step()");
    joinLoop();
    scene().moveToNextTimeStep();
}

void Omega::reset() {
    if (inLoopThread()) throw std::runtime_error("O.reset() cannot be called from inside the simulation loop");
    pause();
    scenes[current] = std::make_shared<Scene>();
}

void Omega::setScene(std::shared_ptr<Scene> s) {
    if (inLoopThread()) throw std::runtime_error("a scene cannot be loaded from inside the simulation loop");
    pause();
    scenes[current] = std::move(s);
}

void Omega::switchWorld() {
    requireStopped("O.switchWorld()");
    joinLoop();
    current = 1 - current;
}

} // namespace yade
