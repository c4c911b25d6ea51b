#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <lib/serialization/Node.hpp>

namespace yade {

static const char binaryMagic[] = "YADE-CLONE-BINARY\n";
static const char xmlMagic[] = "<?xml";

std::string FormatError::printable(const std::string& s) {
    std::string r;
    for (unsigned char c : s) {
        if (c >= 32 && c < 127) r += static_cast<char>(c);
        else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            r += buf;
        }
    }
    return r;
}

const std::string& Node::attr(const std::string& name) const {
    auto it = attrs.find(name);
    if (it == attrs.end()) throw FormatError("<" + tag + "> lacks the attribute '" + name + "'");
    return it->second;
}

const Node* Node::find(const std::string& childTag) const {
    for (const auto& c : children)
        if (c.tag == childTag) return &c;
    return nullptr;
}

const Node& Node::child(const std::string& childTag) const {
    if (const Node* c = find(childTag)) return *c;
    throw FormatError("<" + tag + "> lacks the element <" + childTag + ">");
}

// ---------------------------------------------------------------- XML, read as it streams

XmlReader::XmlReader(ByteSource& source, std::string prefix) : in(source), s(std::move(prefix)) {}

bool XmlReader::more() {
    if (atEnd) return false;
    char chunk[1 << 16];
    const size_t n = in.read(chunk, sizeof chunk);
    s.append(chunk, n);
    atEnd = n < sizeof chunk;
    return n > 0;
}

bool XmlReader::have(size_t n) {
    while (s.size() - pos < n)
        if (!more()) return false;
    return true;
}

size_t XmlReader::find(char c) {
    for (size_t from = pos;;) {
        const size_t at = s.find(c, from);
        if (at != std::string::npos) return at;
        from = s.size();
        if (!more()) return std::string::npos;
    }
}

void XmlReader::fail(const std::string& what) const {
    size_t line = 1 + linesBefore;
    for (size_t i = 0; i < pos && i < s.size(); ++i) line += s[i] == '\n';
    throw FormatError("corrupt XML at line " + std::to_string(line) + ": " + what);
}

void XmlReader::skipSpace() {
    while (have(1) && std::isspace((unsigned char)s[pos])) ++pos;
}

std::string XmlReader::unescape(size_t from, size_t to) const {
    std::string r;
    r.reserve(to - from);
    for (size_t i = from; i < to; ++i) {
        if (s[i] != '&') {
            r += s[i];
            continue;
        }
        const size_t semi = s.find(';', i);
        if (semi == std::string::npos || semi >= to) throw FormatError("corrupt XML: unterminated entity");
        const std::string ent = s.substr(i + 1, semi - i - 1);
        if (ent == "lt") r += '<';
        else if (ent == "gt") r += '>';
        else if (ent == "amp") r += '&';
        else if (ent == "quot") r += '"';
        else throw FormatError("corrupt XML: unknown entity &" + ent + ";");
        i = semi;
    }
    return r;
}

std::string XmlReader::name() {
    const size_t start = pos;
    while (have(1) && (std::isalnum((unsigned char)s[pos]) || s[pos] == '_' || s[pos] == '.' || s[pos] == '-')) ++pos;
    if (pos == start) fail("expected a name");
    return s.substr(start, pos - start);
}

void XmlReader::declaration() {
    while (s.find("?>") == std::string::npos)
        if (!more()) fail("bad XML declaration");
    pos = s.find("?>") + 2;
}

// The attributes of a start tag after its name, to its end: false if it ends in "/>".
bool XmlReader::startTag(Node& n) {
    for (;;) {
        skipSpace();
        if (!have(1)) fail("unexpected end of file");
        if (have(2) && s.compare(pos, 2, "/>") == 0) {
            pos += 2;
            return false;
        }
        if (s[pos] == '>') {
            ++pos;
            return true;
        }
        const std::string key = name();
        skipSpace();
        if (!have(2) || s[pos] != '=' || s[pos + 1] != '"') fail("expected =\"value\" after " + key);
        pos += 2;
        const size_t end = find('"');
        if (end == std::string::npos) fail("unterminated attribute value");
        n.attrs[key] = unescape(pos, end);
        pos = end + 1;
    }
}

