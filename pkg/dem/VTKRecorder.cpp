#include <Eigen/Eigenvalues>
#include <cmath>
#include <core/Scene.hpp>
#include <filesystem>
#include <fstream>
#include <lib/vtk/VTKWriter.hpp>
#include <pkg/common/Box.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/VTKRecorder.hpp>
#include <set>
#include <stdexcept>

namespace yade {

namespace {

const std::vector<std::string>& knownRecorders() {
    static const std::vector<std::string> k{"all",      "spheres", "facets",     "boxes", "intr", "pericell", "velocity", "ids",
                                            "mass",     "clumpId", "colors",     "stress", "materialId", "mask", "bstresses"};
    return k;
}

std::string xmlEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

void push(std::vector<double>& to, const Vector3r& v) { to.insert(to.end(), {(double)v[0], (double)v[1], (double)v[2]}); }

// Which bodies and arrays go out: the recorders' names resolved once per run.
struct Selection {
    std::set<std::string> on;
    bool has(const char* r) const { return on.count(r) > 0; }
};

const Sphere* sphereOf(const Body* b) { return b && b->shape ? dynamic_cast<const Sphere*>(b->shape.get()) : nullptr; }

// Per body, from its real contacts (NormShearPhys): the summed normal and shear forces over the contact area
// π·min(r1, r2)² (the reference's normalStress and shearStress, signed as the contact's normalForce), and its
// stress tensor 1/V Σ f ⊗ (x_c - x_b), f the force on the body (utils.bodyStressTensors).
struct ContactSums {
    std::vector<Vector3r> normal, shear;
    std::vector<Matrix3r> tensor;
    ContactSums(const Scene& s, bool stresses, bool tensors) {
        const size_t n = s.bodies.size();
        if (stresses) normal.assign(n, Vector3r::Zero()), shear.assign(n, Vector3r::Zero());
        if (tensors) tensor.assign(n, Matrix3r::Zero());
        if (!stresses && !tensors) return;
        const InteractionContainer& I = s.interactions;
        for (size_t k = 0; k < I.size(); ++k) {
            if (!I.isReal(k)) continue;
            const auto* phys = dynamic_cast<const NormShearPhys*>(I.phys(k));
            if (!phys) continue;
            const int id1 = I.pairIds[2 * k], id2 = I.pairIds[2 * k + 1];
            const Sphere *s1 = sphereOf(s.bodies[id1].get()), *s2 = sphereOf(s.bodies[id2].get());
            if (stresses && (s1 || s2)) {
                const Real r = std::min(s1 ? s1->radius : s2->radius, s2 ? s2->radius : s1->radius);
                const Real area = M_PI * r * r;
                for (int id : {id1, id2}) {
                    normal[id] += phys->normalForce / area;
                    shear[id] += phys->shearForce / area;
                }
            }
            const auto* geom = dynamic_cast<const ScGeom*>(I.geom(k));
            if (tensors && geom) {
                const Vector3r f = phys->normalForce + phys->shearForce; // on body 2
                const Vector3r shift = I.periodic ? s.cell->shift(I.cellDist[k]) : Vector3r::Zero();
                tensor[id1] -= f * (geom->contactPoint - s.bodies[id1]->state->pos()).transpose();
                tensor[id2] += f * (geom->contactPoint - s.bodies[id2]->state->pos() - shift).transpose();
            }
        }
    }
};

// Adds the arrays the recorders ask for, for the bodies `ids` (one point or cell each).
void bodyArrays(const Scene& s, const std::vector<int>& ids, const Selection& sel, const ContactSums* sums,
                std::deque<VtkArray>& out, bool isSphere) {
    auto add = [&](const char* name, int c) -> std::vector<double>& {
        out.push_back(VtkArray{name, c, {}});
        out.back().values.reserve(ids.size() * c);
        return out.back().values;
    };
    if (sel.has("ids")) {
        auto& a = add("id", 1);
        for (int id : ids) a.push_back(id);
    }
    if (sel.has("mask")) {
        auto& a = add("mask", 1);
        for (int id : ids) a.push_back(s.bodies[id]->mask);
    }
    if (sel.has("mass")) {
        auto& a = add("mass", 1);
        for (int id : ids) a.push_back(s.bodies[id]->state->mass());
    }
    if (sel.has("clumpId")) {
        auto& a = add("clumpId", 1);
        for (int id : ids) a.push_back(s.bodies[id]->clumpId);
    }
    if (sel.has("colors")) {
        auto& a = add("color", 3);
        for (int id : ids) push(a, s.bodies[id]->shape->color);
    }
    if (sel.has("velocity") && isSphere) {
        auto &lv = add("linVelVec", 3), &av = add("angVelVec", 3);
        for (int id : ids) push(lv, s.bodies[id]->state->vel()), push(av, s.bodies[id]->state->angVel());
        auto &ll = add("linVelLen", 1), &al = add("angVelLen", 1);
        for (int id : ids) ll.push_back(s.bodies[id]->state->vel().norm()), al.push_back(s.bodies[id]->state->angVel().norm());
    }
    if (sel.has("stress") && isSphere && sums) {
        auto &n = add("normalStress", 3), &t = add("shearStress", 3), &nn = add("normalStressNorm", 1);
        for (int id : ids) push(n, sums->normal[id]), push(t, sums->shear[id]), nn.push_back(sums->normal[id].norm());
    }
    if (sel.has("stress") && !isSphere) { // facets and boxes: the force on them over their area
        auto &v = add("stressVec", 3), &l = add("stressLen", 1);
        auto& forces = const_cast<Scene&>(s).forces;
        for (int id : ids) {
            const Body& b = *s.bodies[id];
            Real area = NaN;
            if (const auto* f = dynamic_cast<const Facet*>(b.shape.get())) area = f->area;
            else if (const auto* x = dynamic_cast<const Box*>(b.shape.get()))
                area = 8 * (x->extents[0] * x->extents[1] + x->extents[1] * x->extents[2] + x->extents[0] * x->extents[2]);
            const Vector3r f = forces.getForce(id) / area;
            push(v, f), l.push_back(f.norm());
        }
    }
    if (sel.has("materialId")) {
        auto& a = add("materialId", 1);
        for (int id : ids) a.push_back(s.bodies[id]->material ? s.bodies[id]->material->id : -1);
    }
    if (sel.has("bstresses") && isSphere && sums) {
        std::vector<double>* sig[3] = {&add("sigI", 1), &add("sigII", 1), &add("sigIII", 1)};
        std::vector<double>* dir[3] = {&add("dirI", 3), &add("dirII", 3), &add("dirIII", 3)};
        for (int id : ids) {
            const Real r = sphereOf(s.bodies[id].get())->radius;
            const Matrix3r t = sums->tensor[id] / (4. / 3. * M_PI * r * r * r);
            Eigen::SelfAdjointEigenSolver<Matrix3r> eig(Real(.5) * (t + t.transpose()));
            for (int i = 0; i < 3; ++i) { // I the largest
                sig[i]->push_back(eig.eigenvalues()[2 - i]);
                push(*dir[i], eig.eigenvectors().col(2 - i));
            }
        }
    }
}

} // namespace

void VTKRecorder::postLoad() {
    for (const std::string& r : recorders)
        if (std::find(knownRecorders().begin(), knownRecorders().end(), r) == knownRecorders().end()) {
            std::string names;
            for (const std::string& k : knownRecorders()) names += (names.empty() ? "" : ", ") + k;
            throw std::invalid_argument("VTKRecorder.recorders: unknown recorder '" + r + "' (known: " + names + ")");
        }
}

void VTKRecorder::action() {
    const Scene& s = *scene;
    Selection sel;
    for (const std::string& r : recorders) sel.on.insert(r);
    if (sel.has("all")) {
        for (const std::string& r : knownRecorders())
            if (r != "bstresses" && r != "pericell") sel.on.insert(r);
        if (s.isPeriodic) sel.on.insert("pericell");
    }
    auto wrap = [&](const Vector3r& p) { return s.isPeriodic ? s.cell->wrap(p) : p; };

    std::vector<int> spheres, facets, boxes;
    for (size_t i = 0; i < s.bodies.size(); ++i) {
        const Body* b = s.bodies[(int)i].get();
        if (!b || !b->shape || b->isClump()) continue;
        if (mask != 0 && !(b->mask & mask)) continue;
        if (skipNondynamic && !b->isDynamic()) continue;
        if (dynamic_cast<const Sphere*>(b->shape.get())) spheres.push_back((int)i);
        else if (dynamic_cast<const Facet*>(b->shape.get())) facets.push_back((int)i);
        else if (dynamic_cast<const Box*>(b->shape.get())) boxes.push_back((int)i);
    }
    std::unique_ptr<ContactSums> sums;
    if (sel.has("spheres")) sums = std::make_unique<ContactSums>(s, sel.has("stress"), sel.has("bstresses"));

    std::vector<std::pair<std::string, VtkPiece>> pieces; // (kind, what its file holds)
    if (sel.has("spheres")) {
        VtkPiece p;
        p.cellType = 1;
        auto& radii = p.addPointArray("radii", 1).values;
        for (int id : spheres) {
            push(p.points, wrap(s.bodies[id]->state->pos()));
            p.connectivity.push_back((int64_t)p.connectivity.size());
            radii.push_back(sphereOf(s.bodies[id].get())->radius);
        }
        bodyArrays(s, spheres, sel, sums.get(), p.pointData, true);
        pieces.emplace_back("spheres", std::move(p));
    }
    if (sel.has("facets")) {
        VtkPiece p;
        p.cellType = 5;
        p.pointsPerCell = 3;
        for (int id : facets) {
            const Body& b = *s.bodies[id];
            const Matrix3r R = b.state->ori().toRotationMatrix();
            for (const Vector3r& v : static_cast<const Facet&>(*b.shape).vertices) {
                p.connectivity.push_back((int64_t)p.numPoints());
                push(p.points, b.state->pos() + R * v);
            }
        }
        bodyArrays(s, facets, sel, nullptr, p.cellData, false);
        pieces.emplace_back("facets", std::move(p));
    }
    if (sel.has("boxes")) {
        VtkPiece p;
        p.cellType = 12; // hexahedron: the bottom face's 4 corners, then the top face's, counterclockwise
        p.pointsPerCell = 8;
        static const int corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
        for (int id : boxes) {
            const Body& b = *s.bodies[id];
            const Matrix3r R = b.state->ori().toRotationMatrix();
            const Vector3r& e = static_cast<const Box&>(*b.shape).extents;
            for (const auto& c : corner) {
                p.connectivity.push_back((int64_t)p.numPoints());
                push(p.points, b.state->pos() + R * Vector3r(c[0] * e[0], c[1] * e[1], c[2] * e[2]));
            }
        }
        bodyArrays(s, boxes, sel, nullptr, p.cellData, false);
        pieces.emplace_back("boxes", std::move(p));
    }
    if (sel.has("intr")) { // one line per contact, from body 1 to body 2 (its image across the cell when periodic)
        VtkPiece p;
        p.polyData = true;
        p.cellType = 3;
        p.pointsPerCell = 2;
        auto &fn = p.addCellArray("forceN", 1).values, &ft = p.addCellArray("absForceT", 1).values;
        auto& fnv = p.addCellArray("forceNvec", 3).values;
        const InteractionContainer& I = s.interactions;
        for (size_t k = 0; k < I.size(); ++k) {
            if (!I.isReal(k)) continue;
            const auto* phys = dynamic_cast<const NormPhys*>(I.phys(k));
            if (!phys) continue;
            const Body *b1 = s.bodies[I.pairIds[2 * k]].get(), *b2 = s.bodies[I.pairIds[2 * k + 1]].get();
            if (skipFacetIntr && (!sphereOf(b1) || !sphereOf(b2))) continue;
            if (mask != 0 && !((b1->mask | b2->mask) & mask)) continue;
            const Vector3r x1 = b1->state->pos(), x2 = b2->state->pos() + (I.periodic ? s.cell->shift(I.cellDist[k]) : Vector3r::Zero());
            const Vector3r w1 = wrap(x1);
            p.connectivity.push_back((int64_t)p.numPoints());
            push(p.points, w1);
            p.connectivity.push_back((int64_t)p.numPoints());
            push(p.points, w1 == x1 ? x2 : Vector3r(w1 + (x2 - x1))); // (x2 itself when body 1 is inside the cell: no rounding)
            fn.push_back(phys->normalForce.norm());
            const auto* ns = dynamic_cast<const NormShearPhys*>(phys);
            ft.push_back(ns ? ns->shearForce.norm() : 0.);
            push(fnv, phys->normalForce);
        }
        pieces.emplace_back("intrs", std::move(p));
    }
    if (sel.has("pericell") && s.isPeriodic) {
        VtkPiece p;
        p.cellType = 12;
        p.pointsPerCell = 8;
        static const int corner[8][3] = {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
        for (const auto& c : corner) {
            p.connectivity.push_back((int64_t)p.numPoints());
            push(p.points, s.cell->hSize * Vector3r(c[0], c[1], c[2]));
        }
        pieces.emplace_back("pericell", std::move(p));
    }

    const std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
    try {
        if (!folder.empty()) std::filesystem::create_directories(folder);
    } catch (const std::filesystem::filesystem_error& e) {
        throw std::runtime_error("VTKRecorder: cannot make the folder " + folder.string() + " of fileName: " + e.code().message());
    }
    VtkWriteOptions options;
    options.ascii = ascii;
    options.compress = compress;
    const std::string iter = std::to_string(s.iter);
    if (multiblock) {
        const std::string file = fileName + iter + ".vtm";
        writeVtkMultiblock(file, pieces, options);
        if (pvd) writeSeries("series", file);
        return;
    }
    for (const auto& [kind, piece] : pieces) {
        const std::string file = fileName + kind + "." + iter + (piece.polyData ? ".vtp" : ".vtu");
        writeVtkPiece(file, piece, options);
        if (pvd) writeSeries(kind, file);
    }
}

// fileName + kind + ".pvd": every file of that kind written so far, with its simulated time (file names
// relative to the .pvd, which lies in the same folder).
void VTKRecorder::writeSeries(const std::string& kind, const std::string& file) {
    auto& list = series[kind];
    list.emplace_back(scene->time, std::filesystem::path(file).filename().string());
    const std::string pvdFile = fileName + kind + ".pvd";
    std::ofstream out(pvdFile, std::ios::trunc);
    out.precision(17);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
    for (const auto& [time, name] : list) out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"0\" file=\"" << xmlEscaped(name) << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    if (!out) throw std::runtime_error("VTKRecorder: cannot write " + pvdFile);
}

} // namespace yade
