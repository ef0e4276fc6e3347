// bench-report: the last step of `make bench` (reports/bench/run_bench.sh). Reads the JSON files
// the benchmark's runs left in BENCH_DIR and writes OUT_DIR/bench.json (all of them in one file)
// and OUT_DIR/bench.md (the tables and what they were measured on). Reads and writes JSON with
// nlohmann-json: the shell script only runs programs.
//
//   bench-report BENCH_DIR OUT_DIR --steps N --reps N --skin TEXT --cases "mu05:0.5 mu0:0 mu0:0.5"
//                [--sizes "8000 64000 ..."] [--size-plan TEXT] [--cores N] [--cpu TEXT]
//                [--load-start TEXT] [--load-end TEXT] [--date YYYY-MM-DD]
//   bench-report lammps-json LOG_DIR OUT.json ...   (lammps_bench.sh's JSON from its LAMMPS logs:
//                validation/tools/bench_report_lammps.cpp)
//
// BENCH_DIR holds, from dem-bench: bench.json, shear.json, laws.json and size_<N>_tiled.json for each of
// --sizes; from reports/bench/lammps_bench.sh: lammps_<packing>_<friction>.json for each case
// PACKING:FRICTION of --cases, and lammps_size_<N>.json. A file or a run that is missing is an
// error naming it (exit 1); bad arguments exit 2.
#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "study/markdown_table.hpp"
#include "study/utc_day.hpp"

namespace {

using json = nlohmann::ordered_json;  // ordered: the files' keys stay in the order their writers chose

std::string format(const char* f, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* f, ...) {
  va_list args;
  va_start(args, f);
  char buf[1024];
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  return buf;
}

json read_json(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": missing (the benchmark's run that writes it did not finish)");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
}

// A number of a JSON object, or an error naming the file and the key.
double number(const json& j, const std::string& key, const std::string& file) {
  if (!j.contains(key) || !j.at(key).is_number()) throw std::runtime_error(file + ": no number '" + key + "' in " + j.dump());
  return j.at(key).get<double>();
}

// A string of a JSON object, or an error naming the file and the key.
std::string text(const json& j, const std::string& key, const std::string& file) {
  if (!j.contains(key) || !j.at(key).is_string()) throw std::runtime_error(file + ": no string '" + key + "' in the laws' record");
  return j.at(key).get<std::string>();
}

// The run of `list` (an array of runs) whose keys have the given values; an error naming them if none.
const json& run_where(const json& doc, const std::string& list, const std::vector<std::pair<std::string, json>>& keys,
                      const std::string& file) {
  if (doc.contains(list))
    for (const json& r : doc.at(list)) {
      bool match = true;
      for (const auto& [k, v] : keys) match = match && r.contains(k) && r.at(k) == v;
      if (match) return r;
    }
  std::string what;
  for (const auto& [k, v] : keys) what += (what.empty() ? "" : ", ") + k + " = " + v.dump();
  throw std::runtime_error(file + ": no run in '" + list + "' with " + what);
}

// 1000000 -> "1,000,000".
std::string commas(long long n) {
  std::string s = std::to_string(n), out;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (k > 0 && (s.size() - k) % 3 == 0) out += ',';
    out += s[k];
  }
  return out;
}

struct Case {
  std::string packing, friction;  // the friction as written in --cases (and in the file's name)
  double mu;
};

struct Options {
  std::string bench_dir, out_dir, skin, cases = "mu05:0.5 mu0:0 mu0:0.5", sizes, size_plan, cpu = "unknown";
  std::string load_start = "unknown", load_end = "unknown";
  std::string date;  // the day the benchmark ran (UTC, YYYY-MM-DD)
  long steps = 0;
  int reps = 0, cores = 0;
};

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// How far apart the two codes' contacts per sphere (2Nc/N) may be on the packing jammed with mu = 0
// before the side-by-side table is refused. LAMMPS's figure is taken after its 200 warm-up steps,
// ours after the timed run; on the same packing they differed by at most 0.01 in both committed runs
// (6.02 / 6.02 and 5.97 / 5.98 on 2026-11-24, 6.11 / 6.11 and 6.07 / 6.08 before), and a cell read
// without its tilts gave 6.11 / 4.37. 0.1 is 400 of the 8,000 spheres' 24,400 contacts (1.6 %): ten
// times the largest difference seen on the same packing.
constexpr double kSamePackingContacts = 0.1;

