// Figs. 1 and 2 (figure_entry.hpp): the grading, the lattice before compression and each prepared
// sample, with the settings of the chosen sample's scenes the scripts quote; the note's cell sides.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "figures/figure_entry.hpp"
#include "generate/grading.hpp"
#include "io/state_io.hpp"
#include "judge/quantities.hpp"
#include "study/columns.hpp"
#include "study/format.hpp"
#include "study/manifest.hpp"
#include "study/settings.hpp"

namespace fs = std::filesystem;

namespace validation {

namespace {

// The chosen sample's preparation scenes, by density.
using Preparations = std::map<std::string, dem::SceneConfig>;

// The numbers of the scenes the scripts quote: the stress path, each preparation's friction and
// the paper's values of the samples.
Preparations scene_values(const FigureSource& src, FigureFolder& out) {
  Preparations prepare;
  for (const std::string& d : src.densities)
    if (auto s = scene_of((fs::path(src.chosen.dir) / (d + "_prepare.h5")).string())) prepare[d] = *s;
  const PathSettings path = path_settings(src);
  if (path.shear_friction) out.values.number("friction_shear", *path.shear_friction);
  out.values.number("mean_stress_kPa", path.p / 1e3);
  out.values.number("stress_ratio", path.R);
  for (const std::string& d : src.densities) {
    out.values.number("has_prepare_" + d, prepare.count(d) ? 1 : 0);
    out.values.number("friction_prepare_" + d, prepare.count(d) ? dem::friction_coefficient(prepare[d].material.law) : NAN);
    for (const auto& [quantity, name] : std::vector<std::pair<std::string, std::string>>{
             {"coordination_after_preparation", "cn"}, {"void_ratio_after_preparation", "e0"}, {"cell_side_cm_after_preparation", "side_cm"}})
      out.values.number("paper_" + name + "_" + d, paper_value(src.paper, quantity, d).value_or(NAN));
  }
  out.values.number("paper_slope", paper_value(src.paper, "qp_strong_fabric_slope", "").value_or(NAN));
  return prepare;
}

// Fig. 1 (the grading) and Fig. 2 (A: the lattice before compression) from the dense preparation's
// scene. Without a dense preparation these stay at "none" (has_lattice = 0) and the scripts say
// "not run".
void fig01_fig02_lattice(const FigureSource& src, Preparations& prepare, FigureFolder& out) {
  out.values.number("has_lattice", 0);
  out.values.text("grading_basis", "none");
  for (const char* v : {"grading_d_min_mm", "grading_d50_mm", "grading_d_max_mm", "lattice_side_mm", "target_pressure_kPa"})
    out.values.number(v, 1);
  out.values.number("particles", 0);
  out.write("fig01_grading_target.dat", none_table("no dense preparation"), "Fig. 1");
  out.write("fig01_grading_sample.dat", none_table("no dense preparation"), "Fig. 1");
  out.write("fig02_lattice.dat", none_table("no dense preparation"), "Fig. 2 (A)");
  if (!prepare.count("dense")) return;
  const dem::SceneConfig& dense = prepare["dense"];
  out.write("fig01_grading_target.dat", grading_target(dense), "Fig. 1: target grading (" + src.from + "/dense_prepare)");
  const dem::ParticleSource& g = dense.particles;
  out.values.text("grading_basis", g.grading_basis == dem::GradingCurve::Basis::Mass ? "mass" : "count");
  out.values.number("grading_d_min_mm", 1e3 * g.grading_diameters_m.front());
  out.values.number("grading_d50_mm", 1e3 * grading_diameter_at(g.grading_diameters_m, g.grading_percent_finer, 50));
  out.values.number("grading_d_max_mm", 1e3 * g.grading_diameters_m.back());
  // The lattice before compression: the preparation scene's own lattice (generate/), not a run.
  if (g.kind != dem::ParticleSource::Kind::Lattice) return;
  dem::Particles lattice;
  dem::PeriodicCell cell;
  dem::make_lattice(g.lattice, dem::GradingCurve(g.grading_diameters_m, g.grading_percent_finer, g.grading_basis),
                    dense.material.density_kg_per_m3, lattice, cell);
  out.write("fig02_lattice.dat", spheres(lattice, cell), "Fig. 2 (A): the lattice of " + src.from + "/dense_prepare before compression");
  out.values.number("has_lattice", 1);
  out.values.number("lattice_side_mm", 1e3 * cell.lengths().maxCoeff());
  out.values.number("particles", static_cast<double>(lattice.size()));
  if (const dem::StageConfig* st = stage_of_type(dense, dem::StageConfig::Type::Stress))
    out.values.number("target_pressure_kPa", st->target_Pa.mean() / 1e3);
}

// Fig. 2: each prepared sample (from /state), and Fig. 1's realised grading of the dense one.
void fig02_samples(const FigureSource& src, const Preparations& prepare, FigureFolder& out) {
  double side_mm = 0;
  for (const std::string& d : src.densities) {
    const std::string f = (fs::path(src.chosen.dir) / (d + "_prepare.h5")).string();
    Table t;
    try {
      if (!prepare.count(d)) throw std::runtime_error("not run");
      const dem::SavedState st = dem::read_state(f);
      t = spheres(st.particles, st.cell);
      side_mm = std::max(side_mm, 1e3 * st.cell.lengths().maxCoeff());
      if (d == "dense")
        out.write("fig01_grading_sample.dat", grading_realised(st.particles.radius), "Fig. 1: the grading of " + src.from + "/dense_prepare");
    } catch (const std::exception& e) {
      t.columns = {"x1 [mm]", "x2 [mm]", "x3 [mm]", "diameter [mm]"};
      t.comments = {std::string("no sample: ") + e.what()};
    }
    out.write("fig02_" + d + ".dat", t, "Fig. 2: the " + d + " sample after compression (" + src.from + "/" + d + "_prepare)");
  }
  out.values.number("sample_side_mm", side_mm > 0 ? std::ceil(side_mm / 5) * 5 : 1);
}

// The headline check before shearing: e0 and the coordination number of every sample of the
// ensemble, by density (1 loose, 2 medium, 3 dense, the x of the figure), labelled by sample.
void fig00_samples(const FigureSource& src, FigureFolder& out) {
  Table t;
  t.columns = {"density [1]", "void ratio e0 [1]", "coordination number [1]"};
  for (std::size_t k = 0; k < src.densities.size(); ++k)
    for (const Sample& s : src.samples) {
      const auto it = s.densities.find(src.densities[k]);
      if (it == s.densities.end() || !it->second.prepared) continue;
      const auto& last = it->second.sample;
      if (!last.count(col::void_ratio) || !last.count(col::coordination_number)) continue;
      t.labels.push_back(s.name.empty() ? "the sample" : s.name);
      t.rows.push_back({static_cast<double>(k + 1), last.at(col::void_ratio), last.at(col::coordination_number)});
    }
  out.write("fig00_samples.dat", t, "e0 and the coordination number of every sample before shearing (" + src.results + ")");
  out.values.number("fig00_samples_rows", static_cast<double>(t.size()));
}

}  // namespace

void sample_figures_data(const FigureSource& src, FigureFolder& out) {
  Preparations prepare = scene_values(src, out);
  fig01_fig02_lattice(src, prepare, out);
  fig02_samples(src, prepare, out);
  fig00_samples(src, out);
}

namespace {

// The resolution of the paper's row of (quantity, density), 0 without a row.
double resolution_of(const std::vector<Row>& rows, const std::string& quantity, const std::string& density) {
  for (const Row& r : rows)
    if (r.quantity == quantity && r.density == density) return r.resolution;
  return 0;
}

// The headline check before shearing: e0 and the coordination number, mean ± sd over the samples,
// against the paper's, with the verdicts of their rows.
void fig00_values(NoteContext& c, Values& v) {
  for (const std::string& d : paper_densities())
    for (const auto& [key, quantity] : std::vector<std::pair<std::string, std::string>>{{"e0", "void_ratio_after_preparation"},
                                                                                        {"cn", "coordination_after_preparation"}}) {
      const RowResult* r = c.values_of(quantity, d);
      if (!r || r->valued == 0) continue;
      // a scatter below the row's resolution is round-off: the mean alone, to six significant digits
      const double sd = r->spread.sd < resolution_of(c.in.paper, quantity, d) ? 0 : r->spread.sd;
      v["fig00." + key + "_" + d] = r->valued > 1 ? mean_pm_sd(r->spread.mean, sd) : number(r->spread.mean);
      v["fig00.inside_" + key + "_" + d] = std::to_string(r->holds) + " of " + std::to_string(r->valued);
      v["fig00.paper_" + key + "_" + d] = c.paper(quantity, d);
      v["fig00.verdict_" + key + "_" + d] = c.phrase(quantity, d);
    }
}

}  // namespace

// Fig. 2: the cell side of each prepared sample, scaled to the paper's sample size.
void sample_figures_notes(NoteContext& c, Values& v) {
  fig00_values(c, v);
  for (const std::string& d : paper_densities()) {
    const DensityResults* r = c.results_of(d);
    if (!r || !r->prepared) continue;
    const double volume = r->sample.at("cell_length_1") * r->sample.at("cell_length_2") * r->sample.at("cell_length_3");
    const auto n = r->sample.find("particles");
    const double scale = n != r->sample.end() && n->second > 0 ? paper_particles / n->second : 1;
    v["fig02.side_" + d] = fixed_unsigned_zero(100 * std::cbrt(volume * scale), 2);
    v["fig02.paper_" + d] = c.paper("cell_side_cm_after_preparation", d);
    v["fig02.verdict_" + d] = c.phrase("cell_side_cm_after_preparation", d);
  }
}

}  // namespace validation
