// cyclic_triax._engine: the engine's library for Python (pybind11). It runs a scene through the
// same function as `dem run` (run/run_request.hpp) and reads results with the engine's own HDF5
// readers and column tables; cyclic_triax/__init__.py builds the Python interface on it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <csignal>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "cli/plot.hpp"
#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"  // ConfigError
#include "io/failure.hpp"
#include "io/h5md.hpp"
#include "io/hdf5.hpp"
#include "io/state_io.hpp"
#include "run/output_path.hpp"
#include "run/run_request.hpp"
#include "source_hash.hpp"
#include "version.hpp"
#include "module.hpp"

namespace py = pybind11;

namespace ct_python {

// The module's exceptions, made in PYBIND11_MODULE (subclasses of Python's own, cyclic_triax/__init__.py documents them).
PyObject* config_error = nullptr;
PyObject* output_path_error = nullptr;
PyObject* run_error = nullptr;

void raise(PyObject* type, const std::string& message) {
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

}  // namespace ct_python

namespace {

using ct_python::config_error;
using ct_python::output_path_error;
using ct_python::raise;
using ct_python::run_error;

// The status of a kept partial result, as `dem run` names it after a failure.
std::string partial_status(const std::string& partial) {
  try {
    dem::h5::Handle f = dem::h5::open_file_read(partial);
    if (dem::h5::has_attribute(f, "status")) return "'" + dem::h5::get_string_attribute(f, "status") + "'";
    return "missing";
  } catch (const std::exception&) {
    return "unreadable";
  }
}

py::dict progress_dict(const dem::RunProgress& p) {
  py::dict d;
  d["scene"] = p.scene, d["stage_name"] = p.stage_name, d["stage"] = p.stage, d["stages"] = p.stages;
  d["step"] = p.step, d["time"] = p.time_s, d["elapsed"] = p.elapsed_s, d["stage_fraction"] = p.stage_fraction;
  d["status"] = p.status;
  return d;
}

// Runs a scene as `dem run` does (run_request), with the GIL released while it steps. Every 256
// steps (the observer's progress report) it takes the GIL to let Python's signal handlers run:
// Ctrl-C's KeyboardInterrupt then stops the run between two steps exactly as SIGINT stops `dem
// run` (its .partial marked "failed: interrupted by SIGINT ..."), and is raised again here. An
// exception of the progress callback or the warning callback stops the run the same way, marked
// with that exception, and is raised again.
py::dict run(const std::string& scene_file, const std::string& scene_text,
             const std::vector<std::pair<std::string, std::string>>& overrides, const std::string& out, int threads,
             bool force, const std::string& resume, const std::string& input_hash, py::object progress, py::object warning,
             py::object note) {
  dem::RunRequest request;
  request.scene_file = scene_file, request.scene_text = scene_text, request.overrides = overrides;
  request.out = out, request.threads = threads, request.force = force, request.input_hash = input_hash;
  if (resume == "if_valid") request.resume = dem::Resume::IfValid;
  else if (resume == "always") request.resume = dem::Resume::Always;
  else if (resume == "never") request.resume = dem::Resume::Never;
  else raise(PyExc_ValueError, "resume must be 'if_valid', 'always' or 'never', got '" + resume + "'");
  if (threads < 1 || threads > 256) raise(config_error, "threads must be in [1, 256], got " + std::to_string(threads));

  volatile std::sig_atomic_t stop = 0;
  std::optional<py::error_already_set> pending;  // the Python exception that stopped the run
  bool keyboard_interrupt = false;
  // Called with the GIL held: a Python exception is kept and the run stopped.
  const auto stopping = [&](const char* where) {
    pending.emplace();  // fetches the current Python error
    if (pending->matches(PyExc_KeyboardInterrupt)) {
      keyboard_interrupt = true;
      stop = SIGINT;  // the run throws RunInterrupted before its next step, as `dem run` on SIGINT
      return;
    }
    throw std::runtime_error(std::string("stopped by ") + where + ": " + pending->what());
  };
  dem::RunObserver observer;
  observer.stop = &stop;
  observer.progress = [&](const dem::RunProgress& p) {
    if (stop) return;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) return stopping("a Python signal handler");
    if (progress.is_none()) return;
    try {
      progress(progress_dict(p));
    } catch (py::error_already_set& e) {
      e.restore();
      stopping("the progress callback");
    }
  };
  const auto message = [&](py::object& callback, const char* what) {
    return [&callback, &stopping, what](const std::string& text) {
      py::gil_scoped_acquire gil;
      if (callback.is_none()) return;
      try {
        callback(text);
      } catch (py::error_already_set& e) {
        e.restore();
        stopping(what);
      }
    };
  };
  observer.warning = message(warning, "the warning callback");
  observer.note = message(note, "the note callback");

