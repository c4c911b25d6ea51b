// Writing VTK's XML files (.vtu, .vtp, .vtm) from plain arrays. The engines gather what goes into a
// file (points, cells, named arrays) without knowing VTK; this is the one place that calls the VTK
// library, and a build without it (libvtk9-dev missing) still links: the functions then throw, saying so.
#pragma once
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace yade {

// A named array of values per point or per cell: `components` values each (1 scalar, 3 vector).
struct VtkArray {
    std::string name;
    int components = 1;
    std::vector<double> values;
};

// One dataset: points, cells of one VTK cell type, and arrays on them. Written as an unstructured grid
// (.vtu) or, when polyData, as poly data (.vtp: lines).
struct VtkPiece {
    bool polyData = false;
    std::vector<double> points;        // 3 coordinates per point
    int cellType = 1;                  // VTK's number: 1 vertex, 3 line, 5 triangle, 12 hexahedron
    int pointsPerCell = 1;
    std::vector<int64_t> connectivity; // pointsPerCell point indices per cell
    std::deque<VtkArray> pointData, cellData; // (a deque: a reference to an array stays valid as more are added)
    size_t numPoints() const { return points.size() / 3; }
    size_t numCells() const { return pointsPerCell ? connectivity.size() / pointsPerCell : 0; }
    VtkArray& addPointArray(const std::string& name, int components) { return add(pointData, name, components); }
    VtkArray& addCellArray(const std::string& name, int components) { return add(cellData, name, components); }

private:
    static VtkArray& add(std::deque<VtkArray>& to, const std::string& name, int components) {
        to.push_back(VtkArray{name, components, {}});
        return to.back();
    }
};

struct VtkWriteOptions {
    bool ascii = false;    // text data (else raw binary, appended)
    bool compress = false; // zlib-compressed binary
};

// Whether this build writes VTK files, and the library's version ("" without it).
bool vtkAvailable();
std::string vtkVersion();
// Writes one piece to `file` (.vtu, or .vtp when piece.polyData). Throws std::runtime_error when the
// file cannot be written or the build has no VTK.
void writeVtkPiece(const std::string& file, const VtkPiece& piece, const VtkWriteOptions& options);
// Writes the named pieces as one multiblock dataset: `file` (.vtm) and its pieces in a folder beside it.
void writeVtkMultiblock(const std::string& file, const std::vector<std::pair<std::string, VtkPiece>>& blocks,
                        const VtkWriteOptions& options);

} // namespace yade
