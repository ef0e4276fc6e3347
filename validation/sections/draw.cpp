#include "sections/draw.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;

namespace sections {

const std::vector<SectionFigure>& section_figures(const std::string& mode) {
  static const std::map<std::string, std::vector<SectionFigure>> figures = {
      {"convergence", {{"convergence_error_vs_time", "", ""}}},
      {"decisions", {{"tornado", "", ""}}},
      {"critical-state",
       {{"critical_state_phi_mu", "", ""},
        {"critical_state_e_cn_mu", "", ""},
        {"critical_state_pi_plane", "", ""},
        {"critical_state_rates", "rates.dat", "rates.png"}}},
      {"liquefaction", {{"liquefaction_csr_nl", "", ""}, {"liquefaction_ru", "", ""}}},
  };
  static const std::vector<SectionFigure> none;
  const auto it = figures.find(mode);
  return it == figures.end() ? none : it->second;
}

namespace {

// Whether a data file (gnuplot's: '#' comments) has a row.
bool has_row(const fs::path& file) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos && line[line.find_first_not_of(" \t\r")] != '#') return true;
  return false;
}

// 'text' quoted for the shell.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

int draw_section(const std::string& mode, const std::string& out, const std::string& gnuplot_dir) {
  const std::vector<SectionFigure>& figures = section_figures(mode);
  if (figures.empty()) return 0;
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    std::fprintf(stderr, "compare-runs: gnuplot not found: the figures of %s are not drawn (apt install gnuplot-nox)\n", out.c_str());
    return 1;
  }
  std::error_code ec;
  const fs::path lib = fs::absolute(gnuplot_dir, ec);
  for (const SectionFigure& f : figures) {
    if (!f.needs.empty() && !has_row(fs::path(out) / f.needs)) {
      if (!f.image.empty()) fs::remove(fs::path(out) / f.image, ec);  // an image of data no longer there
      continue;
    }
    const fs::path script = lib / (f.script + ".gp");
    if (!fs::exists(script, ec)) {
      std::fprintf(stderr, "compare-runs: no gnuplot script %s (--draw names the folder of reports/gnuplot)\n", script.c_str());
      return 1;
    }
    const std::string command = "cd " + quoted(out) + " && GNUPLOT_LIB=" + quoted(lib.string()) + " gnuplot " + quoted(script.string());
    if (std::system(command.c_str()) != 0) {
      std::fprintf(stderr, "compare-runs: gnuplot %s failed in %s\n", script.c_str(), out.c_str());
      return 1;
    }
  }
  return 0;
}

}  // namespace sections
