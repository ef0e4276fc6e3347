// Calibration across sizes: a discrepancy recovers a known shift between two sizes, the posterior
// at the larger size is the analytic one (where the smaller size's alone is biased), and the sets
// chosen for the larger size spread over the posterior.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "discrepancy.hpp"
#include "surrogate.hpp"

namespace {

// A set of one parameter at u whose one curve has the given model values (one sample a set).
calibration::ParameterSet set_at(const std::string& name, double u, const std::vector<double>& model) {
  calibration::ParameterSet s;
  s.name = name;
  s.u = Eigen::VectorXd::Constant(1, u);
  s.misfit.rows = {calibration::RowMisfit{"line", 0, static_cast<int>(model.size()), "", true, model, std::vector<double>(model.size(), 0), 1}};
  return s;
}

const calibration::Parameter unit{"x", {"x"}, "test", calibration::Parameter::Prior::Uniform, 0, 1, {}, {}, {}};

}  // namespace

TEST_CASE("a discrepancy recovers a linear shift between sizes, and the posterior at the larger size is the analytic one", "[calibration]") {
  // Three curve points. At the small size the model is a_j + b_j u; at the large size it is that
  // plus c_j + e_j u, exactly. The reference is the large size's model at u* = 0.4 with sd 0.1 of
  // one specimen. 21 small sets over [0.2, 0.6]; 5 of them again at the large size: 5 pairs >= 1 + 3,
  // so the discrepancy is linear, and it reproduces c_j + e_j u to rounding.
  const double a[] = {0.1, 0.2, 0.3}, b[] = {1, 2, -1}, c[] = {0.05, -0.1, 0.2}, e[] = {0.5, 0.5, -1};
  const auto small_model = [&](double u) { return std::vector<double>{a[0] + b[0] * u, a[1] + b[1] * u, a[2] + b[2] * u}; };
  const auto large_model = [&](double u) {
    std::vector<double> y = small_model(u);
    for (int j = 0; j < 3; ++j) y[static_cast<std::size_t>(j)] += c[j] + e[j] * u;
    return y;
  };
  calibration::References refs;
  calibration::CurveRow curve{"line", "", "x", "y", "dense", "t", 1, 0, {}};
  const std::vector<double> at_truth = large_model(0.4);
  for (int j = 0; j < 3; ++j) curve.points.push_back({static_cast<double>(j), at_truth[static_cast<std::size_t>(j)], 0.1});
  refs.curves = {curve};
  std::vector<calibration::ParameterSet> small, large;
  for (int i = 0; i < 21; ++i) small.push_back(set_at("s" + std::to_string(i), 0.2 + 0.02 * i, small_model(0.2 + 0.02 * i)));
  for (const int i : {2, 6, 10, 14, 18}) large.push_back(set_at("s" + std::to_string(i), 0.2 + 0.02 * i, large_model(0.2 + 0.02 * i)));
  const auto delta = calibration::fit_discrepancy(refs, small, large);
  REQUIRE(delta);
  CHECK(delta->pairs == 5);
  CHECK(delta->linear);
  for (const double u : {0.25, 0.4, 0.55})
    for (int j = 0; j < 3; ++j) {
      const calibration::Quadratic& q = delta->curves[0][static_cast<std::size_t>(j)];
      CHECK(q.value(delta->features(Eigen::VectorXd::Constant(1, u))) == Approx(c[j] + e[j] * u).margin(1e-12));
      CHECK(q.variance(delta->features(Eigen::VectorXd::Constant(1, u))) < 1e-24);
    }
  // The posterior at the large size: Gaussian about 0.4 with sd 1 / sqrt(sum (b + e)^2 / 0.02)
  // (each point's variance: 0.1^2 for the reference's mean, 0.1^2 for the model's one sample at the
  // large size). 4,000 weighted points: the mean within 0.005, the sd within 10 %.
  calibration::Proposal region;
  region.mean = Eigen::VectorXd::Constant(1, 0.4);
  region.covariance = Eigen::MatrixXd::Constant(1, 1, 0.01);
  const auto surface = calibration::fit_surface(refs, small, region);
  REQUIRE(surface);
  std::vector<Eigen::VectorXd> u;
  std::vector<double> w;
  calibration::sample_surface(*surface, {*delta}, refs, 4000, u, w);
  const auto m = calibration::marginal(unit, 0, u, w);
  double slopes = 0;
  for (int j = 0; j < 3; ++j) slopes += (b[j] + e[j]) * (b[j] + e[j]);
  CHECK(m.mean == Approx(0.4).margin(0.005));
  CHECK(m.sd == Approx(1 / std::sqrt(slopes / 0.02)).epsilon(0.1));
  // The small size alone is biased: its least-squares u for the large size's reference,
  // sum b_j (y_j - a_j) / sum b_j^2, is not 0.4; its posterior mean lies there.
  double num = 0, den = 0;
  for (int j = 0; j < 3; ++j) num += b[j] * (at_truth[static_cast<std::size_t>(j)] - a[j]), den += b[j] * b[j];
  REQUIRE(std::abs(num / den - 0.4) > 0.05);
  calibration::sample_surface(*surface, refs, 4000, u, w);
  CHECK(calibration::marginal(unit, 0, u, w).mean == Approx(num / den).margin(0.005));
}

