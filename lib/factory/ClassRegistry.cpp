#include <lib/factory/ClassRegistry.hpp>

namespace yade {

ClassRegistry& ClassRegistry::instance() {
    static ClassRegistry registry;
    return registry;
}

ClassInfo& ClassRegistry::insert(const char* name, const char* baseName, const std::type_info& t) {
    if (byName.count(name)) throw std::logic_error(std::string("class registered twice: ") + name);
    auto info = std::make_unique<ClassInfo>();
    info->name = name;
    info->baseName = baseName;
    info->type = &t;
    ClassInfo& ref = *info;
    byType[std::type_index(t)] = &ref;
    ordered.push_back(&ref);
    byName[name] = std::move(info);
    return ref;
}

const ClassInfo* ClassRegistry::find(const std::string& name) const {
    auto it = byName.find(name);
    return it == byName.end() ? nullptr : it->second.get();
}

const ClassInfo* ClassRegistry::find(const std::type_info& t) const {
    auto it = byType.find(std::type_index(t));
    return it == byType.end() ? nullptr : it->second;
}

const ClassInfo& ClassRegistry::get(const std::type_info& t) const {
    const ClassInfo* i = find(t);
    if (!i) throw std::logic_error(std::string("class not registered: ") + t.name());
    return *i;
}

std::shared_ptr<Serializable> ClassRegistry::create(const std::string& name) const {
    const ClassInfo* i = find(name);
    if (!i) throw std::invalid_argument("unknown class '" + name + "'");
    return i->factory();
}

bool ClassRegistry::isSubclass(const std::string& derived, const std::string& base) const {
    for (const ClassInfo* i = find(derived); i; i = i->baseName.empty() ? nullptr : find(i->baseName))
        if (i->name == base) return true;
    return false;
}

int ClassRegistry::parentIndex(const std::string& family, int index) const {
    auto it = families.find(family);
    if (it == families.end() || index < 0 || index >= (int)it->second.size()) return -1;
    return it->second[index].second;
}

int ClassRegistry::familySize(const std::string& family) const {
    auto it = families.find(family);
    return it == families.end() ? 0 : (int)it->second.size();
}

const ClassInfo* ClassRegistry::byIndex(const std::string& family, int index) const {
    auto it = families.find(family);
    if (it == families.end() || index < 0 || index >= (int)it->second.size()) return nullptr;
    return it->second[index].first;
}

std::string Serializable::getClassName() const {
    const ClassInfo* i = ClassRegistry::instance().find(typeid(*this));
    return i ? i->name : std::string(typeid(*this).name());
}

} // namespace yade
