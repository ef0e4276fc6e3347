#include "bench/lammps_log.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace dem::bench {

namespace {

std::vector<std::string> fields(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool starts(const std::string& line, const char* prefix) { return line.rfind(prefix, 0) == 0; }

// Field k (1-based, as awk's $k) as a number; an error naming the line when it is not there.
double field(const std::vector<std::string>& f, std::size_t k, const std::string& line) {
  if (k > f.size()) throw std::runtime_error("lammps log: no field " + std::to_string(k) + " in '" + line + "'");
  char* end = nullptr;
  const double x = std::strtod(f[k - 1].c_str(), &end);
  if (end == f[k - 1].c_str()) throw std::runtime_error("lammps log: field " + std::to_string(k) + " of '" + line + "' is not a number");
  return x;
}

// sorted[n / 2] (as dem-bench's median), after sorting.
double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

}  // namespace

double six_digits(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return std::strtod(buf, nullptr);
}

nlohmann::ordered_json lammps_runs(const std::string& log_text, double friction, int reps, std::optional<double> peak_rss_kB) {
  if (reps < 1) throw std::invalid_argument("lammps log: reps must be at least 1");
  std::vector<double> rate, cpu;
  double neigh = 0, z0 = 0, z1 = 0, p0 = 0, p1 = 0;
  long long builds = 0, dangerous = 0;
  int ends = 0;
  bool timed = false;
  std::istringstream in(log_text);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = fields(line);
    if (starts(line, "BENCH timed")) timed = true;
    if (starts(line, "Loop time of") && timed) rate.push_back(field(f, 9, line) * field(f, 12, line) / field(f, 4, line));
    if (line.find("% CPU use with") != std::string::npos && timed && !rate.empty()) {
      const double c = field(f, 1, line);  // "99.8%": strtod stops at the '%'
      cpu.resize(rate.size(), 0.0);
      cpu.back() = c > 0 ? rate.back() * 100 / c : rate.back();
    }
    if (starts(line, "Ave neighs/atom") && timed) neigh += field(f, 4, line) / reps;
    if (starts(line, "Neighbor list builds") && timed) builds += static_cast<long long>(field(f, 5, line));
    // Every run's dangerous builds (the warm-up's and `run 0`'s too), as the script always counted.
    if (starts(line, "Dangerous builds")) dangerous += static_cast<long long>(field(f, 4, line)), timed = false;
    if (starts(line, "BENCH warm")) z0 += field(f, 4, line) / reps, p0 += field(f, 6, line) / reps;
    if (starts(line, "BENCH end")) z1 += field(f, 4, line) / reps, p1 += field(f, 6, line) / reps, ++ends;
  }
  if (static_cast<int>(rate.size()) != reps || ends != reps)
    throw std::runtime_error("lammps log: expected " + std::to_string(reps) + " timed runs and 'BENCH end' lines, found " +
                             std::to_string(rate.size()) + " and " + std::to_string(ends));
  cpu.resize(rate.size(), 0.0);
  nlohmann::ordered_json r;
  r["friction"] = friction;
  r["particle_steps_per_s_median"] = six_digits(median(rate));
  r["min"] = six_digits(*std::min_element(rate.begin(), rate.end()));
  r["max"] = six_digits(*std::max_element(rate.begin(), rate.end()));
  r["cpu_rate_median"] = six_digits(median(cpu));
  r["coordination_number_start"] = six_digits(z0);
  r["coordination_number_end"] = six_digits(z1);
  r["neighbours_per_atom"] = six_digits(2 * neigh);
  r["pressure_Pa_start"] = six_digits(p0);
  r["pressure_Pa_end"] = six_digits(p1);
  r["neighbour_list_builds"] = builds;
  r["dangerous_builds"] = dangerous;
  if (peak_rss_kB) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", *peak_rss_kB / 1024);
    r["peak_rss_MB"] = std::strtod(buf, nullptr);
  }
  return r;
}

std::string lammps_version(const std::string& log_text) {
  const std::string first = log_text.substr(0, log_text.find('\n'));
  if (starts(first, "LAMMPS (") && first.size() > 9 && first.back() == ')') return first.substr(8, first.size() - 9);
  return first;
}

std::string lammps_runs_header() {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%-9s %-23s %-25s %-14s %-16s %-11s %s\n", "friction", "particle-steps/s (med)", "min .. max", "2Nc/N",
                "p (kPa)", "neigh/atom", "list builds");
  return buf;
}

std::string lammps_runs_line(const nlohmann::ordered_json& r) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-9g %-23.3e %.3e .. %.3e %5.2f -> %-5.2f %6.1f -> %-6.1f %-11.2f %lld (dangerous %lld)\n",
                r.at("friction").get<double>(), r.at("particle_steps_per_s_median").get<double>(), r.at("min").get<double>(),
                r.at("max").get<double>(), r.at("coordination_number_start").get<double>(), r.at("coordination_number_end").get<double>(),
                r.at("pressure_Pa_start").get<double>() / 1e3, r.at("pressure_Pa_end").get<double>() / 1e3,
                r.at("neighbours_per_atom").get<double>(), r.at("neighbour_list_builds").get<long long>(),
                r.at("dangerous_builds").get<long long>());
  return buf;
}

}  // namespace dem::bench
