#pragma once
// The contact history, in its own store beside the neighbour list (neighbour/verlet_list.hpp),
// shaped by the law: a tangential history (and sliding flag) only with friction, a rolling spring
// only with rolling resistance. Entry k belongs to pair k of the list; when the list is rebuilt,
// `carried` moves the history of the pairs that survive to their new places.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace dem {

struct ContactHistory {
  std::string tangential_name;           // what `tangential` holds ("tangential_spring" [m], "tangential_force" [N]); empty: none
  bool rolling_on = false;
  std::vector<Vec3> tangential;          // the tangential law's history, per pair
  std::vector<std::uint8_t> sliding;     // 1 if the contact slid at the last force evaluation
  std::vector<Vec3> rolling;             // rolling displacement [m], per pair

  bool has_tangential() const { return !tangential_name.empty(); }
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

  // `pairs` unloaded entries of the kinds this history keeps.
  void reset(std::size_t pairs) {
    tangential.assign(has_tangential() ? pairs : 0, Vec3::Zero());
    sliding.assign(has_tangential() ? pairs : 0, 0);
    rolling.assign(rolling_on ? pairs : 0, Vec3::Zero());
  }
  // The history after a rebuild: new pair k had index from_previous[k] in the old list (`none`
  // if it is new, and starts unloaded).
  ContactHistory carried(const std::vector<std::uint32_t>& from_previous) const {
    ContactHistory out{tangential_name, rolling_on, {}, {}, {}};
    if (has_tangential()) {
      out.tangential = moved(tangential, from_previous, Vec3(Vec3::Zero()));
      out.sliding = moved(sliding, from_previous, std::uint8_t{0});
    }
    if (rolling_on) out.rolling = moved(rolling, from_previous, Vec3(Vec3::Zero()));
    return out;
  }
  // The entries of the pairs `keep` (ascending), e.g. the pairs in contact.
  ContactHistory subset(const std::vector<std::size_t>& keep) const {
    ContactHistory out{tangential_name, rolling_on, {}, {}, {}};
    for (std::size_t k : keep) {
      if (has_tangential()) out.tangential.push_back(tangential[k]), out.sliding.push_back(sliding[k]);
      if (rolling_on) out.rolling.push_back(rolling[k]);
    }
    return out;
  }

 private:
  template <class T>
  static std::vector<T> moved(const std::vector<T>& old, const std::vector<std::uint32_t>& from_previous, const T& unloaded) {
    std::vector<T> fresh(from_previous.size(), unloaded);
    for (std::size_t k = 0; k < from_previous.size(); ++k)
      if (from_previous[k] != none) fresh[k] = old[from_previous[k]];
    return fresh;
  }
};

}  // namespace dem