// The side-by-side table (8,000 spheres) and what it was measured on.
std::string side_by_side(const Options& o, const std::vector<Case>& cases, const json& engine, const std::string& engine_file) {
  validation::MarkdownTable table({"packing jammed with", "friction", "2Nc/N (ours / LAMMPS at start → end)", "ours, 1 thread",
                                   "ours, 2 threads", "2 / 1 thread", "ours, 2 runs at once (1 thread each), total", "2 runs / 1 thread",
                                   "LAMMPS, 1 core", "ours (1 thread) / LAMMPS"});
  for (const Case& c : cases) {
    const auto run = [&](int threads) -> const json& {
      return run_where(engine, "runs", {{"packing", c.packing}, {"friction", c.mu}, {"threads", threads}}, engine_file);
    };
    const double e1 = number(run(1), "particle_steps_per_s_median", engine_file);
    const double e2 = number(run(2), "particle_steps_per_s_median", engine_file);
    const double ze = number(run(1), "coordination_number", engine_file);
    const double r2 = number(run_where(engine, "two_runs_at_once", {{"packing", c.packing}, {"friction", c.mu}}, engine_file),
                             "total_particle_steps_per_s_median", engine_file);
    const std::string lammps_file = o.bench_dir + "/lammps_" + c.packing + "_" + c.friction + ".json";
    const json lammps = read_json(lammps_file);
    const json& lr = run_where(lammps, "runs", {{"friction", c.mu}}, lammps_file);
    const double l = number(lr, "particle_steps_per_s_median", lammps_file);
    const double zl = number(lr, "coordination_number_start", lammps_file);
    // The packing jammed with mu = 0 stands without tangential springs, so both codes must time it
    // with the same contacts; a start that differs means LAMMPS read another packing (a tilted cell
    // read as orthogonal gave 4.37 against 6.11), and a row that says "like for like" would not be.
    if (c.packing == "mu0" && std::abs(ze - zl) > kSamePackingContacts)
      throw std::runtime_error(format("%s: on the packing jammed with mu = 0 (friction %s) LAMMPS started at 2Nc/N %.3f, our engine "
                                      "timed %.3f: more than %.2f apart, so the two codes did not time the same packing (its cell, "
                                      "tilts and positions as LAMMPS read them: %s/packing_%s.box and .txt)",
                                      lammps_file.c_str(), c.friction.c_str(), zl, ze, kSamePackingContacts, o.bench_dir.c_str(),
                                      c.packing.c_str()));
    table.row({c.packing == "mu0" ? "μ = 0" : "μ = 0.5", c.friction,
               format("%.2f / %.2f → %.2f", ze, zl,
                      number(lr, "coordination_number_end", lammps_file)),
               format("%.3g", e1), format("%.3g", e2), format("%.2f", e2 / e1), format("%.3g", r2), format("%.2f", r2 / e1),
               format("%.3g", l), format("%.2f", e1 / l)});
  }
  std::string md = table.text();
  md += "\nParticle-steps per second, medians of " + std::to_string(o.reps) + " repetitions of " + std::to_string(o.steps) +
        " steps (dt = 1 µs, 8,000 spheres,\nVerlet skin " + o.skin + " m in both codes),\nmeasured by `make bench` on " +
        o.date + " (" + std::to_string(o.cores) + " cores, " + o.cpu + "),\n" +
        format("force loop %.0f pairs per vector operation (8: AVX-512, 4: AVX2, 0: scalar).\n", number(engine, "vector_lanes", engine_file)) +
        format("Peak memory of dem-bench: %g MB.\n", number(engine, "peak_rss_MB", engine_file)) +
        "LAMMPS runs in a fixed cell without our stress servo and starts without tangential springs. On the\n"
        "packing jammed with μ = 0.5 it loses them and, where its 2Nc/N falls during the run (→ end), it times a\n"
        "loosening packing; μ = 0.5 on the packing jammed with μ = 0 needs no tangential force to stand, so\n"
        "both codes time the same jammed packing with friction: that row is the like-for-like comparison.\n"
        "Load average of the machine (1, 5, 15 min; the benchmark's own runs add 1 to 2): " + o.load_start + " at the\n"
        "start, " + o.load_end + " at the end; above 2 other work shared the two cores.\n";
  return md;
}

