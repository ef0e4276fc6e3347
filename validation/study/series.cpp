#include "study/series.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

Table table_from_text(const std::string& text, const std::string& what) {
  Table t;
  std::vector<std::string> comments;
  std::size_t start = 0, line_number = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1, ++line_number;
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (t.rows.empty()) comments.push_back(line.substr(line.rfind("# ", 0) == 0 ? 2 : 1));
      continue;
    }
    if (t.columns.empty()) {
      if (comments.empty()) throw std::runtime_error(what + ": no column names before the first row");
      std::string header = comments.back();
      comments.pop_back();
      if (header.rfind("label\t", 0) == 0) header = header.substr(6);
      for (std::size_t a = 0; a <= header.size();) {
        const std::size_t b = std::min(header.find('\t', a), header.size());
        std::string name = header.substr(a, b - a);
        name.erase(0, name.find_first_not_of(' '));
        name.erase(name.find_last_not_of(' ') + 1);
        t.columns.push_back(name);
        a = b + 1;
      }
      t.comments = comments;
    }
    std::vector<double> row;
    const char* p = line.c_str();
    if (*p == '"') {  // a label: not kept
      for (++p; *p && *p != '"'; ++p)
        if (*p == '\\' && p[1]) ++p;
      if (*p) ++p;
    }
    for (char* next = nullptr;; p = next) {
      while (*p == '\t' || *p == ' ') ++p;
      if (!*p) break;
      row.push_back(std::strtod(p, &next));
      if (next == p) throw std::runtime_error(what + ": line " + std::to_string(line_number) + " is not numbers: " + line);
    }
    if (row.size() != t.columns.size())
      throw std::runtime_error(what + ": line " + std::to_string(line_number) + " has " + std::to_string(row.size()) + " values for " +
                               std::to_string(t.columns.size()) + " columns");
    t.rows.push_back(std::move(row));
  }
  return t;
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
