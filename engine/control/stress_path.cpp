#include "control/stress_path.hpp"

#include <stdexcept>

namespace dem {

bool is_named_state(const std::string& name) {
  return name == "A" || ((name.size() == 3) && (name.rfind("TC", 0) == 0 || name.rfind("TE", 0) == 0) &&
                         name[2] >= '1' && name[2] <= '3');
}

Vec3 named_state(const std::string& name, double p_Pa, double R) {
  if (!is_named_state(name)) throw std::invalid_argument("unknown stress state '" + name + "' (known: A, TC1..TC3, TE1..TE3)");
  if (name == "A") return Vec3::Constant(p_Pa);
  const int axis = name[2] - '1';
  const bool compression = name[1] == 'C';
  const double named = compression ? 3 * p_Pa * R / (R + 2) : 3 * p_Pa / (2 * R + 1);
  const double other = compression ? 3 * p_Pa / (R + 2) : 3 * p_Pa * R / (2 * R + 1);
  Vec3 s = Vec3::Constant(other);
  s[axis] = named;
  return s;
}

namespace {
void expand(const std::vector<PathItem>& items, Vec3& at, double rate, int& cycle_counter, int cycle,
            std::vector<PathLeg>& legs) {
  for (const PathItem& item : items) {
    if (item.repeat > 0) {
      for (int r = 0; r < item.repeat; ++r) {
        const int this_cycle = ++cycle_counter;
        const std::size_t first = legs.size();
        expand(item.block, at, rate, cycle_counter, this_cycle, legs);
        if (legs.size() > first) legs.back().ends_cycle = true;
      }
      continue;
    }
    const Vec3 delta = item.state_Pa - at;
    const double largest = delta.cwiseAbs().maxCoeff();
    if (largest == 0) continue;
    PathLeg leg;
    leg.from_Pa = at;
    leg.to_Pa = item.state_Pa;
    leg.to_label = item.label;
    leg.duration_s = largest / rate;
    leg.cycle = cycle;
    leg.index = static_cast<int>(legs.size());
    legs.push_back(leg);
    at = item.state_Pa;
  }
}
}  // namespace

std::vector<PathLeg> expand_path(const std::vector<PathItem>& items, const Vec3& start_Pa, double rate_Pa_per_s) {
  std::vector<PathLeg> legs;
  Vec3 at = start_Pa;
  int cycles = 0;
  expand(items, at, rate_Pa_per_s, cycles, 0, legs);
  return legs;
}

}  // namespace dem
