#include <lib/serialization/Columns.hpp>
#include <lib/serialization/Validate.hpp>

namespace yade {

void Encoder::size(uint64_t v) {
    do {
        const unsigned char byte = (v & 0x7f) | (v > 0x7f ? 0x80 : 0);
        out += static_cast<char>(byte);
        v >>= 7;
    } while (v);
}

void Cursor::fail(const std::string& why) const { throw FormatError(std::string("corrupt file (") + what + ": " + why + ")"); }

uint64_t Cursor::size() {
    uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
        if (p >= end) fail("a length runs past the end of the block");
        if (shift > 63) fail("bad length field");
        const unsigned char byte = static_cast<unsigned char>(*p++);
        v |= uint64_t(byte & 0x7f) << shift;
        if (!(byte & 0x80)) return v;
    }
}

uint64_t Cursor::count(size_t itemBytes) {
    const uint64_t n = size();
    if (itemBytes && n > uint64_t(end - p) / itemBytes) fail("a count larger than the block");
    return n;
}

size_t Columns::width(AttrKind k) {
    switch (k) {
        case AttrKind::Bool: return 1;
        case AttrKind::Int: return sizeof(int);
        case AttrKind::Long: return sizeof(long long);
        case AttrKind::Real: return sizeof(Real);
        case AttrKind::Vector2r: return sizeof(Vector2r);
        case AttrKind::Vector2i: return sizeof(Vector2i);
        case AttrKind::Vector3r: return sizeof(Vector3r);
        case AttrKind::Vector3i: return sizeof(Vector3i);
        case AttrKind::Vector6r: return sizeof(Vector6r);
        case AttrKind::Vector6i: return sizeof(Vector6i);
        case AttrKind::Matrix3r: return sizeof(Matrix3r);
        case AttrKind::Quaternionr: return sizeof(Quaternionr);
        case AttrKind::Ptr: return sizeof(ObjectRef);
        default: return 0;
    }
}

std::vector<const AttrInfo*> Columns::saved(const ClassInfo& c) {
    std::vector<const AttrInfo*> r;
    for (const AttrInfo& a : c.attrs)
        if (!a.has(Attr::noSave)) r.push_back(&a);
    return r;
}

void Columns::writeSchema(Encoder& e, const std::vector<const AttrInfo*>& attrs) {
    e.size(attrs.size());
    for (const AttrInfo* a : attrs) {
        e.string(a->name);
        e.put<uint8_t>((uint8_t)a->kind);
    }
}

std::vector<const AttrInfo*> Columns::readSchema(Cursor& c, const ClassInfo& cls) {
    std::vector<const AttrInfo*> r;
    const uint64_t n = c.count(2);
    for (uint64_t i = 0; i < n; ++i) {
        const std::string name = c.string();
        const unsigned kind = c.get<uint8_t>();
        const AttrInfo* a = cls.findAttr(name);
        if (!a) throw FormatError(cls.name + " has no attribute '" + name + "'");
        if ((unsigned)a->kind != kind) throw FormatError(cls.name + "." + name + ": saved as another kind of value than this build has");
        for (const AttrInfo* b : r)
            if (b == a) throw FormatError(cls.name + "." + name + ": the same attribute twice");
        r.push_back(a);
    }
    return r;
}

