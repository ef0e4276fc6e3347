#pragma once
// The settings a study's runs used, read from the resolved scenes inside its results (attribute
// `scene_yaml`): what the report's text quotes (time step, frictions, lattice, stress path, ...).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "config/scene_config.hpp"

namespace validation {

// The resolved scene a result ran (its `scene_yaml` attribute); nothing if the file is not there,
// has no scene, or its scene is one this engine no longer reads; throws, naming the file, if the
// file is there but cannot be read (truncated, not HDF5).
std::optional<dem::SceneConfig> scene_of(const std::string& result);
// The first stage of that type, or null.
const dem::StageConfig* stage_of_type(const dem::SceneConfig& s, dem::StageConfig::Type type);
std::string joined(const std::vector<std::string>& v, const std::string& sep);
// A path as written in a scene on one line: "[TC1, {repeat: 5, ...}]".
std::string one_line(const std::string& yaml);

// The settings a study's runs used, from the resolved scenes of the first sample's
// P<density>_prepare.h5 and P<density>_test<N>.h5 (P = prefix), or of NAME.h5 alone (run); a
// setting no scene gives is absent. SI but where the name says otherwise.
struct RunSettings {
  // The preparation (the last density's that has one; the densities' frictions each).
  std::optional<std::string> grading_basis;  // "count" or "mass"
  std::optional<std::string> damping_form;   // "viscous" or "local"
  std::optional<double> damping_translational, damping_rotational;  // [-]
  std::optional<double> kn_N_per_m, ks_N_per_m;                     // the linear law's stiffnesses
  std::optional<std::string> lattice;                               // "20×20×20"
  std::optional<long> particles;                                    // of the lattice
  std::optional<double> lattice_spacing_mm;
  std::optional<double> target_pressure_kPa, compression_rate_Pa_per_s, max_strain_rate_per_s;  // its stress stage
  std::optional<double> hold_stress_tolerance, hold_unbalanced_force_ratio;
  std::optional<double> max_energy_error, max_time_step_fraction, time_step_prepare_s;
  std::vector<std::pair<std::string, double>> friction_prepare;  // density -> μ, in the paper's order
  // The tests.
  std::vector<std::pair<std::string, double>> friction_shear;    // density -> μ of its first test
  std::optional<double> time_step_test_s, mean_stress_Pa, stress_ratio, stress_rate_Pa_per_s;
  struct TestPath {
    std::string path;  // as the scene writes it, on one line
    int cycles = 0;    // the cycles it makes
    std::vector<std::string> visits;  // the states its legs go to, in order (the path expanded: "TC1", "A", "TE1", ...)
  };
  std::map<int, TestPath> tests;  // test number -> its path
  bool empty() const { return !grading_basis && friction_shear.empty(); }  // no result had a scene
};

RunSettings run_settings(const std::string& results, const std::string& prefix = "", const std::string& run = "");

// Every setting that is there as text, key -> value (what `figure-data settings` prints and the
// report's setting.* keys hold): grading_basis, damping_form, damping_translational, friction_prepare
// ("a / b / c"), friction_shear_<density>, friction_shear, lattice, particles, target_pressure_kPa,
// time_step_prepare_s, time_step_test_s, mean_stress_Pa, stress_ratio, stress_rate_Pa_per_s,
// test<N>_path, test<N>_cycles, hold_*, max_strain_rate_per_s, max_energy_error, max_time_step_fraction, ...
std::map<std::string, std::string> setting_texts(const RunSettings& s);

}  // namespace validation
