// Python classes for every registered C++ class, made generically from the attribute table;
// the few hand-written members below are derived properties and methods, not attributes.
#include <lib/base/ExternalWrites.hpp>
#include <AllHeaders.hpp>
#include <functional>
#include <py/wrapper/Attributes.hpp>
#include <py/wrapper/Classes.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

using CtorArgs = std::function<void(Serializable&, py::args)>;

// Classes that take positional constructor arguments, e.g. BoundDispatcher([Bo1_Sphere_Aabb()]).
static std::map<std::string, CtorArgs>& ctorArgHandlers() {
    static std::map<std::string, CtorArgs> handlers;
    return handlers;
}

static const CtorArgs* findCtorArgs(const ClassInfo& info) {
    for (const ClassInfo* c = &info; c; c = c->baseName.empty() ? nullptr : ClassRegistry::instance().find(c->baseName)) {
        auto it = ctorArgHandlers().find(c->name);
        if (it != ctorArgHandlers().end()) return &it->second;
    }
    return nullptr;
}

static std::shared_ptr<Serializable> construct(const ClassInfo& info, py::handle cls, py::args args, py::kwargs kw) {
    std::shared_ptr<Serializable> obj = info.factory();
    if (args.size() > 0) {
        const CtorArgs* handler = findCtorArgs(info);
        if (!handler) throw py::type_error(info.name + "() takes no positional arguments; give attributes as keywords, e.g. " + info.name + "(label='x')");
        (*handler)(*obj, args);
    }
    py::object wrapper; // made only for Python-side properties such as State.blockedDOFs
    for (auto item : kw) {
        const std::string name = py::cast<std::string>(item.first);
        const AttrInfo* a = info.findAttr(name);
        if (a && !a->has(Attr::hidden)) {
            setAttr(*obj, *a, item.second);
        } else if (py::hasattr(cls, name.c_str()) && py::isinstance(cls.attr(name.c_str()), py::module_::import("builtins").attr("property"))) {
            if (!wrapper) wrapper = py::cast(obj);
            wrapper.attr(name.c_str()) = item.second;
        } else {
            throw py::attribute_error(info.name + " has no attribute '" + name + "'");
        }
    }
    obj->postLoad();
    return obj;
}

template <class T, class Base> void bindClass(py::module_& m, const char* name) {
    const ClassInfo* info = &ClassRegistry::instance().get(typeid(T));
    auto init = [info] {
        return py::init([info](py::args a, py::kwargs k) {
            return std::static_pointer_cast<T>(construct(*info, py::type::handle_of<T>(), a, k));
        });
    };
    if constexpr (std::is_same_v<T, Base>) {
        py::class_<T, std::shared_ptr<T>> cls(m, name);
        cls.def(init());
        defineAttrProperties(cls, *info);
    } else {
        py::class_<T, Base, std::shared_ptr<T>> cls(m, name);
        cls.def(init());
        defineAttrProperties(cls, *info);
    }
}

static std::string hexAddress(const void* p) {
    std::ostringstream os;
    os << p;
    return os.str();
}

// A functor of the same class as an earlier one in the list replaces it (as in Yade:
// LawDispatcher([Law2_X(), Law2_X()]) has one functor, the last one).
static py::object withoutRepeatedClasses(py::handle list) {
    if (!py::isinstance<py::list>(list) && !py::isinstance<py::tuple>(list)) return py::reinterpret_borrow<py::object>(list); // (setAttr says what is wrong)
    py::list out;
    for (py::handle f : list) {
        bool replaced = false;
        for (size_t i = 0; i < out.size() && !replaced; ++i)
            if (!f.is_none() && out[i].get_type().is(f.get_type())) {
                out[i] = f;
                replaced = true;
            }
        if (!replaced) out.append(f);
    }
    return out;
}

template <class D> static void setFunctors(D& d, py::handle list, const char* what) {
    const AttrInfo* a = ClassRegistry::instance().get(typeid(D)).findAttr("functors");
    try {
        setAttr(d, *a, withoutRepeatedClasses(list));
    } catch (py::error_already_set&) {
        throw;
    } catch (py::type_error& e) {
        throw py::type_error(std::string(what) + ": " + e.what());
    }
}

template <class D> static void setFunctorsFromArgs(D& d, py::args a, const char* what) {
    if (a.size() != 1) throw py::value_error(std::string(what) + " takes exactly one list of functors as positional argument");
    setFunctors(d, a[0], what);
}

