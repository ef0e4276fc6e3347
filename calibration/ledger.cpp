#include "ledger.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "config/yaml_section.hpp"
#include "core/content_hash.hpp"
#include "io/atomic_file.hpp"
#include "io/particle_csv.hpp"
#include "study/json_file.hpp"

namespace calibration {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr int schema = 2;  // 1: keyed on the reference files' bytes (read still)

// A number as JSON: null when it is not finite (JSON has no NaN), read back as NaN.
json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
double number_of(const json& j) { return j.is_number() ? j.get<double>() : NAN; }
json numbers(const std::vector<double>& xs) {
  json out = json::array();
  for (const double x : xs) out.push_back(number(x));
  return out;
}
std::vector<double> numbers_of(const json& j) {
  std::vector<double> out;
  for (const json& x : j) out.push_back(number_of(x));
  return out;
}

json misfit_json(const SetMisfit& m) {
  json j{{"chi2", number(m.chi2)}, {"valued", m.valued}, {"left_out", m.left_out}, {"rows", json::array()}};
  for (const RowMisfit& r : m.rows) {
    json row{{"name", r.name},   {"chi2", number(r.chi2)}, {"points", r.points},          {"note", r.note},
             {"valued", r.valued}, {"model", numbers(r.model)}, {"model_sd", numbers(r.model_sd)}, {"samples", r.samples}};
    if (r.consistent) row["consistent"] = *r.consistent;
    j["rows"].push_back(row);
  }
  return j;
}

SetMisfit misfit_of(const json& j) {
  SetMisfit m;
  m.chi2 = number_of(j.at("chi2"));
  m.valued = j.at("valued").get<bool>();
  m.left_out = j.at("left_out").get<std::vector<std::string>>();
  for (const json& row : j.at("rows")) {
    RowMisfit r;
    r.name = row.at("name").get<std::string>();
    r.chi2 = number_of(row.at("chi2"));
    r.points = row.at("points").get<int>();
    r.note = row.at("note").get<std::string>();
    r.valued = row.at("valued").get<bool>();
    r.model = numbers_of(row.at("model"));
    r.model_sd = numbers_of(row.at("model_sd"));
    r.samples = row.at("samples").get<int>();
    if (row.contains("consistent")) r.consistent = row["consistent"].get<bool>();
    m.rows.push_back(std::move(r));
  }
  return m;
}

}  // namespace

const ScoredSet* Ledger::find(const std::string& name, const Eigen::VectorXd& u, const std::vector<std::string>& run_hashes) const {
  for (const ScoredSet& s : sets)
    // The unit values to within what the scene's text of a value keeps: the run hashes say the
    // scenes are the same.
    if (s.name == name && s.u.size() == u.size() && (s.u - u).cwiseAbs().maxCoeff() <= 1e-9 && s.run_hashes == run_hashes) return &s;
  return nullptr;
}

ScoredSet* Ledger::find_set(const std::string& name, const Eigen::VectorXd& u) {
  for (ScoredSet& s : sets)
    if (s.name == name && s.u.size() == u.size() && (s.u - u).cwiseAbs().maxCoeff() <= 1e-9) return &s;
  return nullptr;
}

std::optional<double> Ledger::throughput() const {
  double particle_steps = 0, core_seconds = 0;
  for (const ScoredSet& s : sets)
    if (s.particle_steps > 0 && s.core_seconds > 0) particle_steps += s.particle_steps, core_seconds += s.core_seconds;
  if (core_seconds <= 0) return std::nullopt;
  return particle_steps / core_seconds;
}

std::string references_key(const References& refs) {
  std::ostringstream t;
  t.precision(17);  // every double as it is read back
  for (const CurveRow& c : refs.curves) {
    t << "curve\n" << c.name << '\n' << c.x << '\n' << c.y << '\n' << c.density << '\n' << c.test << '\n' << c.specimens << ' '
      << c.tolerance << '\n';
    for (const CurvePoint& p : c.points) t << p.x << ' ' << p.y << ' ' << p.sd << '\n';
  }
  for (const validation::Row& r : refs.rows)
    t << "row\n" << r.name << '\n' << r.quantity << '\n' << r.check << '\n' << r.variant << '\n' << r.density << '\n' << r.test << '\n'
      << r.rule << '\n' << r.reference << ' ' << r.tolerance << ' ' << r.resolution << ' ' << r.cycle << ' ' << r.from_cycle << ' '
      << r.to_cycle << ' ' << r.quasi_static << '\n';
  return dem::content_hash(t.str());
}