  const std::string partial = out + ".partial";
  dem::RunSummary s;
  try {
    py::gil_scoped_release release;
    s = dem::run_request(request, observer);
  } catch (const dem::OutputPathError& e) {
    raise(output_path_error, std::string(e.what()) + "; nothing was run");
  } catch (const dem::ConfigError& e) {
    raise(config_error, e.what());
  } catch (const std::exception& e) {
    const bool kept = std::filesystem::exists(partial);
    const std::string where = kept ? " (partial result kept in " + partial + ", status " + partial_status(partial) + ")" : "";
    if (keyboard_interrupt) raise(PyExc_KeyboardInterrupt, dem::describe_failure(e) + where);
    if (pending) {  // the callback's own exception, with the run's end in a note
      pending->restore();
      throw py::error_already_set();
    }
    raise(run_error, scene_file + ": " + dem::describe_failure(e) + where);
  }
  py::dict d;
  d["scene"] = s.scene, d["steps"] = s.steps, d["wall_time"] = s.wall_time_s, d["threads"] = s.threads;
  d["steps_on_one_thread"] = s.steps_on_one_thread, d["thread_trials"] = s.thread_trials;
  d["thread_switches"] = s.thread_switches;
  return d;
}

py::list columns(bool legs) {
  py::list l;
  for (const auto& c : legs ? dem::leg_columns() : dem::series_columns()) l.append(py::make_tuple(c.name, c.units, c.doc));
  return l;
}

// What a result file says of itself: status, scene, warnings, versions (what exists in it).
py::dict result_info(const std::string& file) {
  py::dict d;
  dem::h5::Handle f = dem::h5::naming_file(file, [&] { return dem::h5::open_file_read(file); });
  for (const char* name : {"status", "software_version", "scene_file", "input_hash", "damping_form"})
    if (dem::h5::has_attribute(f, name)) d[name] = dem::h5::get_string_attribute(f, name);
  if (dem::h5::has_attribute(f, "schema_version")) d["schema_version"] = dem::h5::get_int_attribute(f, "schema_version");
  if (dem::h5::has_attribute(f, "wall_time_s")) d["wall_time"] = dem::h5::get_double_attribute(f, "wall_time_s");
  if (dem::h5::has_text(f, "scene_yaml")) d["scene_yaml"] = dem::h5::read_text(f, "scene_yaml");
  d["warnings"] = dem::h5::has_text(f, "warnings") ? dem::h5::read_texts(f, "warnings") : std::vector<std::string>{};
  py::list groups;
  for (const char* g : {"timeseries", "legs", "state", "particles"})
    if (dem::h5::exists(f, g)) groups.append(g);
  d["groups"] = groups;
  return d;
}

// Columns of /timeseries or /legs, each a NumPy array of the doubles in the file; names missing
// from the file raise KeyError naming the file and what it has.
py::dict read_columns(const std::string& file, const std::string& group, const std::vector<std::string>& names) {
  py::dict d;
  dem::h5::Handle f = dem::h5::naming_file(file, [&] { return dem::h5::open_file_read(file); });
  if (!dem::h5::exists(f, group)) raise(PyExc_KeyError, file + " has no /" + group);
  dem::h5::Handle g = dem::h5::open_group(f, group);
  for (const std::string& n : names) {
    if (!dem::h5::exists(g, n)) raise(PyExc_KeyError, file + ": /" + group + " has no column '" + n + "'");
    std::size_t cols = 0;
    std::vector<double> v = dem::h5::naming_file(file, [&] { return dem::h5::read<double>(g, n, cols); });
    py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    d[py::str(n)] = a;
  }
  return d;
}

py::array_t<double> vec3_array(const std::vector<dem::Vec3>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int k = 0; k < 3; ++k) m(static_cast<py::ssize_t>(i), k) = v[i][k];
  return a;
}

