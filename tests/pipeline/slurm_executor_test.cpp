// The SLURM executor without a cluster: the study keys (executor, slurm:), the sbatch command line
// and job script of a run, the decision to adopt a job an earlier pipeline left in the queue, and
// the all-or-nothing first submission against stand-in sbatch/squeue/scancel scripts. A real
// cluster runs in tests/slurm/slurm_test.sh (make slurm-test).
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "config/study_config.hpp"
#include "config/yaml_section.hpp"
#include "exec/slurm.hpp"
#include "plan/run_plan.hpp"
#include "pipeline/tiny_scenes.hpp"

namespace fs = std::filesystem;
using namespace pipeline;

namespace {

const std::string study_head =
    "name: tiny\noutput: out\npreparation: prep.yaml\n"
    "densities: [{name: loose, friction: 0.5}]\n"
    "tests: [{name: test1, scene: test.yaml}]\n"
    "profiles: {paper: {lattice: 3}, quick: {lattice: 3}}\n";

fs::path study_dir(const std::string& name) {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / name;
  fs::remove_all(dir);
  pipeline::test::write_tiny_scenes(dir, "2.0e-4", "2.0e-4");
  return dir;
}

Study load(const fs::path& dir, const std::string& tail) {
  std::ofstream(dir / "study.yaml") << study_head << tail;
  return load_study((dir / "study.yaml").string());
}

std::string refusal(const fs::path& dir, const std::string& tail) {
  try {
    load(dir, tail);
  } catch (const dem::ConfigError& e) {
    return e.what();
  }
  return "accepted";
}

bool has(const std::vector<std::string>& args, const std::string& a) {
  return std::find(args.begin(), args.end(), a) != args.end();
}

PlannedRun run_named(const std::string& name, double cost) {
  PlannedRun r;
  r.name = name;
  r.result = "/shared/out/" + name + ".h5";
  r.log = "/shared/out/logs/" + name + ".log";
  r.scene_file = "/shared/out/scenes/" + name + ".yaml";
  r.hash = "abc123";
  r.cost = cost;
  return r;
}

}  // namespace

