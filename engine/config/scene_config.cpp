#include "config/scene_config.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "config/contact_keys.hpp"
#include "config/yaml_section.hpp"

namespace dem {

namespace {

Vec3 vec3(const std::vector<double>& v) { return Vec3(v[0], v[1], v[2]); }

ParticleSource read_particles(Section s) {
  ParticleSource src;
  const int given = int(s.has("lattice")) + int(s.has("csv")) + int(s.has("state"));
  if (given != 1) s.fail("", "give exactly one of 'lattice', 'csv' or 'state'");
  if (s.has("lattice")) {
    src.kind = ParticleSource::Kind::Lattice;
    Section l = s.child("lattice", "simple cubic lattice of spheres, one per site");
    const auto n = l.numbers("n", "", {1, 200}, 3, 3, "lattice sites per axis");
    for (int k = 0; k < 3; ++k) {
      if (n[k] != std::floor(n[k])) l.fail("n", "must be whole numbers");
      src.lattice.n[k] = static_cast<int>(n[k]);
    }
    src.lattice.spacing_m = l.number("spacing", "m", {0, 1, true}, std::nullopt, "centre-to-centre distance");
    src.lattice.seed = static_cast<std::uint64_t>(l.integer("seed", 0, std::numeric_limits<std::int64_t>::max(), 1,
                                                            "random seed of the diameter sampler"));
    l.finish();
    Section g = s.child("grading", "mass-based percent-finer curve, piecewise linear");
    src.grading_diameters_m = g.numbers("diameters", "m", {0, 1, true}, 2, 50, "diameters of the curve's points, increasing");
    src.grading_percent_finer = g.numbers("percent_finer", "%", {0, 100}, 2, 50, "percent finer by mass at each diameter, 0 ... 100");
    if (src.grading_percent_finer.size() != src.grading_diameters_m.size())
      g.fail("percent_finer", "must have as many items as 'diameters' (" +
                                  std::to_string(src.grading_diameters_m.size()) + ")");
    src.grading_basis = g.choice("basis", {"mass", "number"}, "mass",
                                 "mass: percent finer by mass; number: percent finer by count (the baseline, docs/method.md#grading)") == "mass"
                            ? GradingCurve::Basis::Mass
                            : GradingCurve::Basis::Number;
    g.finish();
  } else if (s.has("csv")) {
    src.kind = ParticleSource::Kind::Csv;
    src.path = s.file_path("csv", "CSV file with header x,y,z,radius (m)");
    src.cell_m = vec3(s.numbers("cell", "m", {0, 1e3, true}, 3, 3, "cell lengths L1, L2, L3 for a CSV file"));
  } else {
    src.kind = ParticleSource::Kind::State;
    src.path = s.file_path("state", "result file (HDF5) whose final state to start from");
  }
  s.finish();
  return src;
}

HoldCriteria read_hold(Section h) {
  HoldCriteria c;
  c.stress_tolerance = h.number("stress_tolerance", "", {0, 1, true}, 0.005,
                                "each principal stress within this fraction of its target");
  c.unbalanced_force_ratio = h.number("unbalanced_force_ratio", "", {0, 1, true}, 1e-3,
                                      "mean |net force| / mean contact force below this");
  c.check_interval_steps = h.integer("check_interval", 1, 1000000000, 100, "steps between checks of the criteria");
  c.max_duration_s = h.number("max_duration", "s", {0, 1e6, true}, 10.0,
                              "the stage fails if the criteria do not hold within this time");
  c.creep_rate_per_s = h.number("creep_rate", "1/s", {0, 1e3}, 0.0,
                                "volumetric strain rate over the last creep_window at most this (0: not checked)");
  c.creep_window_s = h.number("creep_window", "s", {0, 1e6, true}, 0.01, "the window over which creep_rate is measured");
  h.finish();
  return c;
}

// A path: a list whose items are a state name, an explicit [s1, s2, s3] (Pa) at mean stress p, or
// {repeat: N, path: [...]} (one cycle per repetition; blocks are not nested).
std::vector<PathItem> read_path(const YAML::Node& node, const Section& s, const std::string& key, double p, double R,
                                bool inside_block) {
  if (!node.IsSequence() || node.size() == 0) s.fail(key, "must be a non-empty list of states or repeat blocks");
  std::vector<PathItem> items;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string at = key + "[" + std::to_string(i) + "]";
    const std::string line = item.Mark().line >= 0 ? " (line " + std::to_string(item.Mark().line + 1) + ")" : "";
    PathItem out;
    if (item.IsScalar()) {
      if (!is_named_state(item.Scalar()))
        s.fail(at, "unknown stress state '" + item.Scalar() + "'" + line + "; known: A, TC1, TC2, TC3, TE1, TE2, TE3, or [s1, s2, s3] in Pa");
      out.label = item.Scalar();
      out.state_Pa = named_state(out.label, p, R);
    } else if (item.IsSequence()) {
      if (item.size() != 3) s.fail(at, "an explicit state needs 3 principal stresses [s1, s2, s3] in Pa" + line);
      for (std::size_t k = 0; k < 3; ++k) {
        double v = 0;
        std::string why;
        if (!item[k].IsScalar() || !parse_decimal(item[k].Scalar(), v, why) || !std::isfinite(v) || v <= 0)
          s.fail(at, "stresses must be positive numbers (Pa)" + line + (why.empty() ? "" : ": '" + item[k].Scalar() + "': " + why));
        out.state_Pa[static_cast<int>(k)] = v;
      }
      const double mean = out.state_Pa.mean();
      if (std::abs(mean - p) > 1e-6 * p) {  // 0.1 Pa at 100 kPa: six significant digits are enough
        std::ostringstream msg;
        msg << "state [" << out.state_Pa[0] << ", " << out.state_Pa[1] << ", " << out.state_Pa[2] << "] has mean stress "
            << mean << " Pa, but the path keeps p = mean_stress = " << p << " Pa constant" << line;
        s.fail(at, msg.str());
      }
      std::ostringstream label;
      label << "[" << out.state_Pa[0] << ", " << out.state_Pa[1] << ", " << out.state_Pa[2] << "]";
      out.label = label.str();
    } else if (item.IsMap()) {
      if (inside_block) s.fail(at, "repeat blocks cannot be nested" + line);
      if (!item["repeat"] || !item["path"] || item.size() != 2)
        s.fail(at, "a block is {repeat: N, path: [...]} with exactly these two keys" + line);
      long long n = 0;
      std::string why;
      if (!item["repeat"].IsScalar() || !parse_decimal_integer(item["repeat"].Scalar(), n, why) || n < 1 || n > 100000)
        s.fail(at + ".repeat", "must be an integer in [1, 100000]" + line + (why.empty() ? "" : ": '" + item["repeat"].Scalar() + "': " + why));
      out.repeat = static_cast<int>(n);
      out.block = read_path(item["path"], s, at + ".path", p, R, true);
      out.label = "repeat";
    } else {
      s.fail(at, "must be a state name, [s1, s2, s3] or {repeat: N, path: [...]}" + line);
    }
    items.push_back(std::move(out));
  }
  return items;
}

int component_index(const std::string& name) {
  for (std::size_t k = 0; k < component_names.size(); ++k)
    if (name == component_names[k]) return static_cast<int>(k);
  return -1;
}

// The `control` of a control stage: per component {strain_rate: r}, {stress: s} or follow.
CellControl read_control(Section s) {
  CellControl c;
  for (std::size_t k = 0; k < 6; ++k) {
    const std::string name = component_names[k];
    const bool axis = k < 3;
    const std::string doc = std::string(axis ? "axis " : "shear ") + name +
                            ": {strain_rate: r} [1/s], {stress: s} [Pa] (compression positive) or follow (set by the constraint)" +
                            (axis ? "" : "; default {strain_rate: 0}");
    if (!s.has(name)) {
      if (axis) s.child(name, doc);  // required: declares and reports it
      continue;
    }
    AxisTarget& t = c.component[k];
    const YAML::Node node = s.raw(name, "{strain_rate: r}, {stress: s} or follow", doc);
    if (node.IsScalar()) {
      if (node.as<std::string>() != "follow") s.fail(name, "must be {strain_rate: r}, {stress: s} or follow");
      t.mode = AxisTarget::Mode::Follow;
      continue;
    }
    Section m = s.child(name, doc);
    const bool rate = m.has("strain_rate"), stress = m.has("stress");
    if (rate == stress)
      m.fail(rate ? "stress" : "strain_rate", rate ? "a component takes one control, not both strain_rate and stress"
                                                   : "give strain_rate or stress");
    if (rate)
      t = {AxisTarget::Mode::StrainRate, m.number("strain_rate", "1/s", {-1e3, 1e3}, std::nullopt, "strain rate, compression positive"), 0, 0};
    else
      t = {AxisTarget::Mode::Stress, 0, m.number("stress", "Pa", {-1e10, 1e10}, std::nullopt,
                                                 "stress target, compression positive (an axis: >= 0, spheres carry no tension)"), 0};
    // Spheres without cohesion carry no tension: a tensile target on an axis is never reached
    // (the stage would stretch the cell at its strain-rate cap to the end). Shear stresses take
    // either sign.
    if (axis && t.mode == AxisTarget::Mode::Stress && t.stress_Pa < 0)
    {
      std::ostringstream msg;
      msg << "is tensile (compression is positive), got " << t.stress_Pa
          << " Pa: a packing without cohesion carries no tension, so the stage could never reach it; allowed: >= 0 Pa";
      m.fail("stress", msg.str());
    }
    m.finish();
  }
  s.finish();
  return c;
}

StageConfig read_stage(Section s) {
  StageConfig st;
  st.name = s.text("name", std::nullopt, "stage name, written into the results");
  const std::string type = s.choice("type", {"strain_rate", "stress", "stress_path", "control"}, std::nullopt,
                                    "strain_rate: fixed strain rates for a duration; stress: ramp to a target stress and hold; "
                                    "stress_path: straight legs between stress states at constant mean stress; "
                                    "control: each component of the cell strain-rate or stress controlled, or set by a constraint");
  st.reset_strain = s.boolean("reset_strain", false, "measure strains from the start of this stage");
  if (type == "strain_rate") {
    st.type = StageConfig::Type::StrainRate;
    st.strain_rate_per_s = vec3(s.numbers("strain_rate", "1/s", {-1e3, 1e3}, 3, 3, "strain rate per axis, compression positive"));
    st.duration_s = s.number("duration", "s", {0, 1e6, true}, std::nullopt, "stage duration");
  } else if (type == "stress_path") {
    st.type = StageConfig::Type::StressPath;
    st.mean_stress_Pa = s.number("mean_stress", "Pa", {0, 1e10, true}, 1e5, "p, kept constant along the path");
    st.stress_ratio = s.number("stress_ratio", "", {1, 100}, 1.24, "R = sigma_max/sigma_min of the named TC/TE states");
    st.stress_rate_Pa_per_s = s.number("rate", "Pa/s", {0, 1e12, true}, std::nullopt,
                                       "rate of the principal stress that changes most on each leg");
    st.max_strain_rate_per_s = s.number("max_strain_rate", "1/s", {0, 1e3, true}, 1.0,
                                        "cap on the cell strain rate of each axis");
    const YAML::Node path = s.raw("path", "list of states (A, TC1..3, TE1..3, [s1, s2, s3]) and {repeat: N, path: [...]}",
                                  "the path, starting from A; each repetition of a block is a cycle");
    st.path = read_path(path, s, "path", st.mean_stress_Pa, st.stress_ratio, false);
    YAML::Emitter e;
    e << YAML::Flow << path;
    st.path_text = e.c_str();
    st.zero_shear_stress = s.boolean("zero_shear_stress", false,
                                     "hold the shear stresses at zero (the cell shears); false: the cell stays orthorhombic");
  } else if (type == "control") {
    st.type = StageConfig::Type::Control;
    st.duration_s = s.number("duration", "s", {0, 1e6, true}, std::nullopt, "the longest the stage runs");
    st.max_strain_rate_per_s = s.number("max_strain_rate", "1/s", {0, 1e3, true}, 1.0,
                                        "cap on the strain rate of each stress-controlled component");
    YAML::Emitter e;
    e << YAML::Flow << YAML::BeginMap;
    for (const char* key : {"control", "constraint", "cyclic", "until"})
      if (s.has(key)) e << YAML::Key << key << YAML::Value << s.raw(key, "", "");
    e << YAML::EndMap;
    st.control_text = e.c_str();
    st.control = read_control(s.child("control", "per component xx yy zz xy xz yz: {strain_rate: r}, {stress: s} or follow"));
    if (s.has("constraint")) {
      Section c = s.child("constraint", "a constraint the following components obey");
      const std::string kind = c.choice("type", {"constant_volume", "constant_mean_stress"}, std::nullopt,
                                        "constant_volume: undrained; constant_mean_stress: p held, the followers split by b");
      CellConstraint& k = st.control.constraint;
      if (kind == "constant_volume") {
        k.kind = CellConstraint::Kind::ConstantVolume;
      } else {
        k.kind = CellConstraint::Kind::ConstantMeanStress;
        k.mean_stress_Pa = c.number("mean_stress", "Pa", {0, 1e10, true}, std::nullopt, "p to hold");
        k.b = c.number("b", "", {0, 1}, 0.0, "intermediate principal stress ratio (s2 - s3)/(s1 - s3), the leader major");
      }
      c.finish();
    }
    if (const std::string error = control_error(st.control); !error.empty()) s.fail("control", error);
    if (s.has("cyclic")) {
      Section c = s.child("cyclic", "one component's loading oscillates as a sine");
      const std::string name = c.choice("component", {"xx", "yy", "zz", "xy", "xz", "yz"}, std::nullopt, "the component");
      st.cyclic.component = component_index(name);
      const std::string q = c.choice("quantity", {"stress", "deviator", "strain"}, "stress",
                                     "stress: its target oscillates about its value in control; deviator: q = s_kk - "
                                     "(other axes)/2 about q at the stage start (an axis); strain: its strain, on top of its rate");
      st.cyclic.quantity = q == "stress" ? CyclicLoading::Quantity::Stress
                           : q == "deviator" ? CyclicLoading::Quantity::Deviator : CyclicLoading::Quantity::Strain;
      st.cyclic.amplitude = c.number("amplitude", "Pa or 1", {0, 1e10, true}, std::nullopt, "amplitude of the sine");
      st.cyclic.period_s = c.number("period", "s", {0, 1e6, true}, std::nullopt, "period of the sine");
      const AxisTarget::Mode mode = st.control.component[static_cast<std::size_t>(st.cyclic.component)].mode;
      const bool wants_stress = st.cyclic.quantity != CyclicLoading::Quantity::Strain;
      if (wants_stress && mode != AxisTarget::Mode::Stress)
        c.fail("component", name + " must be stress-controlled in control to cycle its " + q);
      if (!wants_stress && mode != AxisTarget::Mode::StrainRate)
        c.fail("component", name + " must be strain-rate controlled in control to cycle its strain");
      if (st.cyclic.quantity == CyclicLoading::Quantity::Deviator && st.cyclic.component >= 3)
        c.fail("quantity", "deviator cycles an axis (xx, yy or zz), not " + name);
      const double centre = st.control.component[static_cast<std::size_t>(st.cyclic.component)].stress_Pa;
      if (st.cyclic.quantity == CyclicLoading::Quantity::Stress && st.cyclic.component < 3 && centre - st.cyclic.amplitude < 0) {
        std::ostringstream msg;
        msg << "takes " << name << "'s stress target " << centre << " Pa to " << centre - st.cyclic.amplitude
            << " Pa, a tension (compression is positive) that a packing without cohesion never reaches; allowed: at most "
            << centre << " Pa";
        c.fail("amplitude", msg.str());
      }
      c.finish();
    }
    if (s.has("until")) {
      Section u = s.child("until", "criteria that end the stage before its duration (the first met)");
      if (u.has("strain")) {
        st.until.strain = u.number("strain", "1", {0, 10, true}, std::nullopt, "|strain| of until.component since the stage start");
        st.until.component = component_index(u.choice("component", {"xx", "yy", "zz", "xy", "xz", "yz"}, std::nullopt,
                                                        "whose strain until.strain limits"));
      }
      st.until.pore_pressure_ratio = u.number("pore_pressure_ratio", "", {0, 1, true}, 0.0,
                                              "r_u = 1 - p/p0 (p0 at the stage start) that ends the stage; 0: off");
      st.until.double_amplitude_strain = u.number("double_amplitude_strain", "1", {0, 10}, 0.0,
                                                  "max - min strain of the cyclic component within a cycle; 0: off");
      if (st.until.double_amplitude_strain > 0 && st.cyclic.component < 0)
        u.fail("double_amplitude_strain", "needs a cyclic loading (the stage's cyclic key)");
      u.finish();
    }
  } else {
    st.type = StageConfig::Type::Stress;
    st.target_Pa = vec3(s.numbers("target", "Pa", {0, 1e10, true}, 3, 3, "target principal stresses, compression positive"));
    st.stress_rate_Pa_per_s = s.number("rate", "Pa/s", {0, 1e12, true}, std::nullopt,
                                       "rate at which each target ramps from the stage's starting stress");
    st.max_strain_rate_per_s = s.number("max_strain_rate", "1/s", {0, 1e3, true}, 1.0,
                                        "cap on the cell strain rate of each axis");
    st.zero_shear_stress = s.boolean("zero_shear_stress", false,
                                     "hold the shear stresses at zero (the cell shears), and count them in the hold's "
                                     "stress error; false: the cell stays orthorhombic");
    if (s.has("hold")) st.hold = read_hold(s.child("hold", "equilibrium criteria that end the stage"));
    else s.child("hold", "equilibrium criteria that end the stage");  // required: declares and reports it
  }
  s.finish();
  return st;
}

std::string emit_resolved(const SceneConfig& c) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << c.name;
  out << YAML::Key << "particles" << YAML::Value << YAML::BeginMap;
  const auto& p = c.particles;
  if (p.kind == ParticleSource::Kind::Lattice) {
    out << YAML::Key << "lattice" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "n" << YAML::Value
        << std::vector<int>{p.lattice.n[0], p.lattice.n[1], p.lattice.n[2]} << YAML::Key << "spacing" << YAML::Value
        << p.lattice.spacing_m << YAML::Key << "seed" << YAML::Value << p.lattice.seed << YAML::EndMap;
    out << YAML::Key << "grading" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "diameters"
        << YAML::Value << p.grading_diameters_m << YAML::Key << "percent_finer" << YAML::Value << p.grading_percent_finer
        << YAML::Key << "basis" << YAML::Value << (p.grading_basis == GradingCurve::Basis::Mass ? "mass" : "number")
        << YAML::EndMap;
  } else if (p.kind == ParticleSource::Kind::Csv) {
    out << YAML::Key << "csv" << YAML::Value << p.path << YAML::Key << "cell" << YAML::Value << YAML::Flow
        << std::vector<double>{p.cell_m[0], p.cell_m[1], p.cell_m[2]};
  } else {
    out << YAML::Key << "state" << YAML::Value << p.path;
  }
  out << YAML::EndMap;
  out << YAML::Key << "material" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "density"
      << YAML::Value << c.material.density_kg_per_m3;
  emit_contact_law(out, c.material.law);
  out << YAML::EndMap;
  out << YAML::Key << "damping" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "form" << YAML::Value
      << (c.damping.form == Damping::Form::Viscous ? "viscous" : "local") << YAML::Key << "translational"
      << YAML::Value << c.damping.translational << YAML::Key << "rotational" << YAML::Value << c.damping.rotational
      << YAML::EndMap;
  out << YAML::Key << "numerics" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "time_step"
      << YAML::Value << c.time_step_s << YAML::Key << "max_time_step_fraction" << YAML::Value
      << c.max_time_step_fraction << YAML::Key << "max_energy_error" << YAML::Value << c.max_energy_error
      << YAML::Key << "verlet_skin" << YAML::Value << c.verlet_skin_m << YAML::EndMap;
  out << YAML::Key << "servo" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "gain" << YAML::Value
      << c.servo.gain << YAML::Key << "adapt_window" << YAML::Value << c.servo.adapt_window_steps << YAML::Key
      << "min_stiffness_ratio" << YAML::Value << c.servo.min_stiffness_ratio << YAML::EndMap;
  out << YAML::Key << "output" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "interval"
      << YAML::Value << c.output.interval_steps << YAML::Key << "flush_rows" << YAML::Value << c.output.flush_rows;
  if (c.output.frames_interval_steps > 0)  // only when set: the resolved scenes (and input hashes) of older scenes stay
    out << YAML::Key << "frames" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "interval" << YAML::Value
        << c.output.frames_interval_steps << YAML::Key << "contacts" << YAML::Value << c.output.frames_contacts
        << YAML::EndMap;
  out << YAML::EndMap;
  out << YAML::Key << "stages" << YAML::Value << YAML::BeginSeq;
  for (const auto& s : c.stages) {
    out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << s.name << YAML::Key << "reset_strain"
        << YAML::Value << s.reset_strain;
    if (s.type == StageConfig::Type::StrainRate) {
      out << YAML::Key << "type" << YAML::Value << "strain_rate" << YAML::Key << "strain_rate" << YAML::Value
          << YAML::Flow << std::vector<double>{s.strain_rate_per_s[0], s.strain_rate_per_s[1], s.strain_rate_per_s[2]}
          << YAML::Key << "duration" << YAML::Value << s.duration_s;
    } else if (s.type == StageConfig::Type::StressPath) {
      out << YAML::Key << "type" << YAML::Value << "stress_path" << YAML::Key << "mean_stress" << YAML::Value
          << s.mean_stress_Pa << YAML::Key << "stress_ratio" << YAML::Value << s.stress_ratio << YAML::Key << "rate"
          << YAML::Value << s.stress_rate_Pa_per_s << YAML::Key << "max_strain_rate" << YAML::Value
          << s.max_strain_rate_per_s << YAML::Key << "path" << YAML::Value << parse_yaml(s.path_text, c.file);
      if (s.zero_shear_stress) out << YAML::Key << "zero_shear_stress" << YAML::Value << true;
    } else if (s.type == StageConfig::Type::Control) {
      out << YAML::Key << "type" << YAML::Value << "control" << YAML::Key << "duration" << YAML::Value << s.duration_s
          << YAML::Key << "max_strain_rate" << YAML::Value << s.max_strain_rate_per_s;
      for (const auto& kv : parse_yaml(s.control_text, c.file)) out << YAML::Key << kv.first << YAML::Value << kv.second;
    } else {
      out << YAML::Key << "type" << YAML::Value << "stress" << YAML::Key << "target" << YAML::Value << YAML::Flow
          << std::vector<double>{s.target_Pa[0], s.target_Pa[1], s.target_Pa[2]} << YAML::Key << "rate" << YAML::Value
          << s.stress_rate_Pa_per_s << YAML::Key << "max_strain_rate" << YAML::Value << s.max_strain_rate_per_s
          << YAML::Key << "hold" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "stress_tolerance"
          << YAML::Value << s.hold.stress_tolerance << YAML::Key << "unbalanced_force_ratio" << YAML::Value
          << s.hold.unbalanced_force_ratio << YAML::Key << "check_interval" << YAML::Value
          << s.hold.check_interval_steps << YAML::Key << "max_duration" << YAML::Value << s.hold.max_duration_s;
      if (s.hold.creep_rate_per_s > 0)  // only when set: the resolved scenes (and input hashes) of older scenes stay
        out << YAML::Key << "creep_rate" << YAML::Value << s.hold.creep_rate_per_s << YAML::Key << "creep_window"
            << YAML::Value << s.hold.creep_window_s;
      out << YAML::EndMap;
      if (s.zero_shear_stress) out << YAML::Key << "zero_shear_stress" << YAML::Value << true;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  return out.c_str();
}

std::string fmt(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

// Every stretch of time a stage turns into a step count must give 1 ... max_scene_steps steps
// (a tiny time step overflowed the count: 0 steps and a "complete" result), and so must their
// sum. Checked on the scene, before any particle exists; the messages name the keys.
void check_step_counts(const SceneConfig& c) {
  const double dt = c.time_step_s, max = static_cast<double>(max_scene_steps);
  const std::string at_dt = " at numerics.time_step = " + fmt(dt) + " s";
  const auto too_many = [&](const std::string& key, const std::string& what, double steps) {
    throw ConfigError(c.file + ": " + key + ": " + what + at_dt + " is " + fmt(steps) + " steps, more than the " +
                      fmt(max) + " a run may take; raise numerics.time_step or shorten the stage");
  };
  double total = 0;
  for (std::size_t i = 0; i < c.stages.size(); ++i) {
    const StageConfig& st = c.stages[i];
    const std::string key = "stages[" + std::to_string(i) + "]";
    if (st.type == StageConfig::Type::StressPath) {
      const std::vector<PathLeg> legs = expand_path(st.path, named_state("A", st.mean_stress_Pa, st.stress_ratio),
                                                    st.stress_rate_Pa_per_s);
      double steps = 0;  // each leg runs at least one step
      for (const PathLeg& leg : legs) steps += std::max(1.0, leg.duration_s / dt);
      if (!(steps <= max))
        too_many(key + ".path", "the path (" + std::to_string(legs.size()) + " legs at rate = " + fmt(st.stress_rate_Pa_per_s) +
                                    " Pa/s)", steps);
      total += steps;
      continue;
    }
    const bool hold = st.type == StageConfig::Type::Stress;
    const double duration = hold ? st.hold.max_duration_s : st.duration_s, steps = duration / dt;
    const std::string dkey = key + (hold ? ".hold.max_duration" : ".duration");
    if (!(steps >= 0.5))
      throw ConfigError(c.file + ": " + dkey + ": " + fmt(duration) + " s is less than half of numerics.time_step = " +
                        fmt(dt) + " s: the stage would get 0 steps; lengthen it or lower the time step");
    if (!(steps <= max)) too_many(dkey, fmt(duration) + " s", steps);
    total += steps;
  }
  if (!(total <= max))
    throw ConfigError(c.file + ": stages: together up to " + fmt(total) + " steps" + at_dt + ", more than the " + fmt(max) +
                      " a run may take; raise numerics.time_step or shorten the stages");
}

}  // namespace

std::int64_t steps_in(double duration_s, double dt_s) { return std::llround(duration_s / dt_s); }

static SceneConfig parse_scene(Section root, const std::string& file) {
  SceneConfig c;
  c.file = file;
  c.name = root.text("name", std::filesystem::path(file).stem().string(), "scene name");
  c.particles = read_particles(root.child("particles", "where the particles come from: lattice, csv or state"));

  Section m = root.child("material", "material constants");
  c.material.density_kg_per_m3 = m.number("density", "kg/m^3", {0, 1e5, true}, 2650.0, "solid density");
  c.material.law = read_contact_law(m);
  m.finish();

  {
    Section d = root.optional_child("damping", "damping of particle motion (docs/method.md#damping)");
    c.damping.form = d.choice("form", {"viscous", "local"}, "viscous",
                              "viscous: fraction of critical on the fluctuating velocity; local: Cundall's non-viscous") == "viscous"
                         ? Damping::Form::Viscous
                         : Damping::Form::Local;
    c.damping.translational = d.number("translational", "", {0, 1}, 0.05, "C_t (viscous) or alpha (local)");
    c.damping.rotational = d.number("rotational", "", {0, 1}, 0.05, "C_r (viscous) or alpha for spins (local)");
    if (c.damping.form == Damping::Form::Viscous && !(damping_stiffness(c.material.law) > 0) &&
        (c.damping.translational > 0 || c.damping.rotational > 0))
      d.fail("form", "viscous (the default) scales the damping with a contact stiffness, and material.law " +
                         law_name(c.material.law) + " has none: use damping: {form: local}");
    d.finish();
  }

  Section n = root.child("numerics", "time integration and neighbour search");
  c.time_step_s = n.number("time_step", "s", {0, 1, true}, std::nullopt, "fixed time step");
  c.max_time_step_fraction = n.number("max_time_step_fraction", "", {0, 10, true}, 0.2,
                                      "largest allowed time_step / the law's critical step (linear: 2 sqrt(m_min/kn)); raise only on purpose");
  c.max_energy_error = n.number("max_energy_error", "", {0, 1e6, true}, 0.05,
                                "a run stops when its energy closure error exceeds this (checked at output rows)");
  c.verlet_skin_m = n.number("verlet_skin", "m", {0, 1, true}, 2e-4, "Verlet list skin distance");
  n.finish();

  {
    Section s = root.optional_child("servo", "stress servo of stress-controlled axes");
    c.servo.gain = s.number("gain", "", {0, 1, true}, 1e-3, "fraction of the stress error removed per step");
    c.servo.adapt_window_steps = static_cast<int>(s.integer("adapt_window", 0, 1000000, 250,
        "steps between updates of the learnt stiffness ratio of stress stages (0: off, affine stiffness)"));
    c.servo.min_stiffness_ratio = s.number("min_stiffness_ratio", "", {0, 1, true}, 0.05,
                                           "lower bound of the learnt stiffness ratio");
    s.finish();
  }
  {
    Section o = root.optional_child("output", "time-series output");
    c.output.interval_steps = o.integer("interval", 1, 1000000000, 1000, "steps between time-series rows");
    c.output.flush_rows = o.integer("flush_rows", 1, 1000000, 20, "rows between flushes of the result file to disk");
    c.output.checkpoint_interval_steps = o.integer("checkpoint_interval", 0, 1000000000, 0,
        "steps between checkpoints (RESULT.h5.checkpoint, for dem run --resume; 0: none by steps, else at least " +
            std::to_string(min_checkpoint_interval_steps) + ")");
    if (c.output.checkpoint_interval_steps > 0 && c.output.checkpoint_interval_steps < min_checkpoint_interval_steps)
      o.fail("checkpoint_interval",
             "must be 0 (none by steps) or at least " + std::to_string(min_checkpoint_interval_steps) + ", got " +
                 std::to_string(c.output.checkpoint_interval_steps) +
                 ": each checkpoint copies the whole result so far, so a checkpoint every few steps costs more than the "
                 "steps (every step: 33 steps/s and 30 MB after 1,877 steps); checkpoint_wall_time sets them by wall time");
    c.output.checkpoint_wall_time_s = o.number("checkpoint_wall_time", "s", {0, 1e7}, 600,
        "seconds of wall time between checkpoints (0: none by time)");
    if (o.has("frames")) {
      Section f = o.optional_child("frames", "particle frames for ParaView (RESULT.xdmf) every `interval` steps",
                                   "optional (absent: frames at the start, each checkpoint and the end only)");
      c.output.frames_interval_steps = f.integer("interval", 1, 1000000000, std::nullopt,
          "steps between frames, independent of output.interval (a frame is written at every step that is a "
          "multiple of it, and at the start and the end of the run)");
      c.output.frames_contacts = f.boolean("contacts", false, "also the contact network of each frame (pairs, "
                                           "normal and tangential force, branch vector)");
      f.finish();
    }
    o.finish();
  }
  for (Section& s : root.list("stages", "the stages, run in order")) c.stages.push_back(read_stage(s));
  for (std::size_t i = 0; i < c.stages.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (c.stages[i].name == c.stages[j].name)
        throw ConfigError(file + ": stages[" + std::to_string(i) + "].name: duplicate stage name '" + c.stages[i].name + "'");
  root.finish();
  check_step_counts(c);
  c.input_files.push_back({"the scene file", file});
  if (c.particles.kind != ParticleSource::Kind::Lattice)
    c.input_files.push_back({c.particles.kind == ParticleSource::Kind::Csv ? "particles.csv" : "particles.state", c.particles.path});
  c.resolved_yaml = emit_resolved(c);
  return c;
}

SceneConfig load_scene(const std::string& file, const std::vector<std::pair<std::string, std::string>>& overrides) {
  return parse_scene(Section::load_file(file, overrides), file);
}

SceneConfig scene_from_text(const std::string& text, const std::string& file,
                            const std::vector<std::pair<std::string, std::string>>& overrides) {
  return parse_scene(Section::from_text(text, file, overrides), file);
}

std::string scene_key_reference() {
  // Declarations are recorded as keys are read: read one example of each variant.
  const char* common = "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5, density: 2650}\n"
                       "damping: {form: viscous, translational: 0.05, rotational: 0.05}\n"
                       "numerics: {time_step: 1.0e-6, max_time_step_fraction: 0.2, max_energy_error: 0.05, verlet_skin: 2.0e-4}\n"
                       "servo: {gain: 1.0e-3}\noutput: {interval: 1000, flush_rows: 20, frames: {interval: 1000, contacts: true}}\n";
  scene_from_text(std::string("name: a\nparticles:\n  lattice: {n: [2, 2, 2], spacing: 0.005, seed: 1}\n"
                              "  grading: {diameters: [0.003, 0.0045], percent_finer: [0, 100]}\n") + common +
                      "stages:\n  - {name: s, type: stress, target: [1, 1, 1], rate: 1, max_strain_rate: 1, reset_strain: false,\n"
                      "     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 0.001, check_interval: 100, max_duration: 1}}\n",
                  "example");
  scene_from_text(std::string("particles: {csv: p.csv, cell: [1, 1, 1]}\n") + common +
                      "stages: [{name: s, type: strain_rate, strain_rate: [0, 0, 0], duration: 1}]\n",
                  "example");
  scene_from_text(std::string("particles: {state: s.h5}\n") + common +
                      "stages: [{name: s, type: stress_path, mean_stress: 1.0e5, stress_ratio: 1.24, rate: 2.0e6,\n"
                      "          max_strain_rate: 1, path: [TC1, {repeat: 5, path: [TC2, TC3, TC1]}], zero_shear_stress: true}]\n",
                  "example");
  scene_from_text(std::string("particles: {state: s.h5}\n") + common +
                      "stages:\n  - {name: s, type: control, duration: 1, max_strain_rate: 1,\n"
                      "     control: {xx: follow, yy: follow, zz: {stress: 1.0e5}, xy: {strain_rate: 0}, xz: {stress: 0}, yz: {stress: 0}},\n"
                      "     constraint: {type: constant_volume}, cyclic: {component: zz, quantity: deviator, amplitude: 1.0e4, period: 0.1},\n"
                      "     until: {component: zz, strain: 0.4, pore_pressure_ratio: 0.95, double_amplitude_strain: 0.05}}\n"
                      "  - {name: t, type: control, duration: 1, control: {xx: follow, yy: follow, zz: {strain_rate: 0.1}},\n"
                      "     constraint: {type: constant_mean_stress, mean_stress: 1.0e5, b: 0.5}}\n",
                  "example");
  scene_from_text(std::string("particles: {state: s.h5}\n") +
                      "material: {law: hertz_mindlin, young_modulus: 7.0e10, poisson_ratio: 0.25, friction: 0.5,\n"
                      "           rolling_friction: 0.1, rolling_stiffness: 1.0e6}\ndamping: {form: local}\n"
                      "numerics: {time_step: 1.0e-7}\n"
                      "stages: [{name: s, type: strain_rate, strain_rate: [0, 0, 0], duration: 1}]\n",
                  "example");
  key_docs()["name"].default_value = "the scene file's name without extension";
  std::ostringstream out;
  out << "Scene keys (unit; allowed; default; meaning):\n";
  for (const auto& [key, d] : key_docs())
    out << "  " << key << (d.unit.empty() ? "" : " [" + d.unit + "]") << "; " << d.allowed << "; " << d.default_value
        << "; " << d.doc << "\n";
  return out.str();
}

}  // namespace dem
