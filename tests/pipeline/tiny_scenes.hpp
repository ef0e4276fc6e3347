#pragma once
// The two scene files of the pipeline tests' tiny studies (not a test file itself): prep.yaml, a
// 3x3x3 lattice (the study's profile may set another size) squeezed at 1/s for `prep_duration`
// seconds, and test.yaml, a shear at [1, 0, -1]/s for `test_duration` seconds, both at dt = 1 us.
#include <filesystem>
#include <fstream>
#include <string>

namespace pipeline::test {

inline void write_tiny_scenes(const std::filesystem::path& dir, const std::string& prep_duration,
                              const std::string& test_duration) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "prep.yaml") << "name: prep\n"
                                      "particles:\n"
                                      "  lattice: {n: [3, 3, 3], spacing: 5.0e-3, seed: 1}\n"
                                      "  grading: {diameters: [3.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                                      "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                      "numerics: {time_step: 1.0e-6}\n"
                                      "stages: [{name: squeeze, type: strain_rate, strain_rate: [1, 1, 1], duration: " +
                                          prep_duration + "}]\n";
  std::ofstream(dir / "test.yaml") << "name: t\nparticles: {state: nowhere.h5}\n"
                                      "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                                      "numerics: {time_step: 1.0e-6}\n"
                                      "stages: [{name: shear, type: strain_rate, strain_rate: [1, 0, -1], duration: " +
                                          test_duration + "}]\n";
}

}  // namespace pipeline::test
