#include "surrogate.hpp"

#include "discrepancy.hpp"
#include "study/ensemble.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

namespace calibration {

int quadratic_terms(int d) { return 1 + d + d * (d + 1) / 2; }

Quadratic fit_quadratic(const std::vector<Eigen::VectorXd>& features, const std::vector<double>& y) {
  const Eigen::Index n = static_cast<Eigen::Index>(features.size()), p = features.front().size();
  Eigen::MatrixXd x(n, p);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) x.row(i) = features[static_cast<std::size_t>(i)].transpose(), v(i) = y[static_cast<std::size_t>(i)];
  // A parameter of two values (a discrete reading) makes its square a combination of 1 and itself:
  // the features are then of lower rank than p, and the residuals have n - rank degrees of freedom.
  const auto decomposition = (x.transpose() * x).completeOrthogonalDecomposition();
  const Eigen::MatrixXd xtx_inv = decomposition.pseudoInverse();
  const Eigen::Index rank = decomposition.rank();
  Quadratic q;
  q.coefficients = xtx_inv * x.transpose() * v;
  const double rss = (v - x * q.coefficients).squaredNorm();
  q.residual_variance = n > rank ? rss / static_cast<double>(n - rank) : 0;
  q.covariance = q.residual_variance * xtx_inv;
  return q;
}

Eigen::VectorXd ResponseSurface::features(const Eigen::VectorXd& u) const {
  const Eigen::Index d = u.size();
  const Eigen::VectorXd z = (u - centre).cwiseQuotient(scale);
  Eigen::VectorXd x(quadratic_terms(static_cast<int>(d)));
  Eigen::Index k = 0;
  x(k++) = 1;
  for (Eigen::Index i = 0; i < d; ++i) x(k++) = z(i);
  for (Eigen::Index i = 0; i < d; ++i)
    for (Eigen::Index j = i; j < d; ++j) x(k++) = z(i) * z(j);
  return x;
}

bool ResponseSurface::inside(const Eigen::VectorXd& u) const {
  const Eigen::VectorXd r = u - centre;
  return r.dot(region_inverse * r) <= radius * radius;
}

double ResponseSurface::log_likelihood(const References& refs, const Eigen::VectorXd& u) const {
  return log_likelihood(refs, u, {});
}

namespace {

// The model's mean at u (a surface's plus every discrepancy's), the variance of the fits'
// prediction, and the samples' own term (the largest size's).
struct Prediction {
  double mean = 0, fit_variance = 0;
  const Quadratic* samples_of = nullptr;
};

// The features of u on a surface and on each discrepancy after it.
struct At {
  Eigen::VectorXd x;
  std::vector<Eigen::VectorXd> xd;
  At(const ResponseSurface& s, const Eigen::VectorXd& u, const std::vector<Discrepancy>& larger) : x(s.features(u)) {
    for (const Discrepancy& delta : larger) xd.push_back(delta.features(u));
  }
};

template <class DiscrepancyOf>
Prediction predict(const Quadratic& q, const At& at, const std::vector<Discrepancy>& larger, const DiscrepancyOf& discrepancy_of) {
  Prediction p{q.value(at.x), q.variance(at.x), &q};
  for (std::size_t k = 0; k < larger.size(); ++k) {
    const Quadratic& dq = discrepancy_of(larger[k]);
    if (!covers(dq)) continue;  // a part of a size that does not cover this point
    p.mean += dq.value(at.xd[k]), p.fit_variance += dq.variance(at.xd[k]), p.samples_of = &dq;
  }
  return p;
}

}  // namespace

std::vector<double> ResponseSurface::row_probabilities(const Eigen::VectorXd& u, const std::vector<Discrepancy>& larger) const {
  const At at(*this, u, larger);
  std::vector<double> p;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const RowSurface& row = rows[r];
    const Prediction m = predict(row.q, at, larger, [&](const Discrepancy& delta) -> const Quadratic& { return delta.rows[r]; });
    const double sd = std::sqrt(m.samples_of->sample_variance + m.fit_variance), mean = m.mean;
    const auto below = [&](double v) {  // P(value < v)
      if (std::isinf(v)) return v > 0 ? 1.0 : 0.0;
      if (sd == 0) return mean < v ? 1.0 : 0.0;
      return 0.5 * std::erfc(-(v - mean) / (sd * std::sqrt(2.0)));
    };
    p.push_back(below(row.high) - below(row.low));
  }
  return p;
}

