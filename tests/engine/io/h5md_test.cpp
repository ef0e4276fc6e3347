// The H5MD particle frames of a result and the XDMF beside it (engine/io/h5md.hpp, io/xdmf.hpp):
// read back by an independent reader (the HDF5 command-line tools) as well as by our own API.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"
#include "run/run_scene.hpp"
#include "version.hpp"

using namespace dem;
namespace fs = std::filesystem;

namespace {

// 500 steps of slow isotropic compression (dt = 1 us): the cell, and so x = L o s, changes.
const std::string squeeze_stage = "  - {name: squeeze, type: strain_rate, strain_rate: [0.1, 0.1, 0.1], duration: 5.0e-4}\n";

// h5ls -r: each object's path mapped to the rest of its line (e.g. "Dataset {2/Inf, 27, 3}").
std::map<std::string, std::string> h5ls(const std::string& file) {
  const test::CommandResult r = test::run_command("h5ls -r '" + file + "' 2>&1");
  REQUIRE(r.exit_code == 0);
  std::map<std::string, std::string> objects;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t gap = line.find(' ');
    if (gap == std::string::npos) continue;
    const std::size_t kind = line.find_first_not_of(' ', gap);
    objects[line.substr(0, gap)] = kind == std::string::npos ? "" : line.substr(kind);
  }
  return objects;
}