// The Python class already bound for T, to add hand-written members to it.
template <class T, class Base> static py::class_<T, Base, std::shared_ptr<T>> existing() {
    return py::reinterpret_borrow<py::class_<T, Base, std::shared_ptr<T>>>(py::type::handle_of<T>());
}

// The Python object of functor f of dispatcher d (None for null).
static py::object functorObject(const Dispatcher& d, const Functor* f) {
    for (const auto& g : d.functorsBase())
        if (g.get() == f) return py::cast(std::static_pointer_cast<Serializable>(g));
    return py::none();
}

// D.dispFunctor(a, b): the functor a two-argument dispatcher would choose for these objects.
template <class D, class A, class B> static void bindDispFunctor2D(const char* doc) {
    existing<D, Dispatcher>().def("dispFunctor", [](D& d, std::shared_ptr<A> a, std::shared_ptr<B> b) {
        return functorObject(d, a && b ? d.getFunctor(*a, *b).functor : nullptr);
    }, doc);
}

// D.dispMatrix(names=True): what the functors declare, {(class, ...): functor class name}, with both orders
// of a pair where the dispatcher swaps arguments (Ig2, Ip2); the first functor of a pair wins, as in
// dispatch. names=False: the classes' indices in their family here (the reference's numbers differ).
template <class D> static void bindDispMatrix(std::vector<const char*> families, bool symmetric) {
    existing<D, Dispatcher>().def("dispMatrix", [families, symmetric](D& d, bool names) {
        py::dict r;
        auto add = [&](const std::vector<std::string>& types, const std::string& functor) {
            py::list k;
            for (size_t i = 0; i < types.size(); ++i) {
                if (names) k.append(types[i]);
                else k.append(familyIndexOf(families[i], types[i]));
            }
            const py::tuple key(k);
            if (!r.contains(key)) r[key] = functor;
        };
        for (const auto& f : d.functorsBase()) {
            if (!f) continue;
            const std::vector<std::string> t = f->argTypes();
            if (t.size() != families.size()) continue;
            add(t, f->getClassName());
            if (symmetric && t.size() == 2 && t[0] != t[1]) add({t[1], t[0]}, f->getClassName());
        }
        return r;
    }, py::arg("names") = true, "The dispatch matrix: {(class names): functor class name} of the pairs the functors declare (names=False: class indices)");
}

// Members that are computed, not stored: derived properties and methods.
// An Interaction that O.interactions erased (the collider dropped the pair, a body was erased, the
// interactions were cleared) while Python held it: its attributes raise ReferenceError instead of
// showing a pair that no longer exists (InteractionContainer::eraseAt marks it).
static void guardErasedInteractions(py::module_& m) {
    py::object cls = m.attr("Interaction");
    py::object property = py::module_::import("builtins").attr("property");
    auto check = [](py::handle self, const std::string& name) {
        const Interaction& I = py::cast<const Interaction&>(self);
        if (!I.erased) return;
        const std::string message = ("Interaction ##" + std::to_string(I.id1) + "+" + std::to_string(I.id2) + " was erased from O.interactions "
                    "(the bounds of its bodies no longer overlap, one of them was erased, or the interactions were cleared): "
                    "its ." + name + " can no longer be read or set; get the pair again with O.interactions[id1, id2]");
        PyErr_SetString(PyExc_ReferenceError, message.c_str());
        throw py::error_already_set();
    };
    for (const char* name : {"id1", "id2", "iterBorn", "iterMadeReal", "cellDist", "geom", "phys", "isReal"}) {
        py::object old = cls.attr("__dict__")[name];
        py::object fget = old.attr("fget"), fset = old.attr("fset");
        const std::string n = name;
        py::cpp_function getter([fget, n, check](py::object self) {
            check(self, n);
            return fget(self);
        });
        py::object setter = py::none();
        if (!fset.is_none())
            setter = py::cpp_function([fset, n, check](py::object self, py::object v) {
                check(self, n);
                fset(self, v);
            });
        py::setattr(cls, name, property(getter, setter, py::none(), old.attr("__doc__")));
    }
}

