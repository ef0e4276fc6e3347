#include "figures/figure_data.hpp"

#include <filesystem>

#include "figures/figure_entry.hpp"
#include "io/atomic_file.hpp"
#include "study/settings.hpp"

namespace fs = std::filesystem;

namespace validation {

FigureFolder::FigureFolder(std::string out) : out_(std::move(out)) { fs::create_directories(out_); }

void FigureFolder::write(const std::string& name, const Table& t, const std::string& what) {
  Table copy = t;
  copy.comments.insert(copy.comments.begin(), what);
  dem::write_file_atomically((fs::path(out_) / name).string(), copy.text());
  ++files_;
}

Table none_table(const std::string& comment) {
  Table none;
  none.comments = {comment};
  return none;
}

PathSettings path_settings(const FigureSource& src) {
  PathSettings out;
  for (const std::string& d : src.densities)
    for (int t = 1; t <= 5; ++t)
      if (auto s = scene_of((fs::path(src.chosen.dir) / (d + "_test" + std::to_string(t) + ".h5")).string()))
        if (const dem::StageConfig* st = stage_of_type(*s, dem::StageConfig::Type::StressPath)) {
          out.p = st->mean_stress_Pa, out.R = st->stress_ratio, out.shear_friction = dem::friction_coefficient(s->material.law);
          return out;
        }
  return out;
}

const std::vector<FigureEntry>& figure_entries() {
  static const std::vector<FigureEntry> entries = {
      {"Figs. 1, 2", sample_figures_data, sample_figures_notes},
      {"Figs. 3-6, 8, 9, 12, 13", single_run_figures_data, single_run_figures_notes},
      {"Figs. 7, 10, 11", cycle_figures_data, cycle_figures_notes},
      {"energy balance", energy_figures_data, energy_figures_notes},
  };
  return entries;
}

void write_figure_data(const FigureSource& src, FigureFolder& out) {
  out.values.text("sample", src.sample_label);
  out.values.number("samples_n", static_cast<double>(src.samples.size()));
  for (const FigureEntry& e : figure_entries()) e.data(src, out);
}

}  // namespace validation
