#pragma once
// A constant of a contact law as a scene gives it: one key of the scene's `material` mapping,
// declared once, in the header of the part that reads it, with its unit, range, default and doc.
// config/contact_keys.cpp reads, checks, documents (`dem keys`) and writes back (the resolved
// scene) every law's keys from these declarations alone. A key several parts read (friction, kn)
// is one declaration that each of them lists.
//
// A part lists its keys as `static constexpr std::array parameters{...}`, builds itself with
// `static Part from(const ParameterValues&)` and writes its constants back with
// `void write(ParameterValues&) const`. A part that a key turns on names it in `switched_by`
// (the part is in the law exactly when that key is > 0: friction, rolling_friction,
// contact_damping). An elastic normal part names its law (`law_name`, the value of material.law).
// A key of a new part gives an `example`: the tests that run every law (SIMD against scalar, 1
// against 2 threads, the energy balance) build the part from it (tests/engine/dynamics/packing_support.hpp).
#include <array>
#include <limits>
#include <map>
#include <string>

namespace dem {

inline constexpr double no_default = std::numeric_limits<double>::quiet_NaN();  // the scene must give the key

struct Parameter {
  const char* name;      // the key under `material`
  const char* unit;      // "" if dimensionless
  double min, max;       // allowed range
  bool min_open, max_open;
  double default_value;  // no_default: required (when its part is in the law)
  const char* doc;
  bool accepted_when_off = false;  // given while its part is off: read and checked, not an error
  double example = no_default;     // a typical value (the tests' packings of every law); no_default: the tests' own
  bool required() const { return default_value != default_value; }
};

// The constants of a law, by key name (reading and writing scenes only; never in a loop).
using ParameterValues = std::map<std::string, double>;

template <std::size_t A, std::size_t B>
constexpr std::array<Parameter, A + B> joined(const std::array<Parameter, A>& a, const std::array<Parameter, B>& b) {
  std::array<Parameter, A + B> out{};
  for (std::size_t k = 0; k < A; ++k) out[k] = a[k];
  for (std::size_t k = 0; k < B; ++k) out[A + k] = b[k];
  return out;
}

}  // namespace dem
