#include "io/particle_csv.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include "config/yaml_section.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace dem {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// A token as an error repeats it: at most csv_max_echo characters, then how long it was.
std::string echo(const std::string& t) {
  if (t.size() <= csv_max_echo) return t;
  return t.substr(0, csv_max_echo) + "... (" + std::to_string(t.size()) + " characters)";
}

std::string number_text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

[[noreturn]] void bad_line(const std::string& file, int line, const std::string& what) {
  throw std::runtime_error(file + ": line " + std::to_string(line) + ": " + what);
}

// One value of a line, checked: a decimal number, finite.
double field_value(const std::string& field, const std::string& file, int line_no) {
  const std::string t = trim(field);
  double x = 0;
  std::string why;  // numbers are read one way everywhere: decimal (config/yaml_section.hpp)
  std::string word = t.substr(!t.empty() && (t[0] == '+' || t[0] == '-') ? 1 : 0, 16);
  for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (word == "nan" || word == "inf" || word == "infinity") bad_line(file, line_no, "non-finite value '" + t + "'");
  if (t.empty() || !parse_decimal(t, x, why))
    bad_line(file, line_no, "'" + echo(t) + "' is not a number" + (why.empty() ? "" : " (" + echo(why) + ")"));
  if (!std::isfinite(x)) bad_line(file, line_no, "non-finite value '" + echo(t) + "'");
  return x;
}

// The sphere of one line, checked on its own: its radius in range, its centre at most one radius
// outside the cell [0, L] on each axis.
void check_sphere(const Vec3& x, double r, const PeriodicCell& cell, const std::string& file, int line_no) {
  if (!(r > 0)) bad_line(file, line_no, "radius must be > 0 m, got " + number_text(r));
  if (r < csv_min_radius_m || r > csv_max_radius_m)
    bad_line(file, line_no, "radius must be between " + number_text(csv_min_radius_m) + " and " + number_text(csv_max_radius_m) +
                                " m, got " + number_text(r));
  static const char* axis = "xyz";
  for (int k = 0; k < 3; ++k)
    if (x[k] < -r || x[k] > cell.lengths()[k] + r)
      bad_line(file, line_no, std::string(1, axis[k]) + " = " + number_text(x[k]) + " m is outside the cell (0 to " +
                                  number_text(cell.lengths()[k]) + " m, within one radius, " + number_text(r) + " m)");
}

// No two centres (nearest periodic images) closer than csv_min_centre_distance x the sum of their
// radii: coincident or deeply overlapping spheres, e.g. a line given twice. Spheres are binned on a
// grid of cells at least as wide as the largest such distance, so each is compared only with the
// spheres of its own and the neighbouring bins.
void check_overlaps(const Particles& p, const std::vector<int>& lines, const PeriodicCell& cell, const std::string& file) {
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  const double reach = 2 * csv_min_centre_distance * r_max;
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) n[k] = std::clamp(static_cast<int>(cell.lengths()[k] / reach), 1, 64);  // at most 64^3 bins
  const auto bin_of = [&](const Vec3& s) {
    std::array<int, 3> b{};
    for (int k = 0; k < 3; ++k) b[k] = std::min(n[k] - 1, static_cast<int>(s[k] * n[k]));
    return b;
  };
  const auto index = [&](const std::array<int, 3>& b) { return (static_cast<std::size_t>(b[0]) * n[1] + b[1]) * n[2] + b[2]; };
  std::vector<std::vector<std::size_t>> bins(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  for (std::size_t i = 0; i < p.size(); ++i) bins[index(bin_of(p.s[i]))].push_back(i);
  // The neighbouring bins of an axis, each once (fewer than 3 bins: all of them).
  const auto around = [&](int k, int b) {
    std::vector<int> out;
    for (int d = -1; d <= 1; ++d) {
      const int c = ((b + d) % n[k] + n[k]) % n[k];
      if (std::find(out.begin(), out.end(), c) == out.end()) out.push_back(c);
    }
    return out;
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::array<int, 3> b = bin_of(p.s[i]);
    for (int bx : around(0, b[0]))
      for (int by : around(1, b[1]))
        for (int bz : around(2, b[2]))
          for (std::size_t j : bins[index({bx, by, bz})]) {
            if (j <= i) continue;
            const double d = cell.branch(p.s[i], p.s[j]).norm(), sum = p.radius[i] + p.radius[j];
            if (d < csv_min_centre_distance * sum)
              throw std::runtime_error(file + ": lines " + std::to_string(lines[i]) + " and " + std::to_string(lines[j]) +
                                       ": centres " + number_text(d) + " m apart, closer than " + number_text(csv_min_centre_distance) +
                                       " x the sum of their radii (" + number_text(sum) +
                                       " m): coincident or deeply overlapping spheres (a line given twice?)");
          }
  }
}
}  // namespace

