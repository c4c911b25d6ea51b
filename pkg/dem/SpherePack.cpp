#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <lib/base/Logging.hpp>
#include <pkg/dem/SpherePack.hpp>
#include <random>
#include <sstream>

namespace yade {

namespace {

    using Sph = SpherePack::Sph;

    std::string str(Real x) {
        std::ostringstream s;
        s << x;
        return s.str();
    }

    void require(bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument("SpherePack.makeCloud: " + what);
    }

    // The generation box: lower corner and size; a zero size marks the flat axis of a 2D packing.
    struct Box {
        Vector3r lo, size;
        bool     periodic;

        bool flat(int a) const { return size[a] == 0; }
        // Volume, or area of a 2D box.
        Real measure() const {
            Real m = 1;
            for (int a = 0; a < 3; a++)
                if (!flat(a)) m *= size[a];
            return m;
        }
        bool is2D() const { return flat(0) || flat(1) || flat(2); }
    };

    // Quantiles of the radius distribution given as points (diameter, cumulative fraction), linear in
    // between. With `mass` the fractions are of mass: inside a segment the number of spheres per unit
    // diameter is then ∝ d⁻³, so the cumulative number fraction is linear in d⁻².
    class RadiusDist {
    public:
        RadiusDist(const std::vector<Real>& sizes, const std::vector<Real>& cumm, bool mass)
                : d(sizes)
                , F(cumm)
                , mass(mass) {
            if (mass) {
                F          = numberFractions(sizes, cumm); // not normalized yet: number per unit mass
                meanVolume = Mathr_PI / 6 / F.back();
                for (Real& x : F) x /= F.back();
            } else meanVolume = referenceNumberMeanVolume(sizes, cumm);
        }
        // Radius below which a fraction c of the spheres (by number) lies.
        Real quantile(Real c) const {
            const std::size_t n = d.size();
            std::size_t       k = std::upper_bound(F.begin(), F.end(), c) - F.begin();
            k                   = std::min(std::max<std::size_t>(k, 1), n - 1) - 1;
            if (F[k + 1] <= F[k] || d[k + 1] == d[k]) return d[k + 1] / 2;
            const Real t = (c - F[k]) / (F[k + 1] - F[k]);
            if (!mass) return (d[k] + t * (d[k + 1] - d[k])) / 2;
            const Real a = std::pow(d[k], -2), b = std::pow(d[k + 1], -2);
            return std::pow(a - t * (a - b), -0.5) / 2;
        }
        // Mean sphere volume the reference uses to scale a psd for num spheres: exact for mass
        // distributions; for number distributions Σ ΔF π d̄³ (1 + w²) over segments (d̄: middle, w: half
        // width, not relative), about 6 times the exact value, which leaves such packings looser than asked.
        Real meanVolume;

    private:
        std::vector<Real> d, F; // diameters and the cumulative number fractions at them
        bool              mass;

        // Cumulative numbers of spheres per unit mass of a piecewise-linear mass distribution (∫ m(d)/d³).
        static std::vector<Real> numberFractions(const std::vector<Real>& d, const std::vector<Real>& M) {
            std::vector<Real> N(d.size(), 0.);
            for (std::size_t k = 0; k + 1 < d.size(); k++) {
                const Real dM = M[k + 1] - M[k], dd = d[k + 1] - d[k];
                const Real w  = dd > 0 ? dM / dd * (std::pow(d[k], -2) - std::pow(d[k + 1], -2)) / 2 : dM / std::pow(d[k], 3);
                N[k + 1]      = N[k] + w;
            }
            return N;
        }
        static Real referenceNumberMeanVolume(const std::vector<Real>& d, const std::vector<Real>& F) {
            Real v = 0;
            for (std::size_t k = 0; k + 1 < d.size(); k++) {
                const Real mid = (d[k] + d[k + 1]) / 2, w = (d[k + 1] - d[k]) / 2;
                v += (F[k + 1] - F[k]) * Mathr_PI * mid * mid * mid * (1 + w * w);
            }
            return v;
        }
    };

