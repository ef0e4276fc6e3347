// validate's exit status follows one rule: 0 only when everything asked for was done and
// judged. Missing results, a sample runs.tsv lists whose folder is gone, rows not judged: 1, with
// the reason on stderr (the tables are still written). Bad arguments, a results folder that is not
// there, an --out that is not a folder: 2, with a message, never an uncaught exception.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/io/io_test_support.hpp"
#include "validation/markdown_cells.hpp"

namespace fs = std::filesystem;

namespace {

const std::string bin = std::string(DEM_BINARY_DIR) + "/bin/validate";
const std::string refs = std::string(DEM_SOURCE_DIR) + "/reference_data/paper.yaml";

dem::test::CommandResult validate(const std::string& args) { return dem::test::run_command("'" + bin + "' " + args + " 2>&1"); }

// DIR/runs.tsv of the paper's layout (each density's preparation and 5 tests) for seeds 1..`seeds`,
// every run of `variant` ("-": a study without variants; else its runs named `variant`_...).
void write_paper_manifest(const fs::path& dir, int seeds, const std::string& variant) {
  std::ofstream runs(dir / "runs.tsv");
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  const std::string prefix = variant == "-" ? "" : variant + "_";
  for (int seed = 1; seed <= seeds; ++seed)
    for (const std::string d : {"loose", "medium", "dense"})
      for (const std::string t : {"-", "test1", "test2", "test3", "test4", "test5"}) {
        const std::string run = "seed" + std::to_string(seed) + "/" + prefix + d + "_" + (t == "-" ? "prepare" : t);
        runs << variant << "\t" << d << "\t" << t << "\t" << run << "\t/x/" << run << ".h5\t-\t0\tas written\t" << seed << "\n";
      }
}

}  // namespace

TEST_CASE("validate: an --out or --results that cannot be used is a clear error, exit 2", "[validate][cli]") {
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_args";
  fs::remove_all(dir);
  fs::create_directories(dir / "results");
  SECTION("--out /dev/null (a file, not a folder)") {
    const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out /dev/null");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("--out '/dev/null' is not a folder") != std::string::npos);
  }
  SECTION("--out under a file") {
    std::ofstream(dir / "file") << "x";
    const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / "file" / "sub").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("cannot create the folder") != std::string::npos);
  }
  SECTION("a misspelt --results folder, and --results pointing at the study file") {
    auto r = validate("--results '" + (dir / "resluts").string() + "' --references '" + refs + "' --out '" + (dir / "out").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("does not exist") != std::string::npos);
    r = validate("--results '" + std::string(DEM_SOURCE_DIR) + "/pipeline/studies/paper.yaml' --references '" + refs + "' --out '" +
                 (dir / "out").string() + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.out.find("is not a folder") != std::string::npos);
  }
}

TEST_CASE("validate: missing results and a deleted sample make exit 1, and are listed", "[validate][cli]") {
  // A 3-seed study of the paper's layout whose runs.tsv lists seeds 1-3; seed1/ and seed2/ are
  // there but empty, seed3/ is gone.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_missing";
  fs::remove_all(dir);
  fs::create_directories(dir / "results" / "seed1");
  fs::create_directories(dir / "results" / "seed2");
  write_paper_manifest(dir / "results", 3, "-");
  const auto validate_profile = [&](const std::string& profile) {
    return validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / profile).string() +
                    "' --profile " + profile);
  };
  // Only the runs the rows read count: the quick rows read the preparations alone (2 samples x 3
  // densities); every row of the paper profile reads the preparation and the 5 tests (x 6).
  for (const auto& [profile, files] : {std::pair{"quick", 6}, std::pair{"paper", 36}}) {
    INFO(profile);
    const auto r = validate_profile(profile);
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("lists 1 sample(s) whose folder is gone: seed3") != std::string::npos);
    CHECK(r.out.find(std::to_string(files) + " result file(s) missing") != std::string::npos);
    CHECK(r.out.find("row(s) not judged") != std::string::npos);
    // The tables are written all the same, and say what is missing.
    std::ifstream f(dir / profile / "validation.json");
    const nlohmann::json j = nlohmann::json::parse(f);
    CHECK(j.at("missing_samples") == nlohmann::json::array({"seed3"}));
    CHECK(j.at("missing_results").size() == static_cast<std::size_t>(files));
    CHECK(j.at("missing_results").front() == "seed1/loose_prepare.h5");
    CHECK(j.at("complete") == false);
    CHECK(j.at("samples").size() == 2);
    CHECK_FALSE(j.at("judged_from").contains("variants"));  // a study without variants names none
  }
}

