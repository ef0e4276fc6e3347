#include "parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace calibration {
namespace {

std::size_t bin(double u, std::size_t k) {
  return std::min(k - 1, static_cast<std::size_t>(std::max(0.0, u) * static_cast<double>(k)));
}

std::string exact(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace

double Parameter::value(double u) const {
  switch (prior) {
    case Prior::Uniform: return low + u * (high - low);
    case Prior::LogUniform: return low * std::pow(high / low, u);
    case Prior::Values: {
      const std::size_t k = bin(u, values.size());
      try {
        std::size_t used = 0;
        const double x = std::stod(values[k], &used);
        if (used == values[k].size()) return x;
      } catch (const std::exception&) {
      }
      return static_cast<double>(k);
    }
  }
  return 0;
}

std::size_t Parameter::value_index(double u) const { return bin(u, values.size()); }

std::string Parameter::value_text(double u) const {
  if (prior == Prior::Values) return values[bin(u, values.size())];
  return exact(value(u));
}

std::vector<std::pair<std::string, std::string>> Parameter::overrides(double u) const {
  if (!readings.empty()) return readings[bin(u, readings.size())];
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& key : keys) out.emplace_back(key, value_text(u));
  return out;
}

double Parameter::unit_of(double x) const {
  switch (prior) {
    case Prior::Uniform: return (x - low) / (high - low);
    case Prior::LogUniform: return std::log(x / low) / std::log(high / low);
    case Prior::Values: {
      for (std::size_t k = 0; k < values.size(); ++k)
        if (value((static_cast<double>(k) + 0.5) / static_cast<double>(values.size())) == x)
          return (static_cast<double>(k) + 0.5) / static_cast<double>(values.size());
      throw std::invalid_argument(name + ": " + exact(x) + " is none of its values");
    }
  }
  return 0;
}

double Parameter::prior_unit_sd() const {
  if (prior != Prior::Values) return 1 / std::sqrt(12.0);
  const double k = static_cast<double>(values.size());
  return std::sqrt((k * k - 1) / 12) / k;  // the discrete uniform over the bins' middles
}

}  // namespace calibration
