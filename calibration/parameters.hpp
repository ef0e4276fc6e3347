#pragma once
// The parameters a calibration infers: scene keys with a prior range. Each parameter lives on the
// unit interval u in [0, 1], where its prior is uniform; its value is u mapped onto the range
// (uniform), onto the logarithm of the range (log_uniform), or onto one of a list of values
// (values: u picks the k-th of K by floor(u K); readings: the same, each value a named set of
// scene keys and values).
#include <string>
#include <vector>

namespace calibration {

struct Parameter {
  enum class Prior { Uniform, LogUniform, Values };
  std::string name;               // what tables call it
  std::vector<std::string> keys;  // the scene keys it sets (e.g. material.kn and material.ks)
  // Which runs the keys are set in: "test" (the tests only: the preparations are shared by every
  // set), "prepare" (the preparations only) or "both" (each set prepares its own samples).
  std::string applies_to = "test";
  Prior prior = Prior::Uniform;
  double low = 0, high = 1;            // Uniform, LogUniform
  std::vector<std::string> values;     // Values, as YAML text (of readings: their names)
  // The densities whose tests the keys are set in (applies_to test only); empty: every density.
  std::vector<std::string> densities;
  // Values that are readings: each a set of scene keys and values (parallel to values, which holds
  // their names); keys then lists every key any reading sets.
  std::vector<std::vector<std::pair<std::string, std::string>>> readings;

  bool discrete() const { return prior == Prior::Values; }
  // The value at u (numbers as text the way scene files take them; a reading's name).
  std::string value_text(double u) const;
  // The scene keys and values the parameter sets at u: each key with the value, or the reading's.
  std::vector<std::pair<std::string, std::string>> overrides(double u) const;
  // The index of the value at u (Values: floor(u K) within 0..K-1).
  std::size_t value_index(double u) const;
  // The value at u as a number (Values: the value when it is a number, else its index).
  double value(double u) const;
  // The unit coordinate of a value (the inverse of value; for Values the middle of its bin).
  double unit_of(double value) const;
  // The prior's sd on the unit interval: 1/sqrt(12) (Values: of the bins' middles).
  double prior_unit_sd() const;
};

}  // namespace calibration
