// The calibration's numerics: priors on the unit interval, Sobol draws, the defensive mixture's
// density, and importance weights recovering a known posterior.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "parameters.hpp"
#include "posterior.hpp"

using calibration::Parameter;

TEST_CASE("a parameter maps the unit interval onto its prior", "[calibration]") {
  Parameter u{"mu", {"material.friction"}, "test", Parameter::Prior::Uniform, 0.1, 0.9, {}, {}, {}};
  CHECK(u.value(0.5) == Approx(0.5));
  CHECK(u.unit_of(0.3) == Approx(0.25));
  Parameter l{"kn", {"material.kn"}, "test", Parameter::Prior::LogUniform, 1e5, 1e7, {}, {}, {}};
  CHECK(l.value(0.5) == Approx(1e6));      // the geometric middle
  CHECK(l.unit_of(1e6) == Approx(0.5));
  CHECK(l.value_text(1.0) == "10000000");
  Parameter v{"law", {"material.law"}, "both", Parameter::Prior::Values, 0, 0, {"linear", "hertz_mindlin", "0.5"}, {}, {}};
  CHECK(v.value_text(0.0) == "linear");
  CHECK(v.value_text(0.5) == "hertz_mindlin");
  CHECK(v.value_text(1.0) == "0.5");       // u = 1 is the last bin's
  CHECK(v.value(0.9) == 0.5);              // a number is its value
  CHECK(v.value(0.1) == 0);                // a word is its index
  CHECK(u.prior_unit_sd() == Approx(1 / std::sqrt(12.0)));
  Parameter two{"b", {"k"}, "test", Parameter::Prior::Values, 0, 0, {"1", "2"}, {}, {}};
  CHECK(two.prior_unit_sd() == Approx(0.25));  // bins' middles 0.25 and 0.75: sd 0.25
}

TEST_CASE("the prior's draws are a Sobol sequence: one point in each of 16 strata", "[calibration]") {
  // The first 16 points of a Sobol sequence (its origin included) put exactly one point in each
  // interval [k/16, (k+1)/16) of every coordinate; the sequence starts after the origin, so its
  // first 15 points fill every stratum but the first.
  calibration::Sampler s(3);
  const auto u = s.draw(calibration::Proposal{}, 15);
  for (int j = 0; j < 3; ++j) {
    std::set<int> strata;
    for (const auto& p : u) strata.insert(static_cast<int>(p(j) * 16));
    CHECK(strata.size() == 15);
    CHECK(strata.count(0) == 0);
  }
}

TEST_CASE("a defensive mixture is a density on the cube", "[calibration]") {
  // Integrated on a 200 x 200 midpoint grid: 1 up to the grid's error and the Monte Carlo error of
  // the Gaussian's mass inside (20,000 draws: sd sqrt(p(1-p)/n) < 0.4 %).
  std::vector<Eigen::VectorXd> u;
  std::vector<double> w;
  for (int i = 0; i < 50; ++i) {
    Eigen::VectorXd p(2);
    p << 0.97 + 0.002 * (i % 7), 0.03 - 0.003 * (i % 5);  // near a corner: much of the Gaussian outside
    u.push_back(p), w.push_back(1.0 / 50);
  }
  const calibration::Proposal q = calibration::fit_proposal(u, w, 0.2, 2, 0.08);
  CHECK(q.inside < 0.5);
  double integral = 0;
  const int n = 200;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      Eigen::VectorXd x(2);
      x << (a + 0.5) / n, (b + 0.5) / n;
      integral += q.density(x) / (n * n);
    }
  CHECK(integral == Approx(1).epsilon(0.02));
}