double ResponseSurface::log_likelihood(const References& refs, const Eigen::VectorXd& u, const std::vector<Discrepancy>& larger) const {
  const At at(*this, u, larger);
  double ll = 0;
  const auto at_point = [&](std::size_t c, std::size_t j) {
    return predict(curves[c][j], at, larger, [&](const Discrepancy& delta) -> const Quadratic& { return delta.curves[c][j]; });
  };
  // Points whose deviations are correlated (References::correlated): jointly Gaussian, their
  // covariance the independent parts (tolerance, the fits' prediction) on the diagonal plus the
  // lab mean's and the model mean's common deviations, each sd_j sd_k R_jk.
  std::vector<std::vector<bool>> joint(refs.curves.size());
  for (std::size_t c = 0; c < refs.curves.size(); ++c) joint[c].assign(refs.curves[c].points.size(), false);
  for (const CorrelatedPoints& g : refs.correlated) {
    const Eigen::Index n = static_cast<Eigen::Index>(g.points.size());
    Eigen::VectorXd r(n), lab(n), model(n), own(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const auto [c, j] = g.points[static_cast<std::size_t>(k)];
      const CurveRow& row = refs.curves[c];
      const CurvePoint& p = row.points[j];
      const Prediction m = at_point(c, j);
      r(k) = m.mean - p.y;
      own(k) = row.tolerance * row.tolerance + m.fit_variance;
      lab(k) = p.sd / std::sqrt(static_cast<double>(row.specimens));
      model(k) = std::sqrt(m.samples_of->sample_variance / m.samples_of->samples);
      joint[c][j] = true;
    }
    const Eigen::MatrixXd cov =
        Eigen::MatrixXd(own.asDiagonal()) + (lab * lab.transpose() + model * model.transpose()).cwiseProduct(g.correlation);
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(cov);
    ll += -0.5 * r.dot(ldlt.solve(r)) - 0.5 * ldlt.vectorD().array().log().sum() - 0.5 * static_cast<double>(n) * std::log(2 * M_PI);
  }
  for (std::size_t c = 0; c < refs.curves.size(); ++c) {
    const CurveRow& row = refs.curves[c];
    for (std::size_t j = 0; j < row.points.size(); ++j) {
      if (joint[c][j]) continue;
      const CurvePoint& p = row.points[j];
      const Prediction m = at_point(c, j);
      const double var = row.tolerance * row.tolerance + p.sd * p.sd / row.specimens +
                         m.samples_of->sample_variance / m.samples_of->samples + m.fit_variance;
      const double r = m.mean - p.y;
      ll += -0.5 * r * r / var - 0.5 * std::log(2 * M_PI * var);
    }
  }
  for (const double p : row_probabilities(u, larger)) ll += std::log(std::max(p, 1e-300));
  return ll;
}

