// The skin protocol: whether the bodies' position column (BodyStore::pos, contiguous by id) holds
// the positions the integrator left, and what the collider and the interaction loop may conclude
// from it without visiting the bodies: how far any body moved in a step, and how far from the
// skin's reference.
//
// Who writes: NewtonIntegrator, once per step (beginWrite, its pass over the columns, publish).
// Who reads: InsertionSortCollider (needsRun: has any body left its box?) and InteractionLoop
//   (the shape cache's positions, and the skin's largest displacement). A reader uses positions(),
//   maxStep() and maxMovedSince() only while current() is true.
// Who sets the reference: InteractionLoop, at the start of each skin epoch (setReference); the
//   integrator then measures, in the same pass as it writes, how far bodies are from it.
// What invalidates it (current() turns false until the integrator publishes again):
//   - another engine that moves bodies: it calls invalidate() (StepDisplacer does);
//   - O.bodies changed (append, erase, clear): BodyContainer::changes;
//   - a write from Python to any attribute, vector or quaternion: externalWrites() (counted in
//     one place, the wrapper's setters: lib/base/ExternalWrites.hpp);
//   - a writable NumPy view of the bodies' columns is alive (BodyStore::writableViews);
//   - a step passed without the integrator (it is current for the step it was written in and
//     the next one only).
// See doc/storage.md, "The skin protocol".
#pragma once
#include <lib/base/Math.hpp>
#include <memory>
#include <vector>

namespace yade {

class Scene;

class MotionRecord {
public:
    explicit MotionRecord(const Scene& s) : scene(s) {}
    MotionRecord(const MotionRecord&) = delete;
    MotionRecord& operator=(const MotionRecord&) = delete;

    // --- the integrator (the only writer) ---
    // Before its pass over the n bodies: whether it continues from the positions of the last step
    // (then maxStep bounds the move), and the reference to measure from (or null).
    struct Write {
        bool continues;
        const Vector3r* reference;
    };
    Write beginWrite(size_t n);
    // After its pass (the column holds every body's new position): the fastest body's squared
    // velocity, and the largest squared distance from the reference (when beginWrite gave one).
    // The positions are then current for this step.
    void publish(const Write& w, Real maxV2, Real dt, Real maxMoved2);

    // --- the readers ---
    bool current() const;
    // The positions (BodyStore::pos; an entry of a hole in the ids means nothing), the step that
    // wrote them, and a bound on how far any body moved in that step (Inf when it did not start
    // from the positions before it).
    const Vector3r* positions() const;
    long long step() const { return iter; }
    Real maxStep() const { return maxStepLen; }

    // --- the interaction loop's skin ---
    // The positions of the epoch's start, tagged with a number unique to the epoch.
    void setReference(std::shared_ptr<const std::vector<Vector3r>> ref, long long tag);
    // The largest squared distance of a body from the reference tagged `tag`, as the integrator
    // found it in the step that wrote the current positions; NaN if it did not measure from it.
    Real maxMovedSince(long long tag) const;

    // --- any other engine that moves bodies ---
    void invalidate() { iter = -1; }

private:
    const Scene& scene;
    size_t count = 0;                               // how many bodies when written
    long long iter = -1, writes = -1, changes = -1; // when written: step, externalWrites(), bodies.changes
    long long writesBefore = -1;                    // externalWrites() when the write began
    Real maxStepLen = Inf;
    std::shared_ptr<const std::vector<Vector3r>> reference;
    long long referenceTag = -1, maxMovedTag = -1;
    Real maxMoved2 = NaN;
};

} // namespace yade
