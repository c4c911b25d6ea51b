// The registry of classes: name, base, factory, attribute table and dispatch index of each
// class; filled once at start-up from the classes.def lists (see pkg/RegisterClasses.cpp).
#pragma once
#include <lib/factory/Indexable.hpp>
#include <lib/serialization/Serializable.hpp>
#include <functional>
#include <map>
#include <new>
#include <stdexcept>
#include <typeindex>
#include <unordered_map>

namespace yade {

// One attribute of one class, type-erased; made from a single v.attr(...) line.
struct AttrInfo {
    std::string name, doc;
    unsigned flags = 0;
    AttrKind kind;
    std::function<void*(Serializable&)> address; // where the member lives in an object
    // Where its value can be read without making anything (a side record made when first written
    // is not made: its defaults are read). The writer of saved files reads through it.
    std::function<const void*(Serializable&)> peek;
    // For Ptr / PtrVector kinds: the pointee type and type-checked access.
    const std::type_info* pointee = nullptr;
    std::function<std::shared_ptr<Serializable>(void*)> getPtr;
    std::function<bool(void*, const std::shared_ptr<Serializable>&)> setPtr; // false: wrong type
    std::function<std::vector<std::shared_ptr<Serializable>>(void*)> getPtrVector;
    std::function<bool(void*, const std::vector<std::shared_ptr<Serializable>>&)> setPtrVector;
    bool has(unsigned f) const { return (flags & f) != 0; }
};

struct ClassInfo {
    std::string name, baseName;
    std::string doc; // the class's own T::classDoc (empty if it declares none); Python's __doc__ starts with it
    const std::type_info* type = nullptr;
    std::function<std::shared_ptr<Serializable>()> factory;
    std::vector<AttrInfo> attrs; // all attributes, inherited ones first
    size_t ownAttrsBegin = 0;    // attrs[ownAttrsBegin:] are declared by this class itself
    std::string family;          // indexable family root ("Shape", "Material"...), empty if none
    int classIndex = -1;
    // Objects of the class in memory someone else manages (ContactPool): sizeof, alignof, a copy
    // constructed at an address, and a copy assigned to an object of the class (set for the
    // classes with HasViewTarget only: contact geometry and physics).
    size_t size = 0, align = 0;
    Serializable* (*copyAt)(void* at, const Serializable& from) = nullptr;
    void (*assign)(Serializable& to, const Serializable& from) = nullptr;
    const AttrInfo* findAttr(const std::string& n) const {
        for (const auto& a : attrs)
            if (a.name == n) return &a;
        return nullptr;
    }
};

class ClassRegistry {
public:
    static ClassRegistry& instance();

    template <class T, class Base> void add(const char* name);