TEST_CASE("a constant discrepancy from three pairs: their mean difference, with its variance", "[calibration]") {
  // Differences 1, 2 and 4 at three u: a constant 7/3 whose variance is the residual variance
  // (sum of squared deviations / 2 = 7/3) over 3 pairs, 7/9. The larger size's samples' variance:
  // the reference's sd squared (one sample a set). An unscored set counts for no pair; with two
  // pairs there is no discrepancy.
  calibration::References refs;
  calibration::CurveRow curve{"line", "", "x", "y", "dense", "t", 1, 0, {{0, 0, 0.3}}};
  refs.curves = {curve};
  std::vector<calibration::ParameterSet> small{set_at("p", 0.2, {1}), set_at("q", 0.5, {1}), set_at("r", 0.8, {1}), set_at("s", 0.9, {1})};
  std::vector<calibration::ParameterSet> large{set_at("p", 0.2, {2}), set_at("q", 0.5, {3}), set_at("r", 0.8, {5}), set_at("s", 0.9, {9})};
  large[3].misfit.valued = false;
  const auto delta = calibration::fit_discrepancy(refs, small, large);
  REQUIRE(delta);
  CHECK(delta->pairs == 3);
  CHECK_FALSE(delta->linear);
  const calibration::Quadratic& q = delta->curves[0][0];
  const Eigen::VectorXd x = delta->features(Eigen::VectorXd::Constant(1, 0.3));
  CHECK(q.value(x) == Approx(7.0 / 3));
  CHECK(q.variance(x) == Approx(7.0 / 9));
  CHECK(q.sample_variance == Approx(0.09));
  large.resize(2);
  CHECK_FALSE(calibration::fit_discrepancy(refs, small, large));
}

TEST_CASE("the sets chosen for the larger size spread over the posterior, within 2 sd of it", "[calibration]") {
  // A posterior N(0.5, 0.05^2) on a grid. Candidates at -1.8, -1, 0, 1, 1.8 sd and two far outside
  // (0.2 and 0.9). For a line, the prediction variance averaged over the posterior falls most for
  // points far apart: the two picks are the extremes within 2 sd, one on each side.
  std::vector<Eigen::VectorXd> pu;
  std::vector<double> pw;
  for (int i = 0; i <= 400; ++i) {
    const double u = 0.3 + 0.4 * i / 400.0;
    pu.push_back(Eigen::VectorXd::Constant(1, u));
    pw.push_back(std::exp(-0.5 * std::pow((u - 0.5) / 0.05, 2)));
  }
  std::vector<Eigen::VectorXd> candidates;
  for (const double u : {0.2, 0.41, 0.45, 0.5, 0.55, 0.59, 0.9}) candidates.push_back(Eigen::VectorXd::Constant(1, u));
  std::vector<std::size_t> picked = calibration::choose_for_larger_size(candidates, {}, pu, pw, 2);
  std::sort(picked.begin(), picked.end());
  CHECK(picked == std::vector<std::size_t>{1, 5});
  // With those two at the larger size, the next of the rest is the one at the posterior's mean: for
  // x = (1, z), A = sum x x^T = diag(2, 6.48), and the gain E[(x_p A^-1 x_c)^2] / (1 + x_c A^-1 x_c)
  // is (0.25 + z^2 / 42) / (1.5 + z^2 / 6.48): 0.167 at z = 0 against 0.165 at z = 1.
  const std::vector<Eigen::VectorXd> rest{candidates[0], candidates[2], candidates[3], candidates[4], candidates[6]};
  CHECK(calibration::choose_for_larger_size(rest, {candidates[1], candidates[5]}, pu, pw, 1) == std::vector<std::size_t>{2});
  // Asking for more than there are candidates near the posterior gives the nearest ones too.
  CHECK(calibration::choose_for_larger_size(candidates, {}, pu, pw, 7).size() == 7);
}

