#pragma once
// A study: every density x test combination of the paper, read from YAML into typed structs; a
// study may also list variants (convergence, stability), each a set of scene overrides, and
// seeds: an ensemble of samples, every density x test x variant run on each seed's own sample.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace dem {
class Section;
}

namespace pipeline {

// Scene overrides, (key path, YAML value) in the order written: what `dem run --set` takes.
using Overrides = std::vector<std::pair<std::string, std::string>>;

// `key:` of `s`, a mapping of scene key paths to values, as Overrides (each value as flow YAML);
// the keys' form checked, and with `for_test` the keys the pipeline sets in a test refused. Absent:
// none (the key declared, so that a misspelt one gets a suggestion).
Overrides read_overrides(dem::Section& s, const std::string& key, bool for_test, const std::string& doc);

// Whether `key` has the form of a scene key path (names of letters, digits and _, each with an
// optional [index], joined by '.').
bool is_key_path(const std::string& key);

// Why an override may not set `key`, "" if it may: the rules of a study's overrides in one place,
// which read_overrides, the study's variants and calibrate's parameters (each set a variant) apply.
// `scope`: "set" (the preparation and the tests), "prepare" or "test"; `ensemble`: the study has
// seeds (a variant cannot set the seed then); `has_tests`: the study has tests (a variant's set:
// cannot change their particles then).
std::string override_key_refusal(const std::string& key, const std::string& scope, bool ensemble, bool has_tests);

struct Density {
  std::string name;    // loose, medium, dense
  double friction = 0; // mu during isotropic compression
};

struct TestCase {
  std::string name;   // test1 ... test5
  std::string scene;  // scene file (absolute path)
  Overrides set;      // applied to this test's scene in every variant
};

// One setting of a study: the preparation and the tests with these overrides applied after the
// profile's. A variant with no preparation overrides shares the preparation of the variant before
// it with the same resolved preparation (the plan merges identical preparations).
struct Variant {
  std::string name;
  Overrides set;            // applied to the preparation and the tests
  Overrides prepare, test;  // then these, to the preparation only / the tests only
  std::vector<std::pair<std::string, Overrides>> per_test;  // then these, to the named test only
  std::vector<std::pair<std::string, Overrides>> per_density;  // then these, to the named density's tests only
  bool shear_with_preparation_friction = false;  // the tests' material.friction = the density's preparation friction
  std::optional<double> time_step_fraction;  // numerics.time_step = this x the sample's critical step
  bool may_fail = false;    // a run that stops with a message is an outcome, not a study failure
  // Its own samples (study key seeds, same forms) in place of the profile's: e.g. many small
  // samples beside a few large ones. Empty: the profile's. Only in an ensemble.
  std::vector<std::int64_t> seeds;
  // Where the variant comes from, for messages about its scenes: "" for the study's own
  // (`<study file>: variants[N] (name)`); a calibration names its file and the set.
  std::string origin;
};

struct Profile {
  std::string name;
  int lattice = 20;     // lattice sites per axis of the preparation (20 -> 8,000 spheres)
  int max_repeat = 0;   // > 0: each repeat block of a test runs at most this many cycles
  int cycles = 0;       // > 0: each test (each stress-path stage) runs at most this many cycles in all
  std::vector<std::int64_t> seeds;  // the samples (seeds of the diameter sampler); empty: the template's one sample
};

// How the SLURM executor submits this study's runs (study key `slurm:`; pipeline/README.md). None of
// it is part of any input hash: where a run is computed does not change its result.
struct SlurmOptions {
  std::string partition;    // sbatch --partition (empty: the cluster's default)
  std::string account;      // sbatch --account (empty: the user's default)
  int cpus_per_run = 1;     // sbatch --cpus-per-task, and the run's dem --threads
  // Each job's time limit: time_factor x the run's estimated particle-steps / throughput, at least
  // time_floor minutes and, if time_ceiling > 0, at most time_ceiling minutes (a run cut short by
  // its limit resumes from its checkpoint when the pipeline is started again).
  double throughput = 2.5e7;  // particle-steps per second of one run
  double time_factor = 3;
  double time_floor = 10;     // minutes
  double time_ceiling = 0;    // minutes; 0: none
  std::vector<std::string> sbatch_args;  // further sbatch options, e.g. --qos=normal, --mem=4G
  double poll_interval = 10;  // seconds between two looks at the queue (squeue)
  bool operator==(const SlurmOptions& o) const;
};

struct Study {
  std::string file;         // the study YAML
  std::string name;
  std::string output;       // results folder (absolute)
  std::string preparation;  // preparation scene template (absolute); friction set per density
  Overrides preparation_set;  // overrides of the preparation in every variant (before the variant's)
  std::vector<Density> densities;
  std::vector<TestCase> tests;      // may be empty when the study has variants (preparations only)
  std::vector<Profile> profiles;
  std::vector<Variant> variants;    // empty: the paper study's form, runs named <density>_<test>
  std::optional<std::string> executor;  // "local" or "slurm" if the study names one (pipeline --executor wins)
  SlurmOptions slurm;
  const Profile& profile(const std::string& name) const;  // throws naming the declared profiles
  const Profile& default_profile() const;  // `paper` if declared, else the first declared
};

// The variant's settings in one line (the tables of the report name variants by them).
std::string describe(const Variant& v);

// The variant as a study file writes it under variants: (one flow mapping), so that a variant made
// by a program (a calibration's set) can be pasted into a study and read back the same.
std::string variant_yaml(const Variant& v);

// Reads and validates a study; relative paths are taken from the study file's folder.
Study load_study(const std::string& file);

// Keeps only the named variants, in the study's order (pipeline --variant); throws ConfigError
// naming an unknown one and the study's variants.
void keep_variants(Study& study, const std::vector<std::string>& names);

}  // namespace pipeline
