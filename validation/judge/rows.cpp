#include "judge/rows.hpp"
#include "judge/weak_verdicts.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <set>

#include "config/yaml_section.hpp"
#include "study/format.hpp"

namespace validation {

namespace {

// A row's keys, for the message about an unknown one.
const char* const row_keys =
    "name, group, quantity, variant, density, test, cycle, from_cycle, to_cycle, reference, check, tolerance, resolution, "
    "rule, must_pass, source, reason, profiles";

struct ProfileEntry {
  double tolerance;
  bool must_pass;
  std::string reason;
};

// A row's `profiles: {NAME: {tolerance, must_pass, reason}}`.
std::map<std::string, ProfileEntry> profile_entries(dem::Section& s, const Row& r) {
  std::map<std::string, ProfileEntry> out;
  if (!s.has("profiles")) return out;
  const YAML::Node node = s.raw("profiles", "mapping: profile name -> {tolerance, must_pass, reason}",
                                "the row's tolerance, must_pass and reason for a profile (its samples smaller, its tests shorter)");
  if (!node.IsMap() || node.size() == 0)
    s.fail("profiles", "must be a mapping of profile names to {tolerance, must_pass, reason}, e.g. {quick: {tolerance: 0.03, reason: ...}}");
  for (const auto& kv : node) {
    const std::string name = kv.first.Scalar();
    if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
      s.fail("profiles", "'" + name + "' is not a profile name (letters, digits, _ and -, as the study names its profiles)");
    dem::Section e(kv.second, s.file(), s.key_path("profiles") + "." + name);
    ProfileEntry entry;
    entry.tolerance = e.number("tolerance", "", {0, 1e9}, r.tolerance, "tolerance for this profile");
    if (entry.tolerance > 0 && r.check != "within")
      e.fail("tolerance", "applies to check: within only; with check: " + r.check + " write the bound into reference");
    entry.must_pass = e.boolean("must_pass", false, "must be consistent for this profile");
    entry.reason = e.text("reason", std::nullopt, "why the tolerance differs for this profile");
    e.finish();
    out[name] = entry;
  }
  return out;
}

Row read_row(dem::Section& s, const std::string& name) {
  Row r;
  r.name = name;
  r.origin = s.file() + ": " + s.path() + " (\"" + r.name + "\")";
  r.quantity = s.text("quantity", std::nullopt, "what is computed");
  if (!known_quantity(r.quantity)) {
    std::string known;
    for (const std::string& q : known_quantities()) known += (known.empty() ? "" : ", ") + q;
    s.fail("quantity", "unknown quantity '" + r.quantity + "'; known: " + known + " (and <quantity>_magnitude of each)");
  }
  r.variant = s.text("variant", std::string(), "the study's variant whose runs the row reads (runs.tsv); default: the only one");
  r.density = s.text("density", std::string(), "the study's density whose runs the row reads (runs.tsv); default: the only one");
  r.test = s.text("test", std::string(),
                  "the study's test the row reads (runs.tsv), or the one an ordering (ev_lead, ev_lag) is about; default: every test");
  r.reference = s.number("reference", "", {-1e9, 1e9}, std::nullopt, "reference value");
  r.check = s.choice("check", {"within", "at_least", "at_most"}, std::nullopt, "how measured and reference compare");
  r.tolerance = s.number("tolerance", "", {0, 1e9}, 0.0, "allowed |measured - reference| for check: within");
  if (r.tolerance > 0 && r.check != "within")  // it would be ignored in silence
    s.fail("tolerance", "applies to check: within only; with check: " + r.check + " write the bound into reference");
  r.resolution = s.number("resolution", "", {0, 1e9}, 0.0,
                          "the smallest difference that means something (shifts are counted in max(sd, resolution))");
  r.must_pass = s.boolean("must_pass", false, "an inconsistent verdict fails the validation");
  r.quasi_static = s.boolean("quasi_static", false,
                             "the reference holds in the quasi-static limit (I -> 0): not judged on runs at a finite rate");
  r.reason = s.text("reason", std::nullopt, "why this tolerance");
  r.source = s.text("source", std::nullopt, "where the value comes from: a table, figure or section of the paper, a lab report");
  r.group = s.text("group", std::string("other"), "the report's group of rows (one tornado chart each)");
  r.rule = s.choice("rule", {"interval", "majority", "every"}, std::string("interval"),
                    "interval: the reference's region overlaps the 95 % prediction interval of one sample; "
                    "majority: the statement holds in more than half of the samples (trends, orderings); "
                    "every: it holds in every sample, one or more (a case without scatter, such as a perfect lattice)");
  r.cycle = static_cast<int>(s.integer("cycle", 0, 1000, 0, "cycle for per-cycle quantities"));
  r.from_cycle = static_cast<int>(s.integer("from_cycle", 0, 1000, 0, "first cycle of a change"));
  r.to_cycle = static_cast<int>(s.integer("to_cycle", 0, 1000, 0, "last cycle of a change"));
  return r;
}

// `message` (FILE: rows[i]...: what) with the row's name after rows[i].
std::string naming_row(std::string message, const dem::Section& s, const std::string& name) {
  const std::size_t at = message.find(s.path(), s.file().size());
  if (!name.empty() && at != std::string::npos) message.insert(at + s.path().size(), " (\"" + name + "\")");
  return message;
}

// judge_values' warnings: each distinct misfit of the samples' values, a consistent verdict with no
// sample in the paper's region, and an interval too wide for the tolerance (rule interval, check
// within, a tolerance above 0).
std::vector<std::string> warnings_of(const Row& row, const RowResult& r) {
  std::vector<std::string> out;
  for (const RowResult::PerSample& ps : r.samples)
    if (!ps.measured.misfit.empty() && std::find(out.begin(), out.end(), ps.measured.misfit) == out.end())
      out.push_back(ps.measured.misfit);
  // Consistent only because the interval of one sample is wide: no sample's own value lies in the
  // paper's region (e.g. a coordination number of 6.08-6.14 in every sample against 5.94 +/- 0.15).
  if (row.rule == "interval" && r.verdict == Verdict::Consistent && r.valued > 0 && r.holds == 0)
    out.push_back(std::string(width_only_words) + ": none of the " + std::to_string(r.valued) +
                  " samples lies in the paper's region; the interval of one sample reaches it");
  if (const auto w = too_few_warning(row, r.spread)) out.push_back(*w);
  return out;
}

}  // namespace

References read_references(const std::string& file, const std::string& profile) {
  dem::Section root = dem::Section::load_file(file);
  References refs;
  refs.source = root.text("source", std::nullopt, "where the reference values come from");
  refs.label = root.text("label", std::string("reference"), "what the tables call the reference (paper.yaml: paper)");
  std::vector<std::pair<Row, std::map<std::string, ProfileEntry>>> rows;
  std::map<std::string, std::string> first_of;  // row name -> where it was first given
  for (dem::Section& s : root.list("rows", "the checked statements")) {
    std::string name;
    try {
      name = s.text("name", std::nullopt, "row name");
      if (const auto [it, fresh] = first_of.emplace(name, s.path()); !fresh)
        s.fail("name", "'" + name + "' is the name of " + it->second + " too; each row needs its own (the tables are keyed on it)");
      Row r = read_row(s, name);
      auto entries = profile_entries(s, r);
      try {
        s.finish();
      } catch (const dem::ConfigError& e) {
        throw dem::ConfigError(std::string(e.what()) + "; a row's keys: " + row_keys);
      }
      rows.emplace_back(std::move(r), std::move(entries));
    } catch (const dem::ConfigError& e) {
      throw dem::ConfigError(naming_row(e.what(), s, name));
    }
  }
  root.finish();
  // A profile the file names in some row's `profiles` judges only those rows, with their entries.
  const bool restricted = std::any_of(rows.begin(), rows.end(), [&](const auto& r) { return r.second.count(profile) > 0; });
  for (const auto& [r, entries] : rows)
    for (const auto& [n, e] : entries) refs.profiles.insert(n);
  for (auto& [r, entries] : rows) {
    const auto it = entries.find(profile);
    if (it != entries.end()) r.tolerance = it->second.tolerance, r.must_pass = it->second.must_pass, r.reason = it->second.reason;
    if (!restricted || it != entries.end()) refs.rows.push_back(std::move(r));
  }
  return refs;
}

std::vector<Row> load_references(const std::string& file, const std::string& profile) { return read_references(file, profile).rows; }

bool bound_is_reading(const Row& row) { return row.rule == "majority"; }

RowResult judge_values(const Row& row, std::vector<RowResult::PerSample> samples) {
  RowResult out;
  out.paper = paper_region(row.check, row.reference, row.tolerance);
  std::vector<double> values;
  for (const RowResult::PerSample& ps : samples)
    if (ps.measured.value) {
      values.push_back(*ps.measured.value);
      out.holds += out.paper.contains(*ps.measured.value);
    }
  out.samples = std::move(samples);
  out.valued = static_cast<int>(values.size());
  out.spread = spread(values);
  if (row.rule == "majority")
    out.verdict = out.valued < 2 ? Verdict::NotJudged : 2 * out.holds > out.valued ? Verdict::Consistent : Verdict::Inconsistent;
  else if (row.rule == "every")
    out.verdict = out.valued < 1 ? Verdict::NotJudged : out.holds == out.valued ? Verdict::Consistent : Verdict::Inconsistent;
  else
    out.verdict = judge(out.spread, out.paper);
  if (row.quasi_static) out.verdict = Verdict::NotJudged;
  out.warnings = warnings_of(row, out);
  if (row.quasi_static)
    out.warnings.insert(out.warnings.begin(),
                        std::string(quasi_static_words) + " (I -> 0) and these runs are sheared at a finite rate; " +
                            (taken_to_quasi_static_limit(row.quantity)
                                 ? "the critical-state section compares it with its rate series taken to I -> 0"
                                 : "no section takes " + row.quantity + " to I -> 0"));
  return out;
}

bool taken_to_quasi_static_limit(const std::string& quantity) { return quantity == "critical_state_friction_angle"; }

RowResult shifted(const Row& row, const RowResult& r, double by) {
  std::vector<RowResult::PerSample> samples = r.samples;
  for (RowResult::PerSample& ps : samples)
    if (ps.measured.value) *ps.measured.value += by;
  return judge_values(row, std::move(samples));
}

RowResult evaluate(const Row& row, const std::vector<std::pair<std::string, const DensityResults*>>& samples) {
  std::vector<RowResult::PerSample> values;
  for (const auto& [name, results] : samples)
    values.push_back({name, results ? compute({row.quantity, row.density, row.cycle, row.from_cycle, row.to_cycle, row.test}, *results)
                                    : Measured{std::nullopt, "no results"}});
  return judge_values(row, std::move(values));
}

RowResult evaluate(const Row& row, const std::vector<Sample>& samples) {
  std::vector<std::pair<std::string, const DensityResults*>> of_density;
  for (const Sample& s : samples) {
    const auto it = s.densities.find(row.density);
    of_density.emplace_back(s.name, it == s.densities.end() ? nullptr : &it->second);
  }
  return evaluate(row, of_density);
}

}  // namespace validation
