#include "discrepancy.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>

namespace calibration {

int linear_discrepancy_pairs(int d) { return d + 3; }  // d + 1 terms, two degrees of freedom left

Eigen::VectorXd Discrepancy::features(const Eigen::VectorXd& u) const {
  if (!linear) return Eigen::VectorXd::Ones(1);
  Eigen::VectorXd x(u.size() + 1);
  x(0) = 1;
  x.tail(u.size()) = (u - centre).cwiseQuotient(scale);
  return x;
}

Discrepancy extended(const Discrepancy& delta, const References& part, const References& all) {
  Discrepancy out = delta;
  out.curves.clear(), out.rows.clear();
  Quadratic none;
  none.samples = 0;
  none.coefficients = Eigen::VectorXd::Zero(delta.linear ? delta.centre.size() + 1 : 1);
  none.covariance = Eigen::MatrixXd::Zero(none.coefficients.size(), none.coefficients.size());
  for (const CurveRow& c : all.curves) {
    const auto in = std::find_if(part.curves.begin(), part.curves.end(), [&](const CurveRow& p) { return p.name == c.name; });
    out.curves.push_back(in == part.curves.end() ? std::vector<Quadratic>(c.points.size(), none)
                                                 : delta.curves[static_cast<std::size_t>(in - part.curves.begin())]);
  }
  for (const validation::Row& r : all.rows) {
    const auto in = std::find_if(part.rows.begin(), part.rows.end(), [&](const validation::Row& p) { return p.name == r.name; });
    out.rows.push_back(in == part.rows.end() ? none : delta.rows[static_cast<std::size_t>(in - part.rows.begin())]);
  }
  return out;
}

std::optional<Discrepancy> fit_discrepancy(const References& refs, const std::vector<ParameterSet>& small,
                                           const std::vector<ParameterSet>& large) {
  std::map<std::string, const ParameterSet*> small_by_name;
  for (const ParameterSet& s : small)
    if (s.misfit.valued) small_by_name[s.name] = &s;
  std::vector<std::pair<const ParameterSet*, const ParameterSet*>> pairs;  // (small, large)
  for (const ParameterSet& s : large)
    if (const auto found = small_by_name.find(s.name); found != small_by_name.end() && s.misfit.valued) pairs.emplace_back(found->second, &s);
  if (static_cast<int>(pairs.size()) < min_discrepancy_pairs) return std::nullopt;
  const Eigen::Index d = pairs.front().first->u.size();
  Discrepancy delta;
  delta.pairs = static_cast<int>(pairs.size());
  delta.linear = delta.pairs >= linear_discrepancy_pairs(static_cast<int>(d));
  delta.centre = Eigen::VectorXd::Zero(d);
  for (const auto& p : pairs) delta.centre += p.second->u / static_cast<double>(pairs.size());
  delta.scale = Eigen::VectorXd::Zero(d);
  for (const auto& p : pairs) delta.scale += (p.second->u - delta.centre).cwiseAbs2() / static_cast<double>(pairs.size());
  delta.scale = delta.scale.cwiseSqrt();
  for (Eigen::Index k = 0; k < d; ++k)
    if (!(delta.scale(k) > 0)) delta.scale(k) = 1;  // every pair at one value of it: its slope is not fitted (minimum norm)
  std::vector<Eigen::VectorXd> x;
  for (const auto& p : pairs) x.push_back(delta.features(p.second->u));
  // Each point's difference fitted; its samples' variance, the large size's: a curve point's, their
  // own over the sets with 3 samples or more, else the reference's sd squared (one specimen's
  // scatter stands for one sample's, as on a surface); a scalar row's, their own with 2 or more
  // (its likelihood is about one sample), else its resolution (or tolerance) squared.
  const auto fit_point = [&](std::size_t row, std::size_t point, int own_from, double otherwise) {
    std::vector<double> y;
    double own = 0;
    for (const auto& p : pairs) {
      const RowMisfit& large = p.second->misfit.rows[row];
      y.push_back(large.model.at(point) - p.first->misfit.rows[row].model.at(point));
      own += large.model_sd.at(point) * large.model_sd.at(point) / static_cast<double>(pairs.size());
    }
    Quadratic q = fit_quadratic(x, y);
    q.samples = std::max(1, pairs.front().second->misfit.rows[row].samples);
    q.sample_variance = q.samples >= own_from ? own : otherwise;
    return q;
  };
  for (std::size_t c = 0; c < refs.curves.size(); ++c) {
    std::vector<Quadratic> per_point;
    for (std::size_t j = 0; j < refs.curves[c].points.size(); ++j)
      per_point.push_back(fit_point(c, j, 3, std::pow(refs.curves[c].points[j].sd, 2)));
    delta.curves.push_back(std::move(per_point));
  }
  for (std::size_t r = 0; r < refs.rows.size(); ++r) {
    const validation::Row& row = refs.rows[r];
    delta.rows.push_back(fit_point(refs.curves.size() + r, 0, 2, std::pow(row.resolution > 0 ? row.resolution : row.tolerance, 2)));
  }
  return delta;
}

std::vector<std::size_t> choose_for_larger_size(const std::vector<Eigen::VectorXd>& candidates,
                                                const std::vector<Eigen::VectorXd>& chosen,
                                                const std::vector<Eigen::VectorXd>& posterior_u,
                                                const std::vector<double>& posterior_w, int n) {
  std::vector<std::size_t> picked;
  if (candidates.empty() || posterior_u.empty() || n <= 0) return picked;
  const Eigen::Index d = posterior_u.front().size();
  // The posterior's weighted mean and covariance standardise the linear features.
  const double total = std::accumulate(posterior_w.begin(), posterior_w.end(), 0.0);
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
  for (std::size_t i = 0; i < posterior_u.size(); ++i) mean += posterior_w[i] / total * posterior_u[i];
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(d, d);
  for (std::size_t i = 0; i < posterior_u.size(); ++i) {
    const Eigen::VectorXd r = posterior_u[i] - mean;
    cov += posterior_w[i] / total * r * r.transpose();
  }
  cov += 1e-8 * Eigen::MatrixXd::Identity(d, d);
  const Eigen::VectorXd sd = cov.diagonal().cwiseSqrt();
  const Eigen::MatrixXd inverse = cov.inverse();
  const auto features = [&](const Eigen::VectorXd& u) {
    Eigen::VectorXd x(d + 1);
    x(0) = 1;
    x.tail(d) = (u - mean).cwiseQuotient(sd);
    return x;
  };
  // The candidates near the posterior: within distance 2, or the nearest n.
  std::vector<std::pair<double, std::size_t>> by_distance;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Eigen::VectorXd r = candidates[i] - mean;
    by_distance.emplace_back(std::sqrt(r.dot(inverse * r)), i);
  }
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<std::size_t> near;
  for (const auto& [distance, i] : by_distance)
    if (distance <= 2 || static_cast<int>(near.size()) < n) near.push_back(i);
  // A = ridge I + sum x x^T over the sets already at the larger size; each pick the candidate c that
  // maximises sum_p w_p (x_p^T A^-1 x_c)^2 / (1 + x_c^T A^-1 x_c), the fall of the weighted
  // prediction variance when c is added (Sherman-Morrison); then A += x_c x_c^T.
  Eigen::MatrixXd a = 1e-3 * Eigen::MatrixXd::Identity(d + 1, d + 1);
  for (const Eigen::VectorXd& u : chosen) a += features(u) * features(u).transpose();
  std::vector<Eigen::VectorXd> xp;
  for (const Eigen::VectorXd& u : posterior_u) xp.push_back(features(u));
  while (static_cast<int>(picked.size()) < n && picked.size() < near.size()) {
    const Eigen::MatrixXd a_inv = a.inverse();
    double best_gain = -1;
    std::size_t best = near.front();
    for (const std::size_t i : near) {
      if (std::find(picked.begin(), picked.end(), i) != picked.end()) continue;
      const Eigen::VectorXd xc = features(candidates[i]);
      const Eigen::VectorXd v = a_inv * xc;
      double gain = 0;
      for (std::size_t p = 0; p < xp.size(); ++p) gain += posterior_w[p] / total * std::pow(xp[p].dot(v), 2);
      gain /= 1 + xc.dot(v);
      if (gain > best_gain) best_gain = gain, best = i;
    }
    picked.push_back(best);
    const Eigen::VectorXd xb = features(candidates[best]);
    a += xb * xb.transpose();
  }
  return picked;
}

