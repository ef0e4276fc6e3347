#pragma once
// A study's baseline: a short hash of the preparation settings every study shares with the paper
// study, so that a report can tell a section made on the paper study's baseline from one that was
// not (an older time step, another damping, ...). Read from a result's resolved scene.
#include <string>

namespace validation {

// 16 hex digits: FNV-1a 64 of the resolved scene (YAML text) without what every study varies or
// what names a place rather than a setting: `name`, `output`, `particles.lattice.n`,
// `particles.lattice.seed`, the particle files (`particles.state`, `particles.csv`),
// `material.friction` (the preparation friction sets the density) and `material.ks` (the
// friction's stiffness, which a resolved scene holds only with friction > 0). What is left is written
// canonically first: map keys sorted, a scalar that reads as a number as that double (%.17g), so
// key order and `1e-6` against `1.0e-6` do not change it. Throws std::runtime_error for text that
// is not YAML (`where` names it).
std::string baseline_of(const std::string& scene_yaml, const std::string& where = "scene");

// The baseline of a result's resolved scene (`scene_yaml`); "" if the file is not there or has no
// scene; throws, naming the file, if it is there but cannot be read. A pipeline's copy of a run
// (`copied_from`) has the baseline of the run it copies while that file is here (a copy made before
// copies recorded the resolved scene holds the study's text of it).
std::string baseline_of_result(const std::string& result);

}  // namespace validation
