// Geometric sphere packings (yade.pack.SpherePack): a list of (center, radius, clump id), with the loose
// random "cloud" generators makeCloud (spheres) and makeClumpCloud (clumps), and text save/load. Plain C++:
// no bodies, no scene, no Python.
#pragma once
#include <lib/base/Math.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace yade {

class SpherePack {
public:
    struct Sph {
        Vector3r c;
        Real     r;
        int      clumpId = -1; // spheres with the same id >= 0 are the members of one clump; -1: a sphere alone
    };
    // Thrown when a file cannot be opened or written, with errno and the file name (Python: OSError, so
    // FileNotFoundError for a missing file).
    struct FileError : std::runtime_error {
        FileError(const std::string& what, int err, const std::string& file)
                : std::runtime_error(what)
                , err(err)
                , file(file) { }
        int         err;
        std::string file;
    };

    // Tries to place one sphere at a random non-overlapping position before makeCloud gives up
    // (the value of the reference implementation: "Exceeded 1000 tries to insert non-overlapping sphere").
    static constexpr int maxTries = 1000;
    // Tries to place one clump (a new random position and orientation each) before makeClumpCloud gives up
    // (the reference's value: "Exceeded 200 attempts to place non-overlapping clump").
    static constexpr int maxClumpTries = 200;

    std::vector<Sph> pack;
    Vector3r         cellSize          = Vector3r::Zero(); // periodic cell size; zero when not periodic
    Real             appliedPsdScaling = 1.;               // factor applied to psdSizes by the last makeCloud

    // Random loose packing in the box [minCorner, maxCorner] (one flat axis makes it 2D), appended to the
    // spheres already there, which are avoided as well. Radii come from:
    //  - psdSizes/psdCumm: piecewise-linear cumulative distribution of diameters (of mass fractions when
    //    distributeMass); with num>0 the psd is scaled down (appliedPsdScaling) for num spheres to fill
    //    about (1-porosity) of the box, by the reference's mean-volume estimate, and further if they do not fit;
    //  - rMean>0: uniform in rMean·(1±rRelFuzz);
    //  - rMean<0 and num>0: rMean = ∛(V(1-p) / (4/3 π (1+rRelFuzz²) num)), p = porosity.
    // With num>0 the radii are deterministic quantiles placed largest first, and (except with rMean>0) an
    // attempt that cannot place them all is repeated with porosity raised to 1-0.9(1-p). Without num they
    // are random and generation stops at the first sphere that cannot be placed in maxTries tries.
    // seed<0: random seed. For a given seed the spheres are those of the reference (same mt19937 draws).
    // Returns the number of spheres in the packing (as the reference does: previous ones included).
    long makeCloud(const Vector3r& minCorner, const Vector3r& maxCorner, Real rMean = -1, Real rRelFuzz = 0,
            int num = -1, bool periodic = false, Real porosity = 0.65, const std::vector<Real>& psdSizes = {},
            const std::vector<Real>& psdCumm = {}, bool distributeMass = false, long seed = -1);

    // Random loose packing of clumps in the box [minCorner, maxCorner] (3D only), appended to the spheres
    // already there, which are avoided as well. clumps: the templates, each a packing of the member spheres in
    // the clump's own frame; each clump picks one at random, then up to maxClumpTries random (position c,
    // orientation q) until no member overlaps a sphere already placed (through the periodic images if
    // periodic) and, if not periodic, all members lie inside the box. As the reference does, the members go
    // to c + q·(p + C), p a member's position in its template and C the centre of the template's aabb().
    // The new clumps take the ids after the largest one in the packing. num>0: that many clumps (a warning
    // if fewer fit); num<0: until one cannot be placed. seed<0: random seed; for a given seed the clumps are
    // those of the reference (same mt19937 draws). Returns the number of clumps placed by this call.
    long makeClumpCloud(const Vector3r& minCorner, const Vector3r& maxCorner, const std::vector<SpherePack>& clumps, bool periodic = false,
            int num = -1, long seed = -1);

    void                          add(const Vector3r& c, Real r);
    bool                          hasClumps() const;
    // (indices of the spheres alone, [indices of the members of each clump, by increasing clump id])
    std::pair<std::vector<int>, std::vector<std::vector<int>>> getClumps() const;
    std::size_t                   size() const { return pack.size(); }
    bool                          isPeriodic() const { return cellSize != Vector3r::Zero(); }
    std::pair<Vector3r, Vector3r> aabb() const; // corners of the spheres' box, radii included
    Vector3r                      dim() const;
    Vector3r                      center() const;
    Real                          relDensity() const; // spheres' volume / volume of aabb()
    void                          translate(const Vector3r& shift);
    // Periodic packings only (std::logic_error otherwise): count[i] copies of the cell along axis i, each
    // shifted by a whole number of cell sizes; cellSize grows by count (clump ids stay distinct per copy).
    void                          cellRepeat(const Vector3i& count);
    // cellRepeat by the fewest copies that make the cell at least size along each axis.
    void                          cellFill(const Vector3r& size);
    void                          scale(Real factor); // about center(); radii and cellSize too
    // (diameters, cumulative fractions), bins+1 values each, diameters from the smallest to the largest;
    // fractions of the number of spheres, or of their volume when mass.
    std::pair<std::vector<Real>, std::vector<Real>> psd(int bins = 50, bool mass = true) const;
    // Text: optional "##PERIODIC:: sx sy sz" line, then "x y z r" per sphere, "x y z r clumpId" (-1 for a
    // sphere alone) if the packing has clumps; load reads either (the reference always writes 5 columns).
    void save(const std::string& fileName) const;
    void load(const std::string& fileName);
};

} // namespace yade
