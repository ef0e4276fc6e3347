#include "calibration_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"

namespace calibration {
namespace {

// A scene key a parameter sets: in the tests or the preparations, of one density or ("") of all.
struct Claim {
  std::string scope, density, key;
  bool overlaps(const Claim& o) const {
    return scope == o.scope && key == o.key && (density.empty() || o.density.empty() || density == o.density);
  }
};

// `readings: [{name: body, set: {damping.translational: 0.05}}, ...]`: a discrete parameter whose
// values are named sets of scene keys (read as a study variant's overrides are); its keys are
// every key any of them sets, in order.
void read_readings(dem::Section& s, Parameter& p) {
  for (dem::Section r : s.list("readings", "the values, each a named set of scene keys and values (equally likely)")) {
    const std::string name = r.text("name", std::nullopt, "what tables call this reading");
    if (std::find(p.values.begin(), p.values.end(), name) != p.values.end()) r.fail("name", "'" + name + "' names two readings");
    if (!r.has("set")) r.fail("set", "is missing: the scene keys this reading sets");
    pipeline::Overrides overrides = pipeline::read_overrides(r, "set", p.applies_to != "prepare", "the scene keys this reading sets");
    for (const auto& [key, value] : overrides)
      if (std::find(p.keys.begin(), p.keys.end(), key) == p.keys.end()) p.keys.push_back(key);
    r.finish();
    p.values.push_back(name);
    p.readings.push_back(std::move(overrides));
  }
  if (p.readings.size() < 2) s.fail("readings", "is not a list of at least 2 readings");
  p.prior = Parameter::Prior::Values;
}

// `sizes: [{profile: small}, {profile: paper, sets: 8, per_iteration: 3}]`: the study's profiles the
// sets run at, the smallest (every set) first.
void read_sizes(dem::Section& root, Calibration& c) {
  std::set<std::string> profiles, densities;
  for (dem::Section s : root.list("sizes", "the study's profiles the sets run at, smallest first (every set runs at the first)")) {
    Size size;
    size.profile = s.text("profile", std::nullopt, "the study's profile (its lattice and seeds) of this size");
    if (s.has("densities")) {
      if (c.sizes.empty()) s.fail("densities", "is given for the first size, where every set runs every density");
      const YAML::Node d = s.raw("densities", "a list of density names", "the study's densities this part of the largest size runs (its rows and curves only)");
      if (!d.IsSequence() || d.size() == 0) s.fail("densities", "is not a non-empty list of density names");
      for (const YAML::Node& name : d) size.densities.push_back(name.as<std::string>());
      for (const std::string& d : size.densities)
        if (!densities.insert(d).second) s.fail("densities", "'" + d + "' is in two parts of the size: each density in one part at most");
    }
    const bool part = !size.densities.empty();
    if (c.sizes.size() > 1 && part != !c.sizes.back().densities.empty())
      s.fail(part ? "densities" : "profile", "the sizes after the first are either all parts of one size (each with densities:) or none");
    if (part && c.sizes.size() > 1 && size.profile != c.sizes.back().profile)
      s.fail("profile", "'" + size.profile + "': the parts of the largest size share its profile ('" + c.sizes.back().profile + "')");
    if (!(part && c.sizes.size() > 1) && !profiles.insert(size.profile).second) s.fail("profile", "'" + size.profile + "' names two sizes");
    if (c.sizes.empty()) {
      for (const char* key : {"sets", "per_iteration", "confirm", "probe", "named"})
        if (s.has(key)) s.fail(key, "is given for the first size, where every set runs");
    } else {
      size.sets = static_cast<int>(s.integer("sets", 3, 4096, std::nullopt, "the sets run at this size in all (at least 3: a discrepancy's fit)"));
      const int spread = (size.sets + c.min_iterations - 1) / c.min_iterations;
      size.per_iteration = static_cast<int>(s.integer("per_iteration", 1, 4096, spread,
                                                      "the sets chosen to run at this size per iteration (default: sets / min_iterations)"));
      size.confirm = static_cast<int>(s.integer("confirm", 0, 64, 0,
                                                "the sets run at this size after its `sets`, one an iteration, each the one the posterior "
                                                "at this size expects most likely to agree with all of its rows"));
      size.probe = static_cast<int>(s.integer("probe", 0, 64, 0,
                                              "the new sets run at this size after its `confirm` sets, one an iteration, each at the point "
                                              "where the posterior at this size gives the largest probability that one sample agrees with "
                                              "all of its rows (run at the first size too)"));
      if (s.has("named")) {
        const YAML::Node n = s.raw("named", "a list of set names", "sets of the first size (i2s007, ...) run at this size once the iterations end");
        if (!n.IsSequence() || n.size() == 0) s.fail("named", "is not a non-empty list of set names (as the first size's ledger names them)");
        std::set<std::string> seen;
        for (const YAML::Node& name : n) {
          if (!name.IsScalar()) s.fail("named", "holds an entry that is not a set name");
          size.named.push_back(name.as<std::string>());
          if (!seen.insert(size.named.back()).second) s.fail("named", "names '" + size.named.back() + "' twice");
          if (!can_name_set(c, size.named.back()))
            s.fail("named", "'" + size.named.back() + "' is not a set this calibration can draw: i<iteration>s<number> (iteration 1 to " +
                                std::to_string(c.max_iterations) + ", number 1 to " + std::to_string(c.batch) +
                                ", e.g. i2s007) or i<iteration>p<size> (a probe)");
        }
      }
    }
    s.finish();
    c.sizes.push_back(size);
  }
  if (c.sizes.size() < 2) root.fail("sizes", "lists " + std::to_string(c.sizes.size()) + " size(s): give at least 2 (else leave it out and pass --profile)");
  for (std::size_t k = 1; k < c.sizes.size(); ++k)
    if (c.sizes[k].sets > c.sizes[k - 1].sets && k > 1 && c.sizes[k].densities.empty())
      root.fail("sizes", "runs more sets at " + c.sizes[k].profile + " (" + std::to_string(c.sizes[k].sets) + ") than at the size before it, " +
                             c.sizes[k - 1].profile + " (" + std::to_string(c.sizes[k - 1].sets) + "), which its sets are chosen from");
}

}  // namespace

std::string drawn_set_name(int iteration, int number) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "i%ds%03d", iteration, number);
  return buf;
}

