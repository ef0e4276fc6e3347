#include "config/study_config.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "config/yaml_section.hpp"

namespace pipeline {

namespace {

std::string resolve(const std::string& study_file, const std::string& p) {
  namespace fs = std::filesystem;
  const fs::path path(p);
  return (path.is_absolute() ? path : fs::absolute(fs::path(study_file).parent_path() / path)).lexically_normal().string();
}

void require_file(const dem::Section& s, const std::string& key, const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) s.fail(key, "no such file: " + path);
}

// Every name of a study that becomes part of a file name (densities, tests, variants: results,
// scenes and logs are <out>/<variant>_<density>_<test>.h5, ...) is checked here, once: one path
// component of its own, so that two names can never map to one file (`loose` and `x/../loose`)
// nor a run write outside its study's folder. Refused: empty, a separator (/ or \), `..`
// anywhere, a leading dot (hidden files, `.` and `..`), control characters (a tab or newline would
// also break runs.tsv).
void check_path_name(const dem::Section& s, const std::string& key, const std::string& name) {
  std::string why;
  if (name.empty()) why = "is empty";
  else if (name.find_first_of("/\\") != std::string::npos) why = "contains a path separator";
  else if (name.find("..") != std::string::npos) why = "contains '..'";
  else if (name[0] == '.') why = "starts with a dot";
  else if (std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    why = "contains a control character";
  if (!why.empty())
    s.fail(key, "'" + name + "' " + why + "; it becomes part of file names (results, scenes, logs), so it must be one plain "
                "name: no / or \\, no '..', no leading dot, no control characters");
}

}  // namespace

// A mapping of scene key paths to values (`numerics.time_step: 2.0e-6`, `stages[0].rate: 4.0e6`),
// as `dem run --set` takes them. The keys' form is checked here; whether each is a scene key is
// checked when the plan parses the resolved scenes (the engine's parser names what is allowed).
Overrides read_overrides(dem::Section& s, const std::string& key, bool for_test, const std::string& doc) {
  Overrides out;
  if (!s.has(key)) {
    s.optional_child(key, doc);  // declared all the same, so that a misspelt key gets a suggestion
    return out;
  }
  const YAML::Node n = s.raw(key, "mapping of scene key paths to values", doc);
  if (!n.IsMap() || n.size() == 0)
    s.fail(key, "must be a non-empty mapping of scene key paths to values, e.g. {numerics.time_step: 2.0e-6}");
  for (const auto& kv : n) {
    const std::string k = kv.first.IsScalar() ? kv.first.Scalar() : "";
    if (!is_key_path(k))
      s.fail(key, "'" + k + "' is not a scene key path (names of letters, digits and _, each with an optional [index], joined by '.')");
    if (const std::string why = override_key_refusal(k, for_test ? "test" : "prepare", false, false); !why.empty())
      s.fail(key + "." + k, why);
    if (!kv.second || kv.second.IsNull()) s.fail(key + "." + k, "needs a value");
    // A file named in an override is relative to the study file, like every path of a study.
    YAML::Node value = YAML::Clone(kv.second);
    if ((k == "particles.csv" || k == "particles.state") && value.IsScalar()) value = resolve(s.file(), value.Scalar());
    if (k == "particles" && value.IsMap())
      for (const char* f : {"csv", "state"})
        if (value[f] && value[f].IsScalar()) value[f] = resolve(s.file(), value[f].Scalar());
    YAML::Emitter e;
    e << YAML::Flow << value;
    out.emplace_back(k, e.c_str());
  }
  return out;
}

bool is_key_path(const std::string& key) {
  static const std::regex path_re(R"(^[A-Za-z_][A-Za-z0-9_]*(\[[0-9]+\])?(\.[A-Za-z_][A-Za-z0-9_]*(\[[0-9]+\])?)*$)");
  return std::regex_match(key, path_re);
}

namespace {

// Why an override of `key` by `who` may not be given in an ensemble ("" if it may): it sets the
// seed of the diameter sampler, or replaces the mapping that holds it (particles, particles.lattice),
// whose seed the pipeline sets per sample.
std::string sets_ensemble_seed(const std::string& key, const std::string& who) {
  if (key.rfind("particles.lattice.seed", 0) == 0)
    return "the study's seeds choose the samples; " + who + " cannot set the seed of an ensemble";
  if (key == "particles" || key == "particles.lattice")
    return "replaces " + key + ", and with it the seed the study's seeds set for each sample; set the keys inside one by one (e.g. " +
           (key == "particles" ? std::string("particles.grading.basis") : std::string("particles.lattice.spacing")) + ")";
  return "";
}

}  // namespace

std::string override_key_refusal(const std::string& key, const std::string& scope, bool ensemble, bool has_tests) {
  if (!is_key_path(key)) return "is not a scene key path (names of letters, digits and _, each with an optional [index], joined by '.')";
  const bool particles = key.rfind("particles", 0) == 0;
  // The pipeline owns these: run names, and which sample a test starts from.
  if (key == "name" || (scope == "test" && particles)) return "is set by the pipeline; allowed: any other scene key (dem keys lists them)";
  if (scope == "set" && particles && has_tests) return "would change where the tests' particles come from; put it under prepare:";
  if (scope != "test" && ensemble) return sets_ensemble_seed(key, "a variant");
  return "";
}

namespace {

// `key: {name: {scene key: value, ...}, ...}`: test overrides of the study's tests or densities by
// name (`what`: "test" or "density"); a name that is not one of `names` is refused listing them.
std::vector<std::pair<std::string, Overrides>> read_named_overrides(dem::Section& v, const std::string& key, const std::string& what,
                                                                    const std::vector<std::string>& names, const std::string& doc) {
  std::vector<std::pair<std::string, Overrides>> out;
  if (!v.has(key)) {
    v.optional_child(key, doc);
    return out;
  }
  const YAML::Node n = v.raw(key, "a mapping of " + what + " names to scene overrides", doc);
  if (!n.IsMap() || n.size() == 0) v.fail(key, "must be a non-empty mapping of " + what + " names to scene overrides");
  dem::Section per(n, v.file(), v.key_path(key));
  for (const auto& kv : n) {
    const std::string name = kv.first.IsScalar() ? kv.first.Scalar() : "";
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string known;
      for (const std::string& k : names) known += (known.empty() ? "" : ", ") + k;
      v.fail(key + "." + name, "is not a " + what + " of this study (" + (what == "density" ? "densities" : what + "s") + ": " + known + ")");
    }
    out.emplace_back(name, read_overrides(per, name, true, "scene overrides of this " + what + (what == "density" ? "'s tests" : "")));
  }
  per.finish();
  return out;
}

// `seeds: N` (the seeds 1..N) or `seeds: [a, b, ...]` (distinct); the samples of an ensemble.
std::vector<std::int64_t> read_seeds(dem::Section& s, const std::vector<std::int64_t>& def) {
  const std::string doc = "the samples: N (seeds 1..N) or a list of distinct seeds of the diameter sampler";
  if (!s.has("seeds")) {
    s.optional_child("seeds", doc);  // declared all the same, for did-you-mean
    return def;
  }
  const YAML::Node n = s.raw("seeds", "an integer in [1, 1000] or a list of distinct integers >= 0", doc);
  std::vector<std::int64_t> out;
  // Decimal, as every number (dem::parse_decimal_integer): `010` is refused, not octal 8.
  const auto integer = [&](const YAML::Node& e) {
    long long v = 0;
    std::string why;
    if (!e.IsScalar() || !dem::parse_decimal_integer(e.Scalar(), v, why))
      s.fail("seeds", "must be an integer in [1, 1000] or a list of integers >= 0, got " +
                          (e.IsScalar() ? "'" + e.Scalar() + "'" : std::string("a list or mapping")) + (why.empty() ? "" : ": " + why));
    return v;
  };
  try {
    if (n.IsScalar()) {
      const long long count = integer(n);
      if (count < 1 || count > 1000) s.fail("seeds", "must be in [1, 1000], got " + n.Scalar());
      for (long long i = 1; i <= count; ++i) out.push_back(i);
    } else if (n.IsSequence() && n.size() > 0) {
      std::set<std::int64_t> seen;
      for (const YAML::Node& e : n) {
        const long long seed = integer(e);
        if (seed < 0) s.fail("seeds", "seeds must be >= 0, got " + e.Scalar());
        if (!seen.insert(seed).second) s.fail("seeds", "seed " + e.Scalar() + " is listed twice");
        out.push_back(seed);
      }
    } else {
      s.fail("seeds", "must be an integer in [1, 1000] or a non-empty list of seeds");
    }
  } catch (const YAML::Exception&) {
    s.fail("seeds", "must be an integer in [1, 1000] or a list of integers >= 0");
  }
  return out;
}

// Options of sbatch that the pipeline sets itself for each job (or that would change what a job
// is): refused in slurm.sbatch_args, naming the study key that sets them instead.
const std::vector<std::pair<std::vector<std::string>, std::string>>& pipeline_sbatch_options() {
  static const std::vector<std::pair<std::vector<std::string>, std::string>> options = {
      {{"--partition", "-p"}, "slurm.partition"},
      {{"--account", "-A"}, "slurm.account"},
      {{"--time", "-t"}, "slurm.time_factor, time_floor and time_ceiling"},
      {{"--cpus-per-task", "-c"}, "slurm.cpus_per_run"},
      {{"--dependency", "-d", "--kill-on-invalid-dep"}, "the pipeline (a test waits for its sample's job)"},
      {{"--job-name", "-J", "--output", "-o", "--error", "-e", "--open-mode", "--chdir", "-D", "--parsable"},
       "the pipeline (job names, logs and folders are the local executor's)"},
      {{"--array", "-a", "--wrap", "--test-only", "--ntasks", "-n", "--nodes", "-N"}, "the pipeline (one run per job, one task)"},
  };
  return options;
}

// Which of the pipeline's own options `arg` sets, as sbatch reads it ("" if none): sbatch parses
// with getopt_long, which takes any unambiguous prefix of a long option (`--outp=x` is --output)
// and a cluster of short flags (`-vJ name` is -v -J name). A long prefix of an owned option is
// refused even where it is ambiguous (sbatch would refuse it too). Returns "set by <owner>
// (<option>)" to name what was recognised.
std::string pipeline_owned_option(const std::string& arg) {
  if (arg.rfind("--", 0) == 0) {
    const std::string option = arg.substr(0, arg.find('='));
    if (option.size() < 3) return "";
    for (const auto& [names, owner] : pipeline_sbatch_options())
      for (const std::string& name : names)
        if (name.rfind("--", 0) == 0 && name.compare(0, option.size(), option) == 0)
          return "set by " + owner + (option == name ? "" : " (" + option + " abbreviates " + name + ")");
    return "";
  }
  // Short options: the flags that take no value may be followed by more options in one cluster.
  static const std::string flags = "hHkOQsuvVW";
  for (std::size_t i = 1; i < arg.size(); ++i) {
    const std::string option = std::string("-") + arg[i];
    for (const auto& [names, owner] : pipeline_sbatch_options())
      if (std::find(names.begin(), names.end(), option) != names.end())
        return "set by " + owner + (i == 1 ? "" : " (" + option + " in the cluster " + arg + ")");
    if (flags.find(arg[i]) == std::string::npos) break;  // the rest is this option's value
  }
  return "";
}

SlurmOptions read_slurm(dem::Section& root) {
  SlurmOptions o;
  dem::Section s = root.optional_child("slurm", "options of the SLURM executor (pipeline --executor slurm)");
  o.partition = s.text("partition", "", "sbatch --partition (default: the cluster's)");
  o.account = s.text("account", "", "sbatch --account (default: the user's)");
  o.cpus_per_run = static_cast<int>(s.integer("cpus_per_run", 1, 256, 1, "sbatch --cpus-per-task; the run's dem --threads"));
  o.throughput = s.number("throughput", "particle-steps/s", {0, 1e12, true}, 2.5e7,
                          "speed of one run, for the estimated run time behind each job's time limit");
  o.time_factor = s.number("time_factor", "", {1, 1000}, 3, "time limit = this x the estimated run time");
  o.time_floor = s.number("time_floor", "min", {1, 525600}, 10, "the least time limit of a job");
  o.time_ceiling = s.number("time_ceiling", "min", {0, 525600}, 0,
                            "the largest time limit of a job (0: none); a run cut short resumes from its checkpoint");
  if (o.time_ceiling > 0 && o.time_ceiling < o.time_floor)
    s.fail("time_ceiling", "is below time_floor (" + std::to_string(o.time_floor) + " min)");
  o.poll_interval = s.number("poll_interval", "s", {0.2, 3600}, 10, "seconds between two looks at the queue (squeue)");
  if (s.has("sbatch_args")) {
    const YAML::Node n = s.raw("sbatch_args", "a list of sbatch options, e.g. [--qos=normal, --mem=4G]",
                               "further sbatch options of every job");
    if (!n.IsSequence()) s.fail("sbatch_args", "must be a list of sbatch options, e.g. [--qos=normal, --mem=4G]");
    for (const YAML::Node& a : n) {
      const std::string arg = a.IsScalar() ? a.Scalar() : "";
      if (arg.size() < 2 || arg[0] != '-')
        s.fail("sbatch_args", "'" + arg + "' is not an sbatch option (write each as one item, e.g. --mem=4G)");
      if (const std::string owned = pipeline_owned_option(arg); !owned.empty())
        s.fail("sbatch_args", "'" + arg + "' is " + owned + "; allowed: other sbatch options (--qos, --mem, --constraint, --gres, ...)");
      o.sbatch_args.push_back(arg);
    }
  } else {
    s.optional_child("sbatch_args", "further sbatch options of every job");  // declared for did-you-mean
  }
  s.finish();
  return o;
}

}  // namespace

