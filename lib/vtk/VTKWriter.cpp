#include <lib/vtk/VTKWriter.hpp>
#include <algorithm>
#include <stdexcept>

#ifdef YADE_HAVE_VTK
#include <vtkCellArray.h>
#include <vtkCompositeDataSet.h>
#include <vtkInformation.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVersion.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriter.h>
#endif

namespace yade {

#ifdef YADE_HAVE_VTK

bool vtkAvailable() { return true; }
std::string vtkVersion() { return vtkVersion::GetVTKVersion(); }

static vtkSmartPointer<vtkDoubleArray> toVtk(const VtkArray& a, size_t expected, const char* where) {
    if (a.values.size() != expected * (size_t)a.components)
        throw std::logic_error("VTK writer: array " + a.name + " has " + std::to_string(a.values.size()) + " values for " +
                               std::to_string(expected) + " " + where);
    auto v = vtkSmartPointer<vtkDoubleArray>::New();
    v->SetName(a.name.c_str());
    v->SetNumberOfComponents(a.components);
    v->SetNumberOfTuples((vtkIdType)expected);
    std::copy(a.values.begin(), a.values.end(), v->GetPointer(0));
    return v;
}

static vtkSmartPointer<vtkDataSet> toVtk(const VtkPiece& p) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints((vtkIdType)p.numPoints());
    std::copy(p.points.begin(), p.points.end(), static_cast<double*>(points->GetVoidPointer(0)));
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New(), conn = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfTuples((vtkIdType)p.numCells() + 1);
    conn->SetNumberOfTuples((vtkIdType)p.connectivity.size());
    vtkIdType* o = offsets->GetPointer(0);
    for (size_t c = 0; c <= p.numCells(); ++c) o[c] = (vtkIdType)(c * p.pointsPerCell);
    std::copy(p.connectivity.begin(), p.connectivity.end(), conn->GetPointer(0));
    cells->SetData(offsets, conn);
    vtkSmartPointer<vtkDataSet> data;
    if (p.polyData) {
        auto poly = vtkSmartPointer<vtkPolyData>::New();
        poly->SetPoints(points);
        if (p.cellType == 1) poly->SetVerts(cells);
        else poly->SetLines(cells);
        data = poly;
    } else {
        auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
        grid->SetPoints(points);
        grid->SetCells(p.cellType, cells);
        data = grid;
    }
    for (const VtkArray& a : p.pointData) data->GetPointData()->AddArray(toVtk(a, p.numPoints(), "points"));
    for (const VtkArray& a : p.cellData) data->GetCellData()->AddArray(toVtk(a, p.numCells(), "cells"));
    return data;
}

static void configure(vtkXMLWriter* w, const VtkWriteOptions& o) {
    if (o.ascii) w->SetDataModeToAscii();
    else w->SetDataModeToAppended();
    w->EncodeAppendedDataOff(); // raw bytes, not base64
    if (o.compress) w->SetCompressorTypeToZLib();
    else w->SetCompressorTypeToNone();
}

static void write(vtkXMLWriter* w, const std::string& file) {
    w->SetFileName(file.c_str());
    if (w->Write() != 1 || w->GetErrorCode() != 0)
        throw std::runtime_error("VTK writer: cannot write " + file + " (does its folder exist and is it writable?)");
}

void writeVtkPiece(const std::string& file, const VtkPiece& piece, const VtkWriteOptions& options) {
    vtkSmartPointer<vtkDataSet> data = toVtk(piece);
    if (piece.polyData) {
        vtkNew<vtkXMLPolyDataWriter> w;
        configure(w, options);
        w->SetInputData(data);
        write(w, file);
    } else {
        vtkNew<vtkXMLUnstructuredGridWriter> w;
        configure(w, options);
        w->SetInputData(data);
        write(w, file);
    }
}

void writeVtkMultiblock(const std::string& file, const std::vector<std::pair<std::string, VtkPiece>>& blocks,
                        const VtkWriteOptions& options) {
    vtkNew<vtkMultiBlockDataSet> set;
    set->SetNumberOfBlocks((unsigned)blocks.size());
    for (size_t i = 0; i < blocks.size(); ++i) {
        set->SetBlock((unsigned)i, toVtk(blocks[i].second));
        set->GetMetaData((unsigned)i)->Set(vtkCompositeDataSet::NAME(), blocks[i].first.c_str());
    }
    vtkNew<vtkXMLMultiBlockDataWriter> w;
    configure(w, options);
    w->SetInputData(set);
    write(w, file);
}

#else // built without VTK

static const char* missing = "this build has no VTK library (install libvtk9-dev and rebuild: bash scripts/setup.sh)";
bool vtkAvailable() { return false; }
std::string vtkVersion() { return ""; }
void writeVtkPiece(const std::string&, const VtkPiece&, const VtkWriteOptions&) { throw std::runtime_error(missing); }
void writeVtkMultiblock(const std::string&, const std::vector<std::pair<std::string, VtkPiece>>&, const VtkWriteOptions&) {
    throw std::runtime_error(missing);
}

#endif

} // namespace yade