std::string h5md_unit_of(hid_t file, const std::string& dataset) {
  h5::Handle ds(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  return h5::has_attribute(ds, "unit") ? h5::get_string_attribute(ds, "unit") : "<none>";
}

// Every value of a dataset of any rank, in storage order.
std::vector<double> read_all(hid_t file, const std::string& dataset) {
  h5::Handle ds(H5Dopen2(file, dataset.c_str(), H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  h5::Handle space(H5Dget_space(ds));
  std::vector<double> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  REQUIRE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0);
  return out;
}

// The files FILE.tmp* beside `file`: what an atomic write of it left behind.
int temps_beside(const std::string& file) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(file).parent_path()))
    if (e.path().filename().string().rfind(fs::path(file).filename().string() + ".tmp", 0) == 0) ++n;
  return n;
}

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("a result holds H5MD particle frames at the start and end of the run, and an XDMF beside it", "[io][h5md]") {
  if (!test::have_program("h5ls") || !test::have_program("h5dump")) {
    WARN("h5ls/h5dump not installed (package hdf5-tools): skipped");
    return;
  }
  const std::string dir = test::scratch_dir("h5md_complete");
  const SceneConfig scene = scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml");
  run_scene(scene, dir + "/r.h5");
  const std::size_t n = 27;

  SECTION("h5ls sees the H5MD layout: two frames of N x 3, shared step and time, the box") {
    const auto objects = h5ls(dir + "/r.h5");
    for (const std::string element : {"position", "velocity", "angular_velocity"}) {
      INFO(element);
      CHECK(objects.at("/particles/all/" + element + "/value") == "Dataset {2/Inf, 27, 3}");
    }
    // Every element's step and time are one dataset each, hard-linked (H5MD allows sharing them):
    // h5ls describes it at the first path it visits and refers to that path afterwards.
    for (const std::string element : {"position", "velocity", "angular_velocity", "box/edges"})
      for (const std::string name : {"step", "time"}) {
        std::string line = objects.at("/particles/all/" + element + "/" + name);
        const std::string same = "Dataset, same as ";
        if (line.rfind(same, 0) == 0) line = objects.at(line.substr(same.size()));
        INFO(element << "/" << name);
        CHECK(line == "Dataset {2/Inf}");
      }
    CHECK(objects.at("/particles/all/box/edges/value") == "Dataset {2/Inf, 3}");
    CHECK(objects.at("/particles/all/radius") == "Dataset {27}");
    CHECK(objects.at("/particles/all/mass") == "Dataset {27}");
    CHECK(objects.at("/h5md/author") == "Group");
    CHECK(objects.at("/state/position") == "Dataset {27, 3}");  // the continuation state is still there
  }
  SECTION("h5dump sees the H5MD version and the box attributes") {
    const test::CommandResult v = test::run_command("h5dump -a /h5md/version '" + dir + "/r.h5' 2>&1");
    INFO(v.out);
    CHECK(v.out.find("DATASPACE  SIMPLE { ( 2 ) / ( 2 ) }") != std::string::npos);
    CHECK(v.out.find("(0): 1, 1") != std::string::npos);
    const test::CommandResult b = test::run_command("h5dump -A -g /particles/all/box '" + dir + "/r.h5' 2>&1");
    INFO(b.out);
    CHECK(b.out.find("(0): \"periodic\", \"periodic\", \"periodic\"") != std::string::npos);
    CHECK(b.out.find("ATTRIBUTE \"dimension\"") != std::string::npos);
  }
  h5::Handle f = h5::open_file_read(dir + "/r.h5");
  SECTION("metadata and units") {
    CHECK(h5::get_int_attribute(f, "schema_version") == schema_version);
    CHECK(h5::get_string_attribute(h5::open_group(f, "h5md/author"), "name") == "cyclic-triax");
    h5::Handle creator = h5::open_group(f, "h5md/creator");
    CHECK(h5::get_string_attribute(creator, "name") == "dem");
    CHECK(h5::get_string_attribute(creator, "version") == software_version);
    CHECK(h5::get_int_attribute(h5::open_group(f, "particles/all/box"), "dimension") == 3);
    const std::map<std::string, std::string> units = {
        {"position/value", "m"},  {"position/time", "s"},       {"velocity/value", "m s-1"},
        {"angular_velocity/value", "rad s-1"}, {"box/edges/value", "m"}, {"radius", "m"}, {"mass", "kg"}};
    for (const auto& [name, unit] : units) {
      INFO(name);
      CHECK(h5md_unit_of(f, "/particles/all/" + name) == unit);
    }
  }
  SECTION("frames: steps 0 and 500, the first positions are L o s of the initial particles") {
    std::size_t cols = 0;
    CHECK(h5::read<std::int64_t>(f, "particles/all/position/step", cols) == std::vector<std::int64_t>{0, 500});
    const auto time = h5::read<double>(f, "particles/all/position/time", cols);
    REQUIRE(time.size() == 2);
    CHECK(time[0] == 0);
    CHECK(time[1] == Approx(5e-4).epsilon(1e-12));

    // The initial particles, built again from the scene (the build is deterministic).
    const Simulation start = build_simulation(scene);
    const Vec3 L0 = start.cell().lengths();
    // Frame 0 is the first N x 3 values.
    const auto x = read_all(f, "/particles/all/position/value");
    REQUIRE(x.size() == 2 * n * 3);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) {
        const double expected = L0[k] * start.particles().s[i][k];
        CHECK(std::abs(x[3 * i + k] - expected) <= 1e-12 * std::abs(expected));
      }
    // The last frame's edges are the final cell lengths, also recorded in /state.
    const auto edges = h5::read<double>(f, "particles/all/box/edges/value", cols);
    CHECK(cols == 3);
    const auto L_end = h5::read<double>(h5::open_group(f, "state"), "cell_lengths", cols);
    CHECK(std::vector<double>(edges.begin() + 3, edges.end()) == L_end);
    CHECK(std::vector<double>(edges.begin(), edges.begin() + 3) == std::vector<double>{L0[0], L0[1], L0[2]});
    CHECK(h5::read<double>(f, "particles/all/radius", cols) == start.particles().radius);
  }
  SECTION("the XDMF names the datasets by relative path, one Polyvertex grid per frame") {
    REQUIRE(fs::exists(dir + "/r.xdmf"));
    CHECK(temps_beside(dir + "/r.xdmf") == 0);  // written through r.xdmf.tmp.<pid>.<n> (io/atomic_file.hpp)
    const std::string xml = test::read_bytes(dir + "/r.xdmf");
    CHECK(count(xml, "CollectionType=\"Temporal\"") == 1);
    CHECK(count(xml, "TopologyType=\"Polyvertex\" NodesPerElement=\"27\"") == 2);
    CHECK(count(xml, "<Time Value=") == 2);
    CHECK(count(xml, ">r.h5:/particles/all/position/value<") == 2);
    CHECK(count(xml, ">r.h5:/particles/all/velocity/value<") == 2);
    CHECK(count(xml, ">r.h5:/particles/all/radius<") == 2);
    CHECK(count(xml, "Dimensions=\"2 27 3\"") == 6);  // three vector datasets per frame, each 2 frames long
    CHECK(count(xml, dir) == 0);                     // no absolute paths
    // Per frame the cell as its 12 edges (lines that hide nothing), corners from /frames/cell_corners.
    CHECK(count(xml, "TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"12\"") == 2);
    CHECK(count(xml, ">0 1 2 3 4 5 6 7 0 2 1 3 4 6 5 7 0 4 1 5 2 6 3 7<") == 2);
    CHECK(count(xml, ">r.h5:/frames/cell_corners<") == 2);
    CHECK(count(xml, "Hexahedron") == 0);
    if (test::have_program("xmllint")) CHECK(test::run_command("xmllint --noout '" + dir + "/r.xdmf' 2>&1").exit_code == 0);
  }
}

TEST_CASE("frames come at their own interval, whatever output.interval is", "[io][h5md][frames]") {
  // 500 steps, rows every 200 steps, frames every 150: frames at 0 (the start), 150, 300, 450 and
  // 500 (the end); a frame interval that is no multiple of the row interval was refused before
  // ("not a multiple of output.interval"), and the frames came only with rows. Rows are unchanged:
  // 0, 200, 400, and the stage's end 500.
  const std::string dir = test::scratch_dir("h5md_frame_interval");
  const SceneConfig scene = scene_from_text(
      test::tiny_scene(squeeze_stage, "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}",
                       "output: {interval: 200, frames: {interval: 150}}\n"),
      dir + "/s.yaml");
  run_scene(scene, dir + "/r.h5");
  h5::Handle f = h5::open_file_read(dir + "/r.h5");
  std::size_t cols = 0;
  CHECK(h5::read<std::int64_t>(f, "particles/all/position/step", cols) == std::vector<std::int64_t>{0, 150, 300, 450, 500});
  const std::vector<double> row_time = h5::read<double>(f, "timeseries/time", cols);
  std::vector<long> row_steps;
  for (double t : row_time) row_steps.push_back(std::lround(t / 1e-6));
  CHECK(row_steps == std::vector<long>{0, 200, 400, 500});
}