    // Uniform grid over the box; each sphere is listed in every cell its bounding box touches (cells
    // wrapped in periodic boxes), so that overlap candidates are found in the cells of the new sphere's box.
    class CloudGrid {
    public:
        CloudGrid(const Box& box, Real cell)
                : box(box) {
            for (int a = 0; a < 3; a++) {
                const Real cells = box.flat(a) ? 1 : (box.periodic ? std::floor(box.size[a] / cell) : std::ceil(box.size[a] / cell));
                n[a]             = static_cast<int>(std::max<Real>(1, cells));
                len[a]           = box.flat(a) ? 1 : box.size[a] / n[a];
            }
            head.assign(static_cast<std::size_t>(n[0]) * n[1] * n[2], -1);
        }
        void insert(int id, const Vector3r& c, Real r) {
            forCells(c, r, [&](std::size_t cell) {
                entries.push_back({ id, head[cell] });
                head[cell] = static_cast<int>(entries.size()) - 1;
                return false;
            });
        }
        // Whether test(id) is true for some sphere listed in the cells touched by the box of (c, r).
        template <class Test> bool any(const Vector3r& c, Real r, const Test& test) const {
            return forCells(c, r, [&](std::size_t cell) {
                for (int e = head[cell]; e >= 0; e = entries[e].next)
                    if (test(entries[e].id)) return true;
                return false;
            });
        }

    private:
        struct Entry {
            int id, next;
        };
        Box                box;
        int                n[3];
        Real               len[3];
        std::vector<int>   head; // first entry of each cell, -1 if none
        std::vector<Entry> entries;

        // Cells [i0, i1] along axis a covering [from, to]; clamped to the grid, or (periodic) i0 in [0, n).
        void range(int a, Real from, Real to, int& i0, int& i1) const {
            Real t0 = std::floor((from - box.lo[a]) / len[a]), t1 = std::floor((to - box.lo[a]) / len[a]);
            if (!box.periodic || box.flat(a)) {
                i0 = static_cast<int>(std::clamp<Real>(t0, 0, n[a] - 1));
                i1 = static_cast<int>(std::clamp<Real>(t1, 0, n[a] - 1));
            } else if (t1 - t0 + 1 >= n[a]) {
                i0 = 0;
                i1 = n[a] - 1;
            } else {
                const Real shift = std::floor(t0 / n[a]) * n[a];
                i0               = static_cast<int>(t0 - shift);
                i1               = static_cast<int>(t1 - shift);
            }
        }
        // Calls f(cell) for each cell touched by the box of (c, r) until f returns true.
        template <class F> bool forCells(const Vector3r& c, Real r, const F& f) const {
            int i0[3], i1[3];
            for (int a = 0; a < 3; a++) range(a, c[a] - r, c[a] + r, i0[a], i1[a]);
            for (int i = i0[0]; i <= i1[0]; i++)
                for (int j = i0[1]; j <= i1[1]; j++)
                    for (int k = i0[2]; k <= i1[2]; k++) {
                        const std::size_t cell = (static_cast<std::size_t>(i % n[0]) * n[1] + j % n[1]) * n[2] + k % n[2];
                        if (f(cell)) return true;
                    }
            return false;
        }
    };

    // Strict overlap (touching is allowed), through the nearest periodic image if periodic.
    bool overlaps(const Box& box, const Vector3r& c, Real r, const Sph& s) {
        Vector3r d = s.c - c;
        if (box.periodic)
            for (int a = 0; a < 3; a++)
                if (!box.flat(a)) d[a] -= box.size[a] * std::round(d[a] / box.size[a]);
        return d.squaredNorm() < (r + s.r) * (r + s.r);
    }

    // Places spheres at random non-overlapping positions in the box, next to those already in `pack`.
    class Cloud {
    public:
        Cloud(std::vector<Sph>& pack, const Box& box, Real cell, std::mt19937& rng)
                : pack(pack)
                , box(box)
                , grid(box, cell)
                , rng(rng) {
            for (std::size_t i = 0; i < pack.size(); i++) grid.insert(static_cast<int>(i), pack[i].c, pack[i].r);
        }
        // Tries maxTries random positions; appends the sphere at the first free one.
        bool place(Real r) {
            if (!fitsInBox(r)) return false;
            for (int t = 0; t < SpherePack::maxTries; t++) {
                const Vector3r c = randomCenter(r);
                if (grid.any(c, r, [&](int id) { return overlaps(box, c, r, pack[id]); })) continue;
                grid.insert(static_cast<int>(pack.size()), c, r);
                pack.push_back({ c, r });
                return true;
            }
            return false;
        }