bool XmlReader::closing(const std::string& tag) {
    if (!have(2) || s.compare(pos, 2, "</") != 0) return false;
    pos += 2;
    if (name() != tag) fail("mismatched closing tag for <" + tag + ">");
    skipSpace();
    if (!have(1) || s[pos] != '>') fail("expected '>'");
    ++pos;
    return true;
}

bool XmlReader::child(Node& start, bool& empty, const std::string& parent) {
    // (what was read before this child is dropped: a large file streams through a small buffer)
    for (size_t i = 0; i < pos; ++i) linesBefore += s[i] == '\n';
    s.erase(0, pos);
    pos = 0;
    const size_t lt = find('<');
    if (lt == std::string::npos) fail("missing </" + parent + ">");
    pos = lt;
    if (closing(parent)) return false;
    ++pos;
    start = Node(name());
    empty = !startTag(start);
    return true;
}

Node XmlReader::rest(Node n, bool empty, int depth) {
    if (empty) return n;
    for (;;) { // text and children until the closing tag
        const size_t lt = find('<');
        if (lt == std::string::npos) fail("missing </" + n.tag + ">");
        n.text += unescape(pos, lt);
        pos = lt;
        if (closing(n.tag)) {
            if (!n.children.empty()) n.text.clear(); // indentation between children
            return n;
        }
        n.children.push_back(element(depth + 1));
    }
}

Node XmlReader::element(int depth) {
    if (depth > NodeIO::maxDepth) fail("nesting too deep");
    skipSpace();
    if (!have(1) || s[pos] != '<') fail("expected '<'");
    ++pos;
    Node n(name());
    const bool open = startTag(n);
    return rest(std::move(n), !open, depth);
}

void XmlReader::finish() {
    skipSpace();
    if (have(1)) fail("extra content after the root element");
}

namespace {
// ---------------------------------------------------------------- binary (format version 1, read only)
// sizes as unsigned LEB128 varints: 7 bits per byte, high bit set on all but the last byte
struct BinaryReader {
    const std::string& s;
    size_t pos;
    uint64_t size() {
        uint64_t v = 0;
        for (int shift = 0;; shift += 7) {
            if (pos >= s.size()) throw FormatError("truncated file (ends at byte " + std::to_string(s.size()) + ")");
            if (shift > 63) throw FormatError("corrupt file (bad length field)");
            const unsigned char byte = static_cast<unsigned char>(s[pos++]);
            v |= uint64_t(byte & 0x7f) << shift;
            if (!(byte & 0x80)) return v;
        }
    }
    std::string string() {
        const uint64_t n = size();
        if (n > s.size() - pos) throw FormatError("truncated or corrupt file (a string runs past the end)");
        std::string r = s.substr(pos, n);
        pos += n;
        return r;
    }
    Node node(int depth) {
        if (depth > NodeIO::maxDepth) throw FormatError("corrupt file (nesting too deep)");
        Node n(string());
        const uint64_t na = size();
        if (na > s.size()) throw FormatError("corrupt file (impossible attribute count)");
        for (uint64_t i = 0; i < na; ++i) {
            std::string k = string();
            n.attrs[k] = string();
        }
        n.text = string();
        const uint64_t nc = size();
        if (nc > s.size()) throw FormatError("corrupt file (impossible child count)");
        n.children.reserve(nc);
        for (uint64_t i = 0; i < nc; ++i) n.children.push_back(node(depth + 1));
        return n;
    }
};
} // namespace

Node NodeIO::parse(const std::string& data) {
    if (data.empty()) throw FormatError("empty file");
    if (data.compare(0, sizeof binaryMagic - 1, binaryMagic) == 0) {
        BinaryReader r{data, sizeof binaryMagic - 1};
        Node n = r.node(0);
        if (r.pos != data.size()) throw FormatError("corrupt file (extra bytes after the scene)");
        return n;
    }
    if (data.compare(0, sizeof xmlMagic - 1, xmlMagic) == 0) {
        auto source = stringSource(data);
        XmlReader p(*source, "");
        p.declaration();
        Node n = p.element(0);
        p.finish();
        return n;
    }
    throw FormatError("not a saved scene (unknown format: neither the binary nor the XML header)");
}

} // namespace yade
