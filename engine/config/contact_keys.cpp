#include "config/contact_keys.hpp"

#include <sstream>
#include <string>
#include <type_traits>

namespace dem {

namespace {

std::string format_number(double x) {  // as the range messages print numbers (default stream format)
  std::ostringstream s;
  s << x;
  return s.str();
}

// The keys that belong to each law, for the message when one is given to another law.
struct LawKeys {
  const char* law;
  std::vector<std::string> keys;
};
const LawKeys law_keys[] = {{"linear", {"kn", "ks"}}, {"hertz_mindlin", {"young_modulus", "poisson_ratio"}}};

void refuse_keys_of_other_laws(const Section& m, const std::string& law) {
  for (const LawKeys& other : law_keys)
    if (other.law != law)
      for (const std::string& key : other.keys)
        if (m.has(key)) {
          std::string own;
          for (const LawKeys& mine : law_keys)
            if (mine.law == law)
              for (const std::string& k : mine.keys) own += (own.empty() ? "" : " and ") + m.key_path(k);
          m.fail(key, "belongs to " + m.key_path("law") + ": " + other.law + "; law " + law + " reads " + own);
        }
}

template <class Normal, class Tangential>
AnyContactLaw with_rolling(const Normal& normal, const Tangential& tangential, const RollingSpring& rolling) {
  if (rolling.mu_r > 0) return ContactLaw<Normal, Tangential, RollingSpring>{normal, tangential, rolling};
  return ContactLaw<Normal, Tangential>{normal, tangential, {}};
}

}  // namespace

AnyContactLaw read_contact_law(Section& m) {
  const std::string law = m.choice("law", {"linear", "hertz_mindlin"}, "linear",
                                   "contact law: linear springs (kn, ks) or Hertz-Mindlin (young_modulus, poisson_ratio)");
  refuse_keys_of_other_laws(m, law);
  const double mu = m.number("friction", "", {0, 10}, std::nullopt, "Coulomb friction coefficient mu; 0 = frictionless kernel");
  RollingSpring rolling;
  rolling.mu_r = m.number("rolling_friction", "", {0, 10}, 0.0,
                          "rolling friction coefficient mu_r: rolling moment capped at mu_r R* f_n; 0 = no rolling resistance");
  if (rolling.mu_r > 0) {
    try {
      rolling.kr = m.number("rolling_stiffness", "N/m", {0, 1e12, true}, std::nullopt,
                            "stiffness k_r of the rolling spring (moment R* k_r u_r); needed when rolling_friction > 0");
    } catch (const ConfigError& e) {
      // A key that is optional elsewhere: say why it is missing here.
      if (m.has("rolling_stiffness")) throw;
      throw ConfigError(std::string(e.what()) + "; needed because " + m.key_path("rolling_friction") + " = " +
                        format_number(rolling.mu_r) + " > 0 turns rolling resistance on");
    }
    if (mu == 0)
      m.fail("rolling_friction", "needs " + m.key_path("friction") + " > 0 (a frictionless contact has no rolling), got " +
                                     m.key_path("friction") + " = 0");
  } else if (m.has("rolling_stiffness")) {
    m.fail("rolling_stiffness", "is read only when rolling_friction > 0 (rolling resistance on); give both or neither");
  }

  const double zeta = m.number("contact_damping", "", {0, 1, false, true}, 0.0,
                               "contact dashpots, fraction zeta of critical: c_n = 2 zeta sqrt(m* k_n), c_t = 2 zeta sqrt(m* k_t) "
                               "(tangential while sticking); 0 = none");
  if (zeta > 0 && rolling.mu_r > 0)
    m.fail("contact_damping", "and rolling_friction > 0 together are not compiled (no such law); give one of them");
  if (law == "linear") {
    const LinearNormal normal{m.number("kn", "N/m", {0, 1e12, true}, std::nullopt, "normal contact stiffness (law linear)")};
    const double ks = m.number("ks", "N/m", {0, 1e12}, std::nullopt, "tangential contact stiffness (law linear)");
    if (mu > 0 && ks <= 0) m.fail("ks", "must be > 0 when friction > 0, got " + std::to_string(ks));
    if (zeta > 0) {
      const Dashpot<LinearNormal> damped{normal, zeta};
      if (mu == 0) return LinearDashpotLaw{damped, {}, {}};
      return LinearFrictionDashpotLaw{damped, LinearCoulomb{ks, mu}, {}};
    }
    if (mu == 0) return LinearLaw{normal, {}, {}};
    return with_rolling(normal, LinearCoulomb{ks, mu}, rolling);
  }
  HertzNormal normal;
  normal.young_modulus_Pa = m.number("young_modulus", "Pa", {0, 1e13, true}, std::nullopt,
                                     "Young's modulus E of the grains (law hertz_mindlin)");
  // Open at 0.5: an isotropic elastic solid has -1 < nu <= 0.5, and nu = 0.5 (incompressible) is refused.
  normal.poisson_ratio = m.number("poisson_ratio", "", {-1, 0.5, true, true}, std::nullopt,
                                  "Poisson's ratio nu of the grains (law hertz_mindlin)");
  if (zeta > 0) {
    if (mu == 0) m.fail("contact_damping", "with law hertz_mindlin is compiled with friction > 0 only");
    return HertzMindlinDashpotLaw{Dashpot<HertzNormal>{normal, zeta}, MindlinCoulomb::of(normal, mu), {}};
  }
  if (mu == 0) return HertzLaw{normal, {}, {}};
  return with_rolling(normal, MindlinCoulomb::of(normal, mu), rolling);
}

void emit_contact_law(YAML::Emitter& out, const AnyContactLaw& any) {
  std::visit(
      [&](const auto& law) {
        using Law = std::decay_t<decltype(law)>;
        if constexpr (std::is_base_of_v<LinearNormal, typename Law::NormalLaw>) {
          out << YAML::Key << "law" << YAML::Value << "linear" << YAML::Key << "kn" << YAML::Value << law.normal.kn;
          double ks = 0, mu = 0;
          if constexpr (Law::has_tangential) ks = law.tangential.ks, mu = law.tangential.mu;
          out << YAML::Key << "ks" << YAML::Value << ks << YAML::Key << "friction" << YAML::Value << mu;
        } else {
          out << YAML::Key << "law" << YAML::Value << "hertz_mindlin" << YAML::Key << "young_modulus" << YAML::Value
              << law.normal.young_modulus_Pa << YAML::Key << "poisson_ratio" << YAML::Value << law.normal.poisson_ratio;
          double mu = 0;
          if constexpr (Law::has_tangential) mu = law.tangential.mu;
          out << YAML::Key << "friction" << YAML::Value << mu;
        }
        if constexpr (Law::damped) out << YAML::Key << "contact_damping" << YAML::Value << law.normal.damping_ratio;
        if constexpr (Law::has_rolling)
          out << YAML::Key << "rolling_friction" << YAML::Value << law.rolling.mu_r << YAML::Key << "rolling_stiffness"
              << YAML::Value << law.rolling.kr;
      },
      any);
}

}  // namespace dem
