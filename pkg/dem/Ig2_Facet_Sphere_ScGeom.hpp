// Contact of a facet and a sphere: with the face, an edge or a vertex.
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Ig2_Facet_Sphere_ScGeom : public IGeomFunctorBatched<Ig2_Facet_Sphere_ScGeom, Facet, Sphere, ScGeom> {
public:
    static constexpr const char* classDoc = "Ig2 functor: ScGeom of a Facet and a Sphere, the contact being with the face, an edge or a vertex.";
    Real shrinkFactor = 0;
    bool hertzian = false;
    static constexpr Real hertzianFacetRadius = 1e5; // [m], as the reference: R* = r·1e5/(r+1e5)
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("hertzian", hertzian, "Give the facet a very large radius (1e5 m) instead of twice the sphere's, so that a Hertzian law sees a sphere on a plane (effective radius r)");
        v.attr("shrinkFactor", shrinkFactor, "Shrink the facet's edges inwards by this fraction of the sphere radius", Attr::nonNegative);
    }
    bool go(const Facet& f, const Sphere& s, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
            Contact& contact);
    // The batch reads the spheres' radii from BodyColumns (contiguous) instead of their shapes.
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;
    bool go(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
    Real quickRejectFactor() const override { return 1; } // go() returns false when the plane is out of reach

    // The geometry kernel (core/ContactKernel.hpp): facet f[i] turned by ori[i] and a sphere of radius
    // r in lane i, body 2 shifted by shift2; oldNormal is the contact's normal at the last step
    // (unused for a new contact). distance: the sphere centre's distance from the facet's plane.
    template <class T>
    YADE_KERNEL ScGeom::Values<T> kernel(const Facet* const* f, const Quaternionr* const* ori, T r, const PairMotion<T>& m, const Vec3<T>& shift2,
            const Vec3<T>& oldNormal, bool isNew, T dt, T& distance) const {
        constexpr int lanes = lanesOf<T>;
        const T zero(0.0);
        // the sphere centre in the facet's frame (lane by lane, Eigen's rotation)
        Matrix3r toGlobal[lanes];
        Vector3r local[lanes];
        const Vec3<T> d = (m.pos2 + shift2) - m.pos1;
        for (int i = 0; i < lanes; ++i) {
            toGlobal[i] = ori[i]->toRotationMatrix();
            local[i] = toGlobal[i].transpose() * d.lane(i);
        }
        const Vec3<T> c = lanesOfVec<T>([&](int i) { return local[i]; });
        auto facetVec = [&](auto member) { return lanesOfVec<T>([&](int i) { return member(*f[i]); }); };
        auto facetReal = [&](auto member) { return eachLane<T>([&](int i) { return member(*f[i]); }); };
        // the side of the plane the centre is on
        const Vec3<T> facetNormal = facetVec([](const Facet& x) { return x.normal; });
        const T signedL = dot(facetNormal, c);
        const MaskOf<T> below = greater(zero, signedL);
        Vec3<T> normal = select(below, -facetNormal, facetNormal);
        const T L = select(below, -signedL, signedL);
        distance = L;
        const Vec3<T> cp = c - L * normal; // projection of the centre on the plane
        // The edge whose outward normal points most towards cp decides face / edge / vertex contact:
        // edge m (the first of the largest), its vertex m and the next one.
        const Vec3<T> ne[3] = {facetVec([](const Facet& x) { return x.ne[0]; }), facetVec([](const Facet& x) { return x.ne[1]; }),
                facetVec([](const Facet& x) { return x.ne[2]; })};
        const T b0 = dot(ne[0], cp), b1 = dot(ne[1], cp), b2 = dot(ne[2], cp);
        const MaskOf<T> is1 = greater(b1, b0);
        const T b01 = select(is1, b1, b0);
        const MaskOf<T> is2 = greater(b2, b01);
        const T bm = select(is2, b2, b01);
        auto at = [&](const auto* v, int m0, int m1, int m2) { return select(is2, v[m2], select(is1, v[m1], v[m0])); }; // (v[index] for m = 0, 1, 2)
        const Vec3<T> vu[3] = {facetVec([](const Facet& x) { return x.vu[0]; }), facetVec([](const Facet& x) { return x.vu[1]; }),
                facetVec([](const Facet& x) { return x.vu[2]; })};
        const T vl[3] = {facetReal([](const Facet& x) { return x.vl[0]; }), facetReal([](const Facet& x) { return x.vl[1]; }),
                facetReal([](const Facet& x) { return x.vl[2]; })};
        const T shrink = r * T(shrinkFactor);
        const T shrunk = facetReal([](const Facet& x) { return x.icr; }) - shrink;
        const T icr = select(greater(shrunk, zero), shrunk, zero); // (std::max(0, icr - shrink))
        const MaskOf<T> onFace = greater(icr, bm);                 // inside the (shrunk) triangle
        // otherwise onto edge m, or past its vertex m or m+1
        Vec3<T> onEdge = cp + at(ne, 0, 1, 2) * (icr - bm);
        const MaskOf<T> pastPrev = greater(dot(onEdge, at(ne, 2, 0, 1)), icr), pastNext = greater(dot(onEdge, at(ne, 1, 2, 0)), icr);
        onEdge = select(pastPrev, at(vu, 0, 1, 2) * (at(vl, 0, 1, 2) - shrink), select(pastNext, at(vu, 1, 2, 0) * (at(vl, 1, 2, 0) - shrink), onEdge));
        Vec3<T> toCentre = c - onEdge;
        const T squared = squaredNorm(toCentre);
        const T edgeDepth = r - sqrt(squared);
        toCentre = select(greater(squared, zero), toCentre / sqrt(squared), toCentre); // (Eigen's normalize())
        normal = select(onFace, normal, toCentre);
        ScGeom::Values<T> g;
        g.penetrationDepth = select(onFace, r - L, edgeDepth);
        // back to global coordinates (lane by lane, Eigen's rotation)
        g.normal = lanesOfVec<T>([&](int i) { return Vector3r(toGlobal[i] * normal.lane(i)); });
        g.contactPoint = (m.pos2 + shift2) - (r - T(0.5) * g.penetrationDepth) * g.normal;
        // A facet has no radius: it counts as a sphere twice as big in the linear stiffness, or, with
        // hertzian, as a very large one (the effective radius of the Hertz contact is then r).
        g.refR1 = hertzian ? T(hertzianFacetRadius) : T(2.0) * r;
        g.refR2 = r;
        g.precompute(oldNormal, isNew, m, dt, false, shift2);
        return g;
    }
    // an existing contact's geometry (KernelPass), written into its record
    template <class T> YADE_KERNEL ScGeom::Values<T> batchKernel(const ContactBodies<T>& b, Rows<ScGeom, T>& rows, Real dt) const {
        const Facet* f[lanesOf<T>];
        const Quaternionr* ori[lanesOf<T>];
        for (int i = 0; i < lanesOf<T>; ++i) {
            f[i] = static_cast<const Facet*>(b.b.shape[b.id1.i[i]]);
            ori[i] = &b.b.store.ori[b.id1.i[i]];
        }
        T distance;
        const ScGeom::Values<T> g = kernel<T>(f, ori, gather(b.b.radius, b.id2), b.motion(), Vec3<T>::zero(), rows.get(&ScGeom::normal), false, T(dt), distance);
        g.store(rows);
        return g;
    }
};

} // namespace yade