TEST_CASE("validate: a study of one variant records that variant as the one its rows read", "[validate][cli]") {
  // The layout above with every run of the variant `best` (as `make open-choices-check` runs a
  // calibration's best set): rows that name no variant take the study's only one.
  const fs::path results = fs::path(dem::test::scratch_dir("validate_cli_variant")) / "results";
  for (const char* seed : {"seed1", "seed2"}) fs::create_directories(results / seed);
  write_paper_manifest(results, 2, "best");
  const fs::path out = results.parent_path() / "out";
  const auto r = validate("--results '" + results.string() + "' --references '" + refs + "' --out '" + out.string() + "' --profile quick");
  CHECK(r.exit_code == 1);  // no result files: every row not judged, the record written all the same
  std::ifstream f(out / "validation.json");
  const nlohmann::json j = nlohmann::json::parse(f);
  CHECK(j.at("judged_from").at("variants") == nlohmann::json::array({"best"}));
  CHECK(j.at("missing_results").front() == "seed1/best_loose_prepare.h5");
}

TEST_CASE("validate: a study without runs.tsv, and rows that name what the study lacks, exit 2", "[validate][cli][references]") {
  // A study of one density (dense) and one test (compression), no variants, two samples.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_selectors";
  fs::remove_all(dir);
  fs::create_directories(dir / "results" / "seed1");
  fs::create_directories(dir / "results" / "seed2");
  fs::create_directories(dir / "bare");
  {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int seed = 1; seed <= 2; ++seed) {
      const std::string s = "seed" + std::to_string(seed);
      runs << "-\tdense\t-\t" << s << "/dense_prepare\t/x/" << s << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
      runs << "-\tdense\tcompression\t" << s << "/dense_compression\t/x/" << s << "/dense_compression.h5\t" << s
           << "/dense_prepare\t0\tas written\t" << seed << "\n";
    }
  }
  const auto run = [&](const std::string& row, const std::string& results = "results") {
    const fs::path file = dir / "refs.yaml";
    std::ofstream(file) << "source: lab\nrows:\n  - {name: \"my row\", reference: 30, check: within, source: lab, reason: r, " << row << "}\n";
    return validate("--results '" + (dir / results).string() + "' --references '" + file.string() + "' --out '" + (dir / "out").string() +
                    "' --profile small");
  };
  const std::string at = (dir / "refs.yaml").string() + ": rows[0] (\"my row\")";
  const std::string study = "the study (" + (dir / "results" / "runs.tsv").string() + ")";
  struct Case {
    std::string row, message;
  };
  for (const Case& c : std::vector<Case>{
           {"quantity: peak_friction_angle, density: loose", at + ".density: " + study + " has no density 'loose'; its densities: dense"},
           {"quantity: peak_friction_angle, test: extension", at + ".test: " + study + " has no test 'extension' of density dense; its tests: compression"},
           {"quantity: peak_friction_angle, variant: fast", at + ".variant: " + study + " has no variants, so 'fast' names nothing; leave `variant` out"},
           {"quantity: phi_peak", at + ".quantity: unknown quantity 'phi_peak'; known: "},
           {"quantity: peak_friction_angle, tolerence: 2", at + ": unknown key 'tolerence'"},
       }) {
    INFO(c.row);
    const auto r = run(c.row);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Contains(c.message));
  }
  CHECK_THAT(run("quantity: tolerence").out, Catch::Contains("peak_friction_angle"));  // the known quantities are listed
  CHECK_THAT(run("quantity: peak_friction_angle, tolerence: 2").out, Catch::Contains("a row's keys: name, group, quantity"));
  // The selectors are checked before any result is read or any table written.
  CHECK_FALSE(fs::exists(dir / "out" / "validation.json"));
  // A folder without the study's manifest: exit 2, naming it.
  const auto bare = run("quantity: peak_friction_angle", "bare");
  CHECK(bare.exit_code == 2);
  CHECK_THAT(bare.out, Catch::Contains((dir / "bare" / "runs.tsv").string() + ": no manifest"));
  // Any profile name is taken; a row whose runs are all missing is not judged (exit 1).
  const auto missing = run("quantity: peak_friction_angle, test: compression");
  CHECK(missing.exit_code == 1);
  CHECK_THAT(missing.out, Catch::Contains("2 result file(s) missing"));
  CHECK_THAT(missing.out, Catch::Contains("1 row(s) not judged (fewer than 2 samples with a value): my row"));
}

