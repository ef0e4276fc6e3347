// The sections other studies make, each with its stamp under its heading: a stamp on the paper
// study's baseline and engine is said; one on another baseline is refused, or with
// --allow-other-baseline headed ⚠ with both stamps said; a section without a stamp says it is
// not recorded; a section not run has no line. On fixture report folders.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "engine/io/io_test_support.hpp"
#include "report/other_sections.hpp"
#include "report/report.hpp"
#include "report/report_values.hpp"
#include "study/section_doc.hpp"

namespace fs = std::filesystem;
using validation::Stamp;

namespace {

// A filled report with every listed section's heading and a body line.
std::string report_text() {
  std::string text = "# title\n\nGenerated on 2026-11-27\n\n## Set-up\n\nx\n";
  for (const auto& s : validation::other_study_sections()) text += "\n## " + s.heading + "\n\nbody of " + s.heading + "\n";
  return text;
}

// Every section's table key filled (each section has run).
std::map<std::string, std::string> all_run() {
  std::map<std::string, std::string> v;
  for (const auto& s : validation::other_study_sections()) v[s.table_key] = "| a table |";
  return v;
}

void write_json(const fs::path& file, const nlohmann::ordered_json& j) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << j.dump(1) << "\n";
}

const Stamp paper{"0.1.0+aaaa", "1111111111111111", 8000, 5, "2026-11-27"};

}  // namespace

