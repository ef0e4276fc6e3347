// The response surface: a quadratic fit recovers a known quadratic and its noise, and the
// posterior sampled on it is the analytic one.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "surrogate.hpp"

using calibration::fit_quadratic;

TEST_CASE("a quadratic fit recovers a quadratic, and the noise about it", "[calibration]") {
  calibration::ResponseSurface s;
  s.centre = Eigen::Vector2d(0.5, 0.5), s.scale = Eigen::Vector2d(1, 1);
  std::vector<Eigen::VectorXd> x;
  std::vector<double> exact, noisy;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0, 0.05);
  for (int i = 0; i < 400; ++i) {
    const Eigen::Vector2d u((i % 20) / 19.0, (i / 20) / 19.0);
    x.push_back(s.features(u));
    const double z0 = u(0) - 0.5, z1 = u(1) - 0.5;
    exact.push_back(1 + 2 * z0 - 3 * z1 + 0.5 * z0 * z0 + 4 * z0 * z1 - z1 * z1);  // features: 1, z0, z1, z0^2, z0 z1, z1^2
    noisy.push_back(exact.back() + noise(rng));
  }
  const auto q = fit_quadratic(x, exact);
  const Eigen::VectorXd expected = (Eigen::VectorXd(6) << 1, 2, -3, 0.5, 4, -1).finished();
  CHECK((q.coefficients - expected).cwiseAbs().maxCoeff() < 1e-9);
  CHECK(q.residual_variance < 1e-18);
  // With noise of sd 0.05: the residual variance within 15 % of 0.0025 (its relative sd is
  // sqrt(2 / 394) = 7 %), the prediction variance at the centre about 0.0025 / 400 x a few.
  const auto n = fit_quadratic(x, noisy);
  CHECK(n.residual_variance == Approx(0.0025).epsilon(0.15));
  CHECK(n.variance(s.features(Eigen::Vector2d(0.5, 0.5))) < 0.0025 / 400 * 10);
}

TEST_CASE("a two-valued parameter's square adds no degree of freedom to the fit's noise", "[calibration]") {
  // u0 takes two values (a discrete reading), u1 four: of the 6 features, z0^2 = a + b z0, so the
  // rank is 5 and 12 points leave 7 degrees of freedom, not 6. Over 4,000 fits the mean residual
  // variance is within 5 % of the noise's 0.0025 (its relative sd is sqrt(2 / 7 / 4000) = 0.85 %);
  // dividing by 6 would make it 7 / 6 of it, 17 % high.
  calibration::ResponseSurface s;
  s.centre = Eigen::Vector2d(0.5, 0.5), s.scale = Eigen::Vector2d(0.25, 0.3);
  std::vector<Eigen::VectorXd> x;
  for (int i = 0; i < 12; ++i) x.push_back(s.features(Eigen::Vector2d(i % 2 ? 0.75 : 0.25, (i / 2 % 4) / 3.0)));
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0, 0.05);
  double mean = 0;
  const int fits = 4000;
  for (int k = 0; k < fits; ++k) {
    std::vector<double> y;
    for (int i = 0; i < 12; ++i) y.push_back(1 + (i % 2) - 0.5 * (i / 2 % 4) + noise(rng));
    mean += fit_quadratic(x, y).residual_variance / fits;
  }
  CHECK(mean == Approx(0.0025).epsilon(0.05));
}

