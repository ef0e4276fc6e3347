// compare-runs liquefaction: the undrained cyclic triaxial tests of one or more study folders and
// their unloaded holds, of one sample or an ensemble (seed<N>/ folders). CSR against N_L of each
// cyclic test, r_u against cycles of every run, and the hold's r_u (the same sample's) beside each
// test's; per density and CSR, the median N_L over the samples with its range and how many
// liquefied or were censored. Writes OUT/table.md, csr_nl.dat, csr_nl_summary.dat, ru.dat and
// values.gp (what reports/gnuplot/liquefaction_*.gp need).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include "sections/modes.hpp"
#include "study/columns.hpp"
#include "study/series.hpp"
#include "study/format.hpp"
#include "io/atomic_file.hpp"
#include "sections/liquefaction.hpp"
#include "study/markdown_table.hpp"
#include "study/section_doc.hpp"

namespace fs = std::filesystem;

namespace sections {
namespace {

using validation::Bound;
using validation::Digits;
using validation::bound_text;
using validation::fixed;
using validation::number;

// One run of a liquefaction study: <density>_csr<CSR> (cyclic) or <density>_hold.
struct CyclicRun {
  std::string run, density;
  std::string seed = "-";     // the sample (the manifest's seed; "-": a study of one sample)
  bool hold = false;
  double csr_name = NAN;      // from the name
  std::string note;           // why it has no values, or what to know of them
  bool finished = false;
  int stage = -1;             // index of its control stage
  double period_s = NAN;      // of the cyclic loading (a hold: of its density's cyclic runs)
  double amplitude_Pa = NAN;
  double ru_limit = NAN, strain_limit = NAN;  // the scene's until.pore_pressure_ratio, until.double_amplitude_strain
  std::string stage_end;      // its stage_end_<stage> attribute
  validation::ControlStage control;
  validation::Columns series;
};

// The control stage of a scene: the first stage of type control (-1 if none).
int control_stage(const dem::SceneConfig& scene) {
  for (std::size_t k = 0; k < scene.stages.size(); ++k)
    if (scene.stages[k].type == dem::StageConfig::Type::Control) return static_cast<int>(k);
  return -1;
}

// The runs of one liquefaction study folder (its manifest), read and summarised.
std::vector<CyclicRun> cyclic_runs(const std::string& results) {
  std::vector<CyclicRun> runs;
  for (const ManifestLine& l : read_manifest(results).lines) {
    if (l.test == "-") continue;  // the preparation
    CyclicRun& r = runs.emplace_back();
    r.run = l.run, r.density = l.density, r.hold = l.test == "hold", r.seed = l.seed;
    if (!r.hold) {
      const auto csr = validation::csr_from_name(l.run);
      if (!csr) {
        r.note = "not analysed: test '" + l.test + "' is neither hold nor csr<CSR>";
        continue;
      }
      r.csr_name = *csr;
    }
    const std::string result = validation::result_under(results, l);  // wherever the folder is now
    if (!validation::is_complete(result)) {
      r.note = "missing: " + fs::path(result).filename().string() + " is not finished";
      continue;
    }
    try {
      RunFile f = read_run(result);
      if (!f.scene) throw std::runtime_error(result + ": no resolved scene (scene_yaml)");
      r.stage = control_stage(*f.scene);
      if (r.stage < 0) throw std::runtime_error(result + ": its scene has no control stage");
      const dem::StageConfig& st = f.scene->stages[static_cast<std::size_t>(r.stage)];
      if (!r.hold && st.cyclic.component < 0) throw std::runtime_error(result + ": stages[" + std::to_string(r.stage) + "] has no cyclic loading");
      if (!r.hold) r.period_s = st.cyclic.period_s, r.amplitude_Pa = st.cyclic.amplitude;
      r.ru_limit = st.until.pore_pressure_ratio, r.strain_limit = st.until.double_amplitude_strain;
      r.stage_end = f.stage_end.count(st.name) ? f.stage_end.at(st.name) : "";
      r.series = std::move(f.series);
      r.control = validation::summarise_control_stage(r.series, r.stage, r.period_s);
      r.finished = true;
    } catch (const std::exception& e) {
      r.note = "unreadable: " + std::string(e.what());
    }
  }
  // A hold has no period of its own: its cycles are those of its density's cyclic tests.
  for (CyclicRun& h : runs) {
    if (!h.hold || !h.finished) continue;
    for (const CyclicRun& c : runs)
      if (!c.hold && c.finished && c.density == h.density) h.period_s = c.period_s;  // every sample's: one scene
    if (std::isfinite(h.period_s)) h.control.cycles = (h.control.end_time_s - h.control.start_time_s) / h.period_s;
    else h.note = "no finished cyclic test of " + h.density + " to take the period from";
  }
  return runs;
}

// The outcome of a cyclic test in words: liquefied by which criterion, or a censored point.
std::string outcome(const CyclicRun& r) {
  const std::string c = validation::stop_criterion(r.stage_end);
  if (c == "pore_pressure_ratio") return "liquefied: r_u ≥ " + number(r.ru_limit);
  if (c == "double_amplitude_strain") return "liquefied: double-amplitude strain ≥ " + number(100 * r.strain_limit) + " %";
  if (!c.empty()) return "stopped by until." + c;
  return "not liquefied in " + fixed(r.control.cycles, 1) + " cycles" + (r.stage_end.empty() ? " (no stage_end attribute)" : "");
}

// The hold of a density's sample (the same seed: the same packing held with nothing applied).
const CyclicRun* hold_of(const std::vector<CyclicRun>& runs, const std::string& density, const std::string& seed) {
  for (const CyclicRun& r : runs)
    if (r.hold && r.finished && r.density == density && r.seed == seed) return &r;
  return nullptr;
}

// A hold that reached the r_u limit with nothing applied: its sample collapses at constant volume
// on its own, so no test of that sample can liquefy later than the hold did. A test that liquefied
// earlier, while the hold's r_u was still small, had its N_L set by the loading; one that liquefied
// no earlier than the hold had it set by the collapse.
std::string collapse_notes(const std::vector<CyclicRun>& runs) {
  std::string notes;
  for (const CyclicRun& h : runs) {
    if (!h.hold || !h.finished || validation::stop_criterion(h.stage_end) != "pore_pressure_ratio") continue;
    const double hold_s = h.control.end_time_s - h.control.start_time_s;
    int earlier = 0, later = 0;
    double low = INFINITY, high = -INFINITY, hold_ru = -INFINITY;  // over the tests that liquefied earlier
    for (const CyclicRun& r : runs) {
      if (r.hold || !r.finished || r.density != h.density || r.seed != h.seed || validation::stop_criterion(r.stage_end).empty()) continue;
      const double test_s = r.control.end_time_s - r.control.start_time_s;
      if (test_s >= hold_s) {
        ++later;
        continue;
      }
      ++earlier;
      low = std::min(low, r.control.cycles), high = std::max(high, r.control.cycles);
      hold_ru = std::max(hold_ru, validation::value_since_start(h.series, h.stage, validation::col::pore_pressure_ratio, test_s));
    }
    notes += "\n⚠ " + h.run + " reached r_u ≥ " + number(h.ru_limit) + " with nothing applied after " + fixed(hold_s, 4) + " s (" +
             fixed(h.control.cycles, 2) + " cycles of " + number(h.period_s) + " s): its sample collapses at constant volume on its own, "
             "which bounds the N_L of every test of that sample";
    if (earlier)
      notes += "; " + std::to_string(earlier) + " of its cyclic tests liquefied earlier, after " + fixed(low, 2) + " – " + fixed(high, 2) +
               " cycles, when the hold's r_u was at most " + bound_text(hold_ru, Bound::at_most, 3, Digits::decimals) + ": the loading set their N_L";
    if (later)
      notes += "; " + std::to_string(later) + " liquefied no earlier than the hold: their N_L is the sample's collapse, not set by the loading";
    notes += ".\n";
  }
  return notes;
}

// The cyclic tests of one density at one CSR (of the name), over the samples.
struct CsrGroup {
  std::string density;
  double csr = NAN;
  std::vector<const CyclicRun*> runs;  // finished ones
  validation::CensoredSummary summary;
};

std::vector<CsrGroup> csr_groups(const std::vector<CyclicRun>& runs, const std::vector<std::string>& densities) {
  std::vector<CsrGroup> groups;
  for (const std::string& d : densities) {
    std::vector<double> csrs;
    for (const CyclicRun& r : runs)
      if (!r.hold && r.finished && r.density == d && std::find(csrs.begin(), csrs.end(), r.csr_name) == csrs.end()) csrs.push_back(r.csr_name);
    std::sort(csrs.begin(), csrs.end());
    for (double csr : csrs) {
      CsrGroup& g = groups.emplace_back();
      g.density = d, g.csr = csr;
      std::vector<validation::CensoredCycles> n;
      for (const CyclicRun& r : runs)
        if (!r.hold && r.finished && r.density == d && r.csr_name == csr) {
          g.runs.push_back(&r);
          n.push_back({r.control.cycles, validation::stop_criterion(r.stage_end).empty()});
        }
      g.summary = validation::summarise_censored(n);
    }
  }
  return groups;
}

// "1, 2, 3": the seeds of a density's finished runs ("one sample" for a study without seeds).
std::vector<std::string> seeds_of(const std::vector<CyclicRun>& runs, const std::string& density) {
  std::vector<std::string> seeds;
  for (const CyclicRun& r : runs)
    if (r.density == density && std::find(seeds.begin(), seeds.end(), r.seed) == seeds.end()) seeds.push_back(r.seed);
  return seeds;
}

validation::SectionDoc liquefaction_table(const std::vector<CyclicRun>& runs, const std::vector<std::string>& folders,
                                          const std::vector<std::string>& densities, const std::vector<CsrGroup>& groups) {
  std::ostringstream md;
  std::size_t finished = 0;
  for (const CyclicRun& r : runs) finished += r.finished;
  md << "Undrained cyclic triaxial tests (`scenes/tests/undrained_cyclic.yaml`) and their unloaded twins "
        "(`scenes/tests/undrained_hold.yaml`) from " << folders.size() << " study folder(s); " << finished << " of " << runs.size()
     << " runs finished. Samples: ";
  for (std::size_t k = 0; k < densities.size(); ++k) {
    const std::vector<std::string> seeds = seeds_of(runs, densities[k]);
    std::string list;
    for (const std::string& s : seeds) list += (list.empty() ? "" : ", ") + s;
    md << (k ? "; " : "") << densities[k] << " "
       << (seeds.size() == 1 && seeds[0] == "-" ? "one sample (no seeds)" : std::to_string(seeds.size()) + " (seeds " + list + ")");
  }
  md << ". CSR from the name and from the resolved scene (the cyclic stage's `cyclic.amplitude` / 2 p0, p0 = p at "
        "its start); N_L = (end − start of the cyclic stage) / period; a test that did not liquefy is a censored point "
        "(N_L > N, N the cycles it ran).\n\n";
  // Per density and CSR over the samples.
  validation::MarkdownTable summary({"density", "CSR", "samples", "liquefied", "censored (N_L > N)", "median N_L", "range of N_L (least – largest)"});
  for (const CsrGroup& g : groups) {
    const validation::CensoredSummary& s = g.summary;
    summary.row({g.density, number(g.csr), std::to_string(s.samples), std::to_string(s.liquefied), std::to_string(s.censored),
                 validation::median_text(s) + (s.median_censored ? (std::isinf(s.median_high) ? " (the median is censored)" : " (bracketed: a censored sample)") : ""),
                 validation::censored_text(s.least) + " – " + validation::censored_text(s.largest)});
  }
  md << "Per density and CSR over the samples: the median N_L and its range, censored tests counted as N_L > N (a censored median "
        "is written \"> N\": at least half the samples did not liquefy within the test, and the median's order statistic is one "
        "of them).\n\n"
     << summary.text() << "\n";
  for (const std::string& d : densities) {
    int tests = 0, liquefied = 0, csrs = 0;
    for (const CsrGroup& g : groups)
      if (g.density == d) tests += g.summary.samples, liquefied += g.summary.liquefied, ++csrs;
    if (csrs) md << d << ": " << liquefied << " of " << tests << " tests liquefied over " << csrs << " CSR(s). ";
  }
  md << "\n\nEach test (the last column is the r_u its sample's hold had after the same time with nothing applied: the part of the "
        "test's r_u that the loading does not cause):\n\n";
  validation::MarkdownTable tests({"run", "seed", "CSR (name)", "CSR (scene)", "p0 (kPa)", "N_L (cycles)", "outcome", "r_u at the end",
                                   "hold's r_u at the same time"});
  for (const CyclicRun& r : runs) {
    if (r.hold) continue;
    if (!r.finished) {
      tests.row({r.run, r.seed, fixed(r.csr_name, 3), "—", "—", "—", r.note, "—", "—"});
      continue;
    }
    const double csr = validation::cyclic_stress_ratio(r.amplitude_Pa, r.control.p0_Pa);
    // The consolidation holds every principal stress within 0.5 % of its target, so p0 and the
    // scene's CSR are within about 0.5 % of the nominal; more than 1 % means name and scene disagree.
    constexpr double agree_within = 0.01;
    const bool agrees = std::abs(csr - r.csr_name) <= agree_within * r.csr_name;
    std::string at_hold = "—";
    if (const CyclicRun* h = hold_of(runs, r.density, r.seed)) {
      const double ru = validation::value_since_start(h->series, h->stage, validation::col::pore_pressure_ratio, r.control.end_time_s - r.control.start_time_s);
      at_hold = std::isfinite(ru) ? fixed(ru, 3) : "— (the hold lasted " + fixed(h->control.end_time_s - h->control.start_time_s, 3) + " s)";
    }
    const bool censored = validation::stop_criterion(r.stage_end).empty();
    tests.row({r.run, r.seed, fixed(r.csr_name, 3),
               fixed(csr, 4) + (agrees ? "" : " ⚠ differs from the name by more than " + number(100 * agree_within) + " %"),
               fixed(r.control.p0_Pa / 1e3, 2), (censored ? "> " : "") + fixed(r.control.cycles, 2), outcome(r), fixed(r.control.ru_end, 3),
               at_hold});
  }
  validation::MarkdownTable holds({"run", "seed", "held for (s)", "cycles", "r_u at the end", "largest r_u", "how it ended"});
  for (const CyclicRun& r : runs) {
    if (!r.hold) continue;
    if (!r.finished) {
      holds.row({r.run, r.seed, "—", "—", "—", "—", r.note});
      continue;
    }
    holds.row({r.run, r.seed, fixed(r.control.end_time_s - r.control.start_time_s, 3), fixed(r.control.cycles, 1), fixed(r.control.ru_end, 4),
               fixed(r.control.ru_max, 4), (r.stage_end.empty() ? "no stage_end attribute" : r.stage_end) + (r.note.empty() ? "" : "; " + r.note)});
  }
  md << tests.text() << "\nThe holds (nothing applied after the same consolidation; cycles of the density's cyclic period):\n\n" << holds.text();
  md << collapse_notes(runs);
  md << "\n";
  validation::SectionDoc doc;
  doc.text(md.str()).figure("csr_nl.png", "CSR against the number of cycles to liquefaction").text("\n").figure("ru.png", "r_u against the number of cycles");
  doc.densities = densities;
  return doc;
}

validation::Table summary_data(const std::vector<CsrGroup>& groups, const std::vector<std::string>& densities) {
  validation::Table t;
  t.comments = {"compare-runs liquefaction: per density (values.gp liq_density_<n>) and CSR over the samples: the median N_L and its",
                "least and largest; censored 1: the value is a lower bound (N_L > it); median_high NaN: infinite (the median is censored)"};
  t.columns = {"density [1]", "csr [1]", "samples [1]", "liquefied [1]", "censored [1]", "median_low [1]", "median_high [1]",
               "median_censored [1]", "least [1]", "least_censored [1]", "largest [1]", "largest_censored [1]"};
  for (const CsrGroup& g : groups) {
    const validation::CensoredSummary& s = g.summary;
    const double d = static_cast<double>(std::find(densities.begin(), densities.end(), g.density) - densities.begin() + 1);
    t.labels.push_back(g.density + "_csr" + number(g.csr));
    t.rows.push_back({d, g.csr, static_cast<double>(s.samples), static_cast<double>(s.liquefied), static_cast<double>(s.censored), s.median_low,
                      std::isinf(s.median_high) ? NAN : s.median_high, s.median_censored ? 1.0 : 0.0, s.least.cycles,
                      s.least.censored ? 1.0 : 0.0, s.largest.cycles, s.largest.censored ? 1.0 : 0.0});
  }
  return t;
}

}  // namespace

int liquefaction(const std::string& out, const std::vector<std::string>& folders) {
  std::vector<CyclicRun> runs;
  std::vector<std::string> densities;
  try {
    for (const std::string& dir : folders)
      for (CyclicRun& r : cyclic_runs(dir)) {
        if (std::find(densities.begin(), densities.end(), r.density) == densities.end()) densities.push_back(r.density);
        runs.push_back(std::move(r));
      }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  const std::vector<CsrGroup> groups = csr_groups(runs, densities);
  validation::Table csr;
  csr.comments = {"compare-runs liquefaction: one row per finished cyclic test; density as in values.gp (liq_density_<n>);",
                  "liquefied 0: a censored point, the test ended (duration) before either criterion: N_L > n_cycles; seed -1: one sample"};
  csr.columns = {"density [1]", "csr_name [1]", "csr_scene [1]", "n_cycles [1]", "liquefied [1]", "p0 [kPa]", "seed [1]"};
  validation::Table ru;
  ru.comments = {"compare-runs liquefaction: r_u against cycles since the start of the control stage, one block per run (values.gp: liq_run_<k>)"};
  validation::GnuplotValues values;
  std::vector<std::string> run_names, run_density, run_hold;
  // For the r_u figure's colours and key: a cyclic test's CSR by its rank among its density's CSRs
  // (1, 2, ...; a hold 0), and whether it is the first run drawn of its density and CSR (or hold).
  std::vector<std::string> run_csr, run_csr_rank, run_first;
  std::set<std::string> drawn;
  double ru_limit = NAN, strain_limit = NAN;  // the criteria of the first finished cyclic test (one scene for all)
  for (const CyclicRun& r : runs) {
    if (!r.finished) continue;
    const double d = static_cast<double>(std::find(densities.begin(), densities.end(), r.density) - densities.begin() + 1);
    if (!r.hold) {
      csr.labels.push_back(r.run);
      csr.rows.push_back({d, r.csr_name, validation::cyclic_stress_ratio(r.amplitude_Pa, r.control.p0_Pa), r.control.cycles,
                          validation::stop_criterion(r.stage_end).empty() ? 0.0 : 1.0, r.control.p0_Pa / 1e3,
                          r.seed == "-" ? -1.0 : std::strtod(r.seed.c_str(), nullptr)});
      if (!std::isfinite(ru_limit)) ru_limit = r.ru_limit, strain_limit = r.strain_limit;
    }
    if (!std::isfinite(r.period_s)) continue;  // a hold without a cyclic test to count its cycles by
    const validation::Table t = validation::ru_against_cycles(r.series, r.stage, r.period_s);
    if (!ru.rows.empty()) ru.block_starts.push_back(ru.rows.size());
    for (std::size_t i = 0; i < t.size(); ++i) ru.rows.push_back(t.rows[i]), ru.labels.push_back(r.run);
    run_names.push_back(r.run), run_density.push_back(std::to_string(static_cast<int>(d))), run_hold.push_back(r.hold ? "1" : "0");
    int rank = 0;  // `groups` has each density's CSRs once: the run's rank is how many are at most its own
    if (!r.hold)
      for (const CsrGroup& g : groups) rank += g.density == r.density && g.csr <= r.csr_name;
    run_csr.push_back(r.hold ? "hold" : number(r.csr_name));
    run_csr_rank.push_back(std::to_string(rank));
    run_first.push_back(drawn.insert(r.density + "/" + run_csr.back()).second ? "1" : "0");
  }
  ru.columns = {"cycles [1]", "r_u [1]", "time since the stage start [s]"};
  values.texts("liq_density", densities);
  values.texts("liq_run", run_names);
  values.texts("liq_run_density", run_density);
  values.texts("liq_run_hold", run_hold);
  values.texts("liq_run_csr", run_csr);
  values.texts("liq_run_csr_rank", run_csr_rank);
  values.texts("liq_run_first", run_first);
  values.number("liq_summary_n", static_cast<double>(groups.size()));
  int most = 0;
  for (const CsrGroup& g : groups) most = std::max(most, g.summary.samples);
  values.number("liq_samples_max", most);  // the figure's title: how many samples a median is over, at most
  values.text("liq_criteria", std::isfinite(ru_limit) ? "r_u ≥ " + number(ru_limit) + " or " + number(100 * strain_limit) + " % double-amplitude axial strain"
                                                      : "no finished test");
  try {
    fs::create_directories(out);
    validation::write_section(out, liquefaction_table(runs, folders, densities, groups));
    dem::write_file_atomically((fs::path(out) / "csr_nl.dat").string(), csr.text());
    dem::write_file_atomically((fs::path(out) / "csr_nl_summary.dat").string(), summary_data(groups, densities).text());
    dem::write_file_atomically((fs::path(out) / "ru.dat").string(), ru.text());
    std::string from;
    for (const std::string& f : folders) from += (from.empty() ? "" : ", ") + relative_paths(f, f);
    dem::write_file_atomically((fs::path(out) / "values.gp").string(), values.text_file("Written by compare-runs liquefaction from " + from));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::size_t finished = 0;
  for (const CyclicRun& r : runs) {
    finished += r.finished;
    if (!r.finished) std::fprintf(stderr, "note: %s: %s\n", r.run.c_str(), r.note.c_str());
  }
  std::printf("liquefaction: %zu of %zu runs finished -> %s\n", finished, runs.size(), (fs::path(out) / "table.md").c_str());
  return 0;
}
}  // namespace sections
