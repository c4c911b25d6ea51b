#include <core/Scene.hpp>
#include <lib/base/Logging.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/SpheresFactory.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace yade {

namespace {

    // What a new sphere must not overlap: the spheres of the scene (exactly) and the bounds of other
    // bodies, near the region; those spanning few cells are in a uniform grid, the others in a list.
    class ObstacleGrid {
    public:
        ObstacleGrid(const Vector3r& lo, const Vector3r& hi, Real cell) : lo(lo), hi(hi) {
            const Real span = (hi - lo).maxCoeff();
            h = std::max(cell, span / 1e6);
            if (!(h > 0)) h = 1;
            for (int k = 0; k < 3; ++k) n[k] = (long long)std::floor((hi[k] - lo[k]) / h) + 1;
        }
        bool near(const Vector3r& a, const Vector3r& b) const { return (a.array() <= hi.array()).all() && (b.array() >= lo.array()).all(); }
        void addSphere(const Vector3r& c, Real R) { add(Obstacle{c - Vector3r::Constant(R), c + Vector3r::Constant(R), c, R, true}); }
        void addBox(const Vector3r& a, const Vector3r& b) { add(Obstacle{a, b, Vector3r::Zero(), 0, false}); }
        // Whether a sphere at c of radius r touches nothing (contact at exactly r+R is allowed).
        bool isFree(const Vector3r& c, Real r) const {
            const Vector3r a = c - Vector3r::Constant(r), b = c + Vector3r::Constant(r);
            for (int i : big)
                if (overlaps(obstacles[i], c, r, a, b)) return false;
            long long i0[3], i1[3];
            if (!cellRange(a, b, i0, i1)) return true;
            for (long long x = i0[0]; x <= i1[0]; ++x)
                for (long long y = i0[1]; y <= i1[1]; ++y)
                    for (long long z = i0[2]; z <= i1[2]; ++z) {
                        auto it = cells.find(key(x, y, z));
                        if (it == cells.end()) continue;
                        for (int i : it->second)
                            if (overlaps(obstacles[i], c, r, a, b)) return false;
                    }
            return true;
        }

    private:
        struct Obstacle {
            Vector3r lo, hi, c;
            Real R;
            bool sphere;
        };
        Vector3r lo, hi;
        Real h;
        long long n[3];
        std::vector<Obstacle> obstacles;
        std::vector<int> big;
        std::unordered_map<long long, std::vector<int>> cells;
        long long key(long long x, long long y, long long z) const { return x + n[0] * (y + n[1] * z); }
        static bool overlaps(const Obstacle& o, const Vector3r& c, Real r, const Vector3r& a, const Vector3r& b) {
            if (o.sphere) return (o.c - c).squaredNorm() < (o.R + r) * (o.R + r);
            return (a.array() < o.hi.array()).all() && (b.array() > o.lo.array()).all();
        }
        bool cellRange(const Vector3r& a, const Vector3r& b, long long* i0, long long* i1) const {
            for (int k = 0; k < 3; ++k) {
                const Real s = std::max(a[k], lo[k]), e = std::min(b[k], hi[k]);
                if (!(s <= e)) return false;
                i0[k] = std::min(n[k] - 1, (long long)std::floor((s - lo[k]) / h));
                i1[k] = std::min(n[k] - 1, (long long)std::floor((e - lo[k]) / h));
            }
            return true;
        }
        void add(const Obstacle& o) {
            const int id = (int)obstacles.size();
            obstacles.push_back(o);
            long long i0[3], i1[3];
            if (!cellRange(o.lo, o.hi, i0, i1)) return; // away from the region: cannot matter
            const long long count = (i1[0] - i0[0] + 1) * (i1[1] - i0[1] + 1) * (i1[2] - i0[2] + 1);
            if (count > 512) {
                big.push_back(id);
                return;
            }
            for (long long x = i0[0]; x <= i1[0]; ++x)
                for (long long y = i0[1]; y <= i1[1]; ++y)
                    for (long long z = i0[2]; z <= i1[2]; ++z) cells[key(x, y, z)].push_back(id);
        }
    };

    bool finite(Real x) { return std::isfinite(x); }

} // namespace

Vector3r SpheresFactory::pickRandomPosition(Real) {
    throw std::runtime_error("SpheresFactory::pickRandomPosition() called: SpheresFactory has no region, use BoxFactory or CircularFactory.");
}

void SpheresFactory::checkRegion() const {}