    const ClassInfo* find(const std::string& name) const;
    const ClassInfo* find(const std::type_info& t) const;
    const ClassInfo& get(const std::type_info& t) const; // throws if not registered
    const std::vector<const ClassInfo*>& all() const { return ordered; }
    std::shared_ptr<Serializable> create(const std::string& name) const;
    bool isSubclass(const std::string& derived, const std::string& base) const;
    // Index of the base class in the same family, -1 at the root.
    int parentIndex(const std::string& family, int index) const;
    int familySize(const std::string& family) const;
    const ClassInfo* byIndex(const std::string& family, int index) const;

private:
    std::map<std::string, std::unique_ptr<ClassInfo>> byName;
    std::unordered_map<std::type_index, const ClassInfo*> byType;
    std::vector<const ClassInfo*> ordered; // registration order: bases before derived classes
    std::map<std::string, std::vector<std::pair<const ClassInfo*, int>>> families; // (class, parent index)
    ClassInfo& insert(const char* name, const char* baseName, const std::type_info& t);
};

// Classes some of whose attributes are members of a record outside the object: T::hasSideRecord,
// the record T::sideRecord() (of type T::SideRecord) of the prototype, and T::sideAddress(offset of
// the member in the record) giving where the value of an object is now. A State's hot values are
// in the scene's BodyStore while it is bound; a MindlinPhys keeps the attributes its law seldom
// uses in a record of their own, out of the contact's record that the law streams every step.
template <class T, class = void> struct HasSideRecord : std::false_type {};
template <class T> struct HasSideRecord<T, std::void_t<decltype(T::hasSideRecord)>> : std::bool_constant<T::hasSideRecord> {};
// ...and T::sidePeek(offset), where the value can be read without making the record (else: sideAddress).
template <class T, class = void> struct HasSidePeek : std::false_type {};
template <class T> struct HasSidePeek<T, std::void_t<decltype(std::declval<T&>().sidePeek(std::ptrdiff_t()))>> : std::true_type {};

// Classes whose objects may be views of another object of the same class (a contact's geometry
// or physics kept in a ContactPool): T::viewTarget() is that object, or null (the object's own
// members); every attribute is read and written there.
template <class T, class = void> struct HasViewTarget : std::false_type {};
template <class T> struct HasViewTarget<T, std::void_t<decltype(std::declval<T&>().viewTarget())>> : std::true_type {};

// Classes that describe themselves: `static constexpr const char* classDoc = "...";` in the class
// body. A derived class that declares none would inherit its base's, so ownClassDoc takes it only
// when T's classDoc is another object than Base's.
template <class T, class = void> struct HasClassDoc : std::false_type {};
template <class T> struct HasClassDoc<T, std::void_t<decltype(T::classDoc)>> : std::true_type {};
template <class T, class Base> const char* ownClassDoc() {
    if constexpr (!HasClassDoc<T>::value) return "";
    else if constexpr (std::is_same_v<T, Base> || !HasClassDoc<Base>::value) return T::classDoc;
    else return &T::classDoc == &Base::classDoc ? "" : T::classDoc;
}

// Builds the AttrInfo table of class T by visiting a prototype instance.
template <class T> struct AttrCollector {
    T& proto;
    std::vector<AttrInfo>& out;
    template <class M> void attr(const char* name, M& member, const char* doc, unsigned flags = 0) {
        AttrInfo a;
        a.name = name;
        a.doc = doc;
        a.flags = flags;
        a.kind = AttrKindOf<M>::kind;
        const std::ptrdiff_t offset = reinterpret_cast<char*>(&member) - reinterpret_cast<char*>(&proto);
        a.address = [offset](Serializable& s) -> void* { return reinterpret_cast<char*>(static_cast<T*>(&s)) + offset; };
        if constexpr (HasViewTarget<T>::value)
            a.address = [offset](Serializable& s) -> void* {
                Serializable* target = static_cast<T&>(s).viewTarget();
                return reinterpret_cast<char*>(static_cast<T*>(target ? target : &s)) + offset;
            };
        if constexpr (HasSideRecord<T>::value) { // a member of the object's side record
            const char* lo = reinterpret_cast<const char*>(proto.sideRecord());
            const char* m = reinterpret_cast<const char*>(&member);
            if (m >= lo && m < lo + sizeof(typename T::SideRecord)) {
                const std::ptrdiff_t inRecord = m - lo;
                a.address = [inRecord](Serializable& s) -> void* { return static_cast<T&>(s).sideAddress(inRecord); };
                if constexpr (HasViewTarget<T>::value)
                    a.address = [inRecord](Serializable& s) -> void* {
                        Serializable* target = static_cast<T&>(s).viewTarget();
                        return static_cast<T*>(target ? target : &s)->sideAddress(inRecord);
                    };
                if constexpr (HasSidePeek<T>::value) {
                    a.peek = [inRecord](Serializable& s) -> const void* {
                        Serializable* target = nullptr;
                        if constexpr (HasViewTarget<T>::value) target = static_cast<T&>(s).viewTarget();
                        return static_cast<T*>(target ? target : &s)->sidePeek(inRecord);
                    };
                }
            }
        }
        if (flags & Attr::classWide) { // a static member: the same place for every object
            void* where = &member;
            a.address = [where](Serializable&) -> void* { return where; };
        }
        if (!a.peek) a.peek = [address = a.address](Serializable& s) -> const void* { return address(s); };
        if constexpr (AttrKindOf<M>::kind == AttrKind::Ptr) {
            using P = typename M::element_type;
            a.pointee = &typeid(P);
            a.getPtr = [](void* m) -> std::shared_ptr<Serializable> { return *static_cast<M*>(m); };
            a.setPtr = [](void* m, const std::shared_ptr<Serializable>& v) {
                auto p = std::dynamic_pointer_cast<P>(v);
                if (v && !p) return false;
                *static_cast<M*>(m) = p;
                return true;
            };
        } else if constexpr (AttrKindOf<M>::kind == AttrKind::PtrVector) {
            using P = typename M::value_type::element_type;
            a.pointee = &typeid(P);
            a.getPtrVector = [](void* m) {
                std::vector<std::shared_ptr<Serializable>> r;
                for (const auto& p : *static_cast<M*>(m)) r.push_back(p);
                return r;
            };
            a.setPtrVector = [](void* m, const std::vector<std::shared_ptr<Serializable>>& v) {
                M r;
                for (const auto& p : v) {
                    auto c = std::dynamic_pointer_cast<P>(p);
                    if (!c) return false;
                    r.push_back(c);
                }
                *static_cast<M*>(m) = std::move(r);
                return true;
            };
        }
        out.push_back(std::move(a));
    }
};

template <class T, class Base> void ClassRegistry::add(const char* name) {
    static_assert(std::is_base_of_v<Serializable, T>, "registered classes derive from Serializable");
    static_assert(std::is_same_v<T, Base> || std::is_base_of_v<Base, T>, "Base must be a base of T");
    const bool root = std::is_same_v<T, Base>;
    ClassInfo& info = insert(name, root ? "" : ClassRegistry::get(typeid(Base)).name.c_str(), typeid(T));
    info.factory = [] { return std::static_pointer_cast<Serializable>(std::make_shared<T>()); };
    info.doc = ownClassDoc<T, Base>();
    info.size = sizeof(T);
    info.align = alignof(T);
    if constexpr (HasViewTarget<T>::value) { // (contact geometry and physics: kept in ContactPools)
        info.copyAt = [](void* at, const Serializable& from) -> Serializable* { return new (at) T(static_cast<const T&>(from)); };
        info.assign = [](Serializable& to, const Serializable& from) { static_cast<T&>(to) = static_cast<const T&>(from); };
    }
    T proto;
    AttrCollector<T> collector{proto, info.attrs};
    proto.visit(collector);
    if (!root) {
        const ClassInfo& base = get(typeid(Base));
        info.ownAttrsBegin = base.attrs.size();
        for (size_t i = 0; i < base.attrs.size(); ++i)
            if (i >= info.attrs.size() || info.attrs[i].name != base.attrs[i].name)
                throw std::logic_error(std::string(name) + "::visit must call " + base.name + "::visit first");
    }
    if constexpr (IsIndexable<T>::value) {
        static_assert(std::is_same_v<typename T::IndexedClass, T>, "a class of an indexable family needs YADE_INDEXABLE(Class)");
        info.family = get(typeid(typename T::IndexableRoot)).name;
        auto& fam = families[info.family];
        int parent = -1;
        if constexpr (!std::is_same_v<T, typename T::IndexableRoot>) parent = Base::classIndexStatic();
        T::classIndexStatic() = info.classIndex = static_cast<int>(fam.size());
        fam.emplace_back(&info, parent);
    }
}

} // namespace yade