TEST_CASE("slurm: the executor and slurm: keys of a study", "[pipeline][slurm]") {
  const fs::path dir = study_dir("slurm_keys");
  SECTION("defaults: no executor named, default options") {
    const Study s = load(dir, "");
    CHECK_FALSE(s.executor);
    CHECK(s.slurm == SlurmOptions{});
    CHECK(s.slurm.cpus_per_run == 1);
    CHECK(s.slurm.time_floor == 10);
  }
  SECTION("every option read") {
    const Study s = load(dir,
                         "executor: slurm\n"
                         "slurm: {partition: short, account: grain, cpus_per_run: 4, throughput: 1.0e7, time_factor: 2,\n"
                         "        time_floor: 5, time_ceiling: 600, sbatch_args: [--qos=normal, --mem=2G], poll_interval: 30}\n");
    REQUIRE(s.executor);
    CHECK(*s.executor == "slurm");
    CHECK(s.slurm.partition == "short");
    CHECK(s.slurm.account == "grain");
    CHECK(s.slurm.cpus_per_run == 4);
    CHECK(s.slurm.throughput == 1.0e7);
    CHECK(s.slurm.time_factor == 2);
    CHECK(s.slurm.time_floor == 5);
    CHECK(s.slurm.time_ceiling == 600);
    CHECK(s.slurm.sbatch_args == std::vector<std::string>{"--qos=normal", "--mem=2G"});
    CHECK(s.slurm.poll_interval == 30);
  }
  SECTION("refused, naming the key and what is allowed") {
    const std::vector<std::pair<std::string, std::vector<std::string>>> bad = {
        {"executor: kubernetes\n", {"executor", "one of: local, slurm", "kubernetes"}},
        {"slurm: {partitoin: short}\n", {"slurm", "partitoin", "did you mean 'partition'"}},
        {"slurm: {cpus_per_run: 0}\n", {"slurm.cpus_per_run", "[1, 256]"}},
        {"slurm: {time_factor: 0.5}\n", {"slurm.time_factor", "[1, 1000]"}},
        {"slurm: {time_floor: 30, time_ceiling: 10}\n", {"slurm.time_ceiling", "below time_floor"}},
        {"slurm: {sbatch_args: --mem=2G}\n", {"slurm.sbatch_args", "a list of sbatch options"}},
        {"slurm: {sbatch_args: [mem=2G]}\n", {"slurm.sbatch_args", "'mem=2G' is not an sbatch option"}},
        {"slurm: {sbatch_args: [--time=60]}\n", {"slurm.sbatch_args", "'--time=60' is set by slurm.time_factor"}},
        {"slurm: {sbatch_args: [-p, short]}\n", {"slurm.sbatch_args", "set by slurm.partition"}},
        {"slurm: {sbatch_args: [--dependency=afterany:1]}\n", {"slurm.sbatch_args", "set by the pipeline"}},
        {"slurm: [short]\n", {"slurm", "must be a mapping"}},
        {"slurm: {partition: \"\"}\n", {"slurm.partition", "non-empty text"}},
    };
    for (const auto& [tail, fragments] : bad) {
      const std::string msg = refusal(dir, tail);
      INFO(tail << " -> " << msg);
      CHECK(msg.find("study.yaml") != std::string::npos);
      for (const std::string& f : fragments) CHECK(msg.find(f) != std::string::npos);
    }
  }
  SECTION("the executor and its options change no input hash") {
    const Study plain = load(dir, "");
    const auto before = plan_study(plain, plain.profile("quick"), (dir / "out").string(), "test-engine");
    const Study cluster = load(dir, "executor: slurm\nslurm: {partition: short, cpus_per_run: 8, sbatch_args: [--mem=1G]}\n");
    const auto after = plan_study(cluster, cluster.profile("quick"), (dir / "out").string(), "test-engine");
    REQUIRE(before.size() == after.size());
    for (std::size_t i = 0; i < before.size(); ++i) {
      CHECK(before[i].hash == after[i].hash);
      CHECK(before[i].scene_text == after[i].scene_text);
      CHECK(before[i].result == after[i].result);
    }
  }
}

TEST_CASE("slurm: every spelling sbatch reads as an option the pipeline sets is refused", "[pipeline][slurm][input]") {
  // `--outp=x`, `--wra=x`, `--dep=x` passed the refusal list, but sbatch (getopt_long)
  // takes any unambiguous prefix of a long option: they are --output, --wrap, --dependency. The
  // class swept: every prefix of every long option the pipeline sets (from "--" and one letter up
  // to the whole name; a short prefix that is ambiguous, which sbatch refuses too, is refused as
  // well), with and without a value, and every short one alone, with its value attached, and
  // after flags in one cluster (`-vJ name` is -v -J name). The list is sbatch's options that the
  // pipeline writes into each job (pipeline/README.md, "On a cluster"), written out here.
  const fs::path dir = study_dir("slurm_prefixes");
  const std::vector<std::string> owned_long = {"--partition", "--account", "--time", "--cpus-per-task", "--dependency",
                                               "--kill-on-invalid-dep", "--job-name", "--output", "--error", "--open-mode",
                                               "--chdir", "--parsable", "--array", "--wrap", "--test-only", "--ntasks", "--nodes"};
  const std::string owned_short = "pAtcdJoeDanN";
  std::vector<std::string> refused;
  for (const std::string& name : owned_long)
    for (std::size_t n = 3; n <= name.size(); ++n) refused.push_back(name.substr(0, n)), refused.push_back(name.substr(0, n) + "=x");
  for (const char c : owned_short)
    for (const std::string& form : {std::string("-") + c, std::string("-") + c + "x", std::string("-v") + c, std::string("-vQ") + c + "x"})
      refused.push_back(form);
  for (const std::string& a : {std::string("--outp=x"), std::string("--wra=x"), std::string("--dep=x")}) refused.push_back(a);
  int checked = 0;
  for (const std::string& arg : refused) {
    const std::string msg = refusal(dir, "slurm: {sbatch_args: [\"" + arg + "\"]}\n");
    INFO(arg << " -> " << msg);
    CHECK(msg.find("slurm.sbatch_args") != std::string::npos);
    CHECK(msg.find("'" + arg + "' is set by") != std::string::npos);
    ++checked;
  }
  CHECK(checked > 300);
  // Options of sbatch the pipeline leaves to the study, whole or as sbatch reads them: accepted.
  for (const char* arg : {"--qos=normal", "--mem=4G", "--mem-per-cpu=1G", "--time-min=5", "--constraint=x", "--gres=gpu:1",
                                 "--exclusive", "--export=ALL", "--nice=5", "--comment=x", "-q", "-vq", "--requeue", "--tmp=1G"}) {
    INFO(arg);
    CHECK(refusal(dir, "slurm: {sbatch_args: [\"" + std::string(arg) + "\"]}\n") == "accepted");
  }
}