    private:
        std::vector<Sph>&                    pack;
        const Box&                           box;
        CloudGrid                            grid;
        std::mt19937&                        rng;
        std::uniform_real_distribution<Real> unit { 0., 1. };

        bool fitsInBox(Real r) const {
            for (int a = 0; a < 3; a++)
                if (!box.flat(a) && (box.periodic ? 2 * r >= box.size[a] : 2 * r > box.size[a])) return false;
            return true;
        }
        // Uniform over the positions keeping the sphere inside the box (any position when periodic).
        Vector3r randomCenter(Real r) {
            Vector3r c;
            for (int a = 0; a < 3; a++) {
                if (box.flat(a)) c[a] = box.lo[a];
                else if (box.periodic) c[a] = box.lo[a] + unit(rng) * box.size[a];
                else c[a] = box.lo[a] + r + unit(rng) * (box.size[a] - 2 * r);
            }
            return c;
        }
    };

    // Grid cell: geometric mean of the smallest and largest diameters (few cells per large sphere, few
    // small spheres per cell), not so small that the grid exceeds a few million cells.
    Real gridCell(const Box& box, Real rMin, Real rMax) {
        const Real minCell = std::pow(box.measure() / 4e6, box.is2D() ? 1. / 2 : 1. / 3);
        return std::max({ 2 * std::sqrt(rMin * rMax), rMax / 4, minCell });
    }

    // Radii of num spheres following `dist` deterministically, largest first: quantiles at 1-(i+½)/(num+1)
    // (the values of the reference implementation).
    std::vector<Real> quantiles(const RadiusDist& dist, int num) {
        std::vector<Real> r(num);
        for (int i = 0; i < num; i++) r[i] = dist.quantile(1 - (i + .5) / (num + 1));
        return r;
    }

    // Places radii[i]·scale in order; stops at the first sphere that does not fit. Returns how many fit.
    int placeAll(std::vector<Sph>& pack, const Box& box, const std::vector<Real>& radii, Real scale, std::mt19937& rng) {
        Cloud cloud(pack, box, gridCell(box, radii.back() * scale, radii.front() * scale), rng);
        for (std::size_t i = 0; i < radii.size(); i++)
            if (!cloud.place(radii[i] * scale)) return static_cast<int>(i);
        return static_cast<int>(radii.size());
    }

    // Random radii from `dist` until one cannot be placed.
    void placeRandom(std::vector<Sph>& pack, const Box& box, const RadiusDist& dist, std::mt19937& rng) {
        Cloud                                cloud(pack, box, gridCell(box, dist.quantile(0), dist.quantile(1)), rng);
        std::uniform_real_distribution<Real> unit(0., 1.);
        while (cloud.place(dist.quantile(unit(rng)))) { }
    }

    // Scale of unit radii giving porosity p: the formula of the reference, rMean = ∛(V(1-p) / (4/3 π (1+z²) num)),
    // or ²√(A(1-p) / (π (1+z²) num)) in 2D, z = rRelFuzz.
    Real porosityRadius(const Box& box, Real p, Real z, int num) {
        if (box.is2D()) return std::sqrt(box.measure() * (1 - p) / (Mathr_PI * (1 + z * z) * num));
        return std::cbrt(box.measure() * (1 - p) / (4. / 3. * Mathr_PI * (1 + z * z) * num));
    }

    // Scale (at most 1) of the psd for num spheres of dist.meanVolume to fill (1-p) of the box, as in the
    // reference; a 2D box counts as dMax thick.
    Real psdScale(const Box& box, Real p, const RadiusDist& dist, int num) {
        const Real volume = box.measure() * (box.is2D() ? 2 * dist.quantile(1) : 1);
        return std::min<Real>(1, std::cbrt(volume * (1 - p) / (num * dist.meanVolume)));
    }