namespace {

int componentsOf(AttrKind k) { return int(Columns::width(k) / sizeof(Real)); } // (for the Real kinds)

bool isRealKind(AttrKind k) {
    switch (k) {
        case AttrKind::Real:
        case AttrKind::Vector2r:
        case AttrKind::Vector3r:
        case AttrKind::Vector6r:
        case AttrKind::Matrix3r:
        case AttrKind::Quaternionr: return true;
        default: return false;
    }
}

void writeVariable(Encoder& e, const AttrInfo& a, void* p, RefWriter* refs) {
    switch (a.kind) {
        case AttrKind::String: e.string(*static_cast<std::string*>(p)); break;
        case AttrKind::IntVector: {
            const auto& v = *static_cast<std::vector<int>*>(p);
            e.size(v.size());
            e.bytes(v.data(), v.size() * sizeof(int));
            break;
        }
        case AttrKind::RealVector: {
            const auto& v = *static_cast<std::vector<Real>*>(p);
            e.size(v.size());
            e.bytes(v.data(), v.size() * sizeof(Real));
            break;
        }
        case AttrKind::Vector3rVector: {
            const auto& v = *static_cast<std::vector<Vector3r>*>(p);
            e.size(v.size());
            for (const auto& x : v) e.bytes(x.data(), 3 * sizeof(Real));
            break;
        }
        case AttrKind::Vector2rVector: {
            const auto& v = *static_cast<std::vector<Vector2r>*>(p);
            e.size(v.size());
            for (const auto& x : v) e.bytes(x.data(), 2 * sizeof(Real));
            break;
        }
        case AttrKind::QuaternionrVector: { // (x y z w, as Quaternionr)
            const auto& v = *static_cast<std::vector<Quaternionr>*>(p);
            e.size(v.size());
            for (const auto& x : v) e.bytes(x.coeffs().data(), 4 * sizeof(Real));
            break;
        }
        case AttrKind::StringVector: {
            const auto& v = *static_cast<std::vector<std::string>*>(p);
            e.size(v.size());
            for (const auto& s : v) e.string(s);
            break;
        }
        case AttrKind::PtrVector: {
            const auto v = a.getPtrVector(p);
            e.size(v.size());
            for (const auto& x : v) e.put<ObjectRef>(refs->ref(x, 1));
            break;
        }
        default: throw std::logic_error("Columns: not a kind of variable length");
    }
}

void readVariable(Cursor& c, const AttrInfo& a, void* p, RefReader* refs, const std::string& where) {
    switch (a.kind) {
        case AttrKind::String: *static_cast<std::string*>(p) = Validate::utf8(c.string(), where); break;
        case AttrKind::IntVector: {
            const uint64_t n = c.count(sizeof(int));
            auto& v = *static_cast<std::vector<int>*>(p);
            v.resize(n);
            const char* src = c.bytes(n * sizeof(int));
            if (n) std::memcpy(v.data(), src, n * sizeof(int)); // (an empty vector's data() may be null)
            break;
        }
        case AttrKind::RealVector: {
            const uint64_t n = c.count(sizeof(Real));
            std::vector<Real> x(n);
            const char* src = c.bytes(n * sizeof(Real));
            if (n) std::memcpy(x.data(), src, n * sizeof(Real));
            auto& dst = *static_cast<std::vector<Real>*>(p);
            // (a list as long as the default one, e.g. the unset NaN vertices of Facet(), has its items as defaults)
            Validate::checkFlags(a, x.data(), dst.size() == x.size() ? dst.data() : nullptr, (int)x.size(), where);
            dst = std::move(x);
            break;
        }
        case AttrKind::Vector3rVector: {
            const uint64_t n = c.count(3 * sizeof(Real));
            std::vector<Vector3r> x(n);
            for (auto& v : x) std::memcpy(v.data(), c.bytes(3 * sizeof(Real)), 3 * sizeof(Real));
            auto& dst = *static_cast<std::vector<Vector3r>*>(p);
            if (n) Validate::checkFlags(a, x[0].data(), dst.size() == n ? dst[0].data() : nullptr, int(3 * n), where);
            dst = std::move(x);
            break;
        }
        case AttrKind::Vector2rVector: {
            const uint64_t n = c.count(2 * sizeof(Real));
            std::vector<Vector2r> x(n);
            for (auto& v : x) std::memcpy(v.data(), c.bytes(2 * sizeof(Real)), 2 * sizeof(Real));
            auto& dst = *static_cast<std::vector<Vector2r>*>(p);
            if (n) Validate::checkFlags(a, x[0].data(), dst.size() == n ? dst[0].data() : nullptr, int(2 * n), where);
            dst = std::move(x);
            break;
        }
        case AttrKind::QuaternionrVector: {
            const uint64_t n = c.count(4 * sizeof(Real));
            std::vector<Quaternionr> x(n);
            for (auto& v : x) std::memcpy(v.coeffs().data(), c.bytes(4 * sizeof(Real)), 4 * sizeof(Real));
            for (const auto& v : x)
                if (!v.coeffs().allFinite() || v.coeffs().squaredNorm() == 0) throw FormatError(where + ": a quaternion is not finite or zero");
            *static_cast<std::vector<Quaternionr>*>(p) = std::move(x);
            break;
        }
        case AttrKind::StringVector: {
            const uint64_t n = c.count(1);
            auto& dst = *static_cast<std::vector<std::string>*>(p);
            dst.clear();
            for (uint64_t i = 0; i < n; ++i) dst.push_back(Validate::utf8(c.string(), where));
            break;
        }
        case AttrKind::PtrVector: {
            const uint64_t n = c.count(sizeof(ObjectRef));
            std::vector<ObjectRef> r(n);
            for (auto& x : r) x = c.get<ObjectRef>();
            refs->bindList(p, a, std::move(r), where);
            break;
        }
        default: throw std::logic_error("Columns: not a kind of variable length");
    }
}

} // namespace