TEST_CASE("slurm: a run's sbatch command line and job script", "[pipeline][slurm]") {
  SlurmOptions o;  // 2.5e7 particle-steps/s, factor 3, floor 10 min
  SECTION("time limit: factor x estimated time, at least the floor, at most the ceiling") {
    CHECK(slurm::time_limit_minutes(0, o) == 10);
    CHECK(slurm::time_limit_minutes(2.5e7 * 60 * 10, o) == 30);   // 10 min estimated -> 30 min
    CHECK(slurm::time_limit_minutes(2.5e7 * 60 * 10.1, o) == 31);  // whole minutes, rounded up
    o.time_ceiling = 20;
    CHECK(slurm::time_limit_minutes(2.5e7 * 60 * 10, o) == 20);
  }
  SECTION("a preparation: no dependency; a test: afterok on its sample's job") {
    o.partition = "short";
    o.cpus_per_run = 4;
    o.sbatch_args = {"--qos=normal"};
    const PlannedRun prep = run_named("seed1/loose_prepare", 2.5e7 * 60 * 20);
    const auto args = slurm::sbatch_command(prep, o, "");
    CHECK(has(args, "--parsable"));
    CHECK(has(args, "--job-name=seed1/loose_prepare"));
    CHECK(has(args, "--output=/shared/out/logs/seed1/loose_prepare.log"));
    CHECK(has(args, "--chdir=/shared/out/seed1"));  // where its result goes
    CHECK(has(args, "--cpus-per-task=4"));
    CHECK(has(args, "--time=60"));
    CHECK(has(args, "--partition=short"));
    CHECK(has(args, "--qos=normal"));
    CHECK_FALSE(has(args, "--account="));
    for (const auto& a : args) CHECK(a.rfind("--dependency", 0) == std::string::npos);
    const auto test_args = slurm::sbatch_command(run_named("seed1/loose_test1", 1), o, "4711");
    CHECK(has(test_args, "--dependency=afterok:4711"));
    CHECK(has(test_args, "--kill-on-invalid-dep=yes"));
    CHECK(has(test_args, "--time=10"));
  }
  SECTION("a % in a path is not an sbatch pattern") {
    PlannedRun r = run_named("a", 1);
    r.log = "/shared/100%/a.log";
    CHECK(has(slurm::sbatch_command(r, o, ""), "--output=/shared/100%%/a.log"));
  }
  SECTION("the job script runs the local executor's dem command line and records its exit code") {
    PlannedRun r = run_named("loose_test1", 1);
    r.scene_file = "/shared/it's here/loose_test1.yaml";  // quoted for the shell
    const std::string script = slurm::job_script(r, "/opt/dem/bin/dem", 4);
    INFO(script);
    CHECK(script.rfind("#!/bin/sh\n", 0) == 0);
    CHECK(script.find("'/opt/dem/bin/dem' 'run' '/shared/it'\\''s here/loose_test1.yaml' '--out' '/shared/out/loose_test1.h5' "
                      "'--input-hash' 'abc123' '--threads' '4' '--force'\n") != std::string::npos);
    CHECK(script.find("echo \"$SLURM_JOB_ID $rc\" > '/shared/out/loose_test1.h5.job.exit.tmp.'$$") != std::string::npos);
    CHECK(script.find("exit $rc") != std::string::npos);
  }
}

