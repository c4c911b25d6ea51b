// The periodic cell (3.6): a parallelepiped whose edges are the columns of hSize, deformed by the
// velocity gradient velGrad. O.cell while O.periodic; doc/periodic.md says how each part uses it.
#pragma once
#include <lib/serialization/Serializable.hpp>
#include <lib/base/Math.hpp>
#include <stdexcept>
#include <string>
#include <tuple>

namespace yade {

class Cell : public Serializable {
public:
    static constexpr const char* classDoc = "Periodic cell (3.6): its edges are the columns of hSize; velGrad deforms it at every step (trsf and hSize follow, (3.6.1)), and homoDeform says how the bodies follow that homogeneous field.";
    // Cell.homoDeform: how the bodies follow the homogeneous velocity field velGrad·x (3.6.1).
    enum HomoDeform {
        homoNone = 0, // bodies move only by their own velocities
        homoVel = 1,  // a change of velGrad adds Δ(velGrad)·pos to each velocity
        homoVel2nd = 2, // ... and the convective term dt·velGrad·vel every step (the default)
        homoGradV2 = 3, // (the same here as 2)
    };
    Matrix3r hSize = Matrix3r::Identity();     // edges of the cell, in columns
    Matrix3r refHSize = Matrix3r::Identity();  // hSize when it was last assigned
    Matrix3r trsf = Matrix3r::Identity();      // deformation gradient F since the reference (3.6.1)
    Matrix3r velGrad = Matrix3r::Zero();       // current velocity gradient (set through nextVelGrad)
    Matrix3r nextVelGrad = Matrix3r::Zero();   // the velGrad that the next step takes
    Matrix3r prevVelGrad = Matrix3r::Zero();   // velGrad of the previous step
    Matrix3r prevHSize = Matrix3r::Identity(); // hSize of the previous step
    int homoDeform = homoVel2nd;
    bool velGradChanged = false;
    bool flipFlippable = false;

    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("trsf", trsf, "Deformation gradient F of the cell since the reference state, (3.6.1): F ← (I + ∇v·Δt)·F each step", Attr::finite);
        v.attr("refHSize", refHSize, "Reference cell (hSize when it was last assigned)", Attr::finite);
        v.attr("hSize", hSize, "Base vectors of the cell, in columns (H of 3.6); assigning it also sets refHSize and resets trsf", Attr::finite);
        v.attr("prevHSize", prevHSize, "hSize in the previous step", Attr::finite);
        v.attr("velGrad", velGrad, "Velocity gradient ∇v of the homogeneous field; assigned, it takes effect at the next step", Attr::finite);
        v.attr("nextVelGrad", nextVelGrad, "The velocity gradient the next step takes", Attr::readonly | Attr::finite);
        v.attr("prevVelGrad", prevVelGrad, "Velocity gradient in the previous step", Attr::finite);
        v.attr("homoDeform", homoDeform,
                "How bodies follow the homogeneous field: 0 not at all; 1 a change of velGrad adds Δ∇v·x to each velocity; 2 (default) and 3 also the convective term Δt·∇v·v each step");
        v.attr("velGradChanged", velGradChanged, "velGrad was assigned and the next step takes nextVelGrad");
        v.attr("flipFlippable", flipFlippable, "Flip the cell (flipCell) whenever a flip makes it less skewed (checked by the collider)");
    }
    void postLoad() override { check(); }

    // Column norms of hSize (the lengths of the cell's edges).
    Vector3r size() const { return Vector3r(hSize.col(0).norm(), hSize.col(1).norm(), hSize.col(2).norm()); }
    Real volume() const { return hSize.determinant(); }
    // hSize assigned: refHSize follows and trsf is reset (velGrad kept); throws, leaving the cell as it
    // was, if m is not finite or not an invertible right-handed cell.
    void setHSize(const Matrix3r& m);
    // An axis-aligned box of these edges.
    void setBox(const Vector3r& size);
    // The next step takes this velocity gradient.
    void setVelGrad(const Matrix3r& m);
    // Throws std::invalid_argument unless the cell is finite, of positive volume and its velocity
    // gradient finite (a file or a direct assignment).
    void check() const;

    // hSize with its columns scaled to unit length (the shear and rotation of the cell), and its inverse.
    Matrix3r shearTrsf() const { return hSize * size().cwiseInverse().asDiagonal(); }
    Matrix3r unshearTrsf() const { return shearTrsf().inverse(); }
    Vector3r shearPt(const Vector3r& p) const { return shearTrsf() * p; }
    Vector3r unshearPt(const Vector3r& p) const { return unshearTrsf() * p; }
    // The coordinates of p in the cell's base (p = hSize·s): [0,1) inside the cell.
    Vector3r fractional(const Vector3r& p) const { return hSize.inverse() * p; }
    // p moved by whole cells into the cell (its image inside), and how many cells that took
    // (p = wrap(p) - hSize·period).
    Vector3r wrap(const Vector3r& p) const;
    Vector3r wrap(const Vector3r& p, Vector3i& period) const;
    // p wrapped in the axis-aligned box [0, size) (the cell without its shear).
    Vector3r wrapPt(const Vector3r& p) const;
    // The shift of body 2's image in an interaction of cellDist c, and the velocity of that image
    // relative to body 2 in the homogeneous field.
    Vector3r shift(const Vector3i& c) const { return hSize * c.cast<Real>(); }
    Vector3r shiftVel(const Vector3r& shift2) const { return velGrad * shift2; }

    // The start of a step (Scene::beginStep): the cell deformed by the velocity gradient of the
    // last step, (3.6.1), which becomes prevVelGrad.
    void integrate(Real dt);
    // The integrator's step (NewtonIntegrator): a velocity gradient assigned since becomes the current
    // one (so a scene without an integrator keeps its cell as it is, as in the reference).
    void takeNextVelGrad();

    // Strain measures of trsf (F).
    Matrix3r smallStrain() const { return Real(0.5) * (trsf + trsf.transpose()) - Matrix3r::Identity(); }
    Matrix3r rightCauchyGreen() const { return trsf.transpose() * trsf; }
    Matrix3r leftCauchyGreen() const { return trsf * trsf.transpose(); }
    Matrix3r lagrangianStrain() const { return Real(0.5) * (rightCauchyGreen() - Matrix3r::Identity()); }
    Matrix3r eulerianAlmansiStrain() const { return Real(0.5) * (Matrix3r::Identity() - leftCauchyGreen().inverse()); }
    // F = R·U (polar decomposition): R a rotation, U symmetric positive definite.
    std::pair<Matrix3r, Matrix3r> polarDecomposition() const;
    Matrix3r spin() const { return Real(0.5) * (velGrad - velGrad.transpose()); }
};

} // namespace yade
