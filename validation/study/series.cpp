#include "study/series.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/fabric.hpp"
#include "analysis/measurements.hpp"
#include "study/columns.hpp"

namespace validation {

std::string format_number(double x) {
  if (std::isnan(x)) return "NaN";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string Table::text() const {
  std::string out;
  for (const std::string& c : comments) out += "# " + c + "\n";
  out += "#";
  if (!labels.empty()) out += " label\t";
  for (std::size_t k = 0; k < columns.size(); ++k) {
    out += k ? '\t' : ' ';
    out += columns[k];
  }
  out += "\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0 && std::find(block_starts.begin(), block_starts.end(), i) != block_starts.end()) out += "\n\n";
    if (!labels.empty()) out += quoted(labels[i]) + "\t";
    for (std::size_t k = 0; k < rows[i].size(); ++k) {
      if (k) out += '\t';
      out += format_number(rows[i][k]);
    }
    out += "\n";
  }
  return out;
}

double Table::at(std::size_t row, const std::string& name) const {
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k] == name || columns[k].rfind(name + " [", 0) == 0) return rows.at(row).at(k);
  throw std::out_of_range("no column '" + name + "'");
}

std::size_t row_count(const Columns& series) {
  const auto it = series.find(col::step);
  return it == series.end() ? (series.empty() ? 0 : series.begin()->second.size()) : it->second.size();
}

dem::Mat3 stress_of(const SeriesRow& r) {
  dem::Mat3 s;
  s << r(col::stress_11), r(col::stress_12), r(col::stress_13),  //
      r(col::stress_12), r(col::stress_22), r(col::stress_23),   //
      r(col::stress_13), r(col::stress_23), r(col::stress_33);
  return s;
}

double q_over_p(const dem::Mat3& stress_Pa) {
  const double p = dem::mean_stress(stress_Pa);
  return p > 0 ? dem::deviator_stress(stress_Pa) / p : 0.0;
}

Eigen::Vector2d pi_stress(const dem::Vec3& principal_Pa) {
  const double p = principal_Pa.sum() / 3;
  return p > 0 ? Eigen::Vector2d(dem::pi_plane(principal_Pa) / p) : Eigen::Vector2d::Zero();
}

double fabric_ratio_of(const SeriesRow& r, const std::string& which) {
  dem::Mat3 f;
  const auto c = [&](const char* ij) { return r(which + "_" + ij); };
  f << c("11"), c("12"), c("13"), c("12"), c("22"), c("23"), c("13"), c("23"), c("33");
  const double m = dem::mean_invariant(f);
  return m > 0 ? dem::deviator_invariant(f) / m : 0.0;
}

void GnuplotValues::number(const std::string& name, double value) { lines_.emplace_back(name, format_number(value)); }
void GnuplotValues::text(const std::string& name, const std::string& value) { lines_.emplace_back(name, quoted(value)); }
void GnuplotValues::texts(const std::string& name, const std::vector<std::string>& values) {
  lines_.emplace_back(name + "_n", std::to_string(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k) lines_.emplace_back(name + "_" + std::to_string(k + 1), quoted(values[k]));
}

std::string GnuplotValues::text_file(const std::string& comment) const {
  std::string out = "# " + comment + "\n";
  for (const auto& [name, value] : lines_) out += name + " = " + value + "\n";
  return out;
}

}  // namespace validation