TEST_CASE("the posterior on a surface is the analytic one", "[calibration]") {
  // One parameter; three curve points whose model values are a_j + b_j u exactly, b = (1, 2, -1),
  // each set on one sample; the reference is the model at u* = 0.4, with sd 0.1 of one specimen.
  // Each point's variance: 0.1^2 (the reference's mean) + 0.1^2 / 1 (the model's one sample, whose
  // scatter the reference's sd stands for); the surface has no noise, so adds none. The posterior
  // is Gaussian with mean 0.4 and sd 1 / sqrt(sum b^2 / 0.02) = 0.0577. 4,000 weighted points: the
  // mean within 0.005, the sd within 10 %.
  calibration::References refs;
  calibration::CurveRow c{"line", "", "x", "y", "dense", "t", 1, 0, {}};
  const double a[] = {0.1, 0.2, 0.3}, b[] = {1, 2, -1};
  for (int j = 0; j < 3; ++j) c.points.push_back({static_cast<double>(j), a[j] + b[j] * 0.4, 0.1});
  refs.curves = {c};
  std::vector<calibration::ParameterSet> sets;
  for (int i = 0; i < 21; ++i) {
    calibration::ParameterSet s;
    s.u = Eigen::VectorXd::Constant(1, 0.2 + 0.02 * i);
    calibration::RowMisfit m{"line", 0, 3, "", true, {}, {}, 1};
    for (int j = 0; j < 3; ++j) m.model.push_back(a[j] + b[j] * s.u(0));
    s.misfit.rows = {m};
    sets.push_back(s);
  }
  calibration::Proposal region;
  region.mean = Eigen::VectorXd::Constant(1, 0.4);
  region.covariance = Eigen::MatrixXd::Constant(1, 1, 0.01);
  const auto surface = calibration::fit_surface(refs, sets, region);
  REQUIRE(surface);
  CHECK(surface->sets == 21);  // all within 3 sd (0.1 to 0.7)
  std::vector<Eigen::VectorXd> u;
  std::vector<double> w;
  calibration::sample_surface(*surface, refs, 4000, u, w);
  const calibration::Parameter p{"x", {"x"}, "test", calibration::Parameter::Prior::Uniform, 0, 1, {}, {}, {}};
  const auto m = calibration::marginal(p, 0, u, w);
  CHECK(m.mean == Approx(0.4).margin(0.005));
  CHECK(m.sd == Approx(1 / std::sqrt(300.0)).epsilon(0.1));
  // Too few sets for the features (2 x 3 = 6 needed for one parameter): no surface.
  sets.resize(5);
  CHECK_FALSE(calibration::fit_surface(refs, sets, region));
}

TEST_CASE("a scalar row on the surface: the probability that one sample lies in the paper's region", "[calibration]") {
  // One parameter; a row whose samples' mean is 2 u exactly, with a samples' sd of 0.05 (3 samples
  // a set), read by the paper as 0.8 within 0.1 (region [0.7, 0.9]). The likelihood at u is
  // P(0.7 < X < 0.9), X ~ N(2u, 0.05^2) (the surface is exact: no prediction variance), whose
  // posterior under a uniform prior is symmetric about u = 0.4, with variance, computed here by
  // quadrature of the same density: the posterior sd within 10 % and the mean within 0.005.
  calibration::References refs;
  validation::Row row;
  row.name = "value";
  row.check = "within", row.reference = 0.8, row.tolerance = 0.1, row.resolution = 0.001;
  refs.rows = {row};
  std::vector<calibration::ParameterSet> sets;
  for (int i = 0; i < 21; ++i) {
    calibration::ParameterSet s;
    s.u = Eigen::VectorXd::Constant(1, 0.2 + 0.02 * i);
    calibration::RowMisfit m{"value", 0, 1, "", true, {2 * s.u(0)}, {0.05}, 3};
    s.misfit.rows = {m};
    sets.push_back(s);
  }
  calibration::Proposal region;
  region.mean = Eigen::VectorXd::Constant(1, 0.4);
  region.covariance = Eigen::MatrixXd::Constant(1, 1, 0.01);
  const auto surface = calibration::fit_surface(refs, sets, region);
  REQUIRE(surface);
  REQUIRE(surface->rows.size() == 1);
  CHECK(surface->rows[0].q.sample_variance == Approx(0.0025));
  CHECK(surface->rows[0].low == Approx(0.7));
  CHECK(surface->rows[0].high == Approx(0.9));
  // The likelihood at u = 0.4 (X centred in the region): ln(Phi(2) - Phi(-2)).
  CHECK(surface->log_likelihood(refs, Eigen::VectorXd::Constant(1, 0.4)) == Approx(std::log(std::erf(2 / std::sqrt(2.0)))).epsilon(1e-6));
  // The posterior's moments by quadrature over the surface's region (0.1 to 0.7).
  const auto density = [](double u) {
    const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
    return phi((0.9 - 2 * u) / 0.05) - phi((0.7 - 2 * u) / 0.05);
  };
  double z = 0, m1 = 0, m2 = 0;
  for (int i = 0; i <= 60000; ++i) {
    const double u = 0.1 + 0.6 * i / 60000.0, p = density(u);
    z += p, m1 += p * u, m2 += p * u * u;
  }
  const double mean = m1 / z, sd = std::sqrt(m2 / z - mean * mean);
  std::vector<Eigen::VectorXd> u;
  std::vector<double> w;
  calibration::sample_surface(*surface, refs, 4000, u, w);
  const calibration::Parameter p{"x", {"x"}, "test", calibration::Parameter::Prior::Uniform, 0, 1, {}, {}, {}};
  const auto m = calibration::marginal(p, 0, u, w);
  CHECK(mean == Approx(0.4).margin(1e-6));
  CHECK(m.mean == Approx(mean).margin(0.005));
  CHECK(m.sd == Approx(sd).epsilon(0.1));
}