TEST_CASE("slurm: adopting the jobs an earlier pipeline left in the queue", "[pipeline][slurm]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "slurm_adopt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  PlannedRun r = run_named("loose_test1", 1);
  r.result = (dir / "loose_test1.h5").string();
  SECTION("the record and the exit file") {
    CHECK_FALSE(slurm::read_record(r.result));
    slurm::write_record(r.result, {"42", "abc123"});
    const auto rec = slurm::read_record(r.result);
    REQUIRE(rec);
    CHECK(rec->job_id == "42");
    CHECK(rec->input_hash == "abc123");
    CHECK_FALSE(slurm::recorded_exit(r.result, "42"));
    std::ofstream(slurm::exit_file(r.result)) << "41 0\n";  // an earlier job's: not this one's
    CHECK_FALSE(slurm::recorded_exit(r.result, "42"));
    std::ofstream(slurm::exit_file(r.result)) << "42 2\n";
    CHECK(slurm::recorded_exit(r.result, "42") == 2);
  }
  SECTION("squeue's lines") {
    const slurm::Queue q = slurm::parse_queue("42|loose_test1|PENDING\n43|seed1/dense_prepare|RUNNING\n\n44|x|COMPLETED\n");
    REQUIRE(q.size() == 3);
    CHECK(q.at("43").name == "seed1/dense_prepare");
    CHECK(q.at("43").state == "RUNNING");
    CHECK(slurm::active("PENDING"));
    CHECK(slurm::active("REQUEUED"));
    CHECK(slurm::active("COMPLETING"));
    CHECK_FALSE(slurm::active("COMPLETED"));
    CHECK_FALSE(slurm::active("CANCELLED"));
    CHECK_FALSE(slurm::active("TIMEOUT"));
  }
  SECTION("what a starting pipeline does") {
    using slurm::Adoption;
    const slurm::JobRecord mine{"42", "abc123"}, stale{"42", "old999"};
    const slurm::Queue running = slurm::parse_queue("42|loose_test1|RUNNING\n");
    const slurm::Queue pending = slurm::parse_queue("42|loose_test1|PENDING\n");
    const slurm::Queue ended = slurm::parse_queue("42|loose_test1|CANCELLED\n");
    const slurm::Queue reused_id = slurm::parse_queue("42|someone_else|RUNNING\n");
    CHECK(slurm::adoption(r, std::nullopt, running, true, std::nullopt) == Adoption::Submit);  // no record
    CHECK(slurm::adoption(r, mine, running, true, std::nullopt) == Adoption::Adopt);
    CHECK(slurm::adoption(r, mine, pending, true, std::nullopt) == Adoption::Adopt);
    CHECK(slurm::adoption(r, stale, running, true, std::nullopt) == Adoption::Replace);   // other inputs
    CHECK(slurm::adoption(r, mine, pending, false, std::nullopt) == Adoption::Replace);   // its sample runs again
    CHECK(slurm::adoption(r, mine, ended, true, std::nullopt) == Adoption::Submit);       // resumes from its checkpoint
    CHECK(slurm::adoption(r, mine, {}, true, std::nullopt) == Adoption::Submit);          // forgotten by the cluster
    CHECK(slurm::adoption(r, mine, reused_id, true, std::nullopt) == Adoption::Submit);   // the id is another job's now
    CHECK(slurm::adoption(r, mine, {}, true, 1) == Adoption::Submit);  // a failure: computed again
    r.may_fail = true;
    CHECK(slurm::adoption(r, mine, {}, true, 1) == Adoption::Ended);    // a may_fail stop: its outcome stands
    CHECK(slurm::adoption(r, mine, {}, true, 139) == Adoption::Submit);
    CHECK(slurm::adoption(r, stale, {}, true, 2) == Adoption::Submit);
  }
}

