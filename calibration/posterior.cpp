#include "posterior.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>

#include <boost/math/distributions/normal.hpp>
#include <boost/random/sobol.hpp>

namespace calibration {

struct Sampler::Engine {
  explicit Engine(int d) : sobol(static_cast<std::size_t>(d)) {}
  boost::random::sobol sobol;
};

namespace {

bool in_cube(const Eigen::VectorXd& u) { return (u.array() >= 0).all() && (u.array() <= 1).all(); }

double gaussian_density(const Eigen::VectorXd& u, const Eigen::VectorXd& mean, const Eigen::LLT<Eigen::MatrixXd>& llt) {
  const Eigen::VectorXd z = llt.matrixL().solve(u - mean);
  const double log_det = 2 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
  const double d = static_cast<double>(u.size());
  return std::exp(-0.5 * z.squaredNorm() - 0.5 * log_det - 0.5 * d * std::log(2 * M_PI));
}

}  // namespace

double Proposal::density(const Eigen::VectorXd& u) const {
  if (!in_cube(u)) return 0;
  if (prior_share >= 1) return 1;
  const Eigen::LLT<Eigen::MatrixXd> llt(covariance);
  return prior_share + (1 - prior_share) * gaussian_density(u, mean, llt) / inside;
}

Proposal fit_proposal(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w, double prior_share,
                      double inflation, double floor_sd) {
  const Eigen::Index d = u.front().size();
  Proposal q;
  q.prior_share = prior_share;
  q.mean = Eigen::VectorXd::Zero(d);
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (std::size_t i = 0; i < u.size(); ++i) q.mean += w[i] / total * u[i];
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < u.size(); ++i) c += w[i] / total * (u[i] - q.mean) * (u[i] - q.mean).transpose();
  q.covariance = inflation * c;
  for (Eigen::Index j = 0; j < d; ++j) q.covariance(j, j) = std::max(q.covariance(j, j), floor_sd * floor_sd);
  // Its mass inside the cube, from pseudo-random draws of a fixed seed (deterministic).
  const Eigen::LLT<Eigen::MatrixXd> llt(q.covariance);
  const Eigen::MatrixXd l = llt.matrixL();
  std::mt19937_64 rng(20261127);
  std::normal_distribution<double> normal;
  const int n = 20000;
  int hits = 0;
  Eigen::VectorXd z(d);
  for (int i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < d; ++j) z(j) = normal(rng);
    hits += in_cube(q.mean + l * z);
  }
  q.inside = std::max(1, hits) / static_cast<double>(n);
  return q;
}

// Boost's sequence starts after the origin (a corner of the cube): at (1/2, ..., 1/2).
Sampler::Sampler(int dimensions) : d_(dimensions), engine_(std::make_shared<Engine>(dimensions)) {}

Eigen::VectorXd Sampler::next() {
  Eigen::VectorXd v(d_);
  boost::random::sobol& s = engine_->sobol;
  const double span = static_cast<double>(s.max() - s.min()) + 1.0;
  for (int j = 0; j < d_; ++j) v(j) = (static_cast<double>(s() - s.min()) + 0.5) / span;
  return v;
}

std::vector<Eigen::VectorXd> Sampler::draw(const Proposal& q, int n) {
  std::vector<Eigen::VectorXd> out;
  const int from_prior = q.prior_share >= 1 ? n : static_cast<int>(std::lround(q.prior_share * n));
  while (static_cast<int>(out.size()) < from_prior) out.push_back(next());
  if (static_cast<int>(out.size()) == n) return out;
  const Eigen::MatrixXd l = Eigen::LLT<Eigen::MatrixXd>(q.covariance).matrixL();
  const boost::math::normal standard;
  // A point outside the cube is dropped and the next taken: at most this many tries per set.
  for (long tries = 0; static_cast<int>(out.size()) < n && tries < 1000L * n; ++tries) {
    const Eigen::VectorXd v = next();
    Eigen::VectorXd z(d_);
    for (int j = 0; j < d_; ++j) z(j) = boost::math::quantile(standard, v(j));
    const Eigen::VectorXd u = q.mean + l * z;
    if (in_cube(u)) out.push_back(u);
  }
  while (static_cast<int>(out.size()) < n) out.push_back(next());  // a Gaussian all outside: the prior
  return out;
}