TEST_CASE("points whose specimens are given are taken jointly, with the specimens' correlation", "[calibration]") {
  // Two curves on the same runs, 4 specimens each: point values (1, 2, 3, 4), (2, 4, 6, 8) and
  // (4, 3, 2, 1) correlate +1, +1 and -1 with the first, shrunk by 1 / (4 - 1): +-2/3.
  calibration::References refs;
  calibration::CurveRow a{"a", "", "x", "y", "dense", "t", 4, 0, {{0, 2.5, 0.2, {1, 2, 3, 4}}, {1, 5, 0.3, {2, 4, 6, 8}}}};
  calibration::CurveRow b{"b", "", "x", "z", "dense", "t", 4, 0, {{0, 2.5, 0.1, {4, 3, 2, 1}}}};
  calibration::CurveRow other{"c", "", "x", "y", "loose", "t", 1, 0, {{0, 1, 0.1, {}}}};
  refs.curves = {a, b, other};
  refs.correlated = calibration::correlated_points(refs.curves);
  REQUIRE(refs.correlated.size() == 1);
  const calibration::CorrelatedPoints& g = refs.correlated[0];
  REQUIRE(g.points.size() == 3);
  CHECK(g.correlation(0, 1) == Approx(2.0 / 3));
  CHECK(g.correlation(0, 2) == Approx(-2.0 / 3));
  CHECK(g.correlation(1, 2) == Approx(-2.0 / 3));
  CHECK(g.correlation(2, 2) == Approx(1));
  // The likelihood on an exact surface (no prediction variance): the three points jointly normal,
  // covariance (s s^T) o R with s_j = sd_j / sqrt(4) (the lab's mean) and the model's one sample
  // (sample_variance = sd_j^2, its sd the reference's): 2 s s^T o R; the fourth point alone.
  // Computed here by hand with the inverse of the 3 x 3 covariance.
  std::vector<calibration::ParameterSet> sets;
  for (int i = 0; i < 21; ++i) {
    calibration::ParameterSet s;
    s.u = Eigen::VectorXd::Constant(1, 0.2 + 0.02 * i);
    const double v = s.u(0);
    s.misfit.rows = {calibration::RowMisfit{"a", 0, 2, "", true, {2 + v, 4 + 2 * v}, {0, 0}, 1},
                     calibration::RowMisfit{"b", 0, 1, "", true, {3 - v}, {0}, 1},
                     calibration::RowMisfit{"c", 0, 1, "", true, {1 + v}, {0}, 1}};
    sets.push_back(s);
  }
  calibration::Proposal region;
  region.mean = Eigen::VectorXd::Constant(1, 0.4);
  region.covariance = Eigen::MatrixXd::Constant(1, 1, 0.01);
  const auto surface = calibration::fit_surface(refs, sets, region);
  REQUIRE(surface);
  const double u = 0.45;
  const Eigen::Vector3d r(2 + u - 2.5, 4 + 2 * u - 5, 3 - u - 2.5);
  const Eigen::Vector3d s(0.1, 0.15, 0.05);  // sd / sqrt(4)
  const Eigen::Vector3d m(0.2, 0.3, 0.1);    // the model's one sample: the reference's sd
  const Eigen::Matrix3d cov = (s * s.transpose() + m * m.transpose()).cwiseProduct(g.correlation);
  const double joint = -0.5 * r.dot(cov.inverse() * r) - 0.5 * std::log(cov.determinant()) - 1.5 * std::log(2 * M_PI);
  const double alone_var = 0.1 * 0.1 / 1 + 0.1 * 0.1, alone_r = 1 + u - 1;
  const double alone = -0.5 * alone_r * alone_r / alone_var - 0.5 * std::log(2 * M_PI * alone_var);
  CHECK(surface->log_likelihood(refs, Eigen::VectorXd::Constant(1, u)) == Approx(joint + alone).epsilon(1e-6));
}