TEST_CASE("report stamps: every section another study makes is listed once, under a heading of the template", "[report][stamp]") {
  std::string tmpl;
  {
    std::ifstream in(std::string(DEM_SOURCE_DIR) + "/reports/templates/index.md");
    tmpl.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  std::map<std::string, int> keys;
  std::size_t parts = 0;
  for (const auto& s : validation::other_study_sections()) {
    REQUIRE(tmpl.find("{{" + s.table_key + "}}") != std::string::npos);
    if (s.level == 3) {  // a part of a section's table: its section is listed too
      ++parts;
      continue;
    }
    REQUIRE(tmpl.find("\n## " + s.heading + "\n") != std::string::npos);
    REQUIRE(++keys[s.table_key] == 1);
  }
  REQUIRE(keys.size() == 11);  // decisions, convergence, stability, critical state, liquefaction, literature, the two
                               // calibrations (the demonstration, the open choices), FCC array, the earlier baseline, performance
  REQUIRE(parts == 2);         // the critical state's ensemble and rate series
}

TEST_CASE("report stamps: a part another study feeds has its own stamp, or is refused", "[report][stamp]") {
  // The critical-state section fed by the ensemble and rates studies: each part's heading (in the
  // section's table) gets its study's stamp from the section's stamp.json; a part without one is
  // not stamped, refused, or with --allow-other-baseline headed "⚠ not stamped".
  const fs::path dir = dem::test::scratch_dir("report_stamp_parts");
  const Stamp paper_with_source{"0.1.0+aaaa", "1111111111111111", 8000, 5, "2026-11-27", "src1"};
  const Stamp main{"0.1.0+aaaa", "1111111111111111", 8000, 1, "2026-11-28", "src1"};
  const Stamp ensemble{"0.1.0+aaaa", "1111111111111111", 8000, 3, "2026-11-29", "src1"};
  nlohmann::ordered_json j = validation::stamp_json(main);
  j["ensemble"] = validation::stamp_json(ensemble);
  write_json(dir / "critical_state" / "stamp.json", j);
  for (const char* f : {"decisions/decisions.json", "literature/validation.json", "literature/fcc/validation.json", "bench.json",
                        "baselines/orthorhombic_validation.json"})
    write_json(dir / f, {{"stamp", validation::stamp_json(main)}});
  for (const char* f : {"stability/stamp.json", "liquefaction/stamp.json", "convergence/summary.json", "calibration/synthetic_triaxial/stamp.json",
                        "calibration/paper_open_choices/stamp.json"})
    write_json(dir / f, validation::stamp_json(main));
  std::string text = report_text();
  const std::string body = "body of Appendix: Critical state: friction, void ratio and coordination against μ\n";
  text.insert(text.find(body) + body.size(), "\n### The critical state on 3 samples\n\nensemble table\n\n"
                                             "### Rate convergence: the critical state at I → 0\n\nrates table\n");
  const auto out = validation::stamp_sections(text, dir, all_run(), paper_with_source, false);
  INFO(out.text);
  // The ensemble's own stamp (3 samples, its date), not the section's.
  CHECK(out.text.find("### The critical state on 3 samples\n\n*Made by engine `0.1.0+aaaa` (source `src1`) on baseline `1111111111111111` "
                      "(8,000 spheres, 3 samples, 2026-11-29).*\n\nensemble table") != std::string::npos);
  // The rates part has no stamp: refused, naming it.
  REQUIRE(out.refused.size() == 1);
  CHECK(out.refused[0].find("Rate convergence: the critical state at I → 0") != std::string::npos);
  const auto kept = validation::stamp_sections(text, dir, all_run(), paper_with_source, true);
  CHECK(kept.refused.empty());
  CHECK(kept.text.find("\n### ⚠ not stamped: Rate convergence: the critical state at I → 0\n\n*⚠ Stamp not recorded") != std::string::npos);
}

TEST_CASE("report stamps: a stamp on the paper study's baseline is said under its heading", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("report_stamp_same");
  write_json(dir / "stability" / "stamp.json", validation::stamp_json({"0.1.0+aaaa", "1111111111111111", 27, 1, "2026-11-20"}));
  // The decisions study at 1,000 spheres: its stamp inside decisions.json, on the same baseline.
  write_json(dir / "decisions" / "decisions.json",
             {{"schema", 2}, {"stamp", validation::stamp_json({"0.1.0+aaaa", "1111111111111111", 1000, 3, "2026-11-02"})}});
  const auto out = validation::stamp_sections(report_text(), dir, all_run(), paper, false);
  REQUIRE(out.refused.empty());
  REQUIRE(out.text.find("## Appendix: Stability\n\n*Made by engine `0.1.0+aaaa` on baseline `1111111111111111` (27 spheres, 1 sample, "
                        "2026-11-20). Its baseline is the paper study's, though it may run a scene of its own "
                        "(`scenes/stability/base.yaml`).*\n\nbody of Appendix: Stability\n") != std::string::npos);
  // The sentence follows the stamp: never "not the paper study's" over the paper study's baseline.
  REQUIRE(out.text.find("`1111111111111111` (27 spheres, 1 sample, 2026-11-20). Its baseline is its own scene's") == std::string::npos);
  REQUIRE(out.text.find("## Appendix: What the paper's open choices change\n\n*Made by engine `0.1.0+aaaa` on baseline "
                        "`1111111111111111` (1,000 spheres, 3 samples, 2026-11-02).*\n") != std::string::npos);
  REQUIRE(out.text.find("⚠") == std::string::npos);
  // Stamped again (a section's line already there): replaced, not doubled.
  const auto again = validation::stamp_sections(out.text, dir, all_run(), paper, false);
  REQUIRE(again.text == out.text);
  // Thornton's FCC array (108 equal spheres of its own lattice): its stamp inside its validation.json,
  // its baseline its own study's, said and never compared with the paper study's.
  write_json(dir / "literature" / "fcc" / "validation.json",
             {{"stamp", validation::stamp_json({"0.1.0+aaaa", "4444444444444444", 108, 1, "2026-11-28"})}});
  const auto fcc = validation::stamp_sections(report_text(), dir, all_run(), paper, false);
  REQUIRE(fcc.refused.empty());
  REQUIRE(fcc.text.find("## Appendix: Thornton's face-centred cubic array\n\n*Made by engine `0.1.0+aaaa` on baseline `4444444444444444` "
                        "(108 spheres, 1 sample, 2026-11-28). Its baseline is its own scene's (`pipeline/studies/fcc_thornton.yaml`), "
                        "not the paper study's, by design.*\n") != std::string::npos);
}

TEST_CASE("report stamps: a section without a stamp says so; a section not run has no line", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("report_stamp_none");
  write_json(dir / "decisions" / "decisions.json", {{"schema", 2}});  // made before stamps
  auto values = all_run();
  values["file.liquefaction"] = "";  // not run yet
  const auto out = validation::stamp_sections(report_text(), dir, values, paper, false);
  REQUIRE(out.refused.empty());
  const std::string none = "*Stamp not recorded: made before stamps (its engine and baseline are unknown).*";
  REQUIRE(out.text.find("## Appendix: What the paper's open choices change\n\n" + none + "\n") != std::string::npos);
  REQUIRE(out.text.find("## Appendix: Critical state: friction, void ratio and coordination against μ\n\n" + none + "\n") != std::string::npos);
  REQUIRE(out.text.find("## Appendix: Liquefaction: cyclic stress ratio against cycles\n\nbody of") != std::string::npos);
  // The stability matrix prepares from its own scene: another baseline is said, not refused.
  write_json(dir / "stability" / "stamp.json", validation::stamp_json({"0.1.0+aaaa", "3333333333333333", 216, 1, "2026-11-20"}));
  const auto own = validation::stamp_sections(report_text(), dir, values, paper, false);
  REQUIRE(own.refused.empty());
  REQUIRE(own.text.find("\n## Appendix: Stability\n\n*Made by engine `0.1.0+aaaa` on baseline `3333333333333333` (216 spheres") != std::string::npos);
  // ... and another engine (another commit) is said in its line, not refused.
  write_json(dir / "stability" / "stamp.json", validation::stamp_json({"0.1.0+bbbb", "3333333333333333", 216, 1, "2026-11-20"}));
  const auto other_engine = validation::stamp_sections(report_text(), dir, values, paper, false);
  REQUIRE(other_engine.refused.empty());
  REQUIRE(other_engine.text.find("*Made by engine `0.1.0+bbbb`") != std::string::npos);
  // The paper study's own stamp not recorded: nothing to compare against, nothing refused.
  write_json(dir / "stability" / "stamp.json", validation::stamp_json({"E", "2222222222222222", 27, 1, "2026-11-20"}));
  const auto unknown_paper = validation::stamp_sections(report_text(), dir, values, Stamp{}, false);
  REQUIRE(unknown_paper.refused.empty());
  REQUIRE(unknown_paper.text.find("*Made by engine `E` on baseline `2222222222222222`") != std::string::npos);
}

TEST_CASE("report stamps: another baseline is refused, then headed ⚠ with --allow-other-baseline", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("report_stamp_other");
  // The convergence summary's own fields (engine, baseline, date; no spheres or samples).
  write_json(dir / "convergence" / "summary.json",
             {{"schema", 1}, {"engine", "0.1.0+aaaa"}, {"baseline", "2222222222222222"}, {"date", "2026-11-26"}, {"runs", nlohmann::json::array()}});
  const auto refused = validation::stamp_sections(report_text(), dir, all_run(), paper, false);
  REQUIRE(refused.refused.size() == 1);
  const std::string& why = refused.refused.front();
  REQUIRE_THAT(why, Catch::Contains("Convergence: error against run time") && Catch::Contains("2222222222222222") &&
                        Catch::Contains("1111111111111111") && Catch::Contains("--allow-other-baseline") && Catch::Contains("baseline"));
  const auto kept = validation::stamp_sections(report_text(), dir, all_run(), paper, true);
  REQUIRE(kept.refused.empty());
  REQUIRE(kept.other == std::vector<std::string>{"Appendix: Convergence: error against run time"});
  REQUIRE(kept.text.find("\n## Appendix: ⚠ from another baseline: Convergence: error against run time\n\n*⚠ Made by engine `0.1.0+aaaa` on "
                         "baseline `2222222222222222` (spheres not recorded, samples not recorded, 2026-11-26); the paper study's numbers "
                         "were made by engine `0.1.0+aaaa` on baseline `1111111111111111` (8,000 spheres, 5 samples, 2026-11-27)") !=
          std::string::npos);
  // Still the same section by its name.
  REQUIRE(validation::section_name("## Appendix: ⚠ from another baseline: Convergence: error against run time") ==
          "Convergence: error against run time");
  // Another engine (commit) on the same baseline: kept, unmarked, its line naming its engine.
  write_json(dir / "convergence" / "summary.json", {{"engine", "0.1.0+bbbb"}, {"baseline", "1111111111111111"}, {"date", "2026-11-26"}});
  const auto same_baseline = validation::stamp_sections(report_text(), dir, all_run(), paper, false);
  REQUIRE(same_baseline.refused.empty());
  REQUIRE(same_baseline.text.find("\n## Appendix: Convergence: error against run time\n\n*Made by engine `0.1.0+bbbb` on baseline "
                                  "`1111111111111111`") != std::string::npos);
}

TEST_CASE("report stamps: another engine source is refused, then headed ⚠; another commit of the same source is not", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("report_stamp_engine");
  Stamp paper_checked = paper;
  paper_checked.engine_source = "S schema 4";
  Stamp section{"0.1.0+bbbb", "3333333333333333", 216, 1, "2026-11-20"};
  const std::map<std::string, std::string> stability_run = {{"file.stability", "| a table |"}};  // the only section run
  const auto with = [&](const std::string& source, long stale) {
    Stamp s = section;
    s.engine_source = source, s.other_engine_results = stale;
    write_json(dir / "stability" / "stamp.json", validation::stamp_json(s));
    return validation::stamp_sections(report_text(), dir, stability_run, paper_checked, false);
  };
  // The same source built at another commit: the same engine, said in its line.
  const auto same = with("S schema 4", 0);
  REQUIRE(same.refused.empty());
  REQUIRE(same.text.find("\n## Appendix: Stability\n\n*Made by engine `0.1.0+bbbb` (source `S schema 4`) on baseline") != std::string::npos);
  // Another source; the same source with a stale result; no source recorded (not checked): refused.
  for (const auto& [source, stale] : std::vector<std::pair<std::string, long>>{{"T schema 4", 0}, {"S schema 4", 2}, {"", 0}}) {
    const auto refused = with(source, stale);
    REQUIRE(refused.refused.size() == 1);
    REQUIRE_THAT(refused.refused.front(), Catch::Contains("Stability") && Catch::Contains("another engine"));
  }
  // Kept when allowed, headed ⚠ from another engine, and still the same section by its name.
  write_json(dir / "stability" / "stamp.json", validation::stamp_json(Stamp{"0.1.0+bbbb", "3333333333333333", 216, 1, "2026-11-20", "S schema 4", 2}));
  const auto kept = validation::stamp_sections(report_text(), dir, stability_run, paper_checked, true);
  REQUIRE(kept.other == std::vector<std::string>{"Appendix: Stability"});
  REQUIRE(kept.text.find("\n## Appendix: ⚠ from another engine: Stability\n\n*⚠ Made by engine `0.1.0+bbbb` (source `S schema 4`; 2 results "
                         "not made by it from their inputs) on baseline") != std::string::npos);
  REQUIRE(validation::section_name("## Appendix: ⚠ from another engine: Stability") == "Stability");
  // A section with no stamp at all, once the paper study's engine source is recorded: refused,
  // or headed "⚠ not stamped".
  fs::remove(dir / "stability" / "stamp.json");
  const auto unstamped = validation::stamp_sections(report_text(), dir, stability_run, paper_checked, false);
  REQUIRE(unstamped.refused.size() == 1);
  REQUIRE_THAT(unstamped.refused.front(), Catch::Contains("another engine and baseline (not stamped)"));
  const auto unstamped_kept = validation::stamp_sections(report_text(), dir, stability_run, paper_checked, true);
  REQUIRE(unstamped_kept.text.find("\n## Appendix: ⚠ not stamped: Stability\n\n*⚠ Stamp not recorded") != std::string::npos);
  REQUIRE(validation::section_name("## Appendix: ⚠ not stamped: Stability") == "Stability");
  // Before the paper study's engine source was recorded, no stamp was only said in its line.
  REQUIRE(validation::stamp_sections(report_text(), dir, stability_run, paper, false).refused.empty());
}

TEST_CASE("report stamps: a listed heading missing from the report is an error naming it", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("report_stamp_heading");
  std::string text = report_text();
  const std::string stability = "\n## Appendix: Stability\n";
  text.replace(text.find(stability), stability.size(), "\n## Appendix: Stable\n");
  REQUIRE_THROWS_WITH(validation::stamp_sections(text, dir, all_run(), paper, false), Catch::Contains("## Appendix: Stability"));
}

TEST_CASE("report: each reading's table says its stamp, marked when on another baseline", "[report][stamp]") {
  const fs::path dir = dem::test::scratch_dir("readings_stamps");
  write_json(dir / "validation.json", {{"stamp", validation::stamp_json({"0.1.0+aaaa", "1111111111111111", 8000, 5, "2026-11-28"})}});
  // Each reading's section as compare-runs writes it (study/section_doc.hpp): a group's heading, its
  // chart and its table; the loose study of one of the paper's densities, the dashpot study of all.
  for (const char* r : {"loose", "dashpot"}) {
    fs::create_directories(dir / "readings" / r);
    validation::SectionDoc doc;
    doc.text("\n").heading(1, "fabric").text("\n").figure("tornado_fabric.png", "tornado chart: fabric").text("\n| row | shift |\n|---|---|\n| a | +1 |\n");
    doc.densities = std::string(r) == "loose" ? std::vector<std::string>{"loose"} : std::vector<std::string>{"loose", "medium", "dense"};
    validation::write_section(dir / "readings" / r, doc);
  }
  std::ofstream(dir / "readings" / "loose" / "tornado_fabric.png") << "png";
  // A folder with a table.md alone (written before sections were kept as data) is left out.
  fs::create_directories(dir / "readings" / "old");
  std::ofstream(dir / "readings" / "old" / "table.md") << "### fabric\n\n![tornado chart: fabric](tornado_fabric.png)\n";
  // Only a stamp in decisions.json (not a whole decisions file: its size is then not recorded).
  write_json(dir / "readings" / "loose" / "decisions.json",
             {{"stamp", validation::stamp_json({"0.1.0+aaaa", "1111111111111111", 8000, 3, "2026-11-28"})}});
  write_json(dir / "readings" / "dashpot" / "decisions.json",
             {{"stamp", validation::stamp_json({"0.1.0+bbbb", "2222222222222222", 8000, 3, "2026-11-20"})}});
  validation::Values v;
  validation::add_tables(v, dir, {}, "");
  const std::string& text = v.at("file.readings");
  INFO(text);
  CHECK_THAT(text, Catch::Contains("### Readings of the loose sample (size not recorded)\n\n*Made by engine `0.1.0+aaaa` on baseline "
                                   "`1111111111111111` (8,000 spheres, 3 samples, 2026-11-28).*\n"));
  CHECK_THAT(text, Catch::Contains("### Readings: dashpot (size not recorded)\n\n*⚠ Made by engine `0.1.0+bbbb` on baseline "
                                   "`2222222222222222` (8,000 spheres, 3 samples, 2026-11-20); another baseline than the paper study's "
                                   "(made by engine `0.1.0+aaaa` on baseline `1111111111111111` (8,000 spheres, 5 samples, 2026-11-28)).*\n"));
  // Their own headings one level below their titles', their figures' paths from the report's folder
  // (a figure not drawn said so); the folder without section.json not shown.
  CHECK_THAT(text, Catch::Contains("#### fabric\n\n![tornado chart: fabric](readings/loose/tornado_fabric.png)\n"));
  CHECK_THAT(text, Catch::Contains("#### fabric\n\n*Figure `readings/dashpot/tornado_fabric.png` not drawn.*\n"));
  CHECK(text.find("\n### fabric") == std::string::npos);
  CHECK(text.find("Readings: old") == std::string::npos);
}

TEST_CASE("other sections: a stamp recorded elsewhere is taken only for the same data", "[report][stamp]") {
  const fs::path report = dem::test::scratch_dir("other_sections_elsewhere");
  const auto section = [](const std::string& heading_start) {
    for (const auto& s : validation::other_study_sections())
      if (s.heading.rfind(heading_start, 0) == 0) return s;
    FAIL("no section " << heading_start);
    return validation::OtherStudySection{};
  };
  // The critical-state ensemble: stamp.json without an "ensemble" part; the literature check of
  // the same study stamps it. Its samples' void ratios 0.571, 0.5704, 0.5705 (mean 0.5706333...,
  // sd 0.000321455) and angles 7.98, 8.18, 8.43 (mean 8.196667, sd 0.225462) are ensemble.dat's.
  write_json(report / "critical_state" / "stamp.json", {{"engine", "0.1.0+aaa"}, {"baseline", "b1"}, {"spheres", 8000}, {"samples", 1}});
  const auto literature = [&](double last_angle) {
    nlohmann::ordered_json j = {{"profile", "paper"}, {"samples", {"seed1", "seed2", "seed3"}}, {"missing_samples", nlohmann::json::array()},
                                {"missing_results", nlohmann::json::array()},
                                {"stamp", {{"engine", "0.1.0+aaa"}, {"engine_source", "src"}, {"baseline", "b1"}, {"spheres", 8000},
                                           {"samples", 3}, {"date", "2026-11-28"}}}};
    const auto row = [](const std::string& name, const std::vector<double>& x) {
      nlohmann::ordered_json r = {{"name", name}, {"density", "dense"}, {"per_sample", nlohmann::json::array()}};
      for (std::size_t k = 0; k < x.size(); ++k) r["per_sample"].push_back({{"sample", "seed" + std::to_string(k + 1)}, {"value", x[k]}});
      return r;
    };
    j["rows"] = {row("void ratio", {0.571, 0.5704, 0.5705}), row("angle", {7.98, 8.18, last_angle})};
    write_json(report / "literature" / "validation.json", j);
  };
  const auto ensemble_dat = [&](double e_mean, double e_sd, double phi_mean, double phi_sd) {
    char line[512];
    std::snprintf(line, sizeof line, "\"compression_mu0\"\t0\t1\t3\t%.10g\t%.10g\t0.3\t0.01\t%.10g\t%.10g\t5.8\t0.004\t9.7\t0.2\n", phi_mean, phi_sd,
                  e_mean, e_sd);
    dem::test::write_text((report / "critical_state" / "ensemble.dat").string(),
                          "# ensemble\n# label\t mu [1]\tloading [1]\tsamples [1]\tphi_cs [deg]\tphi_cs_sd [deg]\tq_over_p_cs [1]\t"
                          "q_over_p_cs_sd [1]\te_cs [1]\te_cs_sd [1]\tcn_cs [1]\tcn_cs_sd [1]\tpeak_phi [deg]\tpeak_phi_sd [deg]\n" +
                              std::string(line));
  };
  const double e_mean = (0.571 + 0.5704 + 0.5705) / 3, phi_mean = (7.98 + 8.18 + 8.43) / 3;
  const auto sd3 = [](double a, double b, double c) {
    const double m = (a + b + c) / 3;
    return std::sqrt(((a - m) * (a - m) + (b - m) * (b - m) + (c - m) * (c - m)) / 2);
  };
  ensemble_dat(e_mean, sd3(0.571, 0.5704, 0.5705), phi_mean, sd3(7.98, 8.18, 8.43));
  literature(8.43);
  const Stamp same = validation::read_section_stamp(report, section("The critical state on "));
  CHECK(same.engine == "0.1.0+aaa");
  CHECK(same.samples == 3);
  CHECK(same.date == "2026-11-28");
  // Planted: the literature check of other samples (one angle differs): nothing taken from it.
  literature(8.44);
  CHECK_FALSE(validation::read_section_stamp(report, section("The critical state on ")).recorded());
  // The rates part has no record elsewhere: not recorded, none invented.
  CHECK_FALSE(validation::read_section_stamp(report, section("Rate convergence: ")).recorded());
  // make bench's file without a "stamp": the engine and the spheres it records, and the day it ran
  // where it says (bench-report writes it; earlier files do not).
  write_json(report / "bench.json", {{"engine", {{"version", "0.1.0+1cb397751ed6"}, {"particles", 8000}, {"runs", nlohmann::json::array()}}}});
  const Stamp bench = validation::read_section_stamp(report, section("Appendix: Performance"));
  CHECK(bench.engine == "0.1.0+1cb397751ed6");
  CHECK(bench.spheres == 8000);
  CHECK(bench.baseline.empty());
  CHECK(bench.date.empty());
  CHECK(validation::stamp_text(bench).find("engine `0.1.0+1cb397751ed6`") != std::string::npos);
  write_json(report / "bench.json",
             {{"date", "2026-12-04"}, {"engine", {{"version", "0.1.0+fbd873cbcaac"}, {"particles", 8000}, {"runs", nlohmann::json::array()}}}});
  const Stamp dated = validation::read_section_stamp(report, section("Appendix: Performance"));
  CHECK(dated.date == "2026-12-04");
  CHECK(validation::stamp_text(dated).find("2026-12-04") != std::string::npos);
  // The earlier baseline's record, stamped after the fact with its engine's source alone: what
  // is known said, what is not said so, and another engine than the paper study's.
  write_json(report / "baselines" / "orthorhombic_validation.json",
             {{"stamp", {{"engine", "not recorded"}, {"engine_source", "85398fbd83a3644f"}, {"baseline", "not recorded"}, {"spheres", 8000},
                         {"samples", 5}, {"date", "2026-11-24"}}}});
  const Stamp earlier = validation::read_section_stamp(report, section("Appendix: This baseline against the earlier one (orthorhombic cell)"));
  CHECK(validation::stamp_text(earlier) ==
        "made by an engine not recorded (source `85398fbd83a3644f`) on a baseline not recorded (8,000 spheres, 5 samples, 2026-11-24)");
  const Stamp paper{"0.1.0+3d448a9766e3", "b40cf9b5afd6759b", 8000, 5, "2026-11-28", "7a8331262cc8c4ff schema 4"};
  CHECK(validation::stamp_difference(earlier, paper) == "engine");
}