// The cost against size: rates, rates per CPU-second and peak memory of each size, each against
// the smallest size's.
std::string cost_against_size(const Options& o, const std::vector<long long>& sizes, const std::vector<json>& engine,
                              const std::vector<json>& lammps) {
  const auto engine_file = [&](std::size_t k) { return o.bench_dir + "/size_" + std::to_string(sizes[k]) + "_tiled.json"; };
  const auto lammps_file = [&](std::size_t k) { return o.bench_dir + "/lammps_size_" + std::to_string(sizes[k]) + ".json"; };
  // A value of size k's run of friction mu: ours on `threads`, LAMMPS's with threads = 0.
  const auto value = [&](std::size_t k, double mu, int threads, const std::string& key) {
    if (threads == 0) return number(run_where(lammps[k], "runs", {{"friction", mu}}, lammps_file(k)), key, lammps_file(k));
    return number(run_where(engine[k], "runs", {{"friction", mu}, {"threads", threads}}, engine_file(k)), key, engine_file(k));
  };
  const std::vector<std::pair<double, const char*>> frictions = {{0.5, "0.5"}, {0.0, "0"}};
  // "median (min – max)" of size k's runs of friction mu on `threads`.
  const auto spread = [&](std::size_t k, double mu, int threads) {
    return format("%.3g (%.3g – %.3g)", value(k, mu, threads, "particle_steps_per_s_median"), value(k, mu, threads, "min"),
                  value(k, mu, threads, "max"));
  };
  validation::MarkdownTable rates({"spheres", "friction", "ours, 1 thread (min – max)", "vs 8,000", "ours, 2 threads (min – max)",
                                   "vs 8,000", "2 / 1 thread", "LAMMPS, 1 core (min – max)", "vs 8,000", "ours (1 thread) / LAMMPS"});
  for (const auto& [mu, mu_text] : frictions)
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      const std::string m = "particle_steps_per_s_median";
      const double e1 = value(k, mu, 1, m), e2 = value(k, mu, 2, m), l = value(k, mu, 0, m);
      rates.row({commas(sizes[k]), mu_text, spread(k, mu, 1), format("%.2f", e1 / value(0, mu, 1, m)), spread(k, mu, 2),
                 format("%.2f", e2 / value(0, mu, 2, m)), format("%.2f", e2 / e1), spread(k, mu, 0),
                 format("%.2f", l / value(0, mu, 0, m)), format("%.2f", e1 / l)});
    }
  validation::MarkdownTable per_cpu({"spheres", "friction", "ours, 1 thread", "vs 8,000", "LAMMPS, 1 core", "vs 8,000", "ours / LAMMPS"});
  for (const auto& [mu, mu_text] : frictions)
    for (std::size_t k = 0; k < sizes.size(); ++k) {
      const double e = value(k, mu, 1, "cpu_rate_median"), l = value(k, mu, 0, "cpu_rate_median");
      per_cpu.row({commas(sizes[k]), mu_text, format("%.3g", e), format("%.2f", e / value(0, mu, 1, "cpu_rate_median")),
                   format("%.3g", l), format("%.2f", l / value(0, mu, 0, "cpu_rate_median")), format("%.2f", e / l)});
    }
  std::string md = "\n### Cost against size\n\n" + rates.text();
  md += "\nThe same on one thread per CPU-second of the timed steps (ours: the thread's CPU time; LAMMPS: its \"% CPU\n"
        "use\"), which a busy machine's time-slicing does not inflate (its sharing of caches and memory still counts):\n\n" +
        per_cpu.text();
  // LAMMPS's peak memory: the larger of its runs' (each friction in its own process); 0 if none has one.
  const auto lammps_peak = [&](std::size_t k) {
    double peak = 0;
    for (const json& r : lammps[k].value("runs", json::array()))
      if (r.contains("peak_rss_MB") && r.at("peak_rss_MB").is_number()) peak = std::max(peak, r.at("peak_rss_MB").get<double>());
    return peak;
  };
  validation::MarkdownTable memory({"spheres", "ours: peak memory (MB)", "ours: bytes per sphere beyond 8,000", "LAMMPS: peak memory (MB)",
                                    "LAMMPS: bytes per sphere beyond 8,000"});
  const double e8 = number(engine[0], "peak_rss_MB", engine_file(0)), l8 = lammps_peak(0);
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const double e = number(engine[k], "peak_rss_MB", engine_file(k)), l = lammps_peak(k);
    const auto beyond = static_cast<double>(sizes[k] - sizes[0]);
    const bool first = sizes[k] == sizes[0];
    memory.row({commas(sizes[k]), format("%.0f", e), first ? "–" : format("%.0f", (e - e8) * 1048576 / beyond), format("%.0f", l),
                first ? "–" : format("%.0f", (l - l8) * 1048576 / beyond)});
  }
  md += "\n" + memory.text();
  md += "\nParticle-steps per second, median (min – max) of REPS repetitions of STEPS steps after 200 warm-up steps,\n"
        "the same for both codes (TILES:STEPS:REPS: " + o.size_plan + "), on the μ = 0 packing above tiled n × n × n\n"
        "(`dem-bench size`, LAMMPS `replicate`): identical contacts and stress at every size; Verlet skin " + o.skin + " m.\n"
        "\"vs 8,000\": the median over the same code's 8,000-sphere median of this table. Each size of our engine\n"
        "runs in its own process (peak memory: VmHWM; LAMMPS: GNU time's maximum resident set, μ = 0.5 and μ = 0 runs\n"
        "each in its own process, the larger shown). Our particles are in tiled order (copy after copy); LAMMPS sorts\n"
        "its atoms spatially when a run starts.\n";
  return md;
}