namespace {

// The cells of each line of a Markdown table in `text` (the lines that start with '|'), split at
// the '|' that are not escaped, trimmed, "\|" read back as '|'.
std::vector<std::vector<std::string>> table_lines(const std::string& text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] != '|') continue;
    out.push_back(dem::test::markdown_cells(line));
  }
  return out;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("validate: validation.md and verdicts.md read back cell by cell, a '|' in the reference's texts kept in its cell", "[validate][cli][markdown-table]") {
  // Two samples whose results are not there: every row is written, not judged (exit 1).
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_tables";
  fs::remove_all(dir);
  fs::create_directories(dir / "results" / "seed1");
  fs::create_directories(dir / "results" / "seed2");
  {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int seed = 1; seed <= 2; ++seed) {
      const std::string s = "seed" + std::to_string(seed);
      runs << "-\tdense\t-\t" << s << "/dense_prepare\t/x/" << s << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
      runs << "-\tdense\tcompression\t" << s << "/dense_compression\t/x/" << s << "/dense_compression.h5\t" << s
           << "/dense_prepare\t0\tas written\t" << seed << "\n";
    }
  }
  // The label (a heading of both tables), a row's name, source and reason each with a '|'.
  const fs::path refs_file = dir / "refs.yaml";
  std::ofstream(refs_file) << "source: lab\nlabel: \"lab|2020\"\nrows:\n"
                              "  - {name: \"peak | dense\", quantity: peak_friction_angle, test: compression, reference: 30, tolerance: 2,"
                              " check: within, source: \"Table 1 | col. 2\", reason: \"read | off\"}\n";
  const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + refs_file.string() + "' --out '" +
                          (dir / "out").string() + "' --profile small");
  INFO(r.out);
  CHECK(r.exit_code == 1);
  const auto v = table_lines(text_of(dir / "out" / "validation.md"));
  REQUIRE(v.size() == 3);  // heading, delimiter, the row
  for (const auto& line : v) CHECK(line.size() == 11);
  CHECK(v[0][1] == "lab|2020");
  CHECK(v[2][0] == "peak | dense");
  CHECK(v[2][1] == "30 ± 2");
  CHECK(v[2][5] == "0 of 0");
  CHECK(v[2][7] == "— not judged");
  CHECK(v[2][9] == "Table 1 | col. 2");
  CHECK(v[2][10] == "read | off");
  const auto m = table_lines(text_of(dir / "out" / "verdicts.md"));
  REQUIRE(m.size() == 3);
  for (const auto& line : m) CHECK(line.size() == 5);
  CHECK(m[0] == std::vector<std::string>{"row", "lab|2020", "ours: mean ± sd", "samples in the lab|2020's range", "verdict"});
  CHECK(m[2] == std::vector<std::string>{"peak | dense", "30 ± 2", "—", "0 of 0", "— not judged"});
}

TEST_CASE("validate: a reference file or manifest that would be read wrong in silence is refused, exit 2", "[validate][cli][references]") {
  // Two rows of one name, a tolerance that check: at_least would ignore, a profile the file does
  // not have (paper.yaml names `quick`: `quik` would judge every row as written), a run runs.tsv
  // lists twice (its sample would be counted twice).
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_silent";
  fs::remove_all(dir);
  fs::create_directories(dir / "results" / "seed1");
  const auto manifest = [&](int copies) {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int k = 0; k < copies; ++k) runs << "-\tdense\t-\tseed1/dense_prepare\t/x/seed1/dense_prepare.h5\t-\t0\tas written\t1\n";
  };
  const auto run = [&](const std::string& rows, const std::string& profile = "paper") {
    const fs::path file = dir / "refs.yaml";
    std::ofstream(file) << "source: lab\nrows:\n" << rows;
    return validate("--results '" + (dir / "results").string() + "' --references '" + file.string() + "' --out '" + (dir / "out").string() +
                    "' --profile " + profile);
  };
  const std::string row = "  - {name: e0, quantity: void_ratio_after_preparation, reference: 0.6, check: within, tolerance: 0.1, source: lab, reason: r}\n";
  const std::string refs_file = (dir / "refs.yaml").string();
  manifest(1);
  auto r = run(row + row);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains(refs_file + ": rows[1] (\"e0\").name: 'e0' is the name of rows[0] too"));
  r = run("  - {name: e0, quantity: void_ratio_after_preparation, reference: 0.6, check: at_least, tolerance: 0.1, source: lab, reason: r}\n");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains(refs_file + ": rows[0] (\"e0\").tolerance: applies to check: within only; with check: at_least"));
  r = validate("--results '" + (dir / "results").string() + "' --references '" + refs + "' --out '" + (dir / "out").string() +
               "' --profile quik");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains("--profile 'quik': no row of " + refs + " has it; its profiles: paper (every row as written), quick"));
  // A file that names no profile takes any (the study's own profile names).
  CHECK(run(row, "small").exit_code == 1);  // judged: its result is missing (exit 1), not refused
  fs::remove_all(dir / "out");
  manifest(2);
  r = run(row);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Contains((dir / "results" / "runs.tsv").string() +
                                    ": line 3: the run 'seed1/dense_prepare' again (line 2 lists it)"));
  CHECK_FALSE(fs::exists(dir / "out" / "validation.json"));  // nothing judged on a misread input
}