    // Places all radii (largest first) scaled for the porosity p; after a failed attempt its spheres are
    // removed and p raised to 1-0.9(1-p); each attempt starts from the seed, as in the reference.
    // Returns the scale that succeeded.
    Real placeWithRetries(std::vector<Sph>& pack, const Box& box, const RadiusDist& dist, int num, Real z, bool psd, Real p, unsigned seed) {
        const std::size_t       before = pack.size();
        const std::vector<Real> radii  = quantiles(dist, num);
        while (true) {
            std::mt19937 rng(seed);
            const Real   scale  = psd ? psdScale(box, p, dist, num) : porosityRadius(box, p, z, num);
            const int    placed = placeAll(pack, box, radii, scale, rng);
            if (placed == num || 1 - p < 1e-6) {
                if (placed < num)
                    logWarning("SpherePack.makeCloud: only " + std::to_string(placed) + " of the " + std::to_string(num)
                            + " spheres could be placed, even with porosity " + str(p));
                return scale;
            }
            pack.resize(before);
            p = 1 - 0.9 * (1 - p);
        }
    }

    void checkBox(const Vector3r& minCorner, const Vector3r& maxCorner, bool periodic) {
        require(isFinite(minCorner) && isFinite(maxCorner), "minCorner and maxCorner must be finite");
        int flat = 0;
        for (int a = 0; a < 3; a++) {
            require(maxCorner[a] >= minCorner[a],
                    "maxCorner must be above minCorner on every axis (axis " + std::to_string(a) + ": " + str(minCorner[a]) + " > "
                            + str(maxCorner[a]) + ")");
            flat += maxCorner[a] == minCorner[a];
        }
        require(flat <= 1, "maxCorner must be above minCorner on every axis (or on all but one for a 2D packing)");
        require(!(periodic && flat), "a periodic packing needs maxCorner above minCorner on every axis");
    }

    void checkPsd(const std::vector<Real>& sizes, const std::vector<Real>& cumm, Real rMean) {
        require(sizes.size() == cumm.size(),
                "psdSizes and psdCumm must have the same length (" + std::to_string(sizes.size()) + " != " + std::to_string(cumm.size()) + ")");
        if (sizes.empty()) return;
        require(sizes.size() >= 2, "psdSizes and psdCumm must have at least 2 items");
        require(!(rMean > 0), "rMean can't be combined with psdSizes");
        for (std::size_t i = 0; i < sizes.size(); i++) {
            require(std::isfinite(sizes[i]) && sizes[i] > 0, "psdSizes must be positive");
            require(i == 0 || (sizes[i] >= sizes[i - 1] && cumm[i] >= cumm[i - 1]), "psdSizes and psdCumm must be non-decreasing");
        }
        require(cumm.front() == 0 && cumm.back() == 1, "psdCumm must go from 0 to 1");
    }

    void checkCloudArgs(Real rMean, Real rRelFuzz, int num, Real porosity, bool psd) {
        require(std::isfinite(rMean) && rMean != 0, "rMean must be positive (or negative, to derive it from num and porosity)");
        require(rRelFuzz >= 0 && rRelFuzz < 1, "rRelFuzz must be in [0, 1), got " + str(rRelFuzz));
        require(psd || rMean > 0 || num > 0, "num must be positive when neither rMean nor psdSizes is given (rMean is computed from num and porosity)");
        require(rMean > 0 || num <= 0 || porosity < 1, "porosity must be below 1, got " + str(porosity));
        require(!std::isnan(porosity), "porosity must be a number");
    }

} // namespace

long SpherePack::makeCloud(const Vector3r& minCorner, const Vector3r& maxCorner, Real rMean, Real rRelFuzz, int num, bool periodic,
        Real porosity, const std::vector<Real>& psdSizes, const std::vector<Real>& psdCumm, bool distributeMass, long seed) {
    checkBox(minCorner, maxCorner, periodic);
    checkPsd(psdSizes, psdCumm, rMean);
    const bool psd = !psdSizes.empty();
    checkCloudArgs(rMean, rRelFuzz, num, porosity, psd);

    if (rMean <= 0 && num > 0 && porosity <= 0) {
        logWarning("SpherePack.makeCloud: porosity must be positive, using porosity=0.5 (as Yade does)");
        porosity = .5;
    }
    const Box box { minCorner, maxCorner - minCorner, periodic };
    if (periodic) cellSize = box.size;
    appliedPsdScaling = 1;
    const unsigned   seed0 = seed < 0 ? std::random_device {}() : static_cast<unsigned>(seed);
    std::mt19937     rng(seed0);
    const Real       r0 = rMean > 0 ? rMean : 1; // porosity mode: unit radii scaled later
    const RadiusDist dist
            = psd ? RadiusDist(psdSizes, psdCumm, distributeMass) : RadiusDist({ 2 * r0 * (1 - rRelFuzz), 2 * r0 * (1 + rRelFuzz) }, { 0., 1. }, false);

    if (num < 0) placeRandom(pack, box, dist, rng);
    else if (num > 0 && rMean > 0) {
        const int placed = placeAll(pack, box, quantiles(dist, num), 1, rng);
        if (placed < num)
            logWarning("SpherePack.makeCloud: only " + std::to_string(placed) + " of the " + std::to_string(num) + " spheres could be placed ("
                    + std::to_string(maxTries) + " tries per sphere); use a smaller rMean or num");
    } else if (num > 0) {
        const Real scale = placeWithRetries(pack, box, dist, num, rRelFuzz, psd, porosity, seed0);
        if (psd) appliedPsdScaling = scale;
    }
    return static_cast<long>(pack.size());
}

namespace {