static void bindExtras(py::module_& m) {
    auto serCls = py::reinterpret_borrow<py::class_<Serializable, std::shared_ptr<Serializable>>>(py::type::handle_of<Serializable>());
    serCls.def("dict", [](py::object self) { return attrDict(py::cast<Serializable&>(self), self); },
                  "Attributes as a dict {name: value}")
            .def("updateAttrs", [](py::object self, py::dict d) {
                Serializable& s = py::cast<Serializable&>(self);
                for (auto item : d) {
                    const std::string n = py::cast<std::string>(item.first);
                    if (!py::hasattr(self, n.c_str())) throw py::attribute_error(s.getClassName() + " has no attribute '" + n + "'");
                    self.attr(n.c_str()) = item.second;
                }
            }, "Set attributes from a dict")
            .def("__repr__", [](Serializable& s) { return "<" + s.getClassName() + " instance at " + hexAddress(&s) + ">"; })
            .def("__eq__", [](Serializable& a, py::object b) { return py::isinstance<Serializable>(b) && &a == &py::cast<Serializable&>(b); })
            .def("__ne__", [](Serializable& a, py::object b) { return !(py::isinstance<Serializable>(b) && &a == &py::cast<Serializable&>(b)); })
            .def("__hash__", [](Serializable& a) { return std::hash<const void*>()(&a); });

    for (const char* family : {"Shape", "Material", "Bound", "IGeom", "IPhys", "State"}) {
        m.attr(family).attr("dispIndex") = py::module_::import("builtins").attr("property")(
                py::cpp_function([](py::object self) { return classInfoOf(py::cast<Serializable&>(self)).classIndex; }),
                py::none(), py::none(), "Index of the class for dispatch (read-only)");
    }

    existing<Functor, Serializable>().def_property_readonly("bases", &Functor::argTypes,
            "Names of the classes this functor takes, as the dispatcher matches them (read-only)");

    existing<State, Serializable>()
            .def_property("blockedDOFs", &State::blockedDOFs,
                    [](State& st, const std::string& dofs) {
                        noteExternalWrite();
                        st.setBlockedDOFs(dofs);
                    },
                    "Degrees of freedom the integrator does not change, as a string of 'xyzXYZ' (capitals: rotations)")
            .def_property("se3",
                    [](py::object self) { return py::make_tuple(self.attr("pos"), self.attr("ori")); },
                    [](py::object self, py::object v) {
                        if (!py::isinstance<py::sequence>(v) || py::len(v) != 2) throw py::type_error("State.se3: expected (pos, ori), a Vector3 and a Quaternion");
                        py::sequence pair = v;
                        py::object oldPos = self.attr("pos");
                        self.attr("pos") = pair[0];
                        try {
                            self.attr("ori") = pair[1];
                        } catch (...) {
                            self.attr("pos") = oldPos; // (the state as it was)
                            throw;
                        }
                    },
                    "Position and orientation as one (pos, ori) pair (copies)")
            .def("displ", &State::displ, "Displacement from refPos")
            .def("rot", &State::rot, "Rotation from refOri (axis × angle)");

    existing<Body, Serializable>()
            .def_property("mat", [](py::object self) { return self.attr("material"); },
                    [](py::object self, py::object v) { self.attr("material") = v; }, "Alias of material")
            .def("intrs", [](Body& b) { return bodyInteractions(b); }, "Interactions (real ones) of this body in O.interactions")
            .def_property("dynamic", &Body::isDynamic,
                    [](Body& b, bool d) {
                        noteExternalWrite();
                        b.setDynamic(d);
                    },
                    "Whether forces move this body; False blocks all its degrees of freedom (State.blockedDOFs='xyzXYZ') and it keeps its prescribed velocity")
            .def_property_readonly("isStandalone", [](Body& b) { return b.clumpId < 0; }, "Whether this body is neither a clump nor a clump's member")
            .def_property_readonly("isClump", &Body::isClump, "Whether this body is a clump (O.bodies.appendClumped, O.bodies.clump)")
            .def_property_readonly("isClumpMember", &Body::isClumpMember, "Whether this body is a member of a clump (Body.clumpId is the clump's id)")
            .def_property("groupMask", [](py::object self) { return self.attr("mask"); },
                    [](py::object self, py::object v) { self.attr("mask") = v; }, "Old name of mask");

    existing<Clump, Shape>()
            .def_property_readonly("members",
                    [](const Clump& c) {
                        py::dict d;
                        for (size_t k = 0; k < c.memberIds.size(); ++k) d[py::int_(c.memberIds[k])] = py::make_tuple(c.relPos[k], c.relOri[k]);
                        return d;
                    },
                    "The members: {id: (position, orientation)} in the clump's frame")
            .def_property_readonly("ids", [](const Clump& c) { return c.memberIds; }, "Ids of the members (as memberIds)");

    existing<Interaction, Serializable>()
            .def_property_readonly("isReal", &Interaction::isReal, "Whether geom and phys exist (a contact, not only overlapping bounds)")
            .def_property_readonly("isActive", [](Interaction&) { return true; },
                    "Whether the interaction's forces count (always True here: deactivating an interaction is not supported; O.interactions.erase makes a contact potential)");
    guardErasedInteractions(m);

    ctorArgHandlers()["BoundDispatcher"] = [](Serializable& s, py::args a) { setFunctorsFromArgs(static_cast<BoundDispatcher&>(s), a, "BoundDispatcher"); };
    ctorArgHandlers()["IGeomDispatcher"] = [](Serializable& s, py::args a) { setFunctorsFromArgs(static_cast<IGeomDispatcher&>(s), a, "IGeomDispatcher"); };
    ctorArgHandlers()["IPhysDispatcher"] = [](Serializable& s, py::args a) { setFunctorsFromArgs(static_cast<IPhysDispatcher&>(s), a, "IPhysDispatcher"); };
    ctorArgHandlers()["Collider"] = [](Serializable& s, py::args a) {
        if (a.size() != 1) throw py::type_error("InsertionSortCollider takes one positional argument: the list of Bo1 functors");
        setFunctors(*static_cast<Collider&>(s).boundDispatcher, a[0], "Bo1 functors");
    };
    ctorArgHandlers()["InteractionLoop"] = [](Serializable& s, py::args a) {
        if (a.size() != 3) throw py::type_error("InteractionLoop takes three lists: [Ig2 functors], [Ip2 functors], [Law2 functors]");
        auto& loop = static_cast<InteractionLoop&>(s);
        setFunctors(*loop.geomDispatcher, a[0], "InteractionLoop, first list (Ig2 functors)");
        setFunctors(*loop.physDispatcher, a[1], "InteractionLoop, second list (Ip2 functors)");
        setFunctors(*loop.lawDispatcher, a[2], "InteractionLoop, third list (Law2 functors)");
        loop.checkFunctorChain();
    };
    // ParallelEngine.slaves: a list whose items are an engine (a group of one) or a list of engines
    const auto toGroups = [](py::handle list) {
        if (!py::isinstance<py::list>(list) && !py::isinstance<py::tuple>(list))
            throw py::type_error("ParallelEngine.slaves: expected a list of engines or lists of engines, got " + std::string(py::repr(list)));
        std::vector<std::vector<std::shared_ptr<Engine>>> groups;
        for (py::handle item : list) {
            std::vector<std::shared_ptr<Engine>> group;
            const bool many = py::isinstance<py::list>(item) || py::isinstance<py::tuple>(item);
            for (py::handle e : many ? py::reinterpret_borrow<py::iterable>(item) : py::reinterpret_borrow<py::iterable>(py::make_tuple(item))) {
                if (!py::isinstance<Engine>(e))
                    throw py::type_error("ParallelEngine.slaves: " + std::string(py::repr(e)) + " is not an engine");
                group.push_back(py::cast<std::shared_ptr<Engine>>(e));
            }
            groups.push_back(std::move(group));
        }
        return groups;
    };
    ctorArgHandlers()["ParallelEngine"] = [toGroups](Serializable& s, py::args a) {
        if (a.size() != 1) throw py::type_error("ParallelEngine takes one positional argument: the list of its slaves ([engine, [engine, engine], ...])");
        static_cast<ParallelEngine&>(s).setSlaves(toGroups(a[0]));
    };
    existing<ParallelEngine, Engine>().def_property("slaves",
            [](const ParallelEngine& pe) {
                py::list r;
                for (const auto& group : pe.slaves()) {
                    if (group.size() == 1) r.append(py::cast(group[0]));
                    else r.append(py::cast(group));
                }
                return r;
            },
            [toGroups](ParallelEngine& pe, py::object v) {
                noteExternalWrite();
                pe.setSlaves(toGroups(v));
            },
            "The groups of engines: each item an engine (a group of one) or a list of engines run in that order");
    // (read-only properties that the reference keeps out of dict(), as it does)
    existing<PeriIsoCompressor, BoundaryController>()
            .def_property_readonly("sigma", [](const PeriIsoCompressor& c) { return c.sigma; },
                    "Normal stresses of the packing, -Σ|f_i| / (area of face i) over the contacts, predicted to the end of the step [Pa]")
            .def_property_readonly("currUnbalanced", [](const PeriIsoCompressor& c) { return c.currUnbalanced; },
                    "Unbalanced force at the last check (-1: none yet)");
    ctorArgHandlers()["LawDispatcher"] = [](Serializable& s, py::args a) { setFunctorsFromArgs(static_cast<LawDispatcher&>(s), a, "LawDispatcher"); };

    existing<BoundDispatcher, Dispatcher>().def("dispFunctor", [](BoundDispatcher& d, std::shared_ptr<Shape> s) {
        return functorObject(d, s ? d.getFunctor(*s) : nullptr);
    }, "The functor that would handle this shape (None if none)");
    bindDispFunctor2D<IGeomDispatcher, Shape, Shape>("The functor that would handle this pair of shapes (None if none)");
    bindDispFunctor2D<IPhysDispatcher, Material, Material>("The functor that would handle this pair of materials (None if none)");
    bindDispFunctor2D<LawDispatcher, IGeom, IPhys>("The functor that would handle this (IGeom, IPhys) pair (None if none)");
    bindDispMatrix<BoundDispatcher>({"Shape"}, false);
    bindDispMatrix<IGeomDispatcher>({"Shape", "Shape"}, true);
    bindDispMatrix<IPhysDispatcher>({"Material", "Material"}, true);
    bindDispMatrix<LawDispatcher>({"IGeom", "IPhys"}, false);
}

