// Particles from a CSV file (engine/io/particle_csv.hpp): a header `x,y,z,radius`, then one
// sphere per line. Bad files must be refused with std::runtime_error naming the file and the
// line, as the header promises.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "config/scene_config.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/particle_csv.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

const PeriodicCell cell20mm(Vec3(0.02, 0.02, 0.02));

struct BadCsv {
  std::string what, text;
  std::string expected;  // the message after "<file>: "
};

}  // namespace

TEST_CASE("bad particle CSV files are refused naming the file and the line", "[io][csv]") {
  const std::string dir = test::scratch_dir("bad_csv");
  const std::string good = "0.005,0.005,0.005,0.002\n";
  // Lines are counted from 1 at the header, blank lines included, so the number matches an editor's.
  const std::vector<BadCsv> cases = {
      {"missing header (data on line 1)", good + good, "line 1: header must be 'x,y,z,radius', got '0.005,0.005,0.005,0.002'"},
      {"wrong header", "x,y,z,r\n" + good, "line 1: header must be 'x,y,z,radius', got 'x,y,z,r'"},
      {"header with a fifth column", "x,y,z,radius,colour\n" + good, "line 1: header must be 'x,y,z,radius'"},
      {"3 columns", "x,y,z,radius\n" + good + "0.005,0.015,0.005\n", "line 3: expected 4 values x,y,z,radius, got 3"},
      {"5 columns", "x,y,z,radius\n0.005,0.015,0.005,0.002,7\n", "line 2: expected 4 values x,y,z,radius, got 5"},
      {"a word instead of a number", "x,y,z,radius\n0.005,abc,0.005,0.002\n", "line 2: 'abc' is not a number"},
      {"a number with trailing junk", "x,y,z,radius\n0.005,0.005,0.005,2e-3mm\n", "line 2: '2e-3mm' is not a number"},
      {"an empty field", "x,y,z,radius\n0.005,,0.005,0.002\n", "line 2: '' is not a number"},
      {"space-separated values", "x,y,z,radius\n0.005 0.005 0.005 0.002\n", "line 2: '0.005 0.005 0.005 0.002' is not a number"},
      // std::stod accepts "nan" and "inf"; the reader must still refuse them (non-finite).
      {"NaN", "x,y,z,radius\n" + good + "nan,0.005,0.005,0.002\n", "line 3: non-finite value 'nan'"},
      {"infinity", "x,y,z,radius\n0.005,0.005,inf,0.002\n", "line 2: non-finite value 'inf'"},
      {"overflowing number", "x,y,z,radius\n0.005,0.005,1e400,0.002\n", "line 2: '1e400' is not a number"},
      {"negative radius", "x,y,z,radius\n0.005,0.005,0.005,-0.002\n", "line 2: radius must be > 0 m, got -0.002"},
      {"zero radius", "x,y,z,radius\n0.005,0.005,0.005,0\n", "line 2: radius must be > 0 m, got 0"},
      {"a bad line after blank lines", "x,y,z,radius\n\n" + good + "\n0.005,0.005,0.005,-1\n", "line 5: radius must be > 0 m"},
      {"empty file", "", "the file is empty (expected header x,y,z,radius)"},
      {"header only", "x,y,z,radius\n", "no particles after the header"},
      // Geometry, checked when read (io/particle_csv.hpp): a centre more than one radius outside
      // the cell [0, L] (an input error, not a periodic image to wrap in silence).
      {"a sphere far outside the cell", "x,y,z,radius\n" + good + "0.015,0.05,0.005,0.002\n",
       "line 3: y = 0.05 m is outside the cell (0 to 0.02 m, within one radius, 0.002 m)"},
      {"a sphere just over a radius outside", "x,y,z,radius\n" + good + "0.015,0.015,-0.0021,0.002\n",
       "line 3: z = -0.0021 m is outside the cell"},
      // Radii in [1e-6, 1] m: absurd sizes are refused before they reach the time step.
      {"a radius of 1e308 m", "x,y,z,radius\n" + good + "0.015,0.005,0.005,1e308\n",
       "line 3: radius must be between 1e-06 and 1 m, got 1e+308"},
      {"a radius of 1e-300 m", "x,y,z,radius\n" + good + "0.015,0.005,0.005,1e-300\n",
       "line 3: radius must be between 1e-06 and 1 m, got 1e-300"},
      {"one sphere", "x,y,z,radius\n\n" + good, "1 sphere (line 3); a packing needs at least 2"},
      // Two centres closer than 0.5 x the sum of their radii, both lines named: a duplicated line
      // (distance 0), and a pair 1 mm apart across the periodic boundary (x = 0.5 mm and 19.5 mm
      // in a 20 mm cell; radii sum 4 mm, so the limit is 2 mm).
      {"a duplicated line", "x,y,z,radius\n" + good + "0.015,0.015,0.015,0.002\n" + good,
       "lines 2 and 4: centres 0 m apart, closer than 0.5 x the sum of their radii (0.004 m)"},
      {"a deep overlap across the boundary", "x,y,z,radius\n0.0005,0.01,0.01,0.002\n0.01,0.002,0.01,0.002\n0.0195,0.01,0.01,0.002\n",
       "lines 2 and 4: centres 0.001 m apart, closer than 0.5 x the sum of their radii (0.004 m)"},
      // A bad token is repeated, cut to 80 characters, with its length.
      {"a 1000-character token", "x,y,z,radius\n0.005," + std::string(1000, 'a') + ",0.005,0.002\n",
       "line 2: '" + std::string(80, 'a') + "... (1000 characters)' is not a number"},
  };
  int k = 0;
  for (const BadCsv& c : cases) {
    const std::string file = dir + "/case" + std::to_string(k++) + ".csv";
    test::write_text(file, c.text);
    INFO("case: " << c.what << "\n" << c.text);
    Particles p;
    CHECK_THROWS_MATCHES(read_particle_csv(file, cell20mm, 2650, p), std::runtime_error,
                         Catch::Matchers::Predicate<std::exception>(
                             [&](const std::exception& e) { return std::string(e.what()).rfind(file + ": " + c.expected, 0) == 0; },
                             "message starts with '" + file + ": " + c.expected + "'"));
  }
}

