// A record of values kept out of its owner's memory: made when first written, copied with its
// owner, the default values until then. For the parts of an object that are seldom used, so that
// the part read every step is smaller (MindlinPhys::Extra: a contact's record is streamed through
// the caches at every step, and each byte it carries costs time there).
#pragma once
#include <memory>

namespace yade {

template <class R> class OutOfLine {
public:
    OutOfLine() = default;
    OutOfLine(const OutOfLine& o) : made(o.made ? std::make_unique<R>(*o.made) : nullptr) {}
    OutOfLine(OutOfLine&&) noexcept = default;
    OutOfLine& operator=(const OutOfLine& o) {
        if (this != &o) made = o.made ? std::make_unique<R>(*o.made) : nullptr;
        return *this;
    }
    OutOfLine& operator=(OutOfLine&&) noexcept = default;
    // The values to read (the defaults while none was written).
    const R& get() const { return made ? *made : defaults(); }
    // The values to write (made now if they were not).
    R& edit() {
        if (!made) made = std::make_unique<R>();
        return *made;
    }

private:
    std::unique_ptr<R> made;
    static const R& defaults() {
        static const R r;
        return r;
    }
};

} // namespace yade
