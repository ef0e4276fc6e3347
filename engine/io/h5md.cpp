#include "io/h5md.hpp"

#include "analysis/measurements.hpp"
#include "io/state_io.hpp"  // flatten
#include "version.hpp"

namespace dem {

namespace {

void link(hid_t from_group, const std::string& target, hid_t to_group, const std::string& name) {
  if (H5Lcreate_hard(from_group, target.c_str(), to_group, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    throw h5::Error("HDF5: linking " + name + " to " + target + " failed");
}

}  // namespace

H5mdWriter::H5mdWriter(hid_t file, const Simulation& sim) : file_(file) {
  {
    h5::Handle h5md = h5::create_group(file, "h5md");
    h5::set_attribute(h5md, "version", std::vector<std::int64_t>{1, 1});
    h5::set_attribute(h5::create_group(h5md, "author"), "name", std::string("cyclic-triax"));
    h5::Handle creator = h5::create_group(h5md, "creator");
    h5::set_attribute(creator, "name", std::string("dem"));
    h5::set_attribute(creator, "version", std::string(software_version));
    // H5MD's units module: the `unit` attributes below are SI.
    h5::Handle modules = h5::create_group(h5md, "modules");
    h5::Handle units = h5::create_group(modules, "units");
    h5::set_attribute(units, "version", std::vector<std::int64_t>{1, 0});
    h5::set_attribute(units, "system", std::string("SI"));
  }
  const Particles& p = sim.particles();
  const hsize_t n = p.size();
  h5::Handle particles = h5::create_group(file, "particles");
  h5::Handle all = h5::create_group(particles, "all");

  h5::Handle position = h5::create_group(all, "position");
  step_ = h5::FrameSeries<std::int64_t>(position, "step", {});
  time_ = h5::FrameSeries<double>(position, "time", {});
  h5::set_attribute(time_.id(), h5::unit_attribute, std::string("s"));
  position_ = h5::FrameSeries<double>(position, "value", {n, 3});
  h5::set_attribute(position_.id(), h5::unit_attribute, std::string("m"));

  // Every other time-dependent element shares position's step and time (hard links).
  auto element = [&](hid_t parent, const std::string& name) {
    h5::Handle g = h5::create_group(parent, name);
    link(position, "step", g, "step");
    link(position, "time", g, "time");
    return g;
  };
  h5::Handle velocity = element(all, "velocity");
  velocity_ = h5::FrameSeries<double>(velocity, "value", {n, 3});
  h5::set_attribute(velocity_.id(), h5::unit_attribute, std::string("m s-1"));
  // The engine integrates v relative to the cell's affine deformation (engine/README.md, Model);
  // the total velocity, v - strain_rate o x, depends on where the origin sits, so v is stored.
  h5::set_attribute(velocity_.id(), "doc", std::string("fluctuating velocity: total velocity minus the affine "
                                                       "velocity of the deforming cell"));
  h5::Handle angular_velocity = element(all, "angular_velocity");
  angular_velocity_ = h5::FrameSeries<double>(angular_velocity, "value", {n, 3});
  h5::set_attribute(angular_velocity_.id(), h5::unit_attribute, std::string("rad s-1"));

  h5::Handle box = h5::create_group(all, "box");
  h5::set_attribute(box, "dimension", std::int64_t{3});
  h5::set_attribute(box, "boundary", std::vector<std::string>{"periodic", "periodic", "periodic"});
  h5::Handle edges = element(box, "edges");
  edges_ = h5::FrameSeries<double>(edges, "value", {3});
  h5::set_attribute(edges_.id(), h5::unit_attribute, std::string("m"));

  h5::write(all, "radius", p.radius, 1, "m");
  h5::write(all, "mass", p.mass, 1, "kg");
}

H5mdWriter::H5mdWriter(hid_t file) : file_(file) {
  if (h5::exists(file, "frames")) {
    views_ = true;
    h5::Handle frames = h5::open_group(file, "frames");
    corners_ = h5::FrameSeries<double>(frames, "cell_corners");
    if (h5::exists(frames, "contacts")) {
      contacts_ = true;
      h5::Handle c = h5::open_group(frames, "contacts");
      contact_count_ = h5::FrameSeries<std::int64_t>(c, "count");
      pairs_ = h5::FrameSeries<std::int64_t>(c, "pairs");
      normal_force_ = h5::FrameSeries<double>(c, "normal_force");
      tangential_force_ = h5::FrameSeries<double>(c, "tangential_force");
      branch_ = h5::FrameSeries<double>(c, "branch");
      ends_ = h5::FrameSeries<double>(c, "ends");
    }
  }
  h5::Handle all = h5::open_group(file, "particles/all");
  h5::Handle position = h5::open_group(all, "position");
  step_ = h5::FrameSeries<std::int64_t>(position, "step");
  std::size_t cols = 0;
  const std::vector<std::int64_t> steps = h5::read<std::int64_t>(position, "step", cols);
  if (!steps.empty()) last_step_ = steps.back();
  time_ = h5::FrameSeries<double>(position, "time");
  position_ = h5::FrameSeries<double>(position, "value");
  velocity_ = h5::FrameSeries<double>(all, "velocity/value");
  angular_velocity_ = h5::FrameSeries<double>(all, "angular_velocity/value");
  edges_ = h5::FrameSeries<double>(all, "box/edges/value");
}

void H5mdWriter::create_views(hid_t file, bool contacts) {
  h5::Handle frames = h5::create_group(file, "frames");
  corners_ = h5::FrameSeries<double>(frames, "cell_corners", {8, 3}, 64);
  h5::set_attribute(corners_.id(), h5::unit_attribute, std::string("m"));
  views_ = true;
  if (!contacts) return;
  contacts_ = true;
  h5::Handle c = h5::create_group(frames, "contacts");
  constexpr hsize_t rows = 4096;  // contacts per chunk
  contact_count_ = h5::FrameSeries<std::int64_t>(c, "count", {});
  pairs_ = h5::FrameSeries<std::int64_t>(c, "pairs", {2}, rows);
  normal_force_ = h5::FrameSeries<double>(c, "normal_force", {}, rows);
  h5::set_attribute(normal_force_.id(), h5::unit_attribute, std::string("N"));
  tangential_force_ = h5::FrameSeries<double>(c, "tangential_force", {}, rows);
  h5::set_attribute(tangential_force_.id(), h5::unit_attribute, std::string("N"));
  branch_ = h5::FrameSeries<double>(c, "branch", {3}, rows);
  h5::set_attribute(branch_.id(), h5::unit_attribute, std::string("m"));
  ends_ = h5::FrameSeries<double>(c, "ends", {2, 3}, rows);
  h5::set_attribute(ends_.id(), h5::unit_attribute, std::string("m"));
}

void H5mdWriter::append_contacts(const Simulation& sim) {
  const ContactCounts c = count_contacts(sim, false, true);
  std::vector<double> ends;
  ends.reserve(6 * c.contacts);
  for (std::size_t k = 0; k < c.contacts; ++k) {
    const Vec3 a = sim.cell().to_real(sim.particles().s[static_cast<std::size_t>(c.pairs[2 * k])]);
    const Vec3 b = a + c.branches[k];
    ends.insert(ends.end(), {a[0], a[1], a[2], b[0], b[1], b[2]});
  }
  pairs_.append_frames(c.pairs);
  normal_force_.append_frames(c.normal_forces_N);
  tangential_force_.append_frames(c.tangential_forces_N);
  branch_.append_frames(flatten(c.branches));
  ends_.append_frames(ends);
  contact_count_.append({static_cast<std::int64_t>(c.contacts)});
}

void H5mdWriter::append_frame(const Simulation& sim, bool contacts) {
  const Particles& p = sim.particles();
  const PeriodicCell& cell = sim.cell();
  if (!views_ && step_.frames() == 0) create_views(file_, contacts);
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = cell.to_real(p.s[i]);
  const Vec3& L = cell.lengths();
  std::vector<double> corners;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c = cell.to_real(Vec3(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    corners.insert(corners.end(), {c[0], c[1], c[2]});
  }
  // Step last: should a frame fail part-way, the length of `step` still counts whole frames only.
  position_.append(flatten(x));
  velocity_.append(flatten(p.v));
  angular_velocity_.append(flatten(p.omega));
  edges_.append({L[0], L[1], L[2]});
  if (views_) corners_.append(corners);
  if (contacts_) append_contacts(sim);
  time_.append({sim.time()});
  step_.append({sim.step_count()});
  last_step_ = sim.step_count();
}

std::size_t frame_count(const std::string& file) {
  return h5::naming_file(file, [&]() -> std::size_t {
    h5::Handle f = h5::open_file_read(file);
    if (!h5::exists(f, "particles/all/position/step")) return 0;
    return static_cast<std::size_t>(h5::shape(f, "particles/all/position/step").at(0));
  });
}

Frame read_frame(const std::string& file, std::size_t index) {
  return h5::naming_file(file, [&] {
    const std::size_t frames = frame_count(file);
    if (index >= frames)
      throw h5::Error(frames == 0 ? "no frames (a scene writes them with output.frames: {interval: STEPS})"
                                  : "frame " + std::to_string(index) + " asked for; it has frames 0 to " + std::to_string(frames - 1));
    h5::Handle f = h5::open_file_read(file);
    h5::Handle all = h5::open_group(f, "particles/all");
    Frame fr;
    fr.step = h5::read_rows<std::int64_t>(all, "position/step", index, 1).at(0);
    fr.time_s = h5::read_rows<double>(all, "position/time", index, 1).at(0);
    fr.position = h5::read_rows<double>(all, "position/value", index, 1);
    fr.velocity = h5::read_rows<double>(all, "velocity/value", index, 1);
    fr.angular_velocity = h5::read_rows<double>(all, "angular_velocity/value", index, 1);
    const std::vector<double> edges = h5::read_rows<double>(all, "box/edges/value", index, 1);
    for (int k = 0; k < 3; ++k) fr.edges[k] = edges.at(static_cast<std::size_t>(k));
    std::size_t cols = 0;
    fr.radius = h5::read<double>(all, "radius", cols);
    fr.mass = h5::read<double>(all, "mass", cols);
    if (h5::exists(f, "frames/contacts/count")) {
      fr.has_contacts = true;
      const std::vector<std::int64_t> count = h5::read<std::int64_t>(f, "frames/contacts/count", cols);
      hsize_t first = 0;
      for (std::size_t k = 0; k < index; ++k) first += static_cast<hsize_t>(count.at(k));
      const hsize_t m = static_cast<hsize_t>(count.at(index));
      h5::Handle contacts = h5::open_group(f, "frames/contacts");
      fr.pairs = h5::read_rows<std::int64_t>(contacts, "pairs", first, m);
      fr.normal_force = h5::read_rows<double>(contacts, "normal_force", first, m);
      fr.tangential_force = h5::read_rows<double>(contacts, "tangential_force", first, m);
      fr.branch = h5::read_rows<double>(contacts, "branch", first, m);
    }
    return fr;
  });
}

}  // namespace dem