void SpheresFactory::regionBounds(Vector3r& lo, Vector3r& hi) const {
    lo = hi = Vector3r::Zero();
}

void SpheresFactory::seedRng() {
    if (seed >= 0) {
        if (!rngSeeded || seededWith != seed) rng.seed((std::mt19937::result_type)seed);
        seededWith = seed;
        rngSeeded = true;
    } else if (!rngSeeded || seededWith >= 0) {
        std::random_device device;
        rng.seed(device());
        seededWith = -1;
        rngSeeded = true;
    }
}

void SpheresFactory::checkInput(bool psd) const {
    const std::string name = getClassName();
    auto bad = [&](const std::string& what) { throw std::invalid_argument(name + "." + what); };
    if (std::isnan(massFlowRate)) bad("massFlowRate is NaN: set the mass flow rate [kg/s].");
    if (psd) {
        if (exactDiam && PSDsizes.size() != PSDcum.size())
            bad("PSDsizes: PSDcum and PSDsizes should have an equal number of elements, if exactDiam=True (PSDsizes has "
                + std::to_string(PSDsizes.size()) + ", PSDcum " + std::to_string(PSDcum.size()) + ").");
        if (!exactDiam && PSDsizes.size() != PSDcum.size() + 1)
            bad("PSDsizes should have a number of elements on 1 more, than PSDcum, if exactDiam=False (PSDsizes has "
                + std::to_string(PSDsizes.size()) + ", PSDcum " + std::to_string(PSDcum.size()) + ").");
        for (size_t i = 0; i < PSDcum.size(); ++i)
            if (!finite(PSDcum[i]) || !(PSDcum[i] > 0) || (i > 0 && PSDcum[i] < PSDcum[i - 1]))
                bad("PSDcum should have an ascending positive series of numbers (for example: 0.1, 0.3, 0.5, 1.0).");
        for (size_t i = 0; i < PSDsizes.size(); ++i)
            if (!finite(PSDsizes[i]) || !(PSDsizes[i] > 0) || (i > 0 && PSDsizes[i] < PSDsizes[i - 1]))
                bad("PSDsizes should have an ascending positive series of numbers (for example: 15, 20, 50, 80).");
    } else {
        if (!finite(rMin) || !(rMin > 0)) bad("rMin must be positive and finite (got " + std::to_string(rMin) + ").");
        if (!finite(rMax) || !(rMax > 0)) bad("rMax must be positive and finite (got " + std::to_string(rMax) + ").");
        if (rMin > rMax) bad("rMin (" + std::to_string(rMin) + ") must not exceed rMax (" + std::to_string(rMax) + ").");
    }
    if (!finite(vMin)) bad("vMin is not finite: set the velocities (vMin, vMax; the reference would make NaN velocities).");
    if (!finite(vMax)) bad("vMax is not finite: set the velocities (vMin, vMax; the reference would make NaN velocities).");
    const Vector3r dir = isFinite(normalVel) ? normalVel : normal;
    if (!isFinite(dir) || !(dir.norm() > 0))
        bad("normal: the direction of the velocities is not set (normalVel or normal must be a non-zero finite vector).");
    for (char c : blockedDOFs)
        if (std::string("xyzXYZ").find(c) == std::string::npos) bad("blockedDOFs: invalid letter '" + std::string(1, c) + "' (use x y z X Y Z).");
    if (maxAttempt < 0) bad("maxAttempt must not be negative.");
}

int SpheresFactory::pickPsdClass() {
    const size_t n = PSDcum.size();
    if (psdCount.size() != n) {
        psdCount.assign(n, 0);
        psdMass.assign(n, 0);
    }
    long long sumCount = 0;
    Real sumMass = 0;
    for (size_t i = 0; i < n; ++i) {
        sumCount += psdCount[i];
        sumMass += psdMass[i];
    }
    int best = 0;
    Real bestLag = -Inf;
    for (size_t i = 0; i < n; ++i) {
        const Real target = PSDcum[i] - (i > 0 ? PSDcum[i - 1] : 0);
        Real share = 0;
        if (PSDcalculateMass) share = sumMass > 0 ? psdMass[i] / sumMass : 0;
        else share = sumCount > 0 ? (Real)psdCount[i] / (Real)sumCount : 0;
        if (target - share > bestLag) {
            bestLag = target - share;
            best = (int)i;
        }
    }
    return best;
}

