// The saved form of a scene as a tree of nodes (tag, attributes, text, children): what an XML file
// holds, and a binary file of format version 1 (a length-prefixed encoding, read only: binary files
// are now the block format, core/SceneBlocks.hpp). Both start with a format version.
#pragma once
#include <lib/serialization/Streams.hpp>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace yade {

struct Node {
    std::string tag;
    std::map<std::string, std::string> attrs;
    std::string text;
    std::vector<Node> children;

    Node() = default;
    explicit Node(std::string t) : tag(std::move(t)) {}
    Node& add(std::string childTag) {
        children.emplace_back(std::move(childTag));
        return children.back();
    }
    const std::string& attr(const std::string& name) const; // throws FormatError if missing
    const Node& child(const std::string& childTag) const;   // throws FormatError if missing
    const Node* find(const std::string& childTag) const;
};

// A file that cannot be read: truncated, corrupt, or not a saved scene.
struct FormatError : std::runtime_error {
    // Bytes quoted from a corrupt file may be anything: keep the message printable ASCII.
    explicit FormatError(const std::string& message) : std::runtime_error(printable(message)) {}
    static std::string printable(const std::string& s);
};

namespace NodeIO {
    // 1: every object kept for references; 2 (XML since the block format): only objects marked shared="1"
    constexpr int formatVersion = 2;
    constexpr const char* xmlDeclaration = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    // Detects the encoding from the first bytes; throws FormatError with the reason.
    Node parse(const std::string& data);
    constexpr int maxDepth = 64; // deeper nesting is refused as corrupt (scenes need about 8)
} // namespace NodeIO

// Reads XML as it streams from a source, one element at a time: the elements of a large scene are
// read and dropped one after the other, never the whole tree (the subset of XML that the writer of scenes writes).
class XmlReader {
public:
    // `prefix`: bytes already read from the source (to detect the format).
    XmlReader(ByteSource& in, std::string prefix);
    void declaration(); // <?xml ... ?>
    // The start tag of the next child of the element being read (its tag and attributes; `empty`:
    // written <tag .../>), or false when what comes is the closing tag </parent> (then consumed).
    bool child(Node& start, bool& empty, const std::string& parent);
    // The rest of an element whose start tag child() read: its text, its children, its closing tag.
    Node rest(Node start, bool empty, int depth);
    Node element(int depth); // a whole element
    void finish();           // only whitespace may remain
    [[noreturn]] void fail(const std::string& what) const;

private:
    ByteSource& in;
    std::string s;          // what was read and not yet dropped
    size_t pos = 0;         // the parser's position in s
    size_t linesBefore = 0; // lines dropped from s
    bool atEnd = false;
    bool more();            // reads more into s; false at the end of the source
    bool have(size_t n);    // at least n bytes from pos (reading more if needed)
    size_t find(char c);    // position of c from pos (reading more if needed), npos if none
    void skipSpace();
    std::string name();
    std::string unescape(size_t from, size_t to) const;
    bool startTag(Node& n);                // the attributes, to the end of the tag: false if "/>"
    bool closing(const std::string& tag); // "</tag>" if it comes (consumed), else false
};

} // namespace yade