// The final particles of a complete result (io/state_io.hpp read_state): real positions [m],
// velocities [m/s], angular velocities [rad/s], radii [m], masses [kg], the cell's lengths [m].
py::dict read_final_state(const std::string& file) {
  const dem::SavedState st = dem::read_state(file);
  std::vector<dem::Vec3> x(st.particles.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = st.cell.to_real(st.particles.s[i]);
  py::dict d;
  d["position"] = vec3_array(x), d["velocity"] = vec3_array(st.particles.v), d["angular_velocity"] = vec3_array(st.particles.omega);
  d["radius"] = py::array_t<double>(static_cast<py::ssize_t>(st.particles.radius.size()), st.particles.radius.data());
  d["mass"] = py::array_t<double>(static_cast<py::ssize_t>(st.particles.mass.size()), st.particles.mass.data());
  d["cell"] = py::make_tuple(st.cell.lengths()[0], st.cell.lengths()[1], st.cell.lengths()[2]);
  d["step"] = st.step;
  return d;
}

template <class T>
py::array_t<T> rows_array(const std::vector<T>& v, py::ssize_t cols) {
  py::array_t<T> a({static_cast<py::ssize_t>(v.size()) / cols, cols});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// Frame `index` of a result's particle frames (io/h5md.hpp read_frame): positions [m],
// velocities (the fluctuating part) [m/s], angular velocities [rad/s], radii [m], masses [kg],
// the cell's edges [m], and the contacts if the run wrote them (output.frames.contacts).
py::dict read_frame(const std::string& file, std::size_t index) {
  const dem::Frame f = dem::read_frame(file, index);
  py::dict d;
  d["step"] = f.step, d["time"] = f.time_s;
  d["position"] = rows_array(f.position, 3), d["velocity"] = rows_array(f.velocity, 3);
  d["angular_velocity"] = rows_array(f.angular_velocity, 3);
  d["radius"] = rows_array(f.radius, 1).attr("ravel")(), d["mass"] = rows_array(f.mass, 1).attr("ravel")();
  d["cell"] = py::make_tuple(f.edges[0], f.edges[1], f.edges[2]);
  if (f.has_contacts) {
    d["pairs"] = rows_array(f.pairs, 2);
    d["normal_force"] = rows_array(f.normal_force, 1).attr("ravel")();
    d["tangential_force"] = rows_array(f.tangential_force, 1).attr("ravel")();
    d["branch"] = rows_array(f.branch, 3);
  }
  return d;
}

// `dem plot`'s drawing (cli/plot.cpp) of given series: (key, x, y) each.
void draw_plot(const std::vector<std::tuple<std::string, std::vector<double>, std::vector<double>>>& series,
               const std::string& xlabel, const std::string& ylabel, const std::string& title, const std::string& out,
               const std::string& term) {
  std::vector<dem::PlotSeries> s;
  for (const auto& [key, x, y] : series) s.push_back({key, x, y});
  py::gil_scoped_release release;
  dem::draw_plot(s, {xlabel, ylabel, title, out, term});
}

}  // namespace

PYBIND11_MODULE(_engine, m) {
  m.doc() = "The cyclic-triax engine's library (runs and result files); use the cyclic_triax package.";
  config_error = PyErr_NewException("cyclic_triax.ConfigError", PyExc_ValueError, nullptr);
  output_path_error = PyErr_NewException("cyclic_triax.OutputPathError", PyExc_ValueError, nullptr);
  run_error = PyErr_NewException("cyclic_triax.RunError", PyExc_RuntimeError, nullptr);
  m.attr("ConfigError") = py::handle(config_error);
  m.attr("OutputPathError") = py::handle(output_path_error);
  m.attr("RunError") = py::handle(run_error);
  m.attr("software_version") = dem::software_version;
  m.attr("schema_version") = dem::schema_version;
  m.attr("engine_source_hash") = dem::engine_source_hash;
  m.def("run", &run, py::arg("scene_file"), py::arg("scene_text"), py::arg("overrides"), py::arg("out"), py::arg("threads"),
        py::arg("force"), py::arg("resume"), py::arg("input_hash"), py::arg("progress"), py::arg("warning"), py::arg("note"));
  m.def("columns", &columns, py::arg("legs") = false, "(name, unit, meaning) of every column of /timeseries (or /legs)");
  m.def("columns_markdown", [](bool legs) { return dem::columns_markdown(legs ? dem::leg_columns() : dem::series_columns()); },
        py::arg("legs") = false, "the column table as `dem columns` prints it");
  m.def("scene_key_reference", &dem::scene_key_reference, "every scene key, as `dem keys` prints it");
  m.def("result_info", &result_info, py::arg("file"));
  m.def("read_columns", &read_columns, py::arg("file"), py::arg("group"), py::arg("names"));
  m.def("draw_plot", &draw_plot, py::arg("series"), py::arg("xlabel"), py::arg("ylabel"), py::arg("title"), py::arg("out"),
        py::arg("term"));
  m.def("axis_label", &dem::axis_label, py::arg("column"), py::arg("legs") = false);
  m.def("read_final_state", &read_final_state, py::arg("file"));
  m.def("frame_count", &dem::frame_count, py::arg("file"));
  m.def("read_frame", &read_frame, py::arg("file"), py::arg("index"));
  m.attr("build_dem") = DEM_BUILD_BINARY;
  // Bad input met by the tools' libraries (a study, a reference file, a calibration): ConfigError.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const dem::ConfigError& e) {
      PyErr_SetString(config_error, e.what());
    }
  });
  ct_python::bind_study(m);
  ct_python::bind_calibration(m);
}
