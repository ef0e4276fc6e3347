#pragma once
// Cyclic stress paths at constant mean stress (docs/method.md#stress-paths): named states, and the expansion
// of a path (states, explicit triplets, repeat blocks) into straight legs with cycle numbers.
#include <string>
#include <variant>
#include <vector>

#include "core/types.hpp"

namespace dem {

// The named states of docs/method.md#stress-paths at mean stress p and ratio R = sigma_max/sigma_min:
// A (isotropic), TC1..3 (axis i major: 3pR/(R+2), others 3p/(R+2)), TE1..3 (axis i minor:
// 3p/(2R+1), others 3pR/(2R+1)). Throws std::invalid_argument for an unknown name.
Vec3 named_state(const std::string& name, double p_Pa, double R);
bool is_named_state(const std::string& name);

// One item of a path: a target state (named or explicit), or a block repeated N times. Each
// repetition of a block is one cycle.
struct PathItem {
  std::string label;        // state name, or "[s1, s2, s3]" for explicit triplets
  Vec3 state_Pa = Vec3::Zero();
  int repeat = 0;           // > 0: a block
  std::vector<PathItem> block;
};

struct PathLeg {
  Vec3 from_Pa, to_Pa;
  std::string to_label;
  double duration_s = 0;    // largest principal change / rate
  int cycle = 0;            // repetitions of blocks are numbered 1, 2, ...; legs outside blocks have 0
  int index = 0;            // leg number in the whole path, from 0
  bool ends_cycle = false;  // the last leg of a repetition
};

// Expands the items, starting from `start`, into legs at stress rate `rate` (the principal
// stress that changes most on a leg moves at `rate`). Legs of zero length are dropped.
std::vector<PathLeg> expand_path(const std::vector<PathItem>& items, const Vec3& start_Pa, double rate_Pa_per_s);

}  // namespace dem