std::optional<ResponseSurface> fit_surface(const References& refs, const std::vector<ParameterSet>& sets,
                                           const Proposal& region) {
  if (refs.curves.empty() && refs.rows.empty()) return std::nullopt;
  std::vector<const ParameterSet*> scored;
  for (const ParameterSet& s : sets)
    if (s.misfit.valued) scored.push_back(&s);
  if (scored.empty()) return std::nullopt;
  const int d = static_cast<int>(scored.front()->u.size());
  const std::size_t wanted = static_cast<std::size_t>(2 * quadratic_terms(d));
  if (scored.size() < wanted) return std::nullopt;
  ResponseSurface s;
  s.centre = region.mean.size() ? region.mean : Eigen::VectorXd::Constant(d, 0.5);
  const Eigen::MatrixXd cov = region.mean.size() ? region.covariance : Eigen::MatrixXd::Identity(d, d) / 12.0;
  s.scale = cov.diagonal().cwiseSqrt();
  s.region_inverse = cov.inverse();
  // The sets by their distance from the region's centre: those inside, at least `wanted`.
  std::vector<std::pair<double, const ParameterSet*>> by_distance;
  for (const ParameterSet* p : scored) {
    const Eigen::VectorXd r = p->u - s.centre;
    by_distance.emplace_back(std::sqrt(r.dot(s.region_inverse * r)), p);
  }
  std::sort(by_distance.begin(), by_distance.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t used = 0;
  while (used < by_distance.size() && (by_distance[used].first <= s.radius || used < wanted)) ++used;
  s.radius = std::max(s.radius, by_distance[used - 1].first);
  s.sets = static_cast<int>(used);
  std::vector<Eigen::VectorXd> x;
  for (std::size_t i = 0; i < used; ++i) x.push_back(s.features(by_distance[i].second->u));
  double ratio = 0;
  int points = 0;
  for (std::size_t c = 0; c < refs.curves.size(); ++c) {
    std::vector<Quadratic> per_point;
    for (std::size_t j = 0; j < refs.curves[c].points.size(); ++j) {
      std::vector<double> y;
      for (std::size_t i = 0; i < used; ++i) y.push_back(by_distance[i].second->misfit.rows[c].model[j]);
      per_point.push_back(fit_quadratic(x, y));
      const CurvePoint& p = refs.curves[c].points[j];
      Quadratic& q = per_point.back();
      q.samples = std::max(1, by_distance[0].second->misfit.rows[c].samples);
      q.sample_variance = p.sd * p.sd;
      if (q.samples >= 3) {
        double v = 0;
        for (std::size_t i = 0; i < used; ++i) v += std::pow(by_distance[i].second->misfit.rows[c].model_sd[j], 2) / static_cast<double>(used);
        q.sample_variance = v;
      }
      if (p.sd > 0) ratio += std::sqrt(per_point.back().residual_variance) / (p.sd / std::sqrt(refs.curves[c].specimens)), ++points;
    }
    s.curves.push_back(std::move(per_point));
  }
  for (std::size_t r = 0; r < refs.rows.size(); ++r) {
    const validation::Row& row = refs.rows[r];
    const std::size_t at = refs.curves.size() + r;  // the row's misfit follows the curves' (score)
    std::vector<double> y;
    double variance = 0;
    for (std::size_t i = 0; i < used; ++i) {
      const RowMisfit& m = by_distance[i].second->misfit.rows[at];
      y.push_back(m.model.at(0));
      variance += m.model_sd.at(0) * m.model_sd.at(0) / static_cast<double>(used);
    }
    RowSurface rs;
    rs.q = fit_quadratic(x, y);
    rs.q.samples = std::max(1, by_distance[0].second->misfit.rows[at].samples);
    rs.q.sample_variance = rs.q.samples >= 2 ? variance : std::pow(row.resolution > 0 ? row.resolution : row.tolerance, 2);
    const validation::Region region_of_row = validation::paper_region(row.check, row.reference, row.tolerance);
    rs.low = region_of_row.low, rs.high = region_of_row.high;
    s.rows.push_back(rs);
  }
  s.noise_to_reference = points > 0 ? ratio / points : 0;
  return s;
}

namespace {

// n points from N(mean, cov) inside the cube and the surface's region, weighed by likelihood over
// the Gaussian's density (its normalisation, the same for every point, cancels).
void draw_weighted(const ResponseSurface& s, const std::vector<Discrepancy>& larger, const References& refs, const Eigen::VectorXd& mean,
                   const Eigen::MatrixXd& cov, int n, std::mt19937_64& rng, std::vector<Eigen::VectorXd>& u, std::vector<double>& w) {
  const Eigen::Index d = mean.size();
  const Eigen::MatrixXd l = Eigen::LLT<Eigen::MatrixXd>(cov).matrixL();
  std::normal_distribution<double> normal;
  std::vector<double> log_w;
  u.clear();
  for (long tries = 0; static_cast<int>(u.size()) < n && tries < 100L * n; ++tries) {
    Eigen::VectorXd z(d);
    for (Eigen::Index j = 0; j < d; ++j) z(j) = normal(rng);
    const Eigen::VectorXd p = mean + l * z;
    if ((p.array() < 0).any() || (p.array() > 1).any() || !s.inside(p)) continue;
    u.push_back(p);
    log_w.push_back(s.log_likelihood(refs, p, larger) + 0.5 * z.squaredNorm());
  }
  w.assign(log_w.size(), 0.0);
  if (log_w.empty()) return;
  const double top = *std::max_element(log_w.begin(), log_w.end());
  double sum = 0;
  for (std::size_t i = 0; i < w.size(); ++i) sum += w[i] = std::exp(log_w[i] - top);
  for (double& x : w) x /= sum;
}

}  // namespace

void sample_surface(const ResponseSurface& s, const References& refs, int n, std::vector<Eigen::VectorXd>& u,
                    std::vector<double>& w) {
  sample_surface(s, {}, refs, n, u, w);
}

void sample_surface(const ResponseSurface& s, const std::vector<Discrepancy>& larger, const References& refs, int n,
                    std::vector<Eigen::VectorXd>& u, std::vector<double>& w) {
  std::mt19937_64 rng(20261127);
  // First from the region's Gaussian, then again from a Gaussian fitted to those weights (twice
  // their covariance), which puts the points where the posterior is.
  draw_weighted(s, larger, refs, s.centre, s.region_inverse.inverse(), n, rng, u, w);
  if (u.empty()) return;
  const Proposal q = fit_proposal(u, w, 0, 2, 1e-4);
  draw_weighted(s, larger, refs, q.mean, q.covariance, n, rng, u, w);
}

}  // namespace calibration