void SpheresFactory::action() {
    seedRng();
    const bool psd = !PSDcum.empty();
    checkInput(psd);
    checkRegion();
    if (maxMass > 0 && maxParticles > 0) {
        logWarning(getClassName() + ": Both maxMass and maxParticles cannot be > 0; Setting maxMass=-1");
        maxMass = -1;
    }
    goalMass += massFlowRate * scene->dt;
    auto canMake = [&] {
        return totalMass < goalMass && (maxParticles < 0 || numParticles < maxParticles) && (maxMass < 0 || totalMass < maxMass);
    };
    if (!canMake()) return;

    const int nMat = (int)scene->materials.size();
    const int mid = materialId < 0 ? nMat + materialId : materialId;
    if (mid < 0 || mid >= nMat)
        throw std::invalid_argument(getClassName() + ".materialId: invalid material id " + std::to_string(materialId) + " (O.materials has "
                                    + std::to_string(nMat) + ")");
    const std::shared_ptr<Material> material = scene->materials[mid];
    State blockedProbe;
    blockedProbe.setBlockedDOFs(blockedDOFs);
    const int blockedMask = blockedProbe.blockedDOFsMask();

    const Real rNewMax = psd ? PSDsizes.back() / 2 : std::max(rMin, rMax);
    Vector3r lo, hi;
    regionBounds(lo, hi);
    lo -= Vector3r::Constant(rNewMax);
    hi += Vector3r::Constant(rNewMax);
    ObstacleGrid grid(lo, hi, 2 * rNewMax);
    for (const auto& b : scene->bodies) {
        if (!b || !b->shape) continue;
        if (const auto* s = dynamic_cast<const Sphere*>(b->shape.get())) {
            const Vector3r& p = b->state->pos();
            const Vector3r R = Vector3r::Constant(s->radius);
            if (isFinite(p) && finite(s->radius) && grid.near(p - R, p + R)) grid.addSphere(p, s->radius);
        } else if (b->bound) {
            const Vector3r &a = b->bound->min, &c = b->bound->max;
            if (!a.array().isNaN().any() && !c.array().isNaN().any() && grid.near(a, c)) grid.addBox(a, c);
        }
    }

    // As in the reference: one speed per step, the direction of normalVel (else normal).
    const Real speed = vMin + uniform01() * (vMax - vMin);
    const Vector3r vel = (isFinite(normalVel) ? normalVel : normal).normalized() * speed;
    const bool useColor = (color.array() >= 0).all();

    while (canMake()) {
        int cls = -1;
        Real r;
        if (psd) {
            cls = pickPsdClass();
            const Real d = exactDiam ? PSDsizes[cls] : PSDsizes[cls] + uniform01() * (PSDsizes[cls + 1] - PSDsizes[cls]);
            r = d / 2;
        } else {
            r = rMin + uniform01() * (rMax - rMin);
        }
        bool placed = false;
        Vector3r pos;
        for (int attempt = 0; attempt < maxAttempt; ++attempt) {
            pos = pickRandomPosition(r);
            if (grid.isFree(pos, r)) {
                placed = true;
                break;
            }
        }
        if (!placed) {
            if (!silent)
                logWarning(getClassName() + ": Unable to place new sphere after " + std::to_string(maxAttempt) + " attempts!"
                           + (stopIfFailed ? " (stopIfFailed: massFlowRate set to 0)" : ""));
            if (stopIfFailed) {
                massFlowRate = 0;
                goalMass = totalMass;
            }
            break;
        }
        auto body = std::make_shared<Body>();
        auto sphere = std::make_shared<Sphere>();
        sphere->radius = r;
        if (useColor) sphere->color = color;
        body->shape = sphere;
        body->material = material;
        const Real volume = 4. / 3. * Mathr_PI * r * r * r;
        const Real mass = volume * material->density;
        State& st = *body->state;
        st.pos() = pos;
        st.refPos = pos;
        st.vel() = vel;
        st.mass() = mass;
        st.inertia() = Vector3r::Constant(2. / 5. * mass * r * r);
        st.blockedDOFsMask() = blockedMask;
        if (mask > 0) body->mask = mask;
        auto bound = std::make_shared<Aabb>();
        bound->color = Vector3r(0, 1, 0);
        body->bound = bound;
        const Body::id_t id = scene->appendBody(body);
        grid.addSphere(pos, r);
        ids.push_back(id);
        ++numParticles;
        totalMass += mass;
        totalVolume += volume;
        if (psd) {
            psdCount[cls] += 1;
            psdMass[cls] += mass;
        }
    }
}

} // namespace yade