std::string probe_set_name(int iteration, std::size_t size) { return "i" + std::to_string(iteration) + "p" + std::to_string(size); }

bool can_name_set(const Calibration& c, const std::string& name) {
  int it = 0, n = 0;
  char kind = 0;
  if (std::sscanf(name.c_str(), "i%d%c%d", &it, &kind, &n) != 3 || it < 1 || it > c.max_iterations || n < 1) return false;
  // The name the calibration would give those numbers, character for character (i2s7 is not i2s007).
  if (kind == 's') return n <= c.batch && name == drawn_set_name(it, n);
  // A probe's size: whether it ran one is known once the iterations end, as for any set.
  return kind == 'p' && name == probe_set_name(it, static_cast<std::size_t>(n));
}

Calibration read_calibration(const std::string& file) {
  dem::Section root = dem::Section::load_file(file);
  Calibration c;
  c.file = file;
  c.name = root.text("name", std::nullopt, "the calibration's name (its results and report folder)");
  if (c.name.empty() || c.name.find_first_of("/\\ \t") != std::string::npos)
    root.fail("name", "is '" + c.name + "': a non-empty name without spaces or slashes");
  c.study = root.file_path("study", "the study whose runs are calibrated (its densities, tests, profiles and seeds)");
  c.references = root.file_path("references", "the reference file: curves and/or a validate reference file's rows");
  c.report = root.file_path("report", "the folder posterior.json, the tables and the figures go to");
  c.batch = static_cast<int>(root.integer("batch", 2, 4096, 16, "parameter sets drawn per iteration"));
  c.max_iterations = static_cast<int>(root.integer("max_iterations", 1, 100, 8, "iterations at most"));
  c.min_iterations = static_cast<int>(root.integer("min_iterations", 1, 100, 3, "iterations at least"));
  if (c.min_iterations > c.max_iterations)
    root.fail("min_iterations", "is above max_iterations (" + std::to_string(c.max_iterations) + ")");
  c.tolerance = root.number("tolerance", "", {0, 1, true}, 0.03,
                            "stop when no posterior mean or sd moves by more than this fraction of its prior range");
  c.min_effective_sets = root.number("min_effective_sets", "", {1, 1e6}, static_cast<double>(c.batch),
                                     "stop only when the posterior rests on at least this many effective sets (default: batch)");
  c.prior_share = root.number("prior_share", "", {0, 1, true, true}, 0.2,
                              "share of the prior in each proposal after the first (defensive mixture)");
  std::set<std::string> names;
  std::vector<Claim> claims;  // the keys the parameters so far set
  for (dem::Section s : root.list("parameters", "the scene keys inferred, each with its prior")) {
    Parameter p;
    p.name = s.text("name", std::nullopt, "what tables call the parameter");
    if (!names.insert(p.name).second) s.fail("name", "'" + p.name + "' names two parameters");
    p.applies_to = s.choice("applies_to", {"test", "prepare", "both"}, "test",
                            "the runs the keys are set in: test (preparations shared), prepare, or both");
    if (s.has("readings")) {  // each value a named set of keys: the keys are theirs
      if (s.has("keys")) s.fail("keys", "is given beside readings: a parameter of readings takes its keys from them");
      read_readings(s, p);
    } else {
      const YAML::Node k = s.raw("keys", "a scene key or a list of them", "the scene keys the parameter sets (one value for all)");
      if (k.IsScalar()) p.keys = {k.as<std::string>()};
      else if (k.IsSequence() && k.size() > 0)
        for (const YAML::Node& key : k) p.keys.push_back(key.as<std::string>());
      else s.fail("keys", "is neither a key nor a list of keys");
    }
    if (s.has("densities")) {
      const YAML::Node d = s.raw("densities", "a list of density names", "the densities whose tests the keys are set in (default: all)");
      if (!d.IsSequence() || d.size() == 0) s.fail("densities", "is not a non-empty list of density names");
      for (const YAML::Node& name : d) p.densities.push_back(name.as<std::string>());
      if (p.applies_to != "test")
        s.fail("densities", "sets the keys in some densities' tests only: it needs applies_to: test (got " + p.applies_to + ")");
    }
    // A key may be two parameters only in different runs: the preparation's friction and the
    // test's, or the tests of two densities. A claim without a density covers every density.
    for (const std::string& key : p.keys)
      for (const std::string scope : {"test", "prepare"}) {
        if (p.applies_to != "both" && p.applies_to != scope) continue;
        const std::vector<std::string> in = scope == "test" && !p.densities.empty() ? p.densities : std::vector<std::string>{""};
        for (const std::string& density : in) {
          const Claim claim{scope, density, key};
          if (std::any_of(claims.begin(), claims.end(), [&](const Claim& other) { return other.overlaps(claim); }))
            s.fail("keys", "'" + key + "' is set by two parameters in the " + scope + " runs" +
                               (density.empty() ? "" : " of the " + density + " sample"));
          claims.push_back(claim);
        }
      }
    const bool uniform = s.has("uniform"), log_uniform = s.has("log_uniform"), values = s.has("values");
    if (uniform + log_uniform + values + !p.readings.empty() != 1)
      s.fail("uniform", "give exactly one prior: uniform: [low, high], log_uniform: [low, high], values: [a, b, ...] or "
                        "readings: [{name: a, set: {key: value, ...}}, ...]");
    if (values) {
      const YAML::Node v = s.raw("values", "a list of at least 2 values", "the values the parameter may take (equally likely)");
      if (!v.IsSequence() || v.size() < 2) s.fail("values", "is not a list of at least 2 values");
      p.prior = Parameter::Prior::Values;
      for (const YAML::Node& x : v) p.values.push_back(x.as<std::string>());
    } else if (uniform || log_uniform) {  // (readings: read_readings set the values and the prior)
      const std::string key = uniform ? "uniform" : "log_uniform";
      const std::vector<double> r = s.numbers(key, "", {-1e300, 1e300}, 2, 2, "the prior's range [low, high]");
      if (!(r[0] < r[1])) s.fail(key, "needs low < high");
      if (log_uniform && !(r[0] > 0)) s.fail(key, "needs low > 0 (a log-uniform prior)");
      p.prior = uniform ? Parameter::Prior::Uniform : Parameter::Prior::LogUniform;
      p.low = r[0], p.high = r[1];
    }
    s.finish();
    c.parameters.push_back(std::move(p));
  }
  if (c.parameters.empty()) root.fail("parameters", "is empty: name at least one scene key to infer");
  if (root.has("sizes")) read_sizes(root, c);
  root.finish();
  return c;
}

}  // namespace calibration
