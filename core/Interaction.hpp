// A pair of bodies: created by the collider (potential), real once geom and phys exist (1.2.1).
#pragma once
#include <core/Body.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>

namespace yade {

class Interaction : public Serializable {
public:
    static constexpr const char* classDoc = "A pair of bodies (1.2.1): potential when only their bounds overlap, real once it has geom (IGeom) and phys (IPhys).";
    Body::id_t id1 = -1, id2 = -1;
    long long iterBorn = -1;     // the step the pair was added (the collider, or utils.createInteraction)
    long long iterMadeReal = -1;
    long long iterLastSeen = -1; // last iteration the collider saw the bounds overlap
    Vector3i cellDist = Vector3i::Zero();
    std::shared_ptr<IGeom> geom;
    std::shared_ptr<IPhys> phys;
    // Set when the container erased this interaction while someone (Python) still held it: its
    // Python attributes then raise instead of showing a pair that no longer exists.
    bool erased = false;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("id1", id1, "Id of the first body", Attr::readonly);
        v.attr("id2", id2, "Id of the second body", Attr::readonly);
        v.attr("iterBorn", iterBorn, "Step at which the interaction was added to the simulation", Attr::readonly);
        v.attr("iterMadeReal", iterMadeReal, "Iteration when the interaction became real (-1: not real)", Attr::readonly);
        v.attr("iterLastSeen", iterLastSeen, "Iteration when the collider last saw the bounds overlap", Attr::hidden);
        v.attr("cellDist", cellDist, "Periodic cell shift of body 2 relative to body 1", Attr::readonly);
        v.attr("geom", geom, "Geometry of the contact (IGeom)");
        v.attr("phys", phys, "Physics of the contact (IPhys)");
    }
    Interaction() = default;
    Interaction(Body::id_t a, Body::id_t b) : id1(a), id2(b) {}
    bool isReal() const { return geom && phys; }
    void reset() { // back to a potential interaction
        geom.reset();
        phys.reset();
        iterMadeReal = -1;
    }
    void swapOrder() { std::swap(id1, id2); cellDist = -cellDist; }
};

// One interaction as the batched functors see it (IGeomFunctorBatched, LawFunctorBatched): its
// geometry and physics objects (a contact's are in its ContactPool record) and the two ids, read
// from InteractionContainer's columns; the Interaction object is not touched (a pair has one only
// while Python holds it). A geometry made by an Ig2 functor for a new contact is kept in *made
// until the loop has its physics and moves both into a pool.
class InteractionContainer;
// Body 2's image in a periodic scene: at pos2 + shift2, moving at vel2 + shiftVel2 (from the pair's
// cellDist: hSize·cellDist, and the field's velocity difference between the images).
struct ContactShift {
    Vector3r shift2, shiftVel2;
};
struct Contact {
    Interaction* I = nullptr;               // the interaction, or null: entry k of *owner
    InteractionContainer* owner = nullptr;
    long k = -1;
    IGeom* geom = nullptr;
    IPhys* phys = nullptr;
    Body::id_t id1 = -1, id2 = -1;
    std::shared_ptr<IGeom>* made = nullptr; // where a new geometry goes (the loop's scratch)
    // In a periodic scene, a pair through the cell's faces (else null): where body 2's image is (the
    // functors see the image instead of body 2).
    const ContactShift* shift = nullptr;
    bool isReal() const { return geom && phys; }
    Interaction& interaction() const; // (InteractionContainer.cpp)
    Contact() = default;
    explicit Contact(Interaction& i) : I(&i), geom(i.geom.get()), phys(i.phys.get()), id1(i.id1), id2(i.id2) {}
    Contact(Interaction* i, IGeom* g, IPhys* p, Body::id_t a, Body::id_t b) : I(i), geom(g), phys(p), id1(a), id2(b) {}
    Contact(InteractionContainer* c, long entry, IGeom* g, IPhys* p, Body::id_t a, Body::id_t b)
        : owner(c), k(entry), geom(g), phys(p), id1(a), id2(b) {}
    // A new geometry object of type G for this interaction (Ig2 functors, first contact).
    template <class G> G& makeGeom() {
        auto g = std::make_shared<G>();
        G& r = *g;
        setGeom(std::move(g));
        return r;
    }
    void setGeom(std::shared_ptr<IGeom> g); // (InteractionContainer.cpp)
};

} // namespace yade