// The sheared cell's price (dem-bench shear).
std::string sheared_cell(const Options& o, const json& shear, const std::string& file) {
  const auto value = [&](const std::string& cell, const std::string& key) { return number(run_where(shear, "runs", {{"cell", cell}}, file), key, file); };
  validation::MarkdownTable table({"cell", "particle-steps per CPU-s (median)", "min – max", "vs orthorhombic"});
  for (const char* c : {"orthorhombic", "sheared"})
    table.row({c, format("%.3g", value(c, "cpu_rate_median")), format("%.3g – %.3g", value(c, "min"), value(c, "max")),
               format("%.3f", value(c, "cpu_rate_median") / value("orthorhombic", "cpu_rate_median"))});
  std::string md = "\n### The sheared cell\n\n" + table.text();
  md += "\n`dem-bench shear`: μ = 0.5 on the μ = 0 packing, one thread, the axes held at 100 kPa; \"sheared\" also shears\n"
        "xy at 1/s, so its cell tilts from the first step and every step runs the sheared kernels (nearest image\n"
        "through the tilts, fractional positions in the update). Medians of " + std::to_string(o.reps) + " repetitions of " +
        std::to_string(o.steps) + " steps,\nthe two ways interleaved, per CPU second of the one thread.\n";
  return md;
}

// The contact laws' price (dem-bench laws).
std::string contact_laws(const json& laws, const std::string& file) {
  validation::MarkdownTable table({"law", "steps", "CPU µs per step (median)", "min – max", "over linear (median)", "min – max"});
  if (!laws.contains("runs") || !laws.at("runs").is_array() || laws.at("runs").empty())
    throw std::runtime_error(file + ": no runs");
  for (const json& r : laws.at("runs")) {
    if (!r.contains("law") || !r.at("law").is_string()) throw std::runtime_error(file + ": a run without its 'law'");
    table.row({r.at("law").get<std::string>(), format("%.0f", number(r, "steps", file)),
               format("%.2f", 1e6 * number(r, "cpu_s_per_step_median", file)),
               format("%.2f – %.2f", 1e6 * number(r, "min", file), 1e6 * number(r, "max", file)),
               format("%.3f", number(r, "over_linear_median", file)),
               format("%.3f – %.3f", number(r, "over_linear_min", file), number(r, "over_linear_max", file))});
  }
  std::string keys;
  for (const json& r : laws.at("runs"))
    if (r.contains("set") && r.at("set").is_string() && !r.at("set").get<std::string>().empty())
      keys += "- " + r.at("law").get<std::string>() + ": `" + r.at("set").get<std::string>() + "`\n";
  std::string md = "\n### The contact laws\n\n" + table.text();
  md += "\n`dem-bench laws`: the same test on the same sample with each law, whole runs (`run_scene`: the test's\n"
        "stage, its rows and result file) on one thread, the laws interleaved repetition by repetition, per CPU\n"
        "second of the run per step; \"over linear\": each repetition's cost per step over linear's in the same\n"
        "repetition. The test: " + text(laws, "scene", file) + " with the path " + text(laws, "path", file) + ", " + format("%.0f", number(laws, "repetitions", file)) +
        " repetitions. Each law's keys over the scene's:\n\n" + keys;
  return md;
}

