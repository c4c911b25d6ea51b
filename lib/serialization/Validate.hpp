// The checks a value read from a saved file must pass before it reaches an object, shared by the
// encodings (the tree of doc/file-format.md and the blocks): the same rules as the Python setters.
#pragma once
#include <lib/factory/ClassRegistry.hpp>
#include <lib/serialization/Node.hpp>
#include <string>

namespace yade {
namespace Validate {
    // %.17g: the text that reads back to the same bits.
    std::string fmt(Real x);
    // The positive / nonNegative / finite flags of an attribute, applied to n numbers read from a file
    // as the Python setters apply them to assigned values. A value equal to the constructor's default
    // (dflt, what the object holds before it is read: e.g. the NaN radius of Sphere()) is accepted, as a
    // missing one is; items of lists (dflt null) have no default. Throws FormatError naming `where`.
    void checkFlags(const AttrInfo& a, const Real* x, const Real* dflt, int n, const std::string& where);
    // Whether any of the flags checkFlags applies is set.
    inline bool hasValueFlags(const AttrInfo& a) { return a.has(Attr::positive | Attr::nonNegative | Attr::finite); }
    // Strings come from Python, so they are UTF-8. A damaged one would only fail later, when Python
    // reads it (a label is read at once: UnicodeDecodeError after the scene was replaced), so it
    // refuses the file.
    bool validUtf8(const std::string& s);
    const std::string& utf8(const std::string& s, const std::string& where);
    // A quaternion attribute must be finite and non-zero.
    void checkQuaternion(const Real* xyzw, const std::string& where);
} // namespace Validate
} // namespace yade