TEST_CASE("a particle CSV path that is a directory or missing is refused naming it", "[io][csv]") {
  const std::string dir = test::scratch_dir("csv_paths");
  Particles p;
  CHECK_THROWS_WITH(read_particle_csv(dir, cell20mm, 2650, p), dir + ": is a directory, expected a CSV file");
  CHECK_THROWS_WITH(read_particle_csv(dir + "/none.csv", cell20mm, 2650, p), dir + "/none.csv: cannot be read");
}

TEST_CASE("a valid particle CSV file is read with positions wrapped into the cell", "[io][csv]") {
  const std::string dir = test::scratch_dir("good_csv");
  const std::string file = dir + "/p.csv";
  // Spaces around fields, Windows line ends and blank lines are tolerated (trimmed / skipped).
  // A position within one cell length outside the cell is wrapped by periodicity:
  // x = -0.001 m is the image of 0.019 m, x = 0.021 m the image of 0.001 m (L = 0.02 m).
  test::write_text(file, " x, y ,z,radius \r\n0.005, 0.010 ,0.015,0.002\r\n\r\n-0.001,0.021,0.0,1.5e-3\r\n");
  Particles p;
  read_particle_csv(file, cell20mm, 2000, p);
  REQUIRE(p.size() == 2);
  CHECK(p.s[0].x() == Approx(0.25));
  CHECK(p.s[0].y() == Approx(0.5));
  CHECK(p.s[0].z() == Approx(0.75));
  CHECK(p.s[1].x() == Approx(0.95));
  CHECK(p.s[1].y() == Approx(0.05));
  CHECK(p.s[1].z() == 0.0);
  CHECK(p.radius[0] == 0.002);
  CHECK(p.radius[1] == 1.5e-3);
  // Solid spheres of the given density: m = rho 4/3 pi r^3, I = 2/5 m r^2; at rest.
  const double m0 = 2000 * 4.0 / 3.0 * std::numbers::pi * 8e-9;
  CHECK(p.mass[0] == Approx(m0).epsilon(1e-12));
  CHECK(p.inertia[0] == Approx(0.4 * m0 * 4e-6).epsilon(1e-12));
  CHECK(p.v[1] == Vec3::Zero());
  CHECK(p.omega[1] == Vec3::Zero());
  for (const Vec3& s : p.s) CHECK((s.minCoeff() >= 0.0 && s.maxCoeff() < 1.0));
}

TEST_CASE("a scene reads its CSV file relative to the scene file", "[io][csv][config]") {
  // tests/data/csv_scene/scene.yaml says `csv: particles.csv` (8 spheres in a 20 mm cube).
  const std::string folder = std::string(DEM_SOURCE_DIR) + "/tests/data/csv_scene";
  const SceneConfig scene = load_scene(folder + "/scene.yaml");
  CHECK(std::filesystem::equivalent(scene.particles.path, folder + "/particles.csv"));
  const Simulation sim = build_simulation(scene);
  CHECK(sim.particles().size() == 8);
  CHECK(sim.cell().lengths() == Vec3(0.02, 0.02, 0.02));
  CHECK(sim.particles().radius[6] == 0.0016);

  // A scene whose CSV file is bad: the error names the resolved CSV path and the line, so the
  // user is sent to the right file even though the scene named it relatively.
  const SceneConfig bad = load_scene(folder + "/bad_csv_scene.yaml");
  CHECK_THROWS_WITH(build_simulation(bad), Catch::Matchers::Contains(bad.particles.path + ": line 3: radius must be > 0 m"));
}