// How help() shows the default of an attribute: repr of the value in a new object; objects by
// their class name (an address would change from one run to the next).
static std::string defaultRepr(const AttrInfo& a, py::handle value) {
    if (a.kind == AttrKind::Ptr) return value.is_none() ? "None" : py::str(value.get_type().attr("__name__")).cast<std::string>() + "()";
    if (a.kind == AttrKind::PtrVector) {
        std::string r = "[";
        for (py::handle v : value) r += (r.size() > 1 ? ", " : "") + py::str(v.get_type().attr("__name__")).cast<std::string>() + "()";
        return r + "]";
    }
    return py::repr(value).cast<std::string>();
}

// Python's __doc__ of every class: its classDoc, then its attributes with default values and
// descriptions (own ones first, then those inherited, base by base); each attribute's property
// doc also gets its default. help(Sphere) and IPython's Sphere? show both.
static void setClassDocs(py::module_& m) {
    const ClassRegistry& registry = ClassRegistry::instance();
    for (const ClassInfo* info : registry.all()) {
        py::object cls = m.attr(info->name.c_str());
        py::object proto;
        try {
            proto = py::cast(info->factory());
        } catch (std::exception&) {
        }
        std::string doc = info->doc.empty() ? "(no class description)" : info->doc;
        if (!info->baseName.empty()) doc += "\n\nDerives from " + info->baseName + ".";
        std::string own, inherited;
        std::string lastOwner;
        for (size_t i = 0; i < info->attrs.size(); ++i) {
            const AttrInfo& a = info->attrs[i];
            if (a.has(Attr::hidden)) continue;
            std::string def = "?";
            if (proto) {
                try {
                    def = defaultRepr(a, proto.attr(a.name.c_str()));
                } catch (py::error_already_set&) {
                }
            }
            const std::string line = "    " + a.name + " = " + def + "\n        " + a.doc + (a.has(Attr::readonly) ? " (read-only)" : "") + "\n";
            if (i >= info->ownAttrsBegin) {
                own += line;
                py::object prop = cls.attr("__dict__")[a.name.c_str()];
                std::string pdoc = py::str(prop.attr("__doc__")).cast<std::string>();
                prop.attr("__doc__") = pdoc + " [default: " + def + "]";
            } else {
                std::string owner; // the base class that declares attribute i
                for (const ClassInfo* c = registry.find(info->baseName); c; c = c->baseName.empty() ? nullptr : registry.find(c->baseName))
                    if (i >= c->ownAttrsBegin && i < c->attrs.size()) owner = c->name;
                if (owner != lastOwner) inherited += "  inherited from " + owner + ":\n";
                lastOwner = owner;
                inherited += line;
            }
        }
        if (!own.empty() || !inherited.empty()) doc += "\n\nAttributes (name = default value, then description):\n" + own + inherited;
        cls.attr("__doc__") = doc;
        cls.attr("__module__") = "yade.wrapper"; // where scripts import them from (py/yade/wrapper.py)
    }
}

void bindAllClasses(py::module_& m) {
#define YADE_CLASS(Class, Base) bindClass<Class, Base>(m, #Class);
#include <core/classes.def>
#include <pkg/common/classes.def>
#include <pkg/dem/classes.def>
#undef YADE_CLASS
    bindExtras(m);
    setClassDocs(m);
}

} // namespace yade