std::optional<Confirmation> choose_to_confirm(const ResponseSurface& surface, const std::vector<Discrepancy>& larger,
                                              const std::vector<Eigen::VectorXd>& candidates, const std::vector<std::size_t>& rows) {
  const bool any_inside = std::any_of(candidates.begin(), candidates.end(), [&](const Eigen::VectorXd& u) { return surface.inside(u); });
  std::optional<Confirmation> best;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (any_inside && !surface.inside(candidates[i])) continue;
    const std::vector<double> all = surface.row_probabilities(candidates[i], larger);
    Confirmation c{i, 1, {}};
    for (const std::size_t r : rows) c.row_probability.push_back(all[r]), c.probability *= all[r];
    if (!best || c.probability > best->probability) best = std::move(c);
  }
  return best;
}

Reach reach(const ResponseSurface& surface, const std::vector<Discrepancy>& larger, const std::vector<std::size_t>& rows, int n) {
  Reach r;
  r.row_most.assign(rows.size(), 0.0);
  std::mt19937_64 rng(20261203);  // deterministic: the report says the same on every run
  std::uniform_real_distribution<double> unit(0, 1);
  const Eigen::Index d = surface.centre.size();
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd u(d);
    for (Eigen::Index j = 0; j < d; ++j) u(j) = unit(rng);
    if (!surface.inside(u)) continue;
    ++r.points;
    const std::vector<double> p = surface.row_probabilities(u, larger);
    double all = 1;
    for (std::size_t k = 0; k < rows.size(); ++k) r.row_most[k] = std::max(r.row_most[k], p[rows[k]]), all *= p[rows[k]];
    if (r.all_best.size() == 0 || all > r.all_most) r.all_most = all, r.all_best = u;
  }
  return r;
}

}  // namespace calibration