// A result written before /frames existed: its cell's outline from the box lengths of each frame,
// written into the XML: corner k at (k & 1, k >> 1 & 1, k >> 2 & 1) L. Made from a shipped sample
// with its /frames group taken out (the samples are remade by today's engine, which writes it).
TEST_CASE("the XDMF of a result without cell corners outlines the box of each frame", "[io][h5md]") {
  const std::string dir = test::scratch_dir("h5md_no_corners");
  fs::copy_file(std::string(DEM_SOURCE_DIR) + "/scenes/samples/dense_1k.h5", dir + "/s.h5");
  {
    h5::Handle f = h5::open_file_write(dir + "/s.h5");
    if (h5::exists(f, "frames")) REQUIRE(H5Ldelete(f.id(), "frames", H5P_DEFAULT) >= 0);
  }
  std::vector<double> L;
  {
    h5::Handle f = h5::open_file_read(dir + "/s.h5");
    REQUIRE_FALSE(h5::exists(f, "frames"));
    std::size_t cols = 0;
    L = h5::read<double>(h5::open_group(f, "particles/all"), "box/edges/value", cols);
  }
  REQUIRE(L.size() == 6);  // two frames: the lattice and the end
  write_xdmf(dir + "/s.h5");
  const std::string xml = test::read_bytes(dir + "/s.xdmf");
  CHECK(count(xml, "NumberOfElements=\"12\"") == 2);
  for (std::size_t frame = 0; frame < 2; ++frame) {
    std::string corners;
    for (int k = 0; k < 8; ++k)
      for (std::size_t axis = 0; axis < 3; ++axis) {
        char v[32];
        std::snprintf(v, sizeof v, "%.17g", L[3 * frame + axis]);
        corners += std::string(k || axis ? " " : "") + ((k >> axis) & 1 ? v : "0");
      }
    INFO(corners);
    CHECK(count(xml, ">" + corners + "</DataItem>") == 1);
  }
  CHECK(count(xml, ">s.h5:/particles/all/position/value<") == 2);
}

TEST_CASE("a failed run leaves no XDMF, and its partial result holds only the frames it wrote", "[io][h5md]") {
  // The stress stage cannot finish in 10 us (see result_file_test.cpp): StageError.
  const std::string dir = test::scratch_dir("h5md_failed");
  const std::string stage =
      "  - {name: consolidate, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1.0e-5}}\n";
  const SceneConfig bad = scene_from_text(test::tiny_scene(stage), dir + "/bad.yaml");
  CHECK_THROWS_AS(run_scene(bad, dir + "/r.h5"), StageError);
  CHECK_FALSE(fs::exists(dir + "/r.xdmf"));
  CHECK(temps_beside(dir + "/r.xdmf") == 0);
  h5::Handle f = h5::open_file_read(dir + "/r.h5.partial");
  std::size_t cols = 0;
  CHECK(h5::read<std::int64_t>(f, "particles/all/position/step", cols) == std::vector<std::int64_t>{0});
  CHECK(h5::shape(f, "particles/all/position/value") == std::vector<hsize_t>{1, 27, 3});
}

TEST_CASE("the XDMF of a result is named after it", "[io][h5md]") {
  CHECK(xdmf_path_for("out/R.h5") == "out/R.xdmf");
  CHECK(xdmf_path_for("R.hdf5") == "R.hdf5.xdmf");
  CHECK(xdmf_path_for(".h5") == ".h5.xdmf");
}

TEST_CASE("a complete run replaces the XDMF of an earlier result, a failed one leaves it with its result", "[io][h5md]") {
  const std::string dir = test::scratch_dir("h5md_replace");
  const std::string stale = "<!-- an earlier result's XDMF -->\n";
  test::write_text(dir + "/r.h5", "an earlier result\n");
  test::write_text(dir + "/r.xdmf", stale);
  // A failed run touches neither the earlier result nor the XDMF that describes it.
  const SceneConfig bad = scene_from_text(
      test::tiny_scene("  - {name: c, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e6, hold: {max_duration: 1.0e-5}}\n"),
      dir + "/bad.yaml");
  CHECK_THROWS_AS(run_scene(bad, dir + "/r.h5"), StageError);
  CHECK(test::read_bytes(dir + "/r.xdmf") == stale);
  // A complete run replaces both.
  run_scene(scene_from_text(test::tiny_scene(squeeze_stage), dir + "/s.yaml"), dir + "/r.h5");
  CHECK(count(test::read_bytes(dir + "/r.xdmf"), "<Time Value=") == 2);
}
