// The saved form of a scene: a tree of nodes (tag, attributes, text, children), written either
// as XML or in a compact length-prefixed binary encoding. Both start with a format version.
#pragma once
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
    constexpr int formatVersion = 1;
    std::string toXml(const Node& root);
    std::string toBinary(const Node& root);
    // Detects the encoding from the first bytes; throws FormatError with the reason.
    Node parse(const std::string& data);
    constexpr int maxDepth = 64; // deeper nesting is refused as corrupt (scenes need about 8)
} // namespace NodeIO

} // namespace yade
