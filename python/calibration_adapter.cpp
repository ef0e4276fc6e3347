// calibrate in cyclic_triax._engine: the one file that calls the calibration library
// (calibration/calibrate.hpp), as `calibrate CALIBRATION.yaml [--plan]` does: read the file, hold
// its report folder's lock, run_calibration, write the report after every iteration and at the
// end; returned: the outcome's stop and the posterior's marginals. A change of the calibration's
// entry points changes this file only.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "calibrate.hpp"
#include "calibration_file.hpp"
#include "exec/scheduler.hpp"  // lock_folder
#include "module.hpp"
#include "posterior.hpp"
#include "posterior_report.hpp"

namespace py = pybind11;

namespace {

py::object calibrate(const std::string& file, const std::string& profile, int jobs, int threads, bool plan_only,
                     const std::string& dem) {
  if (jobs < 1 || jobs > 256) ct_python::raise(ct_python::config_error, "jobs must be in [1, 256], got " + std::to_string(jobs));
  if (threads < 1 || threads > 256) ct_python::raise(ct_python::config_error, "threads must be in [1, 256], got " + std::to_string(threads));
  const calibration::Calibration c = calibration::read_calibration(file);
  calibration::RunOptions o;
  o.dem = dem, o.profile = profile, o.jobs = jobs, o.threads = threads, o.plan_only = plan_only;
  std::optional<calibration::Outcome> outcome;
  {
    py::gil_scoped_release release;
    std::unique_ptr<dem::FileLock> lock;  // as calibrate holds it: one calibration at a time in a report folder
    if (!plan_only)
      lock = pipeline::lock_folder(c.report, ".calibrate.lock", "calibrate",
                                   "two would each write its ledger of scored sets and its posterior, and one would be lost");
    o.after_iteration = [](const calibration::Outcome& so_far) { calibration::write_report(so_far, {}); };
    outcome = calibration::run_calibration(c, o);
    if (outcome) calibration::write_report(*outcome, {});
  }
  if (!outcome) return py::none();
  py::list posterior;  // the last iteration's marginals: those posterior.json lists
  for (std::size_t j = 0; j < c.parameters.size(); ++j) {
    const calibration::Marginal mg = outcome->iterations.empty()
                                         ? calibration::marginal(c.parameters[j], j, outcome->posterior_u, outcome->posterior_w)
                                         : outcome->iterations.back().marginals.at(j);
    py::dict d;
    d["parameter"] = c.parameters[j].name, d["mean"] = mg.mean, d["sd"] = mg.sd, d["median"] = mg.median;
    d["lower_95"] = mg.lower_95, d["upper_95"] = mg.upper_95, d["identified"] = mg.identified;
    posterior.append(d);
  }
  py::dict d;
  // The first size's (every set's) folder, profile and sets; the runs of every size.
  int runs = 0;
  for (const calibration::SizeOutcome& s : outcome->sizes) runs += s.runs;
  d["name"] = c.name, d["report"] = c.report, d["results"] = outcome->first().results, d["profile"] = outcome->first().profile;
  d["converged"] = outcome->converged, d["stop_reason"] = outcome->stop_reason;
  d["iterations"] = outcome->iterations.size(), d["sets"] = outcome->first().sets.size(), d["runs"] = runs;
  d["unscored"] = outcome->unscored, d["posterior"] = posterior;
  return d;
}

}  // namespace

namespace ct_python {

void bind_calibration(py::module_& m) {
  m.def("calibrate", &calibrate, py::arg("file"), py::arg("profile"), py::arg("jobs"), py::arg("threads"), py::arg("plan_only"),
        py::arg("dem"));
}

}  // namespace ct_python
