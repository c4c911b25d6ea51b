// Writes the scene to VTK's XML files for ParaView, periodically (manual: "VTKRecorder & Paraview", the 3D
// post-processing tutorial): one file per kind of object and run, named as the reference names them
// (fileName + "spheres." + iteration + ".vtu", "facets", "boxes", "intrs" (.vtp), "pericell"), or one
// multiblock file per run (fileName + iteration + ".vtm"), and a .pvd series per kind so that ParaView
// sees the simulated time. What each file holds is chosen by `recorders`; the writing is lib/vtk.
#pragma once
#include <core/PeriodicEngine.hpp>
#include <map>
#include <string>
#include <vector>

namespace yade {

struct VtkPiece;

class VTKRecorder : public PeriodicEngine {
public:
    static constexpr const char* classDoc =
            "Periodic engine writing the scene to VTK XML files for ParaView: fileName + kind + '.' + iteration + "
            "'.vtu' (kind: spheres, facets, boxes, pericell) or '.vtp' (intrs: the force chains), or one '.vtm' per run "
            "with multiblock; a .pvd file per kind lists the files with their simulated time. recorders chooses the "
            "content: spheres, facets, boxes, intr, pericell, and the arrays velocity, ids, mass, clumpId, colors, stress, "
            "materialId, mask, bstresses; 'all' is every one of them but bstresses.";
    std::string fileName, Key;
    std::vector<std::string> recorders{"all"};
    bool ascii = false, compress = false, multiblock = false, skipFacetIntr = true, skipNondynamic = false, pvd = true;
    int mask = 0;
    template <class V> void visit(V& v) {
        PeriodicEngine::visit(v);
        v.attr("fileName", fileName, "Start of the file names (may hold a folder, made when missing); the kind, the iteration and the extension follow");
        v.attr("recorders", recorders,
               "What is written: spheres, facets, boxes, intr, pericell (files) and velocity, ids, mass, clumpId, colors, "
               "stress, materialId, mask, bstresses (arrays on them); 'all': all of them but bstresses");
        v.attr("ascii", ascii, "Write the data as text (larger, slower; readable)");
        v.attr("compress", compress, "Compress the binary data with zlib (smaller, slower to write)");
        v.attr("multiblock", multiblock, "One multiblock file (.vtm) per run holding every kind, instead of one file per kind");
        v.attr("skipFacetIntr", skipFacetIntr, "Leave out of intrs the contacts that are not between two spheres");
        v.attr("skipNondynamic", skipNondynamic, "Leave out the bodies that are not dynamic");
        v.attr("mask", mask, "Write only the bodies whose mask shares a bit with this one (0: all bodies)");
        v.attr("Key", Key, "A text naming this recorder (kept in the saved scene; not part of the file names, as in the reference)");
        v.attr("pvd", pvd, "Also write fileName + kind + '.pvd', the series of files with their times, for ParaView");
    }
    VTKRecorder() { initRun = true; }
    void action() override;
    void postLoad() override; // (an unknown recorder: ValueError naming the known ones)

    // The files written by this recorder since it was made, per kind, with their simulated times (the .pvd series).
    std::map<std::string, std::vector<std::pair<Real, std::string>>> series;

private:
    void writeSeries(const std::string& kind, const std::string& file);
};

} // namespace yade
