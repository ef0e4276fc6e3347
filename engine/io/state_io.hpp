#pragma once
// The saved state: everything needed to continue a run bit for bit (layout in engine/README.md).
// A cell that has sheared also has cell_tilts, cell_shear_rate and cell_shear_strain (absent: 0).
#include <cstdint>
#include <string>

#include "dynamics/simulation.hpp"
#include "io/hdf5.hpp"

namespace dem {

struct SavedState {
  Particles particles;
  PeriodicCell cell;
  PairList contacts;     // pairs in contact
  ContactHistory history;  // their history (what the law that wrote it keeps)
  CellRates rates;  // the velocity gradient applied in the last step
  std::int64_t step = 0;
  double time_step_s = 0;
};

// N x 3 datasets of vectors.
std::vector<double> flatten(const std::vector<Vec3>& v);
std::vector<Vec3> read_vec3(hid_t group, const std::string& file, const std::string& name);

// A pair list as <prefix>_first, <prefix>_second and its history: <prefix>_<tangential history name>
// (tangential_spring [m] or tangential_force [N]) and <prefix>_sliding with friction,
// <prefix>_rolling_spring [m] with rolling resistance; reading checks the lengths, the order
// (i < j, sorted) and the values.
void write_pairs(hid_t group, const std::string& prefix, const PairList& pairs, const ContactHistory& history);
struct SavedPairs {
  PairList pairs;
  ContactHistory history;
};
SavedPairs read_pairs(hid_t group, const std::string& file, const std::string& prefix, std::size_t particles);

void write_state(hid_t group, const Simulation& sim);
// Reads the /state group of a *complete* result file; throws naming the file otherwise.
SavedState read_state(const std::string& file);
// Reads a group written by write_state (`file` only names it in messages); checks every value.
SavedState read_state(hid_t group, const std::string& file);

}  // namespace dem
