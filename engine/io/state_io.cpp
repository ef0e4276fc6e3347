#include "io/state_io.hpp"

#include "io/result_file.hpp"

#include <cmath>
#include <utility>

namespace dem {

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x[0], x[1], x[2]});
  return out;
}

namespace {

std::string path_of(hid_t group) {
  char path[256] = "";
  H5Iget_name(group, path, sizeof path);
  return path;
}

}  // namespace

std::vector<Vec3> read_vec3(hid_t group, const std::string& file, const std::string& name) {
  std::size_t cols = 0;
  const std::vector<double> d = h5::read<double>(group, name, cols);
  if (cols != 3) throw h5::Error(file + ": " + path_of(group) + "/" + name + " must have 3 columns, has " + std::to_string(cols));
  std::vector<Vec3> out(d.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
  return out;
}

namespace {
// The tangential histories a file can hold, with their units.
constexpr std::pair<const char*, const char*> tangential_histories[] = {{"tangential_spring", "m"}, {"tangential_force", "N"}};
}  // namespace

void write_pairs(hid_t group, const std::string& prefix, const PairList& pairs, const ContactHistory& history) {
  h5::write(group, prefix + "_first", pairs.first, 1, "1");
  h5::write(group, prefix + "_second", pairs.second, 1, "1");
  for (const auto& [name, unit] : tangential_histories)
    if (history.tangential_name == name) {
      h5::write(group, prefix + "_" + name, flatten(history.tangential), 3, unit);
      h5::write(group, prefix + "_sliding", history.sliding, 1, "1");
    }
  if (history.rolling_on) h5::write(group, prefix + "_rolling_spring", flatten(history.rolling), 3, "m");
}

SavedPairs read_pairs(hid_t group, const std::string& file, const std::string& prefix, std::size_t particles) {
  SavedPairs saved;
  PairList& pairs = saved.pairs;
  ContactHistory& history = saved.history;
  std::size_t cols = 0;
  pairs.first = h5::read<std::uint32_t>(group, prefix + "_first", cols);
  pairs.second = h5::read<std::uint32_t>(group, prefix + "_second", cols);
  for (const auto& [name, unit] : tangential_histories)
    if (h5::exists(group, prefix + "_" + name)) {
      history.tangential_name = name;
      history.tangential = read_vec3(group, file, prefix + "_" + name);
      history.sliding = h5::read<std::uint8_t>(group, prefix + "_sliding", cols);
    }
  history.rolling_on = h5::exists(group, prefix + "_rolling_spring");
  if (history.rolling_on) history.rolling = read_vec3(group, file, prefix + "_rolling_spring");
  const std::size_t n = pairs.first.size();
  const bool tangential = history.has_tangential();
  if (pairs.second.size() != n || (tangential && (history.tangential.size() != n || history.sliding.size() != n)) ||
      (history.rolling_on && history.rolling.size() != n))
    throw h5::Error(file + ": " + path_of(group) + " " + prefix + " datasets have different lengths");
  for (std::size_t k = 0; k < n; ++k)
    if (pairs.first[k] >= pairs.second[k] || pairs.second[k] >= particles ||
        (k > 0 && std::make_pair(pairs.first[k - 1], pairs.second[k - 1]) >= std::make_pair(pairs.first[k], pairs.second[k])))
      throw h5::Error(file + ": " + path_of(group) + " " + prefix + " " + std::to_string(k) + " names invalid particles");
    else if ((tangential && (!history.tangential[k].allFinite() || history.sliding[k] > 1)) ||
             (history.rolling_on && !history.rolling[k].allFinite()))
      throw h5::Error(file + ": " + path_of(group) + " " + prefix + " " + std::to_string(k) +
                      " has a non-finite history or a sliding flag other than 0 or 1");
  return saved;
}

void write_state(hid_t group, const Simulation& sim) {
  const Particles& p = sim.particles();
  const PeriodicCell& cell = sim.cell();
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = cell.to_real(p.s[i]);
  h5::write(group, "position", flatten(x), 3, "m");
  h5::write(group, "position_fractional", flatten(p.s), 3, "1");
  h5::write(group, "velocity", flatten(p.v), 3, "m/s");
  h5::write(group, "angular_velocity", flatten(p.omega), 3, "rad/s");
  h5::write(group, "radius", p.radius, 1, "m");
  h5::write(group, "mass", p.mass, 1, "kg");
  h5::write(group, "moment_of_inertia", p.inertia, 1, "kg m^2");
  const Vec3& L = cell.lengths();
  const Vec3& L0 = cell.reference_lengths();
  const Vec3& r = sim.strain_rate();
  h5::write(group, "cell_lengths", std::vector<double>{L[0], L[1], L[2]}, 1, "m");
  h5::write(group, "cell_reference_lengths", std::vector<double>{L0[0], L0[1], L0[2]}, 1, "m");
  h5::write(group, "cell_strain_rate", std::vector<double>{r[0], r[1], r[2]}, 1, "1/s");
  if (cell.sheared() || sim.rates().shears() || cell.shear_strain() != Vec3::Zero()) {
    const Vec3 &t = cell.tilts(), &g = sim.rates().shear, &gamma = cell.shear_strain();
    h5::write(group, "cell_tilts", std::vector<double>{t[0], t[1], t[2]}, 1, "m");
    h5::write(group, "cell_shear_rate", std::vector<double>{g[0], g[1], g[2]}, 1, "1/s");
    h5::write(group, "cell_shear_strain", std::vector<double>{gamma[0], gamma[1], gamma[2]}, 1, "1");
  }

  // Contacts: the pairs whose spheres overlap, with their history.
  const PairList& pairs = sim.pairs();
  PairList contacts;
  std::vector<std::size_t> in_contact;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = pairs.first[k], j = pairs.second[k];
    const double rsum = p.radius[i] + p.radius[j];
    if (cell.branch(p.s[i], p.s[j]).squaredNorm() >= rsum * rsum) continue;
    contacts.first.push_back(i);
    contacts.second.push_back(j);
    in_contact.push_back(k);
  }
  write_pairs(group, "contact", contacts, sim.history().subset(in_contact));
  h5::set_attribute(group, "step", static_cast<std::int64_t>(sim.step_count()));
  h5::set_attribute(group, "time", sim.time());
  h5::set_attribute(group, "time_step", sim.time_step());
}

