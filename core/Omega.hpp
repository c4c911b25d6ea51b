// The simulation controller behind Python's O: owns the scenes and the background loop thread.
#pragma once
#include <core/Scene.hpp>
#include <map>
#include <mutex>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <thread>

namespace yade {

class Omega {
public:
    Omega();
    ~Omega();
    Scene& scene() { return *scenes[current]; }
    std::shared_ptr<Scene> scenePtr() { return scenes[current]; }

    // Starts the loop in a background thread; nSteps > 0 stops after that many steps,
    // otherwise it runs until pause() or until iter reaches stopAtIter.
    // quietError: the caller waits and re-raises, so do not also print the error.
    void run(long long nSteps = -1, bool quietError = false);
    void pause(); // stops after the current step; from the loop thread it only requests the stop
    // Stops the loop if it runs; true if it was still running (not ended by itself) and so may be resumed.
    // yieldToLoop (the 3D view's frames): gives up instead, returning false with the loop still running,
    // when the loop waits for the GUI meanwhile (loopWaitsForGui: a PyRunner's makeVideo waiting for the
    // snapshots the GUI saves), as waiting for each other would stall both; isRunning() then stays true.
    bool interrupt(bool yieldToLoop = false);
    void loopWaitsForGui(bool waits);
    void wait();  // blocks until the loop stops; rethrows what stopped it
    // Waits at most `timeout` for the loop to stop (rethrows nothing); true if it is stopped.
    bool waitFor(std::chrono::milliseconds timeout);
    void step();  // one step in the calling thread (one part of it when O.subStepping)
    // O.speed: steps per second, the mean of the rates (1 / time between two consecutive steps'
    // ends) over the last speedSamples steps; a step with no step before it counts as 0.
    static constexpr int speedSamples = 10;
    double speed() const;
    bool isRunning() const { return running; }
    bool inLoopThread() const { return std::this_thread::get_id() == loopThreadId; }
    void reset();       // a new empty scene
    void resetAll();    // both scenes new and empty (the current one stays current)
    int sceneIndex() const { return current; } // 0 the primary scene, 1 the secondary one
    void switchWorld(); // toggle between the primary and the secondary scene
    // Replaces the current scene (after O.load); stops the loop first.
    void setScene(std::shared_ptr<Scene> s);
    // In-memory snapshots for O.saveTmp / O.loadTmp, by slot name.
    std::map<std::string, std::string> tmpSlots;
    // Error that stopped the last background run and has not been rethrown by wait() yet.
    std::exception_ptr pendingError() const { return error; }
    // Where the error that stopped the last background run arose: "in Class labeled 'label' at
    // iteration N" (the engine, when one threw), kept until the next run; empty if none.
    std::string lastErrorSource() const;

private:
    std::shared_ptr<Scene> scenes[2];
    int current = 0;
    std::thread loopThread;
    std::thread::id loopThreadId;
    std::atomic<bool> running{false}, stopRequested{false}, quiet{false}, endedByRequest{false};
    std::atomic<long long> pauseCalls{0};
    bool guiAwaited = false; // (guarded by mutex) the loop thread waits for the GUI // (interrupt() tells whether someone else asked for the stop too)
    std::exception_ptr error;
    std::string errorSource; // (guarded by mutex)
    mutable std::mutex mutex;
    std::condition_variable wake, stopped;
    bool startRequested = false, shutdown = false;
    void worker();
    void loop();
    void joinLoop();
    void requireStopped(const char* what) const;
    void noteStepDone(); // (for speed())
    double rates[speedSamples] = {};
    int nextRate = 0;
    std::chrono::steady_clock::time_point lastStepEnd;
    bool anyStepEnd = false;
    mutable std::mutex speedMutex;
};

} // namespace yade
