#pragma once
// The calibration CLI tests' fixture: a tiny study (64 spheres at profile small, 125 at large, one
// sample each; drained triaxial compression to 1 % strain), a typed q/p curve per density (named
// "qp" with one density, "<density> qp" with more), and a calibration of the friction over
// [0.1, 0.9], written into a folder.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace dem::test {

struct TinyCalibration {
  std::vector<std::pair<std::string, double>> densities = {{"dense", 0.0}};  // name, preparation friction
  std::string applies_to;  // the parameter's applies_to ("": the default, both)
  int batch = 8;
  std::string sizes;  // a sizes: block, or ""
  std::string rows;   // a reference file's rows: list (YAML), or ""
  int iterations = 2; // min_iterations and max_iterations
  int large_seeds = 1;  // samples a set at profile large (validate judges a row on 2 or more)

  void write(const std::filesystem::path& dir) const {
    const std::string src = DEM_SOURCE_DIR;
    std::string study_densities, curves;
    for (const auto& [name, friction] : densities) {
      study_densities += (study_densities.empty() ? "" : ", ") + std::string("{name: ") + name + ", friction: " + std::to_string(friction) + "}";
      curves += (curves.empty() ? "" : ", ") + std::string("{name: ") + (densities.size() == 1 ? "qp" : "'" + name + " qp'") +
                ", file: curve.csv, x: strain_3, y: q_over_p, density: " + name + ", test: triaxial}";
    }
    std::ofstream(dir / "study.yaml") << "name: tiny\noutput: results\npreparation: " << src << "/scenes/prepare_dense.yaml\n"
                                      << "densities: [" << study_densities << "]\n"
                                      << "tests: [{name: triaxial, scene: " << src << "/scenes/tests/triaxial_drained.yaml, "
                                      << "set: {\"stages[1].until.strain\": 0.01}}]\n"
                                      << "profiles: {small: {lattice: 4, seeds: 1}, large: {lattice: 5, seeds: " << large_seeds << "}}\n";
    std::ofstream(dir / "curve.csv") << "strain_3,q_over_p,sd\n0.002,0.8,0.1\n0.008,0.9,0.1\n";
    std::ofstream(dir / "refs.yaml") << "source: typed\ncurves: [" << curves << "]\n" << (rows.empty() ? "" : "rows: rows.yaml\n");
    if (!rows.empty()) std::ofstream(dir / "rows.yaml") << "source: typed\nrows: " << rows << "\n";
    std::ofstream(dir / "cal.yaml") << "name: tiny\nstudy: study.yaml\nreferences: refs.yaml\nreport: report\n"
                                    << "parameters: [{name: friction, keys: material.friction, "
                                    << (applies_to.empty() ? "" : "applies_to: " + applies_to + ", ") << "uniform: [0.1, 0.9]}]\n"
                                    << "batch: " << batch << "\nmin_iterations: " << iterations << "\nmax_iterations: " << iterations << "\n" << sizes;
  }
};

}  // namespace dem::test