TEST_CASE("spheres just touching, and touching across the periodic boundary, are accepted", "[io][csv]") {
  // The overlap limit refuses centres closer than half the sum of their radii, nothing less deep:
  // two spheres in contact (distance = the sum, 4 mm) and two at 2.1 mm across the boundary
  // (x = 1 mm and 18.9 mm in a 20 mm cell) are read.
  const std::string file = test::scratch_dir("csv_touching") + "/p.csv";
  test::write_text(file, "x,y,z,radius\n0.005,0.005,0.005,0.002\n0.009,0.005,0.005,0.002\n0.001,0.015,0.015,0.002\n0.0189,0.015,0.015,0.002\n");
  Particles p;
  read_particle_csv(file, cell20mm, 2650, p);
  CHECK(p.size() == 4);
}

TEST_CASE("a particle file larger than the cap is refused without reading further", "[io][csv]") {
  // /dev/zero never ends: the reader stops at the cap (here 1 MiB; csv_max_bytes for a run).
  CHECK_THROWS_WITH(read_whole_file("/dev/zero", 1u << 20), "/dev/zero: larger than 1 MiB, the most a particle file may hold");
  CHECK(csv_max_bytes == 256u << 20);
}

TEST_CASE("a FIFO without a writer is waited for without blocking: a stop ends the wait, a writer ends it with its bytes", "[io][csv][fifo]") {
  // Found by a hostile sweep: open() of a FIFO waits for a writer, and with the run's signal
  // handlers (SA_RESTART) it was restarted after SIGTERM, so the run never ended. The reader opens
  // without waiting and polls in steps of read_wait_step_ms, reading `stop` between them.
  const std::string dir = test::scratch_dir("csv_fifo_wait");
  const std::string fifo = dir + "/p.csv";
  REQUIRE(mkfifo(fifo.c_str(), 0644) == 0);
  volatile std::sig_atomic_t stop = 0;
  SECTION("no writer: the stop, set 0.3 s in, ends the wait within a step") {
    std::thread signal([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      stop = SIGTERM;
    });
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_AS(read_whole_file(fifo, csv_max_bytes, &stop), ReadStopped);
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    signal.join();
    // 0.3 s, plus one step, plus scheduling on a busy machine; a blocking open never returned.
    CHECK(took >= 0.3);
    CHECK(took < 0.3 + read_wait_step_ms / 1000.0 + 1.0);
  }
  SECTION("a writer that comes after 0.3 s: its bytes, whole") {
    std::string text = "x,y,z,radius\n";
    for (int i = 0; i < 20000; ++i) text += "0.001,0.002,0.003,0.0015\n";  // 500 KB: several pipe buffers
    std::thread writer([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
      std::ofstream(fifo, std::ios::binary) << text;
    });
    const std::string bytes = read_whole_file(fifo, csv_max_bytes, &stop);
    writer.join();
    CHECK(bytes == text);
  }
}

TEST_CASE("a CSV line with a trailing comma (5 fields) is refused", "[io][csv]") {
  // "a,b,c,d," has five fields, the last one empty, like "a,,c,d" (refused as "'' is not a
  // number"); std::getline would drop the empty last field, so the reader checks for it.
  const std::string dir = test::scratch_dir("csv_trailing_comma");
  const std::string file = dir + "/p.csv";
  test::write_text(file, "x,y,z,radius\n0.005,0.005,0.005,0.002\n0.015,0.005,0.005,0.002,\n");
  Particles p;
  CHECK_THROWS_WITH(read_particle_csv(file, cell20mm, 2650, p),
                    file + ": line 3: trailing comma (expected 4 values x,y,z,radius)");
  // Trailing blanks after the comma do not hide it.
  test::write_text(file, "x,y,z,radius\n0.005,0.005,0.005,0.002, \n");
  CHECK_THROWS_WITH(read_particle_csv(file, cell20mm, 2650, p), Catch::Matchers::StartsWith(file + ": line 2: trailing comma"));
  // Control: the same line without the comma (and with trailing blanks) is read (with a second
  // sphere: a packing needs 2).
  test::write_text(file, "x,y,z,radius\n0.005,0.005,0.005,0.002 \n0.015,0.005,0.005,0.002\n");
  Particles ok;
  read_particle_csv(file, cell20mm, 2650, ok);
  CHECK(ok.size() == 2);
}
