// The compiled part of the yade package.
#include <pkg/RegisterClasses.hpp>
#include <py/wrapper/Classes.hpp>
#include <py/wrapper/DisplayWrapper.hpp>
#include <py/wrapper/Math.hpp>
#include <lib/base/Logging.hpp>
#include <lib/serialization/Node.hpp>
#include <pkg/common/PyRunner.hpp>
#include <pkg/common/SnapshotEngine.hpp>
#include <pkg/dem/NewtonIntegrator.hpp>
#include <pybind11/eval.h>
#include <pybind11/stl.h>
#include <map>
#include <system_error>
#include <lib/factory/ClassRegistry.hpp>
#include <py/wrapper/ArraysWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <py/wrapper/ShopWrapper.hpp>
#include <py/wrapper/SpherePackWrapper.hpp>
#include <py/wrapper/CohesiveWrapper.hpp>
#include <py/wrapper/FrictViscoWrapper.hpp>
#include <py/wrapper/GridWrapper.hpp>
#include <py/wrapper/PolyhedraWrapper.hpp>
#include <py/wrapper/CpmWrapper.hpp>
#include <py/wrapper/HertzMindlinWrapper.hpp>
#include <py/wrapper/TriaxialWrapper.hpp>
#include <lib/vtk/VTKWriter.hpp>
#include <py/wrapper/CellWrapper.hpp>
#include <py/wrapper/ScGeomWrapper.hpp>
#ifdef _OPENMP
#include <omp.h>
#endif

PYBIND11_MODULE(_yade, m) {
    m.doc() = "Yade-compatible DEM engine (C++ core)";
    yade::registerAllClasses();
    yade::registerMath(m);
    yade::bindAllClasses(m);
    pybind11::register_exception<yade::FormatError>(m, "FileFormatError", PyExc_ValueError);
    pybind11::register_exception<yade::StabilityError>(m, "StabilityError", PyExc_RuntimeError);
    // A failed read or write of a file (a full disk): OSError with its errno, as Python's own I/O.
    pybind11::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const std::system_error& e) {
            // (the system's text for the errno, as Python's own I/O errors: O.save adds the file name)
            PyObject* args = Py_BuildValue("(is)", e.code().value(), e.code().message().c_str());
            PyErr_SetObject(PyExc_OSError, args);
            Py_XDECREF(args);
        }
    });
    yade::bindOmega(m);
    yade::bindArrays(m);
    yade::bindShop(m);
    yade::bindSpherePack(m);
    yade::bindHertzMindlin(m);
    yade::bindCell(m);
    yade::bindScGeom(m);
    yade::bindFrictVisco(m);
    yade::bindPolyhedra(m);
    yade::bindCohesive(m);
    yade::bindGrid(m);
    yade::bindTriaxial(m);
    yade::bindCpm(m);
    yade::bindDisplay(m);
    // PyRunner commands run in the namespace of __main__ (the script), holding the GIL; a Python
    // exception propagates as error_already_set and is re-raised by O.wait() with its traceback.
    yade::PyRunner::setCommandRunner([](const std::string& command) {
        pybind11::gil_scoped_acquire gil;
        pybind11::object ns = pybind11::module_::import("__main__").attr("__dict__");
        try {
            // (Python's own exec: pybind11::exec puts a coding line first, so tracebacks said line 2)
            pybind11::module_::import("builtins").attr("exec")(pybind11::str(command), ns);
        } catch (pybind11::error_already_set& e) { // reported as the reference does (yade/_pyrunner.py)
            pybind11::object replacement = pybind11::module_::import("yade._pyrunner").attr("wrapped")(command, e.value(), e.trace());
            if (replacement.is_none()) throw;
            PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(replacement.ptr())), replacement.ptr());
            throw pybind11::error_already_set();
        }
    });
    // SnapshotEngine asks the GUI (yade.qt._takeSnapshot(file, format, timeout): "" when saved, else why not,
    // None when there is no view); without yade.qt imported there is no view.
    yade::SnapshotEngine::setTaker([](yade::SnapshotEngine& e, const std::string& file) -> std::string {
        pybind11::gil_scoped_acquire gil;
        pybind11::dict modules = pybind11::module_::import("sys").attr("modules");
        if (!modules.contains("yade.qt")) return yade::SnapshotEngine::noView;
        pybind11::object take = pybind11::getattr(modules["yade.qt"], "_takeSnapshot", pybind11::none());
        if (take.is_none()) return yade::SnapshotEngine::noView;
        pybind11::object r = take(file, e.format, e.deadTimeout);
        return r.is_none() ? std::string(yade::SnapshotEngine::noView) : r.cast<std::string>();
    });
    m.def("_loopWaitsForGui", [](bool waits) { yade::omega().loopWaitsForGui(waits); },
          "The simulation's thread says it waits for the GUI (yade.qt._waitForSnapshots): the 3D view's frames do not "
          "wait for the end of its step meanwhile");
    // Engine warnings become Python RuntimeWarnings (shown once per message by default).
    yade::setWarningSink([](const std::string& msg) {
        pybind11::gil_scoped_acquire gil;
        auto warn = pybind11::module_::import("warnings").attr("warn");
        warn(msg, pybind11::module_::import("builtins").attr("RuntimeWarning"));
    });
    m.def("setNumThreads", [](int n) {
        if (n < 1) throw pybind11::value_error("number of threads must be >= 1");
#ifdef _OPENMP
        omp_set_num_threads(n);
#endif
        yade::omega().scene().setThreads(n);
    }, "Set the number of OpenMP threads");
    m.def("_classNames", [] {
        std::vector<std::string> names;
        for (const yade::ClassInfo* c : yade::ClassRegistry::instance().all()) names.push_back(c->name);
        return names;
    }, "Names of all registered classes, bases before derived classes (yade.wrapper, yade.system)");
    m.def("_libVersions", [] {
        std::map<std::string, std::string> v;
#if defined(__clang__)
        v["compiler"] = "clang " __clang_version__;
#elif defined(__GNUC__)
        v["compiler"] = "gcc " + std::to_string(__GNUC__) + "." + std::to_string(__GNUC_MINOR__) + "." + std::to_string(__GNUC_PATCHLEVEL__);
#endif
        v["eigen"] = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION);
        v["pybind11"] = std::to_string(PYBIND11_VERSION_MAJOR) + "." + std::to_string(PYBIND11_VERSION_MINOR) + "." + std::to_string(PYBIND11_VERSION_PATCH);
        if (yade::vtkAvailable()) v["vtk"] = yade::vtkVersion();
        v["python"] = std::to_string(PY_MAJOR_VERSION) + "." + std::to_string(PY_MINOR_VERSION) + "." + std::to_string(PY_MICRO_VERSION);
        return v;
    }, "Versions of the libraries compiled in (yade.libVersions)");
    { // yade.config.sourceRoot: this file is <root>/py/wrapper/Module.cpp
        std::string root = __FILE__;
        for (int up = 0; up < 3 && root.find('/') != std::string::npos; ++up) root = root.substr(0, root.rfind('/'));
        m.attr("_sourceRoot") = root;
    }
    m.attr("vtk") = yade::vtkAvailable(); // VTKRecorder writes files (the build found libvtk9-dev)
#ifdef _OPENMP
    m.attr("openmp") = true;
#else
    m.attr("openmp") = false;
#endif
}
