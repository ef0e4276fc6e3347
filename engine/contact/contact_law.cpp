#include "contact/contact_law.hpp"

#include <algorithm>
#include <stdexcept>

namespace dem {

AnyContactLaw linear_law(double kn, double ks, double mu) {
  if (mu > 0) return LinearFrictionLaw{LinearNormal{kn}, LinearCoulomb{ks, mu}, {}};
  return LinearLaw{LinearNormal{kn}, {}, {}};
}

bool has_tangential(const AnyContactLaw& law) {
  return std::visit([](const auto& l) { return l.has_tangential; }, law);
}

bool has_rolling(const AnyContactLaw& law) {
  return std::visit([](const auto& l) { return l.has_rolling; }, law);
}

double friction_coefficient(const AnyContactLaw& law) {
  return std::visit(
      [](const auto& l) {
        if constexpr (std::decay_t<decltype(l)>::has_tangential) return l.tangential.mu;
        return 0.0;
      },
      law);
}

std::string tangential_history_name(const AnyContactLaw& law) {
  return std::visit(
      [](const auto& l) -> std::string {
        if constexpr (std::decay_t<decltype(l)>::has_tangential) return l.tangential.history_name;
        return "";
      },
      law);
}

double critical_time_step(const AnyContactLaw& law, const Particles& p, double density_kg_per_m3) {
  if (p.size() == 0) throw std::invalid_argument("critical_time_step: no particles");
  const double m_min = *std::min_element(p.mass.begin(), p.mass.end());
  const double r_min = *std::min_element(p.radius.begin(), p.radius.end());
  return std::visit([&](const auto& l) { return l.normal.critical_time_step(m_min, r_min, density_kg_per_m3); }, law);
}

std::string critical_time_step_formula(const AnyContactLaw& law) {
  return std::visit([](const auto& l) -> std::string { return l.normal.critical_time_step_formula(); }, law);
}

double damping_stiffness(const AnyContactLaw& law) {
  return std::visit([](const auto& l) { return l.normal.damping_stiffness(); }, law);
}

std::string law_name(const AnyContactLaw& law) {
  return std::visit([](const auto& l) -> std::string { return std::decay_t<decltype(l)>::NormalLaw::law_name; }, law);
}

double contact_damping_ratio(const AnyContactLaw& law) {
  return std::visit(
      [](const auto& l) {
        if constexpr (std::decay_t<decltype(l)>::damped) return l.normal.damping_ratio;
        return 0.0;
      },
      law);
}

}  // namespace dem