// Rows read by the paper as `reference` within 0.1, on one parameter: at the small size each row's
// samples' mean is 2 u; at the large size 2 u - 0.2, exactly, with a samples' sd of 0.05 (3
// samples a set). 21 small sets over [0.2, 0.6]; 3 of them again at the large size: a constant
// discrepancy of -0.2 with no residual. The surface's region: u in [0.1, 0.7] (3 sd of 0.1 about 0.4).
struct RowsAtTwoSizes {
  calibration::References refs;
  std::vector<calibration::ParameterSet> small, large;
  std::vector<Eigen::VectorXd> candidates;  // the small sets' u
  std::optional<calibration::Discrepancy> delta;
  std::optional<calibration::ResponseSurface> surface;

  explicit RowsAtTwoSizes(const std::vector<std::pair<std::string, double>>& rows) {
    for (const auto& [name, reference] : rows) {
      validation::Row row;
      row.name = name, row.check = "within", row.reference = reference, row.tolerance = 0.1, row.resolution = 0.001;
      refs.rows.push_back(row);
    }
    const auto set = [&](const std::string& name, double u, double y) {
      calibration::ParameterSet s;
      s.name = name;
      s.u = Eigen::VectorXd::Constant(1, u);
      for (const auto& [row, reference] : rows) s.misfit.rows.push_back(calibration::RowMisfit{row, 0, 1, "", true, {y}, {0.05}, 3});
      return s;
    };
    for (int i = 0; i < 21; ++i) {
      const double u = 0.2 + 0.02 * i;
      small.push_back(set("s" + std::to_string(i), u, 2 * u));
      candidates.push_back(small.back().u);
    }
    for (const int i : {5, 10, 20}) large.push_back(set("s" + std::to_string(i), 0.2 + 0.02 * i, 2 * (0.2 + 0.02 * i) - 0.2));
    delta = calibration::fit_discrepancy(refs, small, large);
    calibration::Proposal region;
    region.mean = Eigen::VectorXd::Constant(1, 0.4);
    region.covariance = Eigen::MatrixXd::Constant(1, 1, 0.01);
    surface = calibration::fit_surface(refs, small, region);
  }
};

TEST_CASE("the set chosen to confirm is the one the larger size's posterior expects to agree best, with its probability", "[calibration]") {
  // One row read as 0.8 within 0.1 (region [0.7, 0.9]). The small size alone would centre it at
  // u = 0.4; at the large size it is centred at u = 0.5, where one sample agrees with probability
  // P(|X - 0.8| < 0.1), X ~ N(0.8, 0.05^2): erf(2 / sqrt 2).
  const RowsAtTwoSizes x({{"value", 0.8}});
  REQUIRE(x.delta);
  CHECK_FALSE(x.delta->linear);
  REQUIRE(x.surface);
  const auto chosen = calibration::choose_to_confirm(*x.surface, {*x.delta}, x.candidates, {0});
  REQUIRE(chosen);
  CHECK(x.candidates[chosen->index](0) == Approx(0.5));
  CHECK(chosen->probability == Approx(std::erf(2 / std::sqrt(2.0))).epsilon(1e-6));
  REQUIRE(chosen->row_probability.size() == 1);
  CHECK(chosen->row_probability[0] == Approx(chosen->probability));
  // Without the discrepancy, the small size's own best: u = 0.4.
  const auto small_only = calibration::choose_to_confirm(*x.surface, {}, x.candidates, {0});
  REQUIRE(small_only);
  CHECK(x.candidates[small_only->index](0) == Approx(0.4));
  // No candidates: none.
  CHECK_FALSE(calibration::choose_to_confirm(*x.surface, {*x.delta}, {}, {0}));
}

TEST_CASE("how far the larger size's posterior reaches a row: its largest probability over the surface's region", "[calibration]") {
  // The row above, largest at u = 0.5: erf(2 / sqrt 2) = 0.9545; 20,000 uniform points, about
  // 12,000 inside the region, come within 1e-4 of it (the probability is flat to second order at
  // its top). A row read as 2.0 within 0.1 needs u = 1.1, outside: its largest is at u = 0.7, where
  // the mean 1.2 lies 14 sd below its region: about 0.
  const RowsAtTwoSizes x({{"value", 0.8}, {"far", 2.0}});
  REQUIRE(x.delta);
  REQUIRE(x.surface);
  const calibration::Reach r = calibration::reach(*x.surface, {*x.delta}, {0, 1}, 20000);
  CHECK(r.points > 11000);
  CHECK(r.points < 13000);
  REQUIRE(r.row_most.size() == 2);
  CHECK(r.row_most[0] == Approx(std::erf(2 / std::sqrt(2.0))).margin(1e-4));
  CHECK(r.row_most[0] <= std::erf(2 / std::sqrt(2.0)) + 1e-12);
  CHECK(r.row_most[1] < 1e-12);
  CHECK(r.all_most < 1e-12);
}