bool SlurmOptions::operator==(const SlurmOptions& o) const {
  return partition == o.partition && account == o.account && cpus_per_run == o.cpus_per_run &&
         throughput == o.throughput && time_factor == o.time_factor && time_floor == o.time_floor &&
         time_ceiling == o.time_ceiling && sbatch_args == o.sbatch_args && poll_interval == o.poll_interval;
}

std::string describe(const Variant& v) {
  std::string out;
  auto add = [&](const std::string& what, const Overrides& o) {
    if (o.empty()) return;
    out += (out.empty() ? "" : "; ") + what;
    for (std::size_t i = 0; i < o.size(); ++i) {
      // Long values (a whole list of stages) would drown the table: the study file has them.
      const std::string& value = o[i].second;
      out += (i ? ", " : "") + o[i].first + " = " + (value.size() > 48 ? value.substr(0, 45) + "..." : value);
    }
  };
  add("", v.set);
  add("preparation: ", v.prepare);
  add("test: ", v.test);
  for (const auto& [test, o] : v.per_test) add(test + ": ", o);
  for (const auto& [density, o] : v.per_density) add(density + " tests: ", o);
  if (v.shear_with_preparation_friction) out += (out.empty() ? "" : "; ") + std::string("shearing friction = the preparation's");
  if (v.time_step_fraction) {
    std::ostringstream f;
    f << *v.time_step_fraction;
    out += (out.empty() ? "" : "; ") + std::string("time step = ") + f.str() + " x critical";
  }
  if (!v.seeds.empty()) out += (out.empty() ? "" : "; ") + std::to_string(v.seeds.size()) + " samples of its own";
  return out.empty() ? "as written" : out;
}