void write(const std::string& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out.flush()) throw std::runtime_error(file + ": cannot be written");
}

int report(const Options& o) {
  std::vector<Case> cases;
  for (const std::string& w : words(o.cases)) {
    const auto colon = w.find(':');
    if (colon == std::string::npos) throw std::invalid_argument("--cases: '" + w + "' is not PACKING:FRICTION");
    cases.push_back({w.substr(0, colon), w.substr(colon + 1), std::stod(w.substr(colon + 1))});
  }
  std::vector<long long> sizes;
  for (const std::string& w : words(o.sizes)) sizes.push_back(std::stoll(w));

  const std::string engine_file = o.bench_dir + "/bench.json", shear_file = o.bench_dir + "/shear.json";
  const std::string laws_file = o.bench_dir + "/laws.json";
  const json engine = read_json(engine_file), shear = read_json(shear_file), laws = read_json(laws_file);
  json all = {{"date", o.date}, {"engine", engine}, {"sheared_cell", shear}, {"contact_laws", laws}, {"lammps", json::array()}};
  for (const Case& c : cases) all["lammps"].push_back(read_json(o.bench_dir + "/lammps_" + c.packing + "_" + c.friction + ".json"));
  std::vector<json> size_engine, size_lammps;
  for (long long n : sizes) {
    size_engine.push_back(read_json(o.bench_dir + "/size_" + std::to_string(n) + "_tiled.json"));
    size_lammps.push_back(read_json(o.bench_dir + "/lammps_size_" + std::to_string(n) + ".json"));
  }
  all["cost_against_size"] = {{"engine", size_engine}, {"lammps", size_lammps}};

  std::string md = side_by_side(o, cases, engine, engine_file);
  if (!sizes.empty()) md += cost_against_size(o, sizes, size_engine, size_lammps);
  md += sheared_cell(o, shear, shear_file);
  md += contact_laws(laws, laws_file);
  write(o.out_dir + "/bench.json", all.dump(2) + "\n");
  write(o.out_dir + "/bench.md", md);
  return 0;
}

}  // namespace

int lammps_json_main(int argc, char** argv);  // bench_report_lammps.cpp

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "lammps-json") return lammps_json_main(argc - 1, argv + 1);
  CLI::App app{"bench-report: bench.json and bench.md from the JSON files of a `make bench` run (reports/bench/run_bench.sh)"};
  app.name("bench-report");
  Options o;
  app.add_option("BENCH_DIR", o.bench_dir, "the benchmark's folder (dem-bench's and lammps_bench.sh's JSON files)")->required();
  app.add_option("OUT_DIR", o.out_dir, "where bench.json and bench.md go")->required();
  app.add_option("--steps", o.steps, "timed steps of each repetition (8,000 spheres)")->required();
  app.add_option("--reps", o.reps, "repetitions (8,000 spheres)")->required();
  app.add_option("--skin", o.skin, "the Verlet skin, as the tables quote it [m]")->required();
  app.add_option("--cases", o.cases, "PACKING:FRICTION of each side-by-side case, in dem-bench's order")->capture_default_str();
  app.add_option("--sizes", o.sizes, "spheres of each size of the cost against size (none: no such tables)");
  app.add_option("--size-plan", o.size_plan, "TILES:STEPS:REPS of each size, as the tables quote it");
  app.add_option("--cores", o.cores, "cores of the machine");
  app.add_option("--cpu", o.cpu, "the processor's model name");
  app.add_option("--load-start", o.load_start, "the load average (1, 5, 15 min) before the benchmark");
  app.add_option("--load-end", o.load_end, "the load average (1, 5, 15 min) after it");
  o.date = validation::utc_day();
  app.add_option("--date", o.date, "the day the benchmark ran, UTC (the report's stamp of its section)")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](const std::string& d) { return validation::is_utc_day(d) ? std::string() : "not a date YYYY-MM-DD: " + d; },
          "YYYY-MM-DD"));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  try {
    return report(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-report: %s\n", e.what());
    return 1;
  }
}