std::string read_whole_file(const std::string& file, std::size_t max_bytes, const volatile std::sig_atomic_t* stop) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw std::runtime_error(file + ": is a directory, expected a CSV file");
  // O_NONBLOCK: open() of a FIFO returns at once instead of waiting (with the run's signal
  // handlers installed with SA_RESTART, a wait in open() or read() was restarted after every
  // signal, so nothing but SIGKILL ended it). poll() waits instead, in steps, and a FIFO opened
  // this way reports no hang-up before a writer has come: it waits for the first writer.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(file + ": cannot be read");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  std::string bytes;
  std::vector<char> chunk(1 << 16);
  for (;;) {
    if (stop && *stop) throw ReadStopped(file);
    pollfd ready{fd, POLLIN, 0};
    const int n_ready = ::poll(&ready, 1, read_wait_step_ms);  // a regular file is ready at once
    if (n_ready < 0 && errno != EINTR) throw std::runtime_error(file + ": cannot be read");
    if (n_ready <= 0) continue;
    const ssize_t n = ::read(fd, chunk.data(), chunk.size());
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) continue;
    if (n < 0) throw std::runtime_error(file + ": cannot be read");
    if (n == 0) break;
    bytes.append(chunk.data(), static_cast<std::size_t>(n));
    if (bytes.size() > max_bytes)
      throw std::runtime_error(file + ": larger than " + std::to_string(max_bytes >> 20) + " MiB, the most a particle file may hold");
  }
  return bytes;
}

void read_particle_csv(const std::string& file, const PeriodicCell& cell, double density_kg_per_m3, Particles& particles) {
  parse_particle_csv(read_whole_file(file), file, cell, density_kg_per_m3, particles);
}

void parse_particle_csv(const std::string& text, const std::string& file, const PeriodicCell& cell, double density_kg_per_m3,
                        Particles& particles) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + ": the file is empty (expected header x,y,z,radius)");
  {
    std::string h;
    for (char ch : trim(line)) if (ch != ' ') h += ch;
    if (h != "x,y,z,radius") throw std::runtime_error(file + ": line 1: header must be 'x,y,z,radius', got '" + echo(trim(line)) + "'");
  }
  particles = Particles{};
  std::vector<int> lines;  // the line of each sphere, for the errors that name two
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (trim(line).empty()) continue;
    if (trim(line).back() == ',') bad_line(file, line_no, "trailing comma (expected 4 values x,y,z,radius)");
    std::vector<double> v;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) v.push_back(field_value(field, file, line_no));
    if (v.size() != 4) bad_line(file, line_no, "expected 4 values x,y,z,radius, got " + std::to_string(v.size()));
    const Vec3 x(v[0], v[1], v[2]);
    check_sphere(x, v[3], cell, file, line_no);
    Vec3 s = x.cwiseProduct(cell.inverse_lengths());
    PeriodicCell::wrap_any(s);
    particles.add(s, v[3], density_kg_per_m3);
    lines.push_back(line_no);
  }
  if (particles.size() == 0) throw std::runtime_error(file + ": no particles after the header");
  if (particles.size() < 2)
    throw std::runtime_error(file + ": 1 sphere (line " + std::to_string(lines[0]) + "); a packing needs at least 2");
  check_overlaps(particles, lines, cell, file);
}

}  // namespace dem