    void requireClumps(bool ok, const std::string& what) {
        if (!ok) throw std::invalid_argument("SpherePack.makeClumpCloud: " + what);
    }

    // One clump template: its members and the centre C of their box (members go to c + q·(p + C)).
    struct Template {
        std::vector<Sph> members;
        Vector3r         centre;
        Real             rMin, rMax;
    };

    // Refuses a template that fits the box in no orientation: two members i, j (i = j too) need
    // |Δ_a| + r_i + r_j <= side_a on each axis, so |Δ|² <= Σ_a (side_a - r_i - r_j)², each term at least 0.
    void checkFits(const std::vector<Sph>& members, const Box& box, std::size_t t) {
        for (std::size_t i = 0; i < members.size(); i++)
            for (std::size_t j = i; j < members.size(); j++) {
                const Real r = members[i].r + members[j].r;
                Real       room = 0;
                bool       fits = true;
                for (int a = 0; a < 3; a++) {
                    fits = fits && r <= box.size[a];
                    room += std::pow(std::max<Real>(0, box.size[a] - r), 2);
                }
                if (fits && (members[i].c - members[j].c).squaredNorm() <= room * (1 + 1e-9)) continue; // (exact fits pass)
                throw std::invalid_argument("SpherePack.makeClumpCloud: template " + std::to_string(t) + " cannot fit in the box "
                        + (i == j ? "(its sphere " + std::to_string(i) + " of diameter " + str(2 * members[i].r) + " is wider than a side)"
                                  : "in any orientation (its spheres " + std::to_string(i) + " and " + std::to_string(j) + ")"));
            }
    }

    std::vector<Template> checkTemplates(const std::vector<SpherePack>& clumps, const Box& box) {
        requireClumps(!clumps.empty(), "clumps must hold at least one template (a SpherePack of the member spheres)");
        const Real            side = box.size.minCoeff();
        std::vector<Template> out;
        for (std::size_t t = 0; t < clumps.size(); t++) {
            const SpherePack& c = clumps[t];
            requireClumps(c.size() > 0, "template " + std::to_string(t) + " has no spheres");
            Template tpl { c.pack, c.center(), Inf, 0 };
            for (const Sph& s : c.pack) {
                tpl.rMin = std::min(tpl.rMin, s.r);
                tpl.rMax = std::max(tpl.rMax, s.r);
            }
            // (the reference tries anyway, and gives up after its tries with a warning and no clump)
            if (box.periodic)
                requireClumps(2 * tpl.rMax < side,
                        "template " + std::to_string(t) + " cannot fit in the periodic cell: its sphere of diameter " + str(2 * tpl.rMax)
                                + " is not below the cell's smallest side " + str(side));
            else checkFits(c.pack, box, t);
            out.push_back(std::move(tpl));
        }
        return out;
    }

    // Draws one random position and orientation per try, in the reference's order: x, y, z, then the
    // quaternion's z, y, x, w (each in [0, 1), then normalized); places the clump at the first free one.
    class ClumpPlacer {
    public:
        ClumpPlacer(std::vector<Sph>& pack, const Box& box, CloudGrid& grid, std::mt19937& rng)
                : pack(pack)
                , box(box)
                , grid(grid)
                , rng(rng) { }

