#include "figures/figure_bounds.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/series.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

// FILE as a table; none when it is not there.
std::optional<Table> data_file(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return std::nullopt;
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read");
  std::ostringstream s;
  s << in.rdbuf();
  return table_from_text(s.str(), file.string());
}

std::size_t column_of(const Table& t, const std::string& name, const fs::path& file) {
  for (std::size_t k = 0; k < t.columns.size(); ++k)
    if (t.columns[k] == name || t.columns[k].rfind(name + " [", 0) == 0) return k;
  throw std::runtime_error(file.string() + ": no column '" + name + "'");
}

}  // namespace

std::string within_text(double lo, double hi, int decimals) {
  const std::string a = bound_text(lo, Bound::at_least, decimals, Digits::decimals);
  const std::string b = bound_text(hi, Bound::at_most, decimals, Digits::decimals);
  return a == b ? a : a + "–" + b;
}

std::string fig04_p_text(const MinMax& p_kPa) { return within_text(p_kPa.lo, p_kPa.hi, 2); }

std::string fig07_max_abs_text(double max_abs_percent) { return bound_text(max_abs_percent, Bound::below, 2); }

std::string energy_closure_text(double fraction) { return bound_text(100 * fraction, Bound::at_most, 2); }

void add_figure_bounds(Values& v, const fs::path& figures, std::optional<int> last_cycle) {
  for (const std::string& d : paper_densities()) {
    MinMax p, ev;
    for (int t = 1; t <= 5; ++t) {
      const std::string test = d + "_test" + std::to_string(t) + ".dat";
      const fs::path q_p = figures / ("fig04_q_p_" + test), cycles = figures / ("fig07_epsv_cycles_" + test);
      if (const std::optional<Table> table = data_file(q_p)) {
        const std::size_t k = column_of(*table, "p", q_p);
        for (const auto& row : table->rows) p.add(row[k]);
      }
      if (const std::optional<Table> table = data_file(cycles); table && last_cycle) {
        const std::size_t c = column_of(*table, "cycle", cycles), mean = column_of(*table, "mean", cycles);
        for (const auto& row : table->rows)
          if (row[c] <= *last_cycle && std::isfinite(row[mean])) ev.add(std::abs(row[mean]));
      }
    }
    if (p.any()) v["fig04.p_" + d] = fig04_p_text(p);
    if (ev.any()) v["fig07.max_abs_" + d] = fig07_max_abs_text(ev.hi);
    const fs::path energy = figures / ("fig_energy_" + d + "_test1.dat");
    if (const std::optional<Table> table = data_file(energy); table && !table->rows.empty()) {
      const std::size_t work = column_of(*table, "work_by_cell", energy), gap = column_of(*table, "gap", energy);
      const double total = std::abs(table->rows.back()[work]);
      double worst = 0;
      for (const auto& row : table->rows) worst = std::max(worst, std::abs(row[gap]));
      if (total > 0) v["energy.closure_" + d] = energy_closure_text(worst / total);
    }
  }
}

}  // namespace validation