void Columns::write(Encoder& e, const AttrInfo& a, Serializable* const* objs, size_t n, RefWriter* refs) {
    const size_t w = width(a.kind);
    if (!w) {
        e.put<uint8_t>(0);
        for (size_t i = 0; i < n; ++i) writeVariable(e, a, const_cast<void*>(a.peek(*objs[i])), refs);
        return;
    }
    const size_t modeAt = e.out.size();
    e.put<uint8_t>(0);
    const size_t start = e.out.size();
    e.out.resize(start + n * w);
    char* dst = &e.out[start];
    for (size_t i = 0; i < n; ++i, dst += w) {
        const void* p = a.peek(*objs[i]);
        if (a.kind == AttrKind::Bool) *dst = *static_cast<const bool*>(p) ? 1 : 0;
        else if (a.kind == AttrKind::Ptr) {
            const ObjectRef r = refs->ref(a.getPtr(const_cast<void*>(p)), 1);
            std::memcpy(dst, &r, w);
        } else std::memcpy(dst, p, w);
    }
    // one value for all (a shared material, a default left as it is): written once
    const char* first = e.out.data() + start;
    for (size_t i = 1; i < n; ++i)
        if (std::memcmp(first, first + i * w, w) != 0) return;
    if (n > 1) {
        e.out.resize(start + w);
        e.out[modeAt] = 1;
    }
}

void Columns::writeRaw(Encoder& e, const void* data, size_t w, size_t n) {
    const char* d = static_cast<const char*>(data);
    bool same = n > 1;
    for (size_t i = 1; same && i < n; ++i) same = std::memcmp(d, d + i * w, w) == 0;
    e.put<uint8_t>(same ? 1 : 0);
    e.bytes(d, same ? w : n * w);
}

std::pair<const char*, size_t> Columns::readRaw(Cursor& c, size_t w, size_t n) {
    const unsigned mode = c.get<uint8_t>();
    if (mode > 1) c.fail("unknown column encoding");
    return {c.bytes(mode == 1 ? (n ? w : 0) : n * w), mode == 1 ? 0 : w};
}

void Columns::read(Cursor& c, const AttrInfo& a, Serializable* const* objs, size_t n, RefReader* refs, const std::string& className) {
    const std::string where = className + "." + a.name;
    const unsigned mode = c.get<uint8_t>();
    const size_t w = width(a.kind);
    if (mode > 1 || (mode == 1 && !w)) c.fail(where + ": unknown column encoding");
    if (!w) {
        for (size_t i = 0; i < n; ++i) readVariable(c, a, a.address(*objs[i]), refs, where);
        return;
    }
    const char* src = c.bytes(mode == 1 ? (n ? w : 0) : n * w);
    const size_t step = mode == 1 ? 0 : w;
    const bool flags = Validate::hasValueFlags(a) && isRealKind(a.kind);
    Real x[9];
    for (size_t i = 0; i < n; ++i, src += step) {
        // (a value equal to the object's is not written: a record made when first written, as the
        // seldom used attributes of a MindlinPhys, is not made for defaults)
        if (a.kind != AttrKind::Ptr && a.kind != AttrKind::Bool && std::memcmp(a.peek(*objs[i]), src, w) == 0) continue;
        void* p = a.address(*objs[i]);
        switch (a.kind) {
            case AttrKind::Bool: *static_cast<bool*>(p) = *src != 0; break;
            case AttrKind::Int: {
                int v;
                std::memcpy(&v, src, w);
                if (Validate::hasValueFlags(a)) {
                    const Real xv = v, dflt = *static_cast<int*>(p);
                    Validate::checkFlags(a, &xv, &dflt, 1, where);
                }
                *static_cast<int*>(p) = v;
                break;
            }
            case AttrKind::Ptr: {
                ObjectRef r;
                std::memcpy(&r, src, w);
                refs->bind(p, a, r, where);
                break;
            }
            case AttrKind::Quaternionr:
                std::memcpy(x, src, w);
                Validate::checkQuaternion(x, where);
                std::memcpy(p, x, w);
                break;
            default:
                if (flags) {
                    std::memcpy(x, src, w);
                    Validate::checkFlags(a, x, static_cast<const Real*>(p), componentsOf(a.kind), where);
                }
                std::memcpy(p, src, w); // (Long, the integer vectors: any bits are a value)
        }
    }
}

} // namespace yade
