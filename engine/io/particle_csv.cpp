#include "io/particle_csv.hpp"

#include "config/yaml_section.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
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
}  // namespace

std::string read_whole_file(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw std::runtime_error(file + ": is a directory, expected a CSV file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw std::runtime_error(file + ": cannot be read");
  return bytes.str();
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
    if (h != "x,y,z,radius") throw std::runtime_error(file + ": line 1: header must be 'x,y,z,radius', got '" + trim(line) + "'");
  }
  particles = Particles{};
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (trim(line).empty()) continue;
    if (trim(line).back() == ',')
      throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": trailing comma (expected 4 values x,y,z,radius)");
    std::vector<double> v;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) {
      const std::string t = trim(field);
      double x = 0;
      std::string why;  // numbers are read one way everywhere: decimal (config/yaml_section.hpp)
      std::string word = t.substr(!t.empty() && (t[0] == '+' || t[0] == '-') ? 1 : 0);
      for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (word == "nan" || word == "inf" || word == "infinity")
        throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": non-finite value '" + t + "'");
      if (t.empty() || !parse_decimal(t, x, why))
        throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": '" + t + "' is not a number" +
                                 (why.empty() ? "" : " (" + why + ")"));
      if (!std::isfinite(x))
        throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": non-finite value '" + t + "'");
      v.push_back(x);
    }
    if (v.size() != 4)
      throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": expected 4 values x,y,z,radius, got " +
                               std::to_string(v.size()));
    if (!(v[3] > 0))
      throw std::runtime_error(file + ": line " + std::to_string(line_no) + ": radius must be > 0 m, got " + std::to_string(v[3]));
    Vec3 s = Vec3(v[0], v[1], v[2]).cwiseProduct(cell.inverse_lengths());
    PeriodicCell::wrap_any(s);
    particles.add(s, v[3], density_kg_per_m3);
  }
  if (particles.size() == 0) throw std::runtime_error(file + ": no particles after the header");
}

}  // namespace dem
