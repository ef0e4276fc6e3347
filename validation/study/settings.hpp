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

// key -> value from the resolved scenes of the first sample's P<density>_prepare.h5 and
// P<density>_test<N>.h5 (P = prefix), or of NAME.h5 alone (run); empty if no result has a scene.
// Keys: grading_basis, damping_form, damping_translational, friction_prepare ("a / b / c"),
// friction_shear_<density>, friction_shear, lattice, particles, target_pressure_kPa,
// time_step_prepare_s, time_step_test_s, mean_stress_Pa, stress_ratio, stress_rate_Pa_per_s,
// test<N>_path, test<N>_cycles (the cycles its path makes), hold_*, max_strain_rate_per_s, max_energy_error, max_time_step_fraction, ...
std::map<std::string, std::string> run_settings(const std::string& results, const std::string& prefix = "",
                                                const std::string& run = "");

}  // namespace validation
