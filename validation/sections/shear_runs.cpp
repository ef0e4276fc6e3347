// The runs of the critical-state studies (critical_state_parts.hpp): each run's shear summary, and
// whether it was the test its name says.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "sections/critical_state_parts.hpp"
#include "sections/modes.hpp"
#include "contact/contact_law.hpp"
#include "judge/critical_state.hpp"
#include "study/series.hpp"
#include "study/format.hpp"
#include "io/atomic_file.hpp"
#include "study/line_fit.hpp"
#include "study/markdown_table.hpp"
#include "judge/rows.hpp"

namespace fs = std::filesystem;

namespace sections {

using validation::fixed;
using validation::number;

namespace {

// A number that is the whole of `s` ("0.25"), or none.
std::optional<double> whole_number(const std::string& s) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(x)) return std::nullopt;
  return x;
}

// Whether a shear was the test its name says: p at the peak and at the critical state within 5 %
// of the constraint's, b at the critical state within 0.05 of the target. The consolidation holds
// the stresses within 0.5 %; the constant-p servo, a proportional one, holds p within a few % at
// the critical state (its followers move at a steady rate only on an error), but it can lose p
// altogether when they reach their strain-rate cap (a cap of 1/s: p up to 68 MPa at b = 1). A run
// outside these bounds is kept in the table with its values, and a note that says why they are
// not those of its test. Appends the reasons to r.note.
void held_as_named(ShearRun& r) {
  const validation::ShearSummary& s = *r.summary;
  const auto off = [&](double p) { return std::abs(p / r.p_target_Pa - 1) > 0.05; };
  if (std::isfinite(r.p_target_Pa) && (off(s.peak_p_Pa) || (s.p_Pa.n && off(s.p_Pa.mean)))) {
    r.held = false;
    r.note += "⚠ p not held at " + number(r.p_target_Pa / 1e3) + " kPa: " + fixed(s.peak_p_Pa / 1e3, 1) + " kPa at the peak, " +
              fixed(s.p_Pa.mean / 1e3, 1) + " at the critical state, " + fixed(s.p_min_Pa / 1e3, 1) + " – " + fixed(s.p_max_Pa / 1e3, 1) +
              " over the shear; ";
  }
  if (s.b.n && std::abs(s.b.mean - r.b) > 0.05) {
    r.held = false;
    r.note += "⚠ b not held: " + fixed(s.b.mean, 3) + " at the critical state for " + number(r.b) + "; ";
  }
}

bool parse_shear_test(const std::string& test, ShearRun& r) {
  for (const char* loading : {"compression", "extension"}) {
    const std::string prefix = std::string(loading) + "_mu";
    if (test.rfind(prefix, 0) == 0)
      if (const auto mu = whole_number(test.substr(prefix.size()))) {
        r.loading = loading, r.mu = *mu, r.b = r.loading == "compression" ? 0 : 1;
        return true;
      }
  }
  // The rates study's rate<rate>_mu<μ>: compression at that axial strain rate (the scene's is used).
  if (const auto at = test.find("_mu"); test.rfind("rate", 0) == 0 && at != std::string::npos)
    if (whole_number(test.substr(4, at - 4)))
      if (const auto mu = whole_number(test.substr(at + 3))) {
        r.loading = "compression", r.mu = *mu, r.b = 0;
        return true;
      }
  if (test.rfind("b", 0) == 0)
    if (const auto b = whole_number(test.substr(1))) {
      r.loading = "b series", r.b = *b;
      return true;
    }
  return false;
}

}  // namespace

std::string mean_sd(const validation::Spread& s, int digits) {
  return s.n == 0 ? "—" : fixed(s.mean, digits) + (s.n > 1 ? " ± " + fixed(s.sd, digits) : "");
}

std::vector<ShearRun> shear_runs(const Manifest& manifest, const std::string& results, double cs_to) {
  std::vector<ShearRun> runs;
  for (const ManifestLine& l : manifest.lines) {
    if (l.test == "-") continue;  // the preparation
    ShearRun& r = runs.emplace_back();
    r.run = l.run;
    if (!parse_shear_test(l.test, r)) {
      r.note = "not analysed: test '" + l.test + "' is none of compression_mu<μ>, extension_mu<μ>, b<b>, rate<rate>_mu<μ>";
      continue;
    }
    const std::string result = validation::result_under(results, l);  // wherever the folder is now
    if (!validation::is_complete(result)) {
      r.note = "missing: " + fs::path(result).filename().string() + " is not finished";
      continue;
    }
    try {
      const RunFile f = read_run(result);
      if (!f.radius_m.empty()) {
        double sum = 0;
        for (double radius : f.radius_m) sum += 2 * radius;
        r.diameter_m = sum / static_cast<double>(f.radius_m.size());  // the engine's mean_diameter
      }
      r.summary = validation::summarise_shear(f.series, 0.3, cs_to);
      if (f.scene) {  // μ, p and b as run: the scene's; a name that says otherwise is noted
        const double mu = dem::friction_coefficient(f.scene->material.law);
        if (std::isfinite(r.mu) && std::abs(mu - r.mu) > 1e-9) r.note += "the scene's friction is " + number(mu) + ", not the name's; ";
        r.mu = mu;
        r.density_kg_per_m3 = f.scene->material.density_kg_per_m3;
        r.rate_per_s = std::abs(f.scene->stages.back().control.component[2].strain_rate_per_s);
        const dem::CellConstraint& c = f.scene->stages.back().control.constraint;
        if (c.kind == dem::CellConstraint::Kind::ConstantMeanStress) r.p_target_Pa = c.mean_stress_Pa;
        if (r.loading == "b series" && c.b != r.b) r.note += "the scene's b is " + number(c.b) + ", not the name's; ";
      }
      held_as_named(r);
      if (r.summary->max_axial_strain < cs_to) {
        const std::string why = f.scene && f.stage_end.count(f.scene->stages.back().name) ? f.stage_end.at(f.scene->stages.back().name) : "no stage_end";
        r.note += "reached |ε3| = " + fixed(r.summary->max_axial_strain, 3) + " only (" + why + "); critical state over " +
                  std::to_string(r.summary->cs_rows) + " rows; ";
      }
    } catch (const std::exception& e) {
      r.summary.reset();
      r.note = "unreadable: " + std::string(e.what());
    }
  }
  return runs;
}

}  // namespace sections
