// One attribute of many objects as one typed column: the unit of the block format (doc/file-format.md,
// "Blocks"). A column is written from, and read into, an array of objects of one class, through the
// attribute table (visit()), so a class added later is saved without I/O code of its own.
#pragma once
#include <lib/factory/ClassRegistry.hpp>
#include <lib/serialization/Node.hpp>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace yade {

// Appends little-endian fixed-width values, LEB128 sizes and strings to a buffer.
struct Encoder {
    std::string& out;
    void bytes(const void* p, size_t n) {
        if (n) out.append(static_cast<const char*>(p), n); // (an empty vector's data() may be null)
    }
    template <class T> void put(const T& x) { bytes(&x, sizeof x); }
    void size(uint64_t v);
    void string(const std::string& s) {
        size(s.size());
        out += s;
    }
};

// Reads what an Encoder wrote from a block in memory; every read is checked against the end.
struct Cursor {
    const char* p;
    const char* end;
    const char* what; // the block, for messages
    [[noreturn]] void fail(const std::string& why) const;
    const char* bytes(size_t n) {
        if (n > size_t(end - p)) fail("a field runs past the end of the block");
        const char* r = p;
        p += n;
        return r;
    }
    template <class T> T get() {
        T x;
        std::memcpy(&x, bytes(sizeof x), sizeof x);
        return x;
    }
    uint64_t size();
    // A count of items of at least `itemBytes` bytes each: refused if the block cannot hold them.
    uint64_t count(size_t itemBytes);
    std::string string() {
        const uint64_t n = count(1);
        return std::string(bytes(n), n);
    }
    bool atEnd() const { return p == end; }
};

// A reference to an object of the graph in a column: (table << 32) | row, or -1 for None.
using ObjectRef = int64_t;
constexpr ObjectRef nullRef = -1;

// Gives the reference of an object met in a pointer attribute (numbering it if it is new).
struct RefWriter {
    virtual ObjectRef ref(const std::shared_ptr<Serializable>& p, long extraOwners) = 0;
    virtual ~RefWriter() = default;
};
// Sets a pointer attribute from a reference (at once, or when the object is read).
struct RefReader {
    virtual void bind(void* member, const AttrInfo& a, ObjectRef ref, const std::string& where) = 0;
    virtual void bindList(void* member, const AttrInfo& a, std::vector<ObjectRef> refs, const std::string& where) = 0;
    virtual ~RefReader() = default;
};

namespace Columns {
    // Bytes of one value of a fixed-width kind; 0 for the kinds of variable length (strings and lists).
    size_t width(AttrKind k);
    // The attributes of a class that are saved (not Attr::noSave), in declaration order.
    std::vector<const AttrInfo*> saved(const ClassInfo& c);
    // The schema of a table: per attribute its name and kind.
    void writeSchema(Encoder& e, const std::vector<const AttrInfo*>& attrs);
    // Reads a schema and maps it onto the class's attributes (an unknown name or another kind refuses
    // the file); null entries: none (never).
    std::vector<const AttrInfo*> readSchema(Cursor& c, const ClassInfo& cls);
    // Attribute a of objs[0..n): a mode byte (0: one value per object, 1: one value for all), then the data.
    void write(Encoder& e, const AttrInfo& a, Serializable* const* objs, size_t n, RefWriter* refs);
    // n values of w bytes each, contiguous: a mode byte, then all of them, or one if they are all equal.
    void writeRaw(Encoder& e, const void* data, size_t w, size_t n);
    // Reads what writeRaw wrote: the first value, and the step to the next one (0: one value for all).
    std::pair<const char*, size_t> readRaw(Cursor& c, size_t w, size_t n);
    // Reads a column into objs[0..n) (fresh objects: their values are the defaults the flags accept).
    void read(Cursor& c, const AttrInfo& a, Serializable* const* objs, size_t n, RefReader* refs, const std::string& className);
} // namespace Columns

} // namespace yade
