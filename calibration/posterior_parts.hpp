#pragma once
// The parts of a calibration's report (posterior_report.cpp: posterior.json and the figures' data;
// posterior_section.cpp: section.md), not an interface of the room.
#include <map>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "calibrate.hpp"
#include "row_verdicts.hpp"

namespace calibration {

// What is common to a report's parts: the outcome, the final marginals, the best sets, the rows' verdicts.
struct Report {
  const Outcome& o;
  const std::map<std::string, double>& truth;
  const IterationSummary& last;
  std::size_t best;                 // of the first size's sets
  RowVerdicts verdicts;             // of the first size's sets
  std::optional<std::size_t> best_largest;  // with larger sizes: of the largest size's scored sets
  RowVerdicts largest_verdicts;
  Eigen::MatrixXd correlation;
  // With the largest size in parts (Outcome::in_parts): each part's best set by its own rows, and
  // its rows' verdicts (instead of best_largest and largest_verdicts).
  struct Part {
    std::size_t size = 0;  // index into Outcome::sizes
    std::optional<std::size_t> best;
    RowVerdicts verdicts;
  };
  std::vector<Part> parts;
};

// "uniform [0.1, 0.9]", "one of a b c": a parameter's prior.
std::string prior_text(const Parameter& p);
// "viscous 0.71, local 0.29": the posterior's weight on each value of a parameter of values.
std::string value_shares(const Parameter& p, std::size_t j, const Outcome& o);
// section.md: the tables.
std::string section_markdown(const Report& r);

}  // namespace calibration
