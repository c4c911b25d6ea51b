// Root of every class exposed to Python and saved to files.
#pragma once
#include <lib/serialization/Attr.hpp>
#include <memory>
#include <string>

namespace yade {

// (Not enable_shared_from_this: 16 bytes per body and per contact object. Python gets objects
// through their shared_ptr only, never from a raw pointer.)
class Serializable {
public:
    static constexpr const char* classDoc = "Root of every class exposed to Python and saved to files: its attributes are read, set and saved by name.";
    virtual ~Serializable() = default;
    template <class V> void visit(V&) {}
    // Name of the most derived registered class (looked up in the class registry).
    std::string getClassName() const;
    // Called after attributes were set from Python or a file; recompute derived data here.
    virtual void postLoad() {}
    // Called before the attributes are written to a file (copy run-time state into hidden attributes).
    virtual void preSave() {}
    virtual void postSave() {} // after writing: drop what preSave copied
};

} // namespace yade