TEST_CASE("validate: a NaN in a result and a copied sample are named, exit 1", "[validate][cli]") {
  // Three samples of one density: seed2's preparation is seed1's copied, seed3's has a NaN as the
  // last void ratio. Both would pass as data: the copy counts one sample twice, the NaN spoils the
  // row's statistics.
  const fs::path dir = fs::path(DEM_BINARY_DIR) / "test_tmp" / "validate_cli_nan_copy";
  fs::remove_all(dir);
  const std::string sample = std::string(DEM_SOURCE_DIR) + "/scenes/samples/dense_1k.h5";
  for (int seed = 1; seed <= 3; ++seed) {
    fs::create_directories(dir / "results" / ("seed" + std::to_string(seed)));
    fs::copy_file(sample, dir / "results" / ("seed" + std::to_string(seed)) / "dense_prepare.h5");
  }
  {
    dem::h5::Handle f = dem::h5::open_file_write((dir / "results" / "seed3" / "dense_prepare.h5").string());
    dem::h5::Handle g = dem::h5::open_group(f, "timeseries");
    std::size_t cols = 0;
    std::vector<double> e = dem::h5::read<double>(g, "void_ratio", cols);
    REQUIRE_FALSE(e.empty());
    e.back() = std::nan("");
    REQUIRE(H5Ldelete(g, "void_ratio", H5P_DEFAULT) >= 0);
    dem::h5::write(g, "void_ratio", e, 1, "1");
  }
  {
    std::ofstream runs(dir / "results" / "runs.tsv");
    runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
    for (int seed = 1; seed <= 3; ++seed)
      runs << "-\tdense\t-\tseed" << seed << "/dense_prepare\t/x/seed" << seed << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
  }
  std::ofstream(dir / "refs.yaml") << "source: lab\nrows:\n  - {name: e0, quantity: void_ratio_after_preparation, reference: 0.6, "
                                      "check: within, tolerance: 0.1, source: lab, reason: r}\n";
  const auto r = validate("--results '" + (dir / "results").string() + "' --references '" + (dir / "refs.yaml").string() + "' --out '" +
                          (dir / "out").string() + "'");
  INFO(r.out);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Contains("error: seed1 and seed2 have the same dense preparation (every value of its last row)"));
  CHECK_THAT(r.out, Catch::Contains("error: row 'e0': sample seed3 gives nan, from " + (dir / "results" / "seed3").string() +
                                    " (dense_prepare): a non-finite number in its results"));
  CHECK_THAT(r.out, !Catch::Contains("seed3 have the same"));
}

TEST_CASE("validate: a result marked complete by hand, without the wall time a run writes, is not read", "[validate][cli][complete]") {
  // Found by a hostile sweep: a killed run's .partial renamed to the result with its status set to
  // "complete" was judged. Two samples, the shipped dense sample as each one's preparation; seed2's
  // lacks wall_time_s (what a .partial lacks): it is listed as not complete, exit 1.
  const fs::path results = fs::path(dem::test::scratch_dir("validate_cli_forged")) / "results";
  std::ofstream runs((fs::create_directories(results), results / "runs.tsv"));
  runs << "# variant\tdensity\ttest\trun\tresult\tstarts_from\tmay_fail\tsettings\tseed\n";
  for (int seed = 1; seed <= 2; ++seed) {
    const fs::path s = results / ("seed" + std::to_string(seed));
    fs::create_directories(s);
    fs::copy_file(std::string(DEM_SOURCE_DIR) + "/scenes/samples/dense_1k.h5", s / "dense_prepare.h5");
    runs << "-\tdense\t-\tseed" << seed << "/dense_prepare\t/x/seed" << seed << "/dense_prepare.h5\t-\t0\tas written\t" << seed << "\n";
  }
  runs.close();
  {
    dem::h5::Handle f = dem::h5::open_file_write((results / "seed2" / "dense_prepare.h5").string());
    REQUIRE(H5Adelete(f, "wall_time_s") >= 0);
  }
  std::ofstream(results.parent_path() / "refs.yaml") << "source: lab\nrows:\n  - {name: e0, quantity: void_ratio_after_preparation, "
                                                        "density: dense, reference: 0.6, check: within, tolerance: 0.2, source: s, reason: r}\n";
  const auto r = validate("--results '" + results.string() + "' --references '" + (results.parent_path() / "refs.yaml").string() +
                          "' --out '" + (results.parent_path() / "out").string() + "'");
  INFO(r.out);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.out, Catch::Contains("no wall_time_s"));
  const nlohmann::json j = nlohmann::json::parse(dem::test::read_bytes((results.parent_path() / "out" / "validation.json").string()));
  CHECK(j.at("missing_results") == nlohmann::json::array({"seed2/dense_prepare.h5"}));
}
