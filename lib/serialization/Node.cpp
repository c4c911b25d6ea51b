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

// ---------------------------------------------------------------- XML
static void escape(std::string& out, const std::string& s) {
    for (char c : s) switch (c) {
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '&': out += "&amp;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
}

static void writeXml(std::string& out, const Node& n, int depth) {
    out.append(depth, ' ');
    out += "<" + n.tag;
    for (const auto& a : n.attrs) {
        out += " " + a.first + "=\"";
        escape(out, a.second);
        out += "\"";
    }
    if (n.text.empty() && n.children.empty()) {
        out += "/>\n";
        return;
    }
    out += ">";
    escape(out, n.text);
    if (!n.children.empty()) {
        out += "\n";
        for (const auto& c : n.children) writeXml(out, c, depth + 1);
        out.append(depth, ' ');
    }
    out += "</" + n.tag + ">\n";
}

std::string NodeIO::toXml(const Node& root) {
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    writeXml(out, root, 0);
    return out;
}

namespace {
struct XmlParser {
    const std::string& s;
    size_t pos = 0;
    [[noreturn]] void fail(const std::string& what) const {
        size_t line = 1;
        for (size_t i = 0; i < pos && i < s.size(); ++i) line += s[i] == '\n';
        throw FormatError("corrupt XML at line " + std::to_string(line) + ": " + what);
    }
    void skipSpace() {
        while (pos < s.size() && std::isspace((unsigned char)s[pos])) ++pos;
    }
    std::string unescape(const std::string& t) const {
        std::string r;
        for (size_t i = 0; i < t.size(); ++i) {
            if (t[i] != '&') {
                r += t[i];
                continue;
            }
            const size_t semi = t.find(';', i);
            const std::string ent = t.substr(i + 1, semi - i - 1);
            if (semi == std::string::npos) throw FormatError("corrupt XML: unterminated entity");
            if (ent == "lt") r += '<';
            else if (ent == "gt") r += '>';
            else if (ent == "amp") r += '&';
            else if (ent == "quot") r += '"';
            else throw FormatError("corrupt XML: unknown entity &" + ent + ";");
            i = semi;
        }
        return r;
    }
    std::string name() {
        const size_t start = pos;
        while (pos < s.size() && (std::isalnum((unsigned char)s[pos]) || s[pos] == '_' || s[pos] == '.' || s[pos] == '-')) ++pos;
        if (pos == start) fail("expected a name");
        return s.substr(start, pos - start);
    }
    Node element(int depth = 0) {
        if (depth > NodeIO::maxDepth) fail("nesting too deep");
        skipSpace();
        if (pos >= s.size() || s[pos] != '<') fail("expected '<'");
        ++pos;
        Node n(name());
        for (;;) {
            skipSpace();
            if (pos >= s.size()) fail("unexpected end of file");
            if (s.compare(pos, 2, "/>") == 0) {
                pos += 2;
                return n;
            }
            if (s[pos] == '>') {
                ++pos;
                break;
            }
            const std::string key = name();
            skipSpace();
            if (pos + 1 >= s.size() || s[pos] != '=' || s[pos + 1] != '"') fail("expected =\"value\" after " + key);
            pos += 2;
            const size_t end = s.find('"', pos);
            if (end == std::string::npos) fail("unterminated attribute value");
            n.attrs[key] = unescape(s.substr(pos, end - pos));
            pos = end + 1;
        }
        for (;;) { // text and children until the closing tag
            const size_t lt = s.find('<', pos);
            if (lt == std::string::npos) fail("missing </" + n.tag + ">");
            n.text += unescape(s.substr(pos, lt - pos));
            pos = lt;
            if (s.compare(pos, 2, "</") == 0) {
                pos += 2;
                if (name() != n.tag) fail("mismatched closing tag for <" + n.tag + ">");
                skipSpace();
                if (pos >= s.size() || s[pos] != '>') fail("expected '>'");
                ++pos;
                if (!n.children.empty()) n.text.clear(); // indentation between children
                return n;
            }
            n.children.push_back(element(depth + 1));
        }
    }
};

// ---------------------------------------------------------------- binary
// sizes as unsigned LEB128 varints: 7 bits per byte, high bit set on all but the last byte
void putSize(std::string& out, uint64_t v) {
    do {
        const unsigned char byte = (v & 0x7f) | (v > 0x7f ? 0x80 : 0);
        out += static_cast<char>(byte);
        v >>= 7;
    } while (v);
}
void putString(std::string& out, const std::string& s) {
    putSize(out, s.size());
    out += s;
}
void writeBinary(std::string& out, const Node& n) {
    putString(out, n.tag);
    putSize(out, n.attrs.size());
    for (const auto& a : n.attrs) {
        putString(out, a.first);
        putString(out, a.second);
    }
    putString(out, n.text);
    putSize(out, n.children.size());
    for (const auto& c : n.children) writeBinary(out, c);
}

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

std::string NodeIO::toBinary(const Node& root) {
    std::string out = binaryMagic;
    writeBinary(out, root);
    return out;
}

Node NodeIO::parse(const std::string& data) {
    if (data.empty()) throw FormatError("empty file");
    if (data.compare(0, sizeof binaryMagic - 1, binaryMagic) == 0) {
        BinaryReader r{data, sizeof binaryMagic - 1};
        Node n = r.node(0);
        if (r.pos != data.size()) throw FormatError("corrupt file (extra bytes after the scene)");
        return n;
    }
    if (data.compare(0, sizeof xmlMagic - 1, xmlMagic) == 0) {
        XmlParser p{data};
        p.pos = data.find("?>");
        if (p.pos == std::string::npos) p.fail("bad XML declaration");
        p.pos += 2;
        Node n = p.element();
        p.skipSpace();
        if (p.pos != data.size()) p.fail("extra content after the root element");
        return n;
    }
    throw FormatError("not a saved scene (unknown format: neither the binary nor the XML header)");
}

} // namespace yade