namespace {

SavedState read_state_unchecked(hid_t g, const std::string& file);

}  // namespace

SavedState read_state(const std::string& file) {
  return h5::naming_file(file, [&] {
    h5::Handle f = h5::open_file_read(file);
    if (const std::string why = result_problem(f); !why.empty())
      throw h5::Error(file + ": not a complete result (" + why + "); only a finished run's state can be loaded");
    return read_state_unchecked(h5::open_group(f, "state"), file);
  });
}

SavedState read_state(hid_t group, const std::string& file) {
  return h5::naming_file(file, [&] { return read_state_unchecked(group, file); });
}

namespace {

SavedState read_state_unchecked(hid_t g, const std::string& file) {
  SavedState st;
  std::size_t cols = 0;
  Particles& p = st.particles;
  p.s = read_vec3(g, file, "position_fractional");
  p.v = read_vec3(g, file, "velocity");
  p.omega = read_vec3(g, file, "angular_velocity");
  p.radius = h5::read<double>(g, "radius", cols);
  p.mass = h5::read<double>(g, "mass", cols);
  p.inertia = h5::read<double>(g, "moment_of_inertia", cols);
  const std::size_t n = p.s.size();
  if (p.v.size() != n || p.omega.size() != n || p.radius.size() != n || p.mass.size() != n || p.inertia.size() != n)
    throw h5::Error(file + ": /state particle datasets have different lengths");
  for (std::size_t i = 0; i < n; ++i)
    if (!(p.radius[i] > 0) || !(p.mass[i] > 0) || !(p.inertia[i] > 0) || !std::isfinite(p.radius[i]) ||
        !std::isfinite(p.mass[i]) || !std::isfinite(p.inertia[i]) || !p.v[i].allFinite() || !p.omega[i].allFinite())
      throw h5::Error(file + ": /state particle " + std::to_string(i) + " has a non-finite or non-positive value");
    else if (!(p.s[i].minCoeff() >= 0.0 && p.s[i].maxCoeff() < 1.0))
      throw h5::Error(file + ": /state/position_fractional of particle " + std::to_string(i) + " is outside [0, 1)");
  const auto L = h5::read<double>(g, "cell_lengths", cols);
  const auto L0 = h5::read<double>(g, "cell_reference_lengths", cols);
  const auto r = h5::read<double>(g, "cell_strain_rate", cols);
  if (L.size() != 3 || L0.size() != 3 || r.size() != 3) throw h5::Error(file + ": /state cell datasets must have 3 values");
  for (int k = 0; k < 3; ++k)
    if (!(L[k] > 0) || !(L0[k] > 0) || !std::isfinite(L[k]) || !std::isfinite(L0[k]) || !std::isfinite(r[k]))
      throw h5::Error(file + ": /state cell lengths must be positive and finite, strain rates finite");
  st.cell = PeriodicCell(Vec3(L[0], L[1], L[2]));
  st.cell.set_reference_lengths(Vec3(L0[0], L0[1], L0[2]));
  st.rates.axial = Vec3(r[0], r[1], r[2]);
  if (h5::exists(g, "cell_tilts")) {  // a cell that has sheared
    Vec3 shear[3];
    const char* names[3] = {"cell_tilts", "cell_shear_rate", "cell_shear_strain"};
    for (int q = 0; q < 3; ++q) {
      const auto v = h5::read<double>(g, names[q], cols);
      if (v.size() != 3 || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        throw h5::Error(file + ": /state/" + names[q] + " must be 3 finite values");
      shear[q] = Vec3(v[0], v[1], v[2]);
    }
    st.cell.set_tilts(shear[0]);
    st.rates.shear = shear[1];
    st.cell.set_shear_strain(shear[2]);
    if (std::abs(shear[0][0]) > 0.5 * L[0] * (1 + 1e-12) || std::abs(shear[0][1]) > 0.5 * L[0] * (1 + 1e-12) ||
        std::abs(shear[0][2]) > 0.5 * L[1] * (1 + 1e-12))
      throw h5::Error(file + ": /state/cell_tilts: a tilt is more than half the length it tilts along");
  }
  SavedPairs contacts = read_pairs(g, file, "contact", n);
  st.contacts = std::move(contacts.pairs);
  st.history = std::move(contacts.history);
  st.step = h5::get_int_attribute(g, "step");
  st.time_step_s = h5::get_double_attribute(g, "time_step");
  return st;
}

}  // namespace

}  // namespace dem