namespace {

// Stand-ins for the cluster's commands: squeue lists nothing, sbatch accepts --test-only and
// does what the test says; scancel writes the ids it was given.
slurm::Commands fake_cluster(const fs::path& bin, const std::string& sbatch_behaviour) {
  fs::create_directories(bin);
  const auto script = [&](const std::string& name, const std::string& body) {
    const fs::path p = bin / name;
    std::ofstream(p) << "#!/bin/sh\n" << body;
    fs::permissions(p, fs::perms::owner_all);
    return p.string();
  };
  slurm::Commands c;
  c.squeue = script("squeue", "exit 0\n");
  c.scancel = script("scancel", "echo \"$@\" >> " + (bin / "cancelled").string() + "\n");
  c.sbatch = script("sbatch", "cat > /dev/null\n" + sbatch_behaviour);
  c.sacct = script("sacct", "echo 'Slurm accounting storage is disabled' >&2; exit 1\n");
  return c;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("slurm: nothing is submitted, or nothing is left half-submitted, when the cluster refuses", "[pipeline][slurm]") {
  const fs::path dir = study_dir("slurm_refused");
  const Study study = load(dir, "");
  auto runs = plan_study(study, study.profile("quick"), (dir / "out").string(), "test-engine");
  write_scenes(runs);
  const std::vector<SlurmOptions> options(runs.size(), study.slurm);
  const std::string dem = std::string(DEM_BINARY_DIR) + "/bin/dem";
  const auto job_files = [&] {
    int n = 0;
    for (const auto& r : runs) n += fs::exists(slurm::record_file(r.result));
    return n;
  };
  SECTION("sbatch missing") {
    slurm::Commands c = fake_cluster(dir / "bin", "exit 0\n");
    c.sbatch = (dir / "bin" / "no-sbatch").string();
    CHECK_THROWS_WITH(slurm::execute(runs, options, dem, c),
                      Catch::Matchers::Contains("no-sbatch' is not on the PATH") && Catch::Matchers::Contains("nothing was submitted"));
  }
  SECTION("squeue failing") {
    const slurm::Commands c = fake_cluster(dir / "bin", "exit 0\n");
    std::ofstream(c.squeue) << "#!/bin/sh\necho 'slurm_load_jobs error: Unable to contact slurm controller' >&2\nexit 1\n";
    CHECK_THROWS_WITH(slurm::execute(runs, options, dem, c), Catch::Matchers::Contains("Unable to contact slurm controller"));
  }
  SECTION("an option the cluster refuses: sbatch --test-only fails") {
    const slurm::Commands c = fake_cluster(
        dir / "bin", "echo 'sbatch: error: invalid partition specified: nope' >&2\nexit 1\n");
    CHECK_THROWS_WITH(slurm::execute(runs, options, dem, c),
                      Catch::Matchers::Contains("invalid partition specified") && Catch::Matchers::Contains("nothing was submitted"));
    CHECK_FALSE(fs::exists(dir / "bin" / "cancelled"));
    CHECK(job_files() == 0);
  }
  SECTION("the second submission fails: the first is cancelled") {
    const fs::path count = dir / "bin" / "count";
    const slurm::Commands c = fake_cluster(
        dir / "bin", "case \"$*\" in *--test-only*) exit 0;; esac\n"
                     "n=$(( $(cat " + count.string() + " 2>/dev/null || echo 0) + 1 ))\necho $n > " + count.string() + "\n"
                     "[ $n -lt 2 ] || { echo 'sbatch: error: Batch job submission failed: Invalid qos specification' >&2; exit 1; }\n"
                     "echo $((100 + n))\n");
    CHECK_THROWS_WITH(slurm::execute(runs, options, dem, c), Catch::Matchers::Contains("Invalid qos specification"));
    CHECK(text_of(dir / "bin" / "cancelled") == "101\n");
    CHECK(job_files() == 0);
  }
}