std::string variant_yaml(const Variant& v) {
  const auto overrides = [&](const Overrides& o) {
    YAML::Node n(YAML::NodeType::Map);
    for (const auto& [key, value] : o) n[key] = dem::parse_yaml(value, v.name + ": " + key);
    return n;
  };
  YAML::Node n(YAML::NodeType::Map);
  n["name"] = v.name;
  if (!v.set.empty()) n["set"] = overrides(v.set);
  if (!v.prepare.empty()) n["prepare"] = overrides(v.prepare);
  if (!v.test.empty()) n["test"] = overrides(v.test);
  for (const auto& [test, o] : v.per_test) n["per_test"][test] = overrides(o);
  for (const auto& [density, o] : v.per_density) n["per_density"][density] = overrides(o);
  if (v.shear_with_preparation_friction) n["shear_with_preparation_friction"] = true;
  if (v.time_step_fraction) n["time_step_fraction"] = *v.time_step_fraction;
  if (v.may_fail) n["may_fail"] = true;
  if (!v.seeds.empty()) {
    n["seeds"] = YAML::Node(YAML::NodeType::Sequence);
    for (const std::int64_t s : v.seeds) n["seeds"].push_back(s);
  }
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

void keep_variants(Study& study, const std::vector<std::string>& names) {
  std::string known;
  for (const Variant& v : study.variants) known += (known.empty() ? "" : ", ") + v.name;
  for (const std::string& name : names)
    if (std::none_of(study.variants.begin(), study.variants.end(), [&](const Variant& v) { return v.name == name; }))
      throw dem::ConfigError(study.file + ": --variant " + name + ": the study has no such variant" +
                             (known.empty() ? " (it has no variants)" : " (its variants: " + known + ")"));
  std::erase_if(study.variants, [&](const Variant& v) { return std::find(names.begin(), names.end(), v.name) == names.end(); });
}

const Profile& Study::default_profile() const {
  for (const Profile& p : profiles)
    if (p.name == "paper") return p;
  return profiles.front();  // load_study refuses a study without profiles
}

const Profile& Study::profile(const std::string& wanted) const {
  std::string known;
  for (const Profile& p : profiles) {
    if (p.name == wanted) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw dem::ConfigError(file + ": profiles: no profile '" + wanted + "'; this study declares " + known);
}

Study load_study(const std::string& file) {
  dem::Section root = dem::Section::load_file(file);
  Study st;
  st.file = file;
  st.name = root.text("name", std::nullopt, "study name");
  check_path_name(root, "name", st.name);  // messages and the results' records name the study
  st.output = resolve(file, root.text("output", std::nullopt, "results folder, relative to the study file"));
  st.preparation = resolve(file, root.text("preparation", std::nullopt, "preparation scene template (docs/method.md#preparation)"));
  require_file(root, "preparation", st.preparation);
  st.preparation_set = read_overrides(root, "preparation_set", false, "scene overrides of the preparation in every variant");
  std::set<std::string> names;
  for (dem::Section& d : root.list("densities", "the samples: name and friction during preparation")) {
    Density den;
    den.name = d.text("name", std::nullopt, "sample name (loose, medium, dense); part of file names");
    check_path_name(d, "name", den.name);
    den.friction = d.number("friction", "", {0, 10}, std::nullopt, "mu during isotropic compression");
    d.finish();
    if (!names.insert(den.name).second) d.fail("name", "duplicate name '" + den.name + "'");
    st.densities.push_back(den);
  }
  // A study of variants may have no tests: each variant is then its preparation run alone.
  const bool has_variants = root.has("variants");
  std::vector<dem::Section> tests;
  if (!has_variants || root.has("tests")) tests = root.list("tests", "the cyclic tests: name and scene file");
  for (dem::Section& t : tests) {
    TestCase tc;
    tc.name = t.text("name", std::nullopt, "test name; part of file names");
    check_path_name(t, "name", tc.name);
    tc.scene = resolve(file, t.text("scene", std::nullopt, "scene file of the test, relative to the study file"));
    require_file(t, "scene", tc.scene);
    tc.set = read_overrides(t, "set", true, "scene overrides of this test in every variant");
    t.finish();
    if (!names.insert(tc.name).second) t.fail("name", "duplicate name '" + tc.name + "'");
    st.tests.push_back(tc);
  }
  const std::vector<std::int64_t> seeds = read_seeds(root, {});
  // Profiles: any names, as many as the study needs (pipeline --profile NAME picks one).
  const YAML::Node profile_node = root.raw("profiles", "a mapping of profile names to {lattice, cycles or max_repeat, seeds}",
                                           "named sizes of the study, any names (paper, quick, small, ...)");
  if (!profile_node.IsMap() || profile_node.size() == 0)
    root.fail("profiles", "must be a non-empty mapping of profile names to {lattice, cycles or max_repeat, seeds}");
  dem::Section profiles(profile_node, file, "profiles");
  static const std::regex profile_re("^[A-Za-z0-9_-]+$");  // the results folder <output>/<profile>
  for (const auto& kv : profile_node) {
    const std::string name = kv.first.IsScalar() ? kv.first.Scalar() : "";
    if (!std::regex_match(name, profile_re))
      profiles.fail(name, "a profile name must be letters, digits, _ and - (it names the results folder)");
    dem::Section p = profiles.child(name, "a profile");
    Profile pr;
    pr.name = name;
    pr.lattice = static_cast<int>(p.integer("lattice", 2, 100, 20, "lattice sites per axis of the preparation"));
    pr.max_repeat = static_cast<int>(p.integer("max_repeat", 0, 1000000, 0,
        "cap on each repeat block's cycles (0: none); Test 1 has two blocks, so max_repeat: 1 runs 2 cycles"));
    pr.cycles = static_cast<int>(p.integer("cycles", 0, 1000000, 0,
        "cycles of each test in all (0: every cycle): the repeat blocks in order keep what is left, later ones are dropped"));
    if (pr.max_repeat > 0 && pr.cycles > 0)
      p.fail("cycles", "give either cycles (cycles in all) or max_repeat (a cap per repeat block), not both");
    pr.seeds = read_seeds(p, seeds);
    p.finish();
    st.profiles.push_back(pr);
  }
  profiles.finish();
  // An ensemble: each sample's seed is set by the pipeline, and nothing else may set it (every
  // sample would be the same one, judged by validate as independent samples that agree).
  const bool ensemble = !seeds.empty() || std::any_of(st.profiles.begin(), st.profiles.end(),
                                                     [](const Profile& p) { return !p.seeds.empty(); });
  if (ensemble)
    for (const auto& kv : st.preparation_set)
      if (const std::string why = sets_ensemble_seed(kv.first, "preparation_set"); !why.empty())
        root.fail("preparation_set." + kv.first, why);
  const bool may_fail = root.boolean("may_fail", false, "default of the variants' may_fail");
  if (has_variants) {
    std::set<std::string> variant_names;
    static const std::regex name_re("^[A-Za-z0-9_-]+$");  // part of file names
    for (dem::Section& v : root.list("variants", "settings of the study, each a set of scene overrides")) {
      Variant var;
      var.name = v.text("name", std::nullopt, "variant name (letters, digits, _ and -; part of the run names)");
      check_path_name(v, "name", var.name);
      if (!std::regex_match(var.name, name_re)) v.fail("name", "must be letters, digits, _ and -, got '" + var.name + "'");
      if (!variant_names.insert(var.name).second) v.fail("name", "duplicate name '" + var.name + "'");
      var.set = read_overrides(v, "set", false, "scene overrides of the preparation and the tests");
      var.prepare = read_overrides(v, "prepare", false, "scene overrides of the preparation");
      var.test = read_overrides(v, "test", true, "scene overrides of the tests");
      std::vector<std::string> test_names, density_names;
      for (const TestCase& t : st.tests) test_names.push_back(t.name);
      for (const Density& d : st.densities) density_names.push_back(d.name);
      var.per_test = read_named_overrides(v, "per_test", "test", test_names,
                                          "scene overrides of single tests, by test name (e.g. {test3: {stages[0].path: [...]}})");
      var.per_density = read_named_overrides(v, "per_density", "density", density_names,
                                             "scene overrides of one density's tests, by density name (e.g. {dense: {material.friction: 0.0}})");
      if (!var.per_density.empty() && st.tests.empty()) v.fail("per_density", "sets the tests of a density; this study has no tests");
      var.shear_with_preparation_friction =
          v.boolean("shear_with_preparation_friction", false,
                    "the tests shear with the density's preparation friction instead of their scenes' material.friction");
      if (var.shear_with_preparation_friction && st.tests.empty())
        v.fail("shear_with_preparation_friction", "needs tests to shear (this study has none)");
      for (const Overrides* o : {&var.set, &var.prepare}) {
        const std::string scope = o == &var.set ? "set" : "prepare";
        for (const auto& kv : *o)
          if (const std::string why = override_key_refusal(kv.first, scope, ensemble, !st.tests.empty()); !why.empty())
            v.fail(scope + "." + kv.first, why);
      }
      if (v.has("time_step_fraction")) {
        var.time_step_fraction = v.number("time_step_fraction", "", {0, 10, true}, std::nullopt,
                                          "numerics.time_step as a fraction of the sample's critical step 2 sqrt(m_min/kn)");
        for (const Overrides* o : {&var.set, &var.prepare, &var.test})
          for (const auto& kv : *o)
            if (kv.first == "numerics.time_step")
              v.fail("time_step_fraction", "and numerics.time_step both set the time step; keep one");
      }
      var.may_fail = v.boolean("may_fail", may_fail, "a run that stops with a message is an outcome, not a failure");
      var.seeds = read_seeds(v, {});
      if (!var.seeds.empty() && !ensemble)
        v.fail("seeds", "gives this variant its own samples in place of the profile's; the study has no seeds (an ensemble) to replace");
      v.finish();
      st.variants.push_back(var);
    }
  }
  // Where the runs are computed: not part of any input hash (the plan never reads these).
  if (root.has("executor"))
    st.executor = root.choice("executor", {"local", "slurm"}, std::nullopt, "where the runs are computed (pipeline --executor wins)");
  else
    root.choice("executor", {"local", "slurm"}, "local", "where the runs are computed (pipeline --executor wins)");
  st.slurm = read_slurm(root);
  root.finish();
  return st;
}

}  // namespace pipeline
