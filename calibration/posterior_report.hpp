#pragma once
// What a calibration writes to its report folder: posterior.json (for machines), section.md (the
// tables), and the data of its figures (sets.dat, marginal_<j>.dat, curve_<k>.dat), which
// calibration.gp draws.
#include <map>
#include <string>

#include "calibrate.hpp"

namespace calibration {

// `truth`: the parameters' true values when the references were made by the engine (a
// demonstration), by parameter name; empty otherwise. It is read only here, after the posterior.
void write_report(const Outcome& o, const std::map<std::string, double>& truth);

// The values of the calibration's parameters in a result's resolved scene (/scene_yaml): what a
// synthetic reference was made with. Throws if a key is missing or the keys of a parameter disagree.
std::map<std::string, double> parameters_of_result(const Calibration& c, const std::string& result);

}  // namespace calibration