        Real draw() { return unit(rng); }

        // Up to maxClumpTries tries; appends the members with clumpId at the first free place.
        bool place(const Template& tpl, int clumpId) {
            std::vector<Sph> m(tpl.members.size());
            for (int t = 0; t < SpherePack::maxClumpTries; t++) {
                Vector3r c;
                for (int a = 0; a < 3; a++) c[a] = box.lo[a] + draw() * box.size[a];
                const Real  z = draw(), y = draw(), x = draw(), w = draw();
                Quaternionr q(w, x, y, z);
                q.normalize();
                for (std::size_t i = 0; i < m.size(); i++) m[i] = { c + q * (tpl.members[i].c + tpl.centre), tpl.members[i].r, clumpId };
                if (!fits(m)) continue;
                for (const Sph& s : m) {
                    grid.insert(static_cast<int>(pack.size()), s.c, s.r);
                    pack.push_back(s);
                }
                return true;
            }
            return false;
        }

    private:
        std::vector<Sph>&                    pack;
        const Box&                           box;
        CloudGrid&                           grid;
        std::mt19937&                        rng;
        std::uniform_real_distribution<Real> unit { 0., 1. };

        // No member outside the box (unless periodic) nor overlapping a sphere already placed.
        bool fits(const std::vector<Sph>& members) const {
            for (const Sph& s : members) {
                if (!box.periodic)
                    for (int a = 0; a < 3; a++)
                        if (s.c[a] - s.r < box.lo[a] || s.c[a] + s.r > box.lo[a] + box.size[a]) return false;
                if (grid.any(s.c, s.r, [&](int id) { return overlaps(box, s.c, s.r, pack[id]); })) return false;
            }
            return true;
        }
    };

} // namespace

long SpherePack::makeClumpCloud(
        const Vector3r& minCorner, const Vector3r& maxCorner, const std::vector<SpherePack>& clumps, bool periodic, int num, long seed) {
    requireClumps(isFinite(minCorner) && isFinite(maxCorner), "minCorner and maxCorner must be finite");
    for (int a = 0; a < 3; a++)
        requireClumps(maxCorner[a] > minCorner[a],
                "maxCorner must be above minCorner on every axis, clumps are 3D (axis " + std::to_string(a) + ": " + str(minCorner[a])
                        + " >= " + str(maxCorner[a]) + ")");
    const Box                   box { minCorner, maxCorner - minCorner, periodic };
    const std::vector<Template> templates = checkTemplates(clumps, box);
    if (periodic) cellSize = box.size;

    Real rMin = Inf, rMax = 0;
    for (const Template& t : templates) {
        rMin = std::min(rMin, t.rMin);
        rMax = std::max(rMax, t.rMax);
    }
    int firstId = 0; // (the reference numbers from 0 at each call, so that two calls share ids)
    for (const Sph& s : pack) firstId = std::max(firstId, s.clumpId + 1);
    CloudGrid grid(box, gridCell(box, rMin, rMax));
    for (std::size_t i = 0; i < pack.size(); i++) grid.insert(static_cast<int>(i), pack[i].c, pack[i].r);

    std::mt19937 rng(seed < 0 ? std::random_device {}() : static_cast<unsigned>(seed));
    ClumpPlacer  placer(pack, box, grid, rng);
    const int    n      = static_cast<int>(templates.size());
    long         placed = 0;
    while (num < 0 || placed < num) {
        const int t = std::min(n - 1, static_cast<int>(placer.draw() * n));
        if (!placer.place(templates[t], firstId + static_cast<int>(placed))) break;
        placed++;
    }
    if (num > 0 && placed < num)
        logWarning("SpherePack.makeClumpCloud: exceeded " + std::to_string(maxClumpTries) + " attempts to place a non-overlapping clump; only "
                + std::to_string(placed) + " of the " + std::to_string(num) + " clumps were added");
    return placed;
}

bool SpherePack::hasClumps() const {
    return std::any_of(pack.begin(), pack.end(), [](const Sph& s) { return s.clumpId >= 0; });
}

std::pair<std::vector<int>, std::vector<std::vector<int>>> SpherePack::getClumps() const {
    std::vector<int>                alone;
    std::map<int, std::vector<int>> byId;
    for (std::size_t i = 0; i < pack.size(); i++) {
        if (pack[i].clumpId < 0) alone.push_back(static_cast<int>(i));
        else byId[pack[i].clumpId].push_back(static_cast<int>(i));
    }
    std::vector<std::vector<int>> clumps;
    for (auto& kv : byId) clumps.push_back(std::move(kv.second));
    return { alone, clumps };
}

void SpherePack::add(const Vector3r& c, Real r) {
    if (!isFinite(c)) throw std::invalid_argument("SpherePack.add: center must be finite");
    if (!(std::isfinite(r) && r > 0)) throw std::invalid_argument("SpherePack.add: radius must be positive and finite, got " + str(r));
    pack.push_back({ c, r });
}

std::pair<Vector3r, Vector3r> SpherePack::aabb() const {
    Vector3r lo = Vector3r::Constant(Inf), hi = Vector3r::Constant(-Inf);
    for (const Sph& s : pack) {
        lo = lo.cwiseMin(s.c - Vector3r::Constant(s.r));
        hi = hi.cwiseMax(s.c + Vector3r::Constant(s.r));
    }
    return { lo, hi };
}

Vector3r SpherePack::dim() const {
    const auto box = aabb();
    return box.second - box.first;
}

Vector3r SpherePack::center() const {
    const auto box = aabb();
    return (box.first + box.second) / 2;
}

Real SpherePack::relDensity() const {
    Real volume = 0;
    for (const Sph& s : pack) volume += 4. / 3. * Mathr_PI * s.r * s.r * s.r;
    return volume / dim().prod();
}

void SpherePack::translate(const Vector3r& shift) {
    for (Sph& s : pack) s.c += shift;
}

void SpherePack::cellRepeat(const Vector3i& count) {
    if (!isPeriodic()) throw std::logic_error("cellRepeat cannot be used on non-periodic packing.");
    if (count.minCoeff() < 1) throw std::invalid_argument("SpherePack.cellRepeat: each count must be at least 1");
    int clumpSpan = 0; // copies of clump k take ids k + copy·clumpSpan
    for (const Sph& s : pack) clumpSpan = std::max(clumpSpan, s.clumpId + 1);
    const std::vector<Sph> cell = pack;
    pack.clear();
    pack.reserve(cell.size() * std::size_t(count.prod()));
    int copy = 0;
    for (int i = 0; i < count[0]; ++i)
        for (int j = 0; j < count[1]; ++j)
            for (int k = 0; k < count[2]; ++k, ++copy) {
                const Vector3r shift(i * cellSize[0], j * cellSize[1], k * cellSize[2]);
                for (const Sph& s : cell) pack.push_back(Sph { s.c + shift, s.r, s.clumpId < 0 ? -1 : s.clumpId + copy * clumpSpan });
            }
    cellSize = cellSize.cwiseProduct(count.cast<Real>());
}

void SpherePack::cellFill(const Vector3r& size) {
    if (!isPeriodic()) throw std::logic_error("cellFill cannot be used on non-periodic packing.");
    if (!size.allFinite()) throw std::invalid_argument("SpherePack.cellFill: the size must be finite");
    Vector3i count;
    for (int a = 0; a < 3; ++a) count[a] = std::max(1, int(std::ceil(size[a] / cellSize[a])));
    cellRepeat(count);
}

void SpherePack::scale(Real factor) {
    if (!(std::isfinite(factor) && factor > 0)) throw std::invalid_argument("SpherePack.scale: factor must be positive, got " + str(factor));
    const Vector3r mid = center();
    for (Sph& s : pack) {
        s.c = mid + factor * (s.c - mid);
        s.r *= factor;
    }
    cellSize *= factor;
}

std::pair<std::vector<Real>, std::vector<Real>> SpherePack::psd(int bins, bool mass) const {
    if (bins < 1) throw std::invalid_argument("SpherePack.psd: bins must be at least 1");
    if (pack.empty()) return {};
    Real dMin = Inf, dMax = -Inf;
    for (const Sph& s : pack) {
        dMin = std::min(dMin, 2 * s.r);
        dMax = std::max(dMax, 2 * s.r);
    }
    if (dMin == dMax) { // one size: a bin of width 1 around it, as the reference does
        dMin -= .5;
        dMax += .5;
    }
    std::vector<Real> edges(bins + 1), cumm(bins + 1, 0.), hist(bins, 0.);
    Real              total = 0;
    for (const Sph& s : pack) {
        const int  bin = std::min(bins - 1, static_cast<int>((2 * s.r - dMin) / (dMax - dMin) * bins));
        const Real w   = mass ? s.r * s.r * s.r : 1;
        hist[bin] += w;
        total += w;
    }
    for (int i = 0; i <= bins; i++) edges[i] = dMin + i * (dMax - dMin) / bins;
    for (int i = 0; i < bins; i++) cumm[i + 1] = cumm[i] + hist[i] / total;
    return { edges, cumm };
}

void SpherePack::save(const std::string& fileName) const {
    std::ofstream f(fileName);
    if (!f) throw FileError("SpherePack.save: cannot open '" + fileName + "' for writing", errno, fileName);
    f.imbue(std::locale::classic());
    f << std::setprecision(17);
    if (isPeriodic()) f << "##PERIODIC:: " << cellSize[0] << " " << cellSize[1] << " " << cellSize[2] << "\n";
    const bool clumps = hasClumps();
    for (const Sph& s : pack) {
        f << s.c[0] << " " << s.c[1] << " " << s.c[2] << " " << s.r;
        if (clumps) f << " " << s.clumpId;
        f << "\n";
    }
    if (!f.flush()) throw FileError("SpherePack.save: error writing '" + fileName + "'", errno, fileName);
}

namespace {
    // The numbers of a line, or false if a word is not a number.
    bool parseNumbers(const std::string& line, std::vector<Real>& out) {
        out.clear();
        std::istringstream words(line);
        std::string        w;
        while (words >> w) {
            Real       x;
            const auto res = std::from_chars(w.data(), w.data() + w.size(), x);
            if (res.ec != std::errc() || res.ptr != w.data() + w.size()) return false;
            out.push_back(x);
        }
        return true;
    }
} // namespace

// Reads what save() writes, and the reference's files (5th column: the clump id, negative for none);
// '#' lines other than the periodic header are comments. The packing is replaced only if all is read.
void SpherePack::load(const std::string& fileName) {
    std::ifstream f(fileName);
    if (!f) throw FileError("SpherePack.load: cannot open '" + fileName + "'", errno, fileName);
    SpherePack        loaded;
    std::string       line;
    std::vector<Real> x;
    const std::string header = "##PERIODIC::";
    for (int lineNo = 1; std::getline(f, line); lineNo++) {
        const std::string where = "SpherePack.load: " + fileName + ", line " + std::to_string(lineNo) + ": ";
        const bool        isHeader = line.compare(0, header.size(), header) == 0;
        const std::size_t first    = line.find_first_not_of(" \t\r");
        if (!isHeader && first != std::string::npos && line[first] == '#') continue;
        if (!parseNumbers(isHeader ? line.substr(header.size()) : line, x)) throw std::invalid_argument(where + "not a number in '" + line + "'");
        if (x.empty()) continue;
        if (isHeader) {
            if (x.size() != 3 || !(x[0] > 0 && x[1] > 0 && x[2] > 0)) throw std::invalid_argument(where + "expected 3 positive cell sizes");
            loaded.cellSize = Vector3r(x[0], x[1], x[2]);
            continue;
        }
        if (x.size() != 4 && x.size() != 5) throw std::invalid_argument(where + "expected 'x y z r' or 'x y z r clumpId', got '" + line + "'");
        try {
            loaded.add(Vector3r(x[0], x[1], x[2]), x[3]);
        } catch (const std::invalid_argument& e) { throw std::invalid_argument(where + e.what()); }
        if (x.size() == 5) {
            if (!(x[4] == std::floor(x[4]) && std::abs(x[4]) < 1e9)) throw std::invalid_argument(where + "the clump id (5th column) must be an integer");
            loaded.pack.back().clumpId = x[4] < 0 ? -1 : static_cast<int>(x[4]);
        }
    }
    if (f.bad()) throw FileError("SpherePack.load: error reading '" + fileName + "'", errno, fileName);
    pack     = std::move(loaded.pack);
    cellSize = loaded.cellSize;
}

} // namespace yade