TEST_CASE("importance weights recover a known posterior", "[calibration]") {
  // Likelihood exp(-(u - 0.3)^2 / (2 0.05^2)) on a uniform prior: the posterior is that Gaussian
  // (truncation at 0 and 1 is 6 sd away, negligible). Five iterations of 64 draws, each proposal
  // fitted to the weights so far: the mean within 0.015 (3 x sd / sqrt(ESS) for ESS > 100) and the
  // sd within 20 % (its relative error is about 1 / sqrt(2 ESS)).
  const Parameter p{"x", {"x"}, "test", Parameter::Prior::Uniform, 0, 1, {}, {}, {}};
  calibration::Sampler s(1);
  std::vector<calibration::Proposal> proposals;
  std::vector<int> drawn;
  std::vector<Eigen::VectorXd> u;
  std::vector<double> ll, w;
  for (int it = 0; it < 5; ++it) {
    const calibration::Proposal q = it == 0 ? calibration::Proposal{} : calibration::fit_proposal(u, w, 0.2);
    for (const auto& x : s.draw(q, 64)) {
      u.push_back(x);
      ll.push_back(-0.5 * std::pow((x(0) - 0.3) / 0.05, 2));
    }
    proposals.push_back(q), drawn.push_back(64);
    w = calibration::importance_weights(u, ll, proposals, drawn);
  }
  const double ess = calibration::effective_sample_size(w);
  CHECK(ess > 100);
  const calibration::Marginal m = calibration::marginal(p, 0, u, w);
  CHECK(m.mean == Approx(0.3).margin(0.015));
  CHECK(m.sd == Approx(0.05).epsilon(0.2));
  CHECK(m.lower_95 == Approx(0.3 - 1.96 * 0.05).margin(0.025));
  CHECK(m.upper_95 == Approx(0.3 + 1.96 * 0.05).margin(0.025));
  CHECK(m.identified);                                  // 0.289 / 0.05: narrowed about 6x
  CHECK(m.narrowing == Approx(1 / std::sqrt(12.0) / 0.05).epsilon(0.25));
}

TEST_CASE("a flat likelihood leaves the prior: not identified", "[calibration]") {
  const Parameter p{"x", {"x"}, "test", Parameter::Prior::Uniform, 0, 1, {}, {}, {}};
  calibration::Sampler s(1);
  const auto u = s.draw(calibration::Proposal{}, 63);
  const std::vector<double> w = calibration::importance_weights(u, std::vector<double>(63, -3.0), {calibration::Proposal{}}, {63});
  const calibration::Marginal m = calibration::marginal(p, 0, u, w);
  CHECK(m.mean == Approx(0.5).margin(0.01));
  CHECK(m.narrowing == Approx(1).epsilon(0.05));
  CHECK_FALSE(m.identified);
}

TEST_CASE("a failed set weighs nothing, and when all failed none weighs anything", "[calibration]") {
  std::vector<Eigen::VectorXd> u(3, Eigen::VectorXd::Constant(1, 0.5));
  const auto w = calibration::importance_weights(u, {-1.0, -INFINITY, -1.0}, {calibration::Proposal{}}, {3});
  CHECK(w[1] == 0);
  CHECK(w[0] == Approx(0.5));
  const auto none = calibration::importance_weights(u, {-INFINITY, -INFINITY, -INFINITY}, {calibration::Proposal{}}, {3});
  CHECK(none == std::vector<double>{0, 0, 0});
}

TEST_CASE("weighted quantiles", "[calibration]") {
  CHECK(calibration::weighted_quantile({3, 1, 2}, {1, 1, 1}, 0.5) == 2);
  CHECK(calibration::weighted_quantile({1, 2, 3}, {0.1, 0.1, 0.8}, 0.5) == 3);
  CHECK(calibration::weighted_quantile({1, 2, 3}, {0.1, 0.1, 0.8}, 0.05) == 1);
}

TEST_CASE("a proposal is fitted to weights tempered until they rest on enough sets", "[calibration]") {
  // Ten sets, one far better than the rest: the posterior's weights rest on it alone (ESS ~ 1);
  // tempered, they reach the asked effective sample size, and the best set still weighs most.
  std::vector<Eigen::VectorXd> u;
  std::vector<double> ll;
  for (int i = 0; i < 10; ++i) u.push_back(Eigen::VectorXd::Constant(1, 0.05 + 0.1 * i)), ll.push_back(-50.0 * i);
  const std::vector<calibration::Proposal> prior{calibration::Proposal{}};
  CHECK(calibration::effective_sample_size(calibration::importance_weights(u, ll, prior, {10})) == Approx(1));
  const auto w = calibration::proposal_weights(u, ll, prior, {10}, 6);
  CHECK(calibration::effective_sample_size(w) == Approx(6).epsilon(0.01));
  CHECK(std::max_element(w.begin(), w.end()) == w.begin());
  // Already enough: the weights themselves.
  const std::vector<double> flat(10, -1.0);
  CHECK(calibration::proposal_weights(u, flat, prior, {10}, 6) == calibration::importance_weights(u, flat, prior, {10}));
}