std::vector<double> importance_weights(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& log_likelihood,
                                       const std::vector<Proposal>& proposals, const std::vector<int>& drawn) {
  const double total = std::accumulate(drawn.begin(), drawn.end(), 0.0);
  std::vector<double> log_w(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    double mixture = 0;
    for (std::size_t k = 0; k < proposals.size(); ++k) mixture += drawn[k] / total * proposals[k].density(u[i]);
    log_w[i] = log_likelihood[i] - std::log(mixture);
  }
  const double top = *std::max_element(log_w.begin(), log_w.end());
  std::vector<double> w(u.size(), 0.0);
  if (!std::isfinite(top)) return w;  // every set failed
  double sum = 0;
  for (std::size_t i = 0; i < u.size(); ++i) sum += w[i] = std::exp(log_w[i] - top);
  for (double& x : w) x /= sum;
  return w;
}

std::vector<double> proposal_weights(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& log_likelihood,
                                     const std::vector<Proposal>& proposals, const std::vector<int>& drawn, double at_least) {
  const auto tempered = [&](double t) {
    std::vector<double> ll(log_likelihood);
    for (double& x : ll) x /= t;
    return importance_weights(u, ll, proposals, drawn);
  };
  std::vector<double> w = tempered(1);
  if (effective_sample_size(w) >= at_least) return w;
  double lo = 0, hi = 1;  // log T: hi grows until it is enough (or the likelihood is flattened out)
  while (hi < 60 && effective_sample_size(tempered(std::exp(hi))) < at_least) lo = hi, hi *= 2;
  for (int k = 0; k < 40; ++k) {
    const double mid = 0.5 * (lo + hi);
    (effective_sample_size(tempered(std::exp(mid))) < at_least ? lo : hi) = mid;
  }
  return tempered(std::exp(hi));
}

double effective_sample_size(const std::vector<double>& w) {
  double s = 0, s2 = 0;
  for (const double x : w) s += x, s2 += x * x;
  return s2 > 0 ? s * s / s2 : 0;
}

double weighted_quantile(std::vector<double> x, std::vector<double> w, double q) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  double below = 0;
  for (const std::size_t i : order) {
    below += w[i] / total;
    if (below >= q) return x[i];
  }
  return x[order.back()];
}

Marginal marginal(const Parameter& p, std::size_t j, const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w) {
  Marginal m;
  std::vector<double> value(u.size()), unit(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    unit[i] = p.discrete() ? p.unit_of(p.value(u[i](static_cast<Eigen::Index>(j)))) : u[i](static_cast<Eigen::Index>(j));
    value[i] = p.value(u[i](static_cast<Eigen::Index>(j)));
  }
  double m1 = 0, m2 = 0, u1 = 0, u2 = 0;
  for (std::size_t i = 0; i < u.size(); ++i) m1 += w[i] * value[i], u1 += w[i] * unit[i];
  for (std::size_t i = 0; i < u.size(); ++i)
    m2 += w[i] * (value[i] - m1) * (value[i] - m1), u2 += w[i] * (unit[i] - u1) * (unit[i] - u1);
  m.mean = m1, m.sd = std::sqrt(m2), m.unit_mean = u1, m.unit_sd = std::sqrt(u2);
  m.median = weighted_quantile(value, w, 0.5);
  m.lower_95 = weighted_quantile(value, w, 0.025);
  m.upper_95 = weighted_quantile(value, w, 0.975);
  m.narrowing = m.unit_sd > 0 ? p.prior_unit_sd() / m.unit_sd : INFINITY;
  m.identified = m.narrowing >= identified_narrowing;
  return m;
}

Eigen::MatrixXd correlations(const std::vector<Eigen::VectorXd>& u, const std::vector<double>& w) {
  const Eigen::Index d = u.front().size();
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  for (std::size_t i = 0; i < u.size(); ++i) mean += w[i] * u[i];
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < u.size(); ++i) c += w[i] * (u[i] - mean) * (u[i] - mean).transpose();
  Eigen::MatrixXd r(d, d);
  for (Eigen::Index a = 0; a < d; ++a)
    for (Eigen::Index b = 0; b < d; ++b) {
      const double s = std::sqrt(c(a, a) * c(b, b));
      r(a, b) = s > 0 ? c(a, b) / s : (a == b ? 1 : 0);
    }
  return r;
}

}  // namespace calibration
