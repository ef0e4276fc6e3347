#include "plan/run_plan.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "contact/contact_law.hpp"
#include "control/stress_path.hpp"
#include "dynamics/simulation.hpp"
#include "generate/grading.hpp"
#include "io/atomic_file.hpp"
#include "io/particle_csv.hpp"
#include "io/state_io.hpp"
#include "plan/runs_manifest.hpp"

namespace pipeline {

namespace fs = std::filesystem;

namespace {

// Caps every repeat block of every stress-path stage at `max_repeat` repetitions.
void cap_repeats(YAML::Node scene, int max_repeat) {
  if (max_repeat <= 0 || !scene["stages"] || !scene["stages"].IsSequence()) return;
  for (YAML::Node stage : scene["stages"]) {
    if (!stage["path"] || !stage["path"].IsSequence()) continue;
    for (YAML::Node item : stage["path"]) {
      long long n = 0;
      std::string why;  // read as the engine reads it; a count it refuses is left for it to refuse
      if (item.IsMap() && item["repeat"] && item["repeat"].IsScalar() && dem::parse_decimal_integer(item["repeat"].Scalar(), n, why) &&
          n > max_repeat)
        item["repeat"] = max_repeat;
    }
  }
}

// Keeps at most `cycles` cycles of every stress-path stage: its repeat blocks in order keep what
// is left of the budget, and the blocks after it is spent are dropped (legs outside blocks, such
// as Test 1's first A->TC1, stay: they are cycle 0). Test 1 (5 + 5 cycles) at cycles 1 runs one.
void cap_cycles(YAML::Node scene, int cycles) {
  if (cycles <= 0 || !scene["stages"] || !scene["stages"].IsSequence()) return;
  for (YAML::Node stage : scene["stages"]) {
    if (!stage["path"] || !stage["path"].IsSequence()) continue;
    long long left = cycles;
    YAML::Node kept(YAML::NodeType::Sequence);
    for (YAML::Node item : stage["path"]) {
      long long n = 0;
      std::string why;  // read as the engine reads it; a count it refuses is left for it to refuse
      if (item.IsMap() && item["repeat"] && item["repeat"].IsScalar() && dem::parse_decimal_integer(item["repeat"].Scalar(), n, why)) {
        if (left <= 0) continue;
        if (n > left) item["repeat"] = left;
        left -= std::min(n, left);
      }
      kept.push_back(item);
    }
    stage["path"] = kept;
  }
}

std::string emit(const YAML::Node& n, const std::string& header) {
  YAML::Emitter out;
  out << n;
  return header + out.c_str() + "\n";
}

// What a resolved scene computes: the scene without its header comment and with an empty name.
// Two runs with the same text here give the same result bit for bit.
std::string unnamed(const YAML::Node& scene) {
  YAML::Node copy = YAML::Clone(scene);
  copy["name"] = "";
  return emit(copy, "");
}

// What a test computes, given the sample it starts from: its unnamed scene without the path of that
// sample (the sample enters the input hash by its own hash). So a study copied, renamed or written
// to another folder reuses the runs it shares with the original.
std::string computed_text(const YAML::Node& test) {
  YAML::Node copy = YAML::Clone(test);
  if (copy["particles"] && copy["particles"].IsMap() && copy["particles"]["state"]) copy["particles"]["state"] = "";
  return unnamed(copy);
}

// A control stage runs for its duration, or until a strain-rate controlled component reaches its
// `until.strain` (the other stop criteria cannot be foreseen: their duration is the bound).
double control_duration(const dem::StageConfig& st) {
  if (st.until.strain > 0 && st.until.component >= 0) {
    const dem::AxisTarget& c = st.control.component[static_cast<std::size_t>(st.until.component)];
    if (c.mode == dem::AxisTarget::Mode::StrainRate && c.strain_rate_per_s != 0)
      return std::min(st.duration_s, st.until.strain / std::abs(c.strain_rate_per_s));
  }
  return st.duration_s;
}

// The spheres of a lattice preparation and its cell before the first step.
struct LatticeStart {
  dem::Particles particles;
  dem::PeriodicCell cell;
};
LatticeStart lattice_start(const dem::SceneConfig& scene) {
  if (scene.particles.kind != dem::ParticleSource::Kind::Lattice)
    throw dem::ConfigError(scene.file + ": time_step_fraction needs a preparation from particles.lattice");
  LatticeStart s;
  const dem::ParticleSource& src = scene.particles;
  dem::make_lattice(src.lattice, dem::GradingCurve(src.grading_diameters_m, src.grading_percent_finer, src.grading_basis),
                    scene.material.density_kg_per_m3, s.particles, s.cell);
  return s;
}

// The solid fraction a lattice preparation starts from (a gas: the spheres' volume over the
// cell's); none for a start from a file (a sample already packed).
std::optional<double> gas_solid_fraction(const dem::SceneConfig& scene) {
  if (scene.particles.kind != dem::ParticleSource::Kind::Lattice) return std::nullopt;
  const LatticeStart s = lattice_start(scene);
  double solid = 0;
  for (const double r : s.particles.radius) solid += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return solid / s.cell.volume();
}

// A stress stage ends on its hold criteria, so its length is a model's. From a gas (a lattice
// preparation's first stage) the servo squeezes the cell at the stage's max_strain_rate until the
// spheres jam, taken at a solid fraction of jammed_fraction: ln(phi_jam / phi_0) / 3 of strain on
// each axis. From a packed sample the stress ramps from none at the stage's rate (an upper bound).
// Either way the hold follows, until the unbalanced force ratio has fallen (and, with a creep
// criterion, two creep windows at least). The hold's seconds at 1,000 spheres are measured (by
// friction, hold_seconds); the unbalance has to leave through the sample, so they grow with its edge
// in spheres, N^(1/3). Bounded by the stage's max_duration.
constexpr double jammed_fraction = 0.60;
double hold_seconds(double friction, double spheres) {
  // Measured: the shipped samples (scenes/samples/*_1k.h5, the quick profile's seed-1 preparations,
  // 1,000 spheres from phi_0 = 0.2271, squeezed to jammed_fraction in 0.3238 s), their steps less
  // that squeeze: 679,600 (dense, mu = 0), 363,400 (medium, 0.2) and 333,000 (loose, 0.5) at 1 us.
  constexpr double mu[] = {0.0, 0.2, 0.5}, seconds[] = {0.356, 0.040, 0.009};
  double at_1k = seconds[2];
  if (friction < mu[2]) {
    const int k = friction < mu[1] ? 0 : 1;
    at_1k = seconds[k] + (seconds[k + 1] - seconds[k]) * (std::max(friction, 0.0) - mu[k]) / (mu[k + 1] - mu[k]);
  }
  return at_1k * std::cbrt(spheres / 1000.0);
}
double stress_stage_seconds(const dem::SceneConfig& scene, const dem::StageConfig& st, std::optional<double> gas,
                            double spheres) {
  const double ramp = st.target_Pa.cwiseAbs().maxCoeff() / st.stress_rate_Pa_per_s;
  double squeeze = 0;
  if (gas && *gas < jammed_fraction && st.max_strain_rate_per_s > 0)
    squeeze = std::log(jammed_fraction / *gas) / (3 * st.max_strain_rate_per_s);
  double hold = hold_seconds(dem::friction_coefficient(scene.material.law), spheres);
  if (st.hold.creep_rate_per_s > 0) hold = std::max(hold, 2 * st.hold.creep_window_s);
  return std::min(std::max(ramp, squeeze) + hold, st.hold.max_duration_s);
}

double estimated_steps(const dem::SceneConfig& scene, double spheres) {
  double steps = 0;
  const std::optional<double> gas = gas_solid_fraction(scene);
  for (const dem::StageConfig& st : scene.stages) {
    const bool first = &st == &scene.stages.front();
    if (st.type == dem::StageConfig::Type::StrainRate) steps += st.duration_s / scene.time_step_s;
    else if (st.type == dem::StageConfig::Type::Stress)
      steps += stress_stage_seconds(scene, st, first ? gas : std::nullopt, spheres) / scene.time_step_s;
    else if (st.type == dem::StageConfig::Type::Control) steps += control_duration(st) / scene.time_step_s;
    else
      for (const dem::PathLeg& leg : dem::expand_path(st.path, dem::named_state("A", st.mean_stress_Pa, st.stress_ratio),
                                                      st.stress_rate_Pa_per_s))
        steps += leg.duration_s / scene.time_step_s;
  }
  return steps;
}

// 17 significant digits: the time step read back is the same double, so a fraction of exactly
// max_time_step_fraction is accepted by the engine's check rather than refused by round-off.
std::string exact(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// Errors in scenes with a study's overrides name where the overrides are written (`where`, e.g.
// "study.yaml: variants[2] (dt2)", or a calibration's set: Variant::origin), then the engine's
// message (which names the scene key and what is allowed). Without overrides (`where` empty) the
// engine's message stands alone.
template <class F>
auto in_context(const std::string& where, F&& f) {
  if (where.empty()) return f();
  try {
    return f();
  } catch (const dem::ConfigError& e) {
    throw dem::ConfigError(where + ": " + e.what());
  }
}

// The bytes of the files a preparation reads (a particle CSV or a saved state), by content: an
// edited file changes the input hash, so its result is not reused. "" when it reads none (the
// lattice), so the hashes of such runs are what they were before files were hashed.
std::string read_files(const dem::SceneConfig& scene) {
  if (scene.particles.kind == dem::ParticleSource::Kind::Lattice) return "";
  // Read here for the hash and again by dem: a FIFO or device would give its bytes to one of them.
  std::error_code ec;
  if (fs::exists(scene.particles.path, ec) && !fs::is_regular_file(scene.particles.path, ec))
    throw dem::ConfigError(scene.file + ": particles: " + scene.particles.path +
                           " is not a regular file (a FIFO, device or folder): the pipeline reads it for the input hash and "
                           "dem reads it again; give a regular file");
  std::ifstream in(scene.particles.path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  if (!in) throw dem::ConfigError(scene.file + ": particles: cannot read " + scene.particles.path);
  return "\nreads " + scene.particles.path + " " + content_hash(bytes.str());
}

// The number of spheres a preparation starts from: the lattice's sites, the CSV file's rows or the
// saved state's spheres (for the cost estimate; the files are read again by dem).
double particles_of(const dem::SceneConfig& scene) {
  const dem::ParticleSource& src = scene.particles;
  if (src.kind == dem::ParticleSource::Kind::Lattice) return static_cast<double>(src.lattice.n[0]) * src.lattice.n[1] * src.lattice.n[2];
  if (src.kind == dem::ParticleSource::Kind::State) return static_cast<double>(dem::read_state(src.path).particles.size());
  dem::Particles p;
  dem::parse_particle_csv(dem::read_whole_file(src.path), src.path, dem::PeriodicCell(src.cell_m), scene.material.density_kg_per_m3, p);
  return static_cast<double>(p.size());
}

// An ensemble: every run once per seed, in <out_dir>/seed<N>/, on that seed's own sample.
struct Sample {
  std::optional<std::int64_t> seed;
  std::string folder;  // "" or "seed<N>/"
};

// The profile's seeds, then those only some variants run (a variant's own seeds replace the
// profile's); one sample without a seed when there are none.
std::vector<Sample> ensemble_samples(const Study& study, const Profile& profile, const std::vector<Variant>& variants) {
  std::vector<Sample> samples;
  std::vector<std::int64_t> seeds = profile.seeds;
  for (const Variant& v : variants)
    for (const std::int64_t s : v.seeds)
      if (std::find(seeds.begin(), seeds.end(), s) == seeds.end()) seeds.push_back(s);
  for (const Variant& v : variants)
    if (!v.seeds.empty() && profile.seeds.empty())
      throw dem::ConfigError(study.file + ": variants (" + v.name + "): seeds: the profile " + profile.name +
                             " runs the template's one sample (no seeds), so there are no samples for a variant's own to replace");
  for (const std::int64_t s : seeds) samples.push_back({s, "seed" + std::to_string(s) + "/"});
  if (samples.empty()) samples.push_back({});
  return samples;
}

// A test's scene as the study runs it: its name, the preparation's result it starts from, then the
// test's, the variant's and the variant's per-test and per-density overrides, the shearing
// friction if the variant takes the preparation's, and the profile's caps on repeats and cycles.
void apply_test_overrides(YAML::Node& ts, const TestCase& t, const Variant& v, const Density& d, const Profile& profile,
                          const std::string& name, const std::string& start_from) {
  dem::apply_override(ts, t.scene, "name", name);
  dem::apply_override(ts, t.scene, "particles", "{state: " + fs::absolute(start_from).string() + "}");
  for (const auto& [key, value] : t.set) dem::apply_override(ts, t.scene, key, value);
  for (const auto& [key, value] : v.set) dem::apply_override(ts, t.scene, key, value);
  for (const auto& [key, value] : v.test) dem::apply_override(ts, t.scene, key, value);
  for (const auto& [test, overrides] : v.per_test)
    if (test == t.name)
      for (const auto& [key, value] : overrides) dem::apply_override(ts, t.scene, key, value);
  for (const auto& [density, overrides] : v.per_density)
    if (density == d.name)
      for (const auto& [key, value] : overrides) dem::apply_override(ts, t.scene, key, value);
  if (v.shear_with_preparation_friction) {
    std::ostringstream mu;
    mu << d.friction;
    dem::apply_override(ts, t.scene, "material.friction", mu.str());
  }
  cap_repeats(ts, profile.max_repeat);
  cap_cycles(ts, profile.cycles);
}

}  // namespace

std::vector<PlannedRun> plan_study(const Study& study, const Profile& profile, const std::string& out_dir,
                                   const std::string& engine_version) {
  std::vector<PlannedRun> runs;
  const std::string header = "# Resolved by the pipeline from " + study.file + " (profile " + profile.name +
                             "); do not edit, edit the study or its scenes.\n";
  // A study without variants is one unnamed variant with no overrides: the paper study's runs,
  // names and hashes are those of a pipeline without variants.
  const std::vector<Variant> variants = study.variants.empty() ? std::vector<Variant>{Variant{}} : study.variants;
  const bool named = !study.variants.empty();
  std::map<std::string, int> preparations;  // resolved preparation (without its name) -> run index
  std::map<int, double> particles;          // preparation run index -> its number of spheres
  const std::vector<Sample> samples = ensemble_samples(study, profile, variants);
  const auto runs_on = [&](const Variant& v, const Sample& sample) {
    const std::vector<std::int64_t>& own = v.seeds.empty() ? profile.seeds : v.seeds;
    return !sample.seed || std::find(own.begin(), own.end(), *sample.seed) != own.end();
  };
  auto paths = [&](PlannedRun& r) {
    r.scene_file = (fs::path(out_dir) / "scenes" / (r.name + ".yaml")).string();
    r.result = (fs::path(out_dir) / (r.name + ".h5")).string();
    r.log = (fs::path(out_dir) / "logs" / (r.name + ".log")).string();
  };
  // A plan of very many runs (each scene resolved and checked) takes a while: progress on stderr,
  // at most every 2 s, so that it is not taken for a hang.
  const auto started = std::chrono::steady_clock::now();
  auto said = started;
  std::size_t sample_no = 0;
  for (const Sample& sample_of : samples)
  for (std::size_t vi = 0; vi < variants.size(); ++vi) {
    if (vi == 0) ++sample_no;
    if (const auto now = std::chrono::steady_clock::now(); now - said > std::chrono::seconds(2)) {
      said = now;
      std::fprintf(stderr, "[pipeline] planning study '%s': %zu runs so far, sample %zu of %zu (%.0f s)\n", study.name.c_str(),
                   runs.size(), sample_no, samples.size(), std::chrono::duration<double>(now - started).count());
    }
    const Variant& v = variants[vi];
    if (!runs_on(v, sample_of)) continue;
    const std::string where = !named ? "" : !v.origin.empty() ? v.origin : study.file + ": variants[" + std::to_string(vi) + "] (" + v.name + ")";
    const std::string prefix = sample_of.folder + (named ? v.name + "_" : "");
    for (const Density& d : study.densities) {
      PlannedRun prep;
      // A study of cases (variants, one sample, no tests): each run is its case.
      const bool case_only = named && study.tests.empty() && study.densities.size() == 1;
      prep.name = case_only ? sample_of.folder + v.name : prefix + d.name + "_prepare";
      prep.seed = sample_of.seed;
      prep.density = d.name;
      prep.may_fail = v.may_fail;
      paths(prep);
      YAML::Node scene = dem::load_yaml(study.preparation);
      const std::string n = std::to_string(profile.lattice);
      // A preparation from particles.csv or particles.state starts from its file's spheres: the
      // profile's lattice does not apply, and there is no sampler for a seed to change.
      const bool from_lattice = scene["particles"] && scene["particles"]["lattice"];
      // The resolved scene is written elsewhere: a file it reads is named from the template's folder.
      for (const char* key : {"csv", "state"})
        if (scene["particles"] && scene["particles"][key] && scene["particles"][key].IsScalar()) {
          const fs::path file = scene["particles"][key].as<std::string>();
          if (file.is_relative())
            scene["particles"][key] = (fs::absolute(study.preparation).parent_path() / file).lexically_normal().string();
        }
      if (!from_lattice && sample_of.seed)
        throw dem::ConfigError(study.file + ": profiles." + profile.name + ".seeds: the preparation " + study.preparation +
                               " reads its spheres from a file (particles.csv or particles.state), which no seed changes; "
                               "give seeds only with a particles.lattice preparation");
      dem::Particles sample;  // only for time_step_fraction
      in_context(where, [&] {
        dem::apply_override(scene, study.preparation, "name", prep.name);
        std::ostringstream mu;
        mu << d.friction;
        dem::apply_override(scene, study.preparation, "material.friction", mu.str());
        if (from_lattice)
          dem::apply_override(scene, study.preparation, "particles.lattice.n", "[" + n + ", " + n + ", " + n + "]");
        if (sample_of.seed)
          dem::apply_override(scene, study.preparation, "particles.lattice.seed", std::to_string(*sample_of.seed));
        for (const auto& [key, value] : study.preparation_set) dem::apply_override(scene, study.preparation, key, value);
        for (const auto& [key, value] : v.set) dem::apply_override(scene, study.preparation, key, value);
        for (const auto& [key, value] : v.prepare) dem::apply_override(scene, study.preparation, key, value);
        if (v.time_step_fraction) {
          const dem::SceneConfig parsed = dem::scene_from_text(emit(scene, header), prep.scene_file);
          sample = lattice_start(parsed).particles;
          const double dt = *v.time_step_fraction * dem::critical_time_step(parsed.material.law, sample, parsed.material.density_kg_per_m3);
          dem::apply_override(scene, study.preparation, "numerics.time_step", exact(dt));
        }
        return 0;
      });
      // Variants that change only the tests share one preparation: same scene but for its name.
      const std::string unnamed_text = unnamed(scene);
      int prep_index = -1;
      if (const auto it = preparations.find(unnamed_text); it != preparations.end()) {
        prep_index = it->second;
        runs[static_cast<std::size_t>(prep_index)].variants.push_back(v.name);
        runs[static_cast<std::size_t>(prep_index)].may_fail &= v.may_fail;
      } else {
        prep.scene_text = emit(scene, header);
        const dem::SceneConfig parsed =
            in_context(where, [&] { return dem::scene_from_text(prep.scene_text, prep.scene_file); });
        prep.hash = content_hash(engine_version + "\n" + unnamed_text + read_files(parsed));
        prep_index = static_cast<int>(runs.size());
        particles[prep_index] = particles_of(parsed);
        prep.spheres = particles[prep_index];
        prep.cost = prep.spheres * estimated_steps(parsed, prep.spheres);
        prep.family = d.name + " " + study.preparation;
        prep.variants = {v.name};
        preparations[unnamed_text] = prep_index;
        runs.push_back(prep);
      }
      const PlannedRun from = runs[static_cast<std::size_t>(prep_index)];  // a copy: runs grows below

      for (std::size_t ti = 0; ti < study.tests.size(); ++ti) {
        const TestCase& t = study.tests[ti];
        const std::string test_where =
            !where.empty() ? where : t.set.empty() ? "" : study.file + ": tests[" + std::to_string(ti) + "] (" + t.name + ")";
        PlannedRun run;
        run.name = prefix + d.name + "_" + t.name;
        run.density = d.name;
        run.test = t.name;
        run.seed = sample_of.seed;
        run.variants = {v.name};
        run.may_fail = v.may_fail;
        paths(run);
        YAML::Node ts = dem::load_yaml(t.scene);
        in_context(test_where, [&] {
          apply_test_overrides(ts, t, v, d, profile, run.name, from.result);
          if (v.time_step_fraction) {  // the test's spheres are the sample's; its kn may differ
            const dem::SceneConfig parsed = dem::scene_from_text(emit(ts, header), run.scene_file);
            const double dt = *v.time_step_fraction * dem::critical_time_step(parsed.material.law, sample, parsed.material.density_kg_per_m3);
            dem::apply_override(ts, t.scene, "numerics.time_step", exact(dt));
          }
          return 0;
        });
        run.scene_text = emit(ts, header);
        const dem::SceneConfig tp = in_context(test_where, [&] { return dem::scene_from_text(run.scene_text, run.scene_file); });
        run.hash = content_hash(engine_version + "\n" + computed_text(ts) + "\nfrom " + from.hash);
        run.depends_on = prep_index;
        run.spheres = particles[prep_index];
        run.cost = run.spheres * estimated_steps(tp, run.spheres);
        run.family = d.name + " " + t.scene;
        runs.push_back(run);
      }
    }
  }
  return runs;
}

std::vector<PlannedRun> join_studies(const std::vector<StudyPlan>& plans) {
  std::vector<PlannedRun> runs;
  std::map<std::string, std::string> writer;  // result file -> run
  std::map<std::string, int> computed;        // unnamed scene -> the first run that computes it
  for (const StudyPlan& plan : plans) {
    const int offset = static_cast<int>(runs.size());
    for (PlannedRun r : plan.runs) {
      if (r.depends_on >= 0) r.depends_on += offset;
      if (plans.size() > 1) r.name = plan.name + "/" + r.name;
      const auto [it, added] = writer.emplace(r.result, r.name);
      if (!added)
        throw std::runtime_error("runs " + it->second + " and " + r.name + " would both write " + r.result +
                                 ": give each study once, each with its own output folder");
      if (!r.may_fail) {
        const int index = static_cast<int>(runs.size());
        const auto [first, is_new] = computed.emplace(unnamed(dem::parse_yaml(r.scene_text, r.scene_file)), index);
        if (!is_new) r.copy_of = r.depends_on = first->second, r.cost = 0;
      }
      runs.push_back(std::move(r));
    }
  }
  return runs;
}

void write_scenes(const std::vector<PlannedRun>& runs) {
  for (const PlannedRun& r : runs) {
    fs::create_directories(fs::path(r.scene_file).parent_path());
    fs::create_directories(fs::path(r.log).parent_path());
    fs::create_directories(fs::path(r.result).parent_path());  // seed<N>/ of an ensemble
    std::ifstream in(r.scene_file);
    std::stringstream old;
    old << in.rdbuf();
    if (in && old.str() == r.scene_text) continue;
    std::ofstream out(r.scene_file);
    out << r.scene_text;
    if (!out) throw std::runtime_error(r.scene_file + ": cannot be written");
  }
}

void write_manifest(const std::vector<PlannedRun>& runs, const Study& study, const std::string& out_dir,
                    const std::string& engine_version) {
  fs::create_directories(out_dir);
  std::map<std::string, std::string> settings;
  for (const Variant& v : study.variants) settings[v.name] = describe(v);
  RunsManifest manifest;
  manifest.engine_source = engine_version;
  // Grouped by variant in the study's order (the order of the report's tables).
  std::vector<std::string> order;
  for (const Variant& v : study.variants) order.push_back(v.name);
  if (order.empty()) order.push_back("");
  for (const std::string& v : order)
    for (const PlannedRun& r : runs)
      if (std::find(r.variants.begin(), r.variants.end(), v) != r.variants.end())
        manifest.entries.push_back({v.empty() ? "-" : v, r.density, r.test.empty() ? "-" : r.test, r.name, r.result,
                                    r.depends_on >= 0 ? runs[static_cast<std::size_t>(r.depends_on)].name : std::string("-"), r.may_fail,
                                    settings.count(v) ? settings[v] : "as written", r.seed ? std::to_string(*r.seed) : std::string("-"), r.hash});
  // A reader never sees half a manifest.
  dem::write_file_atomically((fs::path(out_dir) / "runs.tsv").string(), manifest_text(manifest));
}

}  // namespace pipeline
