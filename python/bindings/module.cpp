// sedem._sedem: `sedem run` inside the Python process. The run is the program's own (app::run:
// its folder, files, checkpoint and resume), on a worker thread with the GIL released; the
// calling thread waits, calls the Python progress callback and looks for Ctrl-C between
// waits. Results come out as numpy arrays; the Python side makes the tables.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <vtkObject.h>

#include <QCoreApplication>
#include <QGuiApplication>
#include <chrono>
#include <cmath>
#include <optional>

#include "app/qt_platform.h"
#include "python/bindings/background_run.h"

namespace py = pybind11;
using sedem::python::BackgroundRun;

namespace {

// The run draws its figures and frames through Qt and VTK, as the program does: one
// application object for the process, made on first use and kept (Qt allows one).
void ensure_qt() {
  if (QCoreApplication::instance()) return;
  static int argc = 1;
  static char name[] = "sedem";
  static char* argv[] = {name, nullptr};
  vtkObject::GlobalWarningDisplayOff();
  sedem::app::use_offscreen_platform();
  new QGuiApplication(argc, argv);
}

template <class T>
py::array_t<T> array(const std::vector<T>& v) {
  return py::array_t<T>(py::ssize_t(v.size()), v.data());
}

py::dict readings(const sedem::TestReadings& r) {
  std::vector<double> time, diameter, percent;
  std::vector<std::vector<double>> extra(r.extra_columns.size());
  for (const auto& row : r.rows) {
    time.push_back(row.time);
    diameter.push_back(row.diameter);
    percent.push_back(row.percent_finer);
    for (std::size_t j = 0; j < extra.size(); ++j)
      extra[j].push_back(j < row.extra.size() ? row.extra[j] : std::nan(""));
  }
  py::dict d;
  d["time_s"] = array(time);
  d["diameter_m"] = array(diameter);
  d["percent_finer"] = array(percent);
  for (std::size_t j = 0; j < extra.size(); ++j) d[py::str(r.extra_columns[j])] = array(extra[j]);
  return d;
}

py::dict particles(const sedem::Snapshot& s) {
  const auto& p = s.particles;
  py::dict d;
  d["time_s"] = s.time;
  d["x_m"] = array(p.x);
  d["y_m"] = array(p.y);
  d["vx_m_per_s"] = array(p.vx);
  d["vy_m_per_s"] = array(p.vy);
  d["omega_rad_per_s"] = array(p.omega);
  d["diameter_m"] = array(p.diameter);
  d["weight"] = array(p.weight);
  d["size_class"] = array(p.size_class);
  d["id"] = array(p.id);
  return d;
}

// Waits for the run's end, the GIL released meanwhile. A Python exception (Ctrl-C's
// KeyboardInterrupt, or one raised by the callback) stops the run, which then writes what it
// computed and its checkpoint, as on Ctrl-C in a terminal; the exception is raised after.
int wait(BackgroundRun& run, const py::object& progress, double poll_s) {
  const auto poll = std::chrono::milliseconds(std::max(1, int(poll_s * 1000)));
  std::optional<py::error_already_set> pending;
  for (;;) {
    bool ended;
    {
      py::gil_scoped_release release;
      ended = run.wait_for(poll);
    }
    if (!pending) {
      try {
        const auto p = run.take_progress();
        if (p.fresh && !progress.is_none())
          progress(p.simulated_time, p.end_time, p.particle_steps);
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      } catch (py::error_already_set& e) {
        run.stop();
        pending.emplace(std::move(e));
      }
    }
    if (ended) break;
  }
  if (pending) throw *pending;
  if (!run.error().empty()) throw std::runtime_error(run.error());
  return run.status();
}

std::unique_ptr<BackgroundRun> make_run(const std::string& scene, const std::string& scene_text,
                                        const std::vector<std::string>& overrides,
                                        const std::string& out, bool overwrite,
                                        const std::string& resume,
                                        const std::vector<double>& keep_times,
                                        const std::string& keep, bool quiet) {
  ensure_qt();
  sedem::app::RunOptions o;
  o.scene = scene;
  o.scene_text = scene_text;
  o.overrides = overrides;
  o.out_dir = out;
  o.overwrite = overwrite;
  o.resume_dir = resume;
  o.quiet = quiet;
  using Which = sedem::python::ParticleKeeper::Which;
  const Which which = keep == "last"     ? Which::last
                      : keep == "output" ? Which::output
                      : keep == "all"    ? Which::all
                      : keep == "times"  ? Which::wanted
                                        : throw py::value_error("keep: last, output, all or times");
  return std::make_unique<BackgroundRun>(std::move(o),
                                         sedem::python::ParticleKeeper(keep_times, which));
}

}  // namespace

PYBIND11_MODULE(_sedem, m) {
  m.doc() = "sedem's run inside the Python process (use the sedem package, not this module)";
  m.attr("version") = SEDEM_VERSION;
  py::class_<BackgroundRun>(m, "Run")
      .def(py::init(&make_run), py::arg("scene") = "", py::arg("scene_text") = "",
           py::arg("overrides") = std::vector<std::string>{}, py::arg("out") = "",
           py::arg("overwrite") = false, py::arg("resume") = "",
           py::arg("keep_times") = std::vector<double>{}, py::arg("keep") = "last",
           py::arg("quiet") = true)
      .def("start", &BackgroundRun::start)
      .def("stop", &BackgroundRun::stop, "Ask the run to stop at its next step (any thread)")
      .def("wait", &wait, py::arg("progress") = py::none(), py::arg("poll") = 0.2,
           "Wait for the end; progress(simulated_s, end_s, particle_steps) on this thread")
      .def_property_readonly("running", &BackgroundRun::running)
      .def_property_readonly("stop_asked", &BackgroundRun::stop_asked)
      .def_property_readonly("status", &BackgroundRun::status)
      .def_property_readonly("simulated_time", &BackgroundRun::simulated_time)
      .def("results",
           [](const BackgroundRun& r) {
             py::list tests;
             if (!r.results()) return tests;
             for (const auto& t : r.results()->granulometry.tests) {
               py::dict d;
               d["test"] = t.test;
               d["error_pp"] = t.error;
               d["bias_pp"] = t.bias;
               d["dem"] = readings(t.dem);
               d["reference"] = readings(t.reference);
               tests.append(d);
             }
             return tests;
           })
      .def("true_curve",
           [](const BackgroundRun& r) {
             std::vector<double> diameter, percent;
             if (r.results())
               for (const auto& p : r.results()->granulometry.true_curve) {
                 diameter.push_back(p.diameter);
                 percent.push_back(p.percent_finer);
               }
             py::dict d;
             d["diameter_m"] = array(diameter);
             d["percent_finer"] = array(percent);
             return d;
           })
      .def("particles", [](const BackgroundRun& r) {
        py::list out;
        for (const auto& s : r.particles()) out.append(particles(s));
        return out;
      });
}
