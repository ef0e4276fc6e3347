#include "io/h5md.hpp"

#include "io/state_io.hpp"  // flatten
#include "version.hpp"

namespace dem {

namespace {

void link(hid_t from_group, const std::string& target, hid_t to_group, const std::string& name) {
  if (H5Lcreate_hard(from_group, target.c_str(), to_group, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    throw h5::Error("HDF5: linking " + name + " to " + target + " failed");
}

}  // namespace

H5mdWriter::H5mdWriter(hid_t file, const Simulation& sim) {
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
  h5::set_attribute(time_.id(), "unit", std::string("s"));
  position_ = h5::FrameSeries<double>(position, "value", {n, 3});
  h5::set_attribute(position_.id(), "unit", std::string("m"));

  // Every other time-dependent element shares position's step and time (hard links).
  auto element = [&](hid_t parent, const std::string& name) {
    h5::Handle g = h5::create_group(parent, name);
    link(position, "step", g, "step");
    link(position, "time", g, "time");
    return g;
  };
  h5::Handle velocity = element(all, "velocity");
  velocity_ = h5::FrameSeries<double>(velocity, "value", {n, 3});
  h5::set_attribute(velocity_.id(), "unit", std::string("m s-1"));
  // The engine integrates v relative to the cell's affine deformation (engine/README.md, Model);
  // the total velocity, v - strain_rate o x, depends on where the origin sits, so v is stored.
  h5::set_attribute(velocity_.id(), "doc", std::string("fluctuating velocity: total velocity minus the affine "
                                                       "velocity of the deforming cell"));
  h5::Handle angular_velocity = element(all, "angular_velocity");
  angular_velocity_ = h5::FrameSeries<double>(angular_velocity, "value", {n, 3});
  h5::set_attribute(angular_velocity_.id(), "unit", std::string("rad s-1"));

  h5::Handle box = h5::create_group(all, "box");
  h5::set_attribute(box, "dimension", std::int64_t{3});
  h5::set_attribute(box, "boundary", std::vector<std::string>{"periodic", "periodic", "periodic"});
  h5::Handle edges = element(box, "edges");
  edges_ = h5::FrameSeries<double>(edges, "value", {3});
  h5::set_attribute(edges_.id(), "unit", std::string("m"));

  h5::write(all, "radius", p.radius, 1, "m", "unit");
  h5::write(all, "mass", p.mass, 1, "kg", "unit");
}

H5mdWriter::H5mdWriter(hid_t file) {
  h5::Handle all = h5::open_group(file, "particles/all");
  h5::Handle position = h5::open_group(all, "position");
  step_ = h5::FrameSeries<std::int64_t>(position, "step");
  time_ = h5::FrameSeries<double>(position, "time");
  position_ = h5::FrameSeries<double>(position, "value");
  velocity_ = h5::FrameSeries<double>(all, "velocity/value");
  angular_velocity_ = h5::FrameSeries<double>(all, "angular_velocity/value");
  edges_ = h5::FrameSeries<double>(all, "box/edges/value");
}

void H5mdWriter::append_frame(const Simulation& sim) {
  const Particles& p = sim.particles();
  const PeriodicCell& cell = sim.cell();
  std::vector<Vec3> x(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) x[i] = cell.to_real(p.s[i]);
  const Vec3& L = cell.lengths();
  // Step last: should a frame fail part-way, the length of `step` still counts whole frames only.
  position_.append(flatten(x));
  velocity_.append(flatten(p.v));
  angular_velocity_.append(flatten(p.omega));
  edges_.append({L[0], L[1], L[2]});
  time_.append({sim.time()});
  step_.append({sim.step_count()});
}

}  // namespace dem