namespace {

// The hash of the reference files' bytes, the key of a ledger of schema 1.
std::string references_bytes_hash(const References& refs) {
  std::string text = dem::read_whole_file(refs.file);
  if (!refs.rows_file.empty()) text += dem::read_whole_file(refs.rows_file);
  for (const CurveRow& c : refs.curves) text += dem::read_whole_file(c.file);
  return dem::content_hash(text);
}

// Whether the ledger `j` was scored against `refs`; throws on a schema it does not know.
bool scored_against(const json& j, const References& refs, const std::string& file) {
  const int version = j.at("schema").get<int>();
  if (version == schema) return j.at("references_key").get<std::string>() == references_key(refs);
  if (version == 1) return j.at("references_hash").get<std::string>() == references_bytes_hash(refs);
  throw dem::ConfigError(file + ": schema " + j["schema"].dump() + " is not " + std::to_string(schema) +
                         " (written by another version of calibrate: delete it to run its sets again)");
}

ScoredSet entry_of(const json& s) {
  ScoredSet e;
  e.name = s.at("name").get<std::string>();
  const std::vector<double> u = s.at("u").get<std::vector<double>>();
  e.u = Eigen::Map<const Eigen::VectorXd>(u.data(), static_cast<Eigen::Index>(u.size()));
  e.run_hashes = s.at("run_hashes").get<std::vector<std::string>>();
  e.misfit = misfit_of(s.at("misfit"));
  e.runs = s.at("runs").get<double>();
  e.core_seconds = s.at("core_seconds").get<double>();
  e.particle_steps = s.value("particle_steps", 0.0);
  e.verified_by = s.value("verified_by", std::string());
  return e;
}

// A ledger at `file` that `ledger` does not hold in full is moved aside to <stem>.kept-<N>.json
// (the first N free); returns that path, or "" when there is none to keep.
std::string keep_aside(const std::string& file, const Ledger& ledger, const References& refs) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec))) return "";
  bool held = false;
  try {
    const json j = validation::read_json_file(file);
    held = scored_against(j, refs, file) && std::all_of(j.at("sets").begin(), j.at("sets").end(), [&](const json& s) {
             const ScoredSet e = entry_of(s);
             return ledger.find(e.name, e.u, e.run_hashes) != nullptr;
           });
  } catch (const std::exception&) {  // not readable as a ledger: kept all the same, never overwritten
  }
  if (held) return "";
  const fs::path path(file);
  for (int n = 1;; ++n) {
    const fs::path aside = path.parent_path() / (path.stem().string() + ".kept-" + std::to_string(n) + path.extension().string());
    if (fs::exists(fs::symlink_status(aside, ec))) continue;
    dem::rename_durably(file, aside.string());
    return aside.string();
  }
}

}  // namespace

Ledger read_ledger(const std::string& file, const References& refs) {
  Ledger l;
  l.references_key = references_key(refs);
  if (!fs::exists(file)) return l;
  const json j = validation::read_json_file(file);
  try {
    if (!scored_against(j, refs, file)) {
      l.other_sets = static_cast<int>(j.at("sets").size());
      return l;
    }
    l.stamp = validation::stamp_from_json(j.at("stamp"));
    for (const json& s : j.at("sets")) {
      l.sets.push_back(entry_of(s));
      if (const std::string why = recheck(refs, l.sets.back().misfit); !why.empty())
        throw dem::ConfigError(file + ": set " + l.sets.back().name + ": its score does not follow from its values (" + why +
                               "): edited or damaged; delete the ledger to run its sets again");
    }
  } catch (const json::exception& e) {
    throw dem::ConfigError(file + ": not a ledger of scored sets (" + e.what() + "): delete it to run its sets again");
  }
  return l;
}

std::string write_ledger(const std::string& file, const Ledger& ledger, const References& refs) {
  if (fs::path(file).has_parent_path()) fs::create_directories(fs::path(file).parent_path());
  const std::string kept = keep_aside(file, ledger, refs);
  json j{{"schema", schema},
         {"about", "every set this calibration scored, so that it goes on without the runs' results: a set drawn again "
                   "with the same unit values, run hashes and references takes its score from here"},
         {"references_key", ledger.references_key},
         {"stamp", validation::stamp_json(ledger.stamp)},
         {"sets", json::array()}};
  for (const ScoredSet& s : ledger.sets) {
    j["sets"].push_back({{"name", s.name},
                         {"u", std::vector<double>(s.u.data(), s.u.data() + s.u.size())},
                         {"run_hashes", s.run_hashes},
                         {"runs", s.runs},
                         {"core_seconds", s.core_seconds},
                         {"particle_steps", s.particle_steps},
                         {"misfit", misfit_json(s.misfit)}});
    if (!s.verified_by.empty()) j["sets"].back()["verified_by"] = s.verified_by;
  }
  dem::write_file_atomically(file, j.dump(1) + "\n");
  return kept;
}

int rekey_ledger(const std::string& file, const References& then, const References& now) {
  const json j = validation::read_json_file(file);
  const int version = j.value("schema", 0);
  if (version != 1)
    throw dem::ConfigError(file + ": schema " + std::to_string(version) + ": only a ledger of schema 1 (keyed on the reference files' bytes) is rekeyed");
  const std::string bytes = references_bytes_hash(then);
  if (j.value("references_hash", "") != bytes)
    throw dem::ConfigError(file + ": scored against references whose files hash " + j.value("references_hash", "(none)") + ", not " + then.file +
                           " (" + bytes + "): give the reference files it was scored against (e.g. from version control)");
  if (references_key(then) != references_key(now))
    throw dem::ConfigError(then.file + " and " + now.file + " do not parse the same (a reference, tolerance, rule or point differs): the ledger's scores "
                           "are not of the references now, and it cannot be rekeyed");
  Ledger l;
  l.references_key = references_key(now);
  try {
    l.stamp = validation::stamp_from_json(j.at("stamp"));
    for (const json& s : j.at("sets")) l.sets.push_back(entry_of(s));
  } catch (const json::exception& e) {
    throw dem::ConfigError(file + ": not a ledger of scored sets (" + e.what() + ")");
  }
  for (const ScoredSet& e : l.sets)
    if (const std::string why = recheck(now, e.misfit); !why.empty())
      throw dem::ConfigError(file + ": set " + e.name + ": its score does not follow from its values (" + why + ")");
  write_ledger(file, l, now);
  return static_cast<int>(l.sets.size());
}

}  // namespace calibration
