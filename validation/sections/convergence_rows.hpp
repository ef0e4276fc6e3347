#pragma once
// The convergence budget set against the paper study's rows (compare-runs convergence): is each
// factor's error known within the tolerance of the rows it serves, and is each inconsistent row's
// miss explained by the settings' errors?
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sections/convergence_budget.hpp"

namespace validation {

// One density's budgets, quantity by quantity.
struct DensityBudgets {
  std::string density;
  std::vector<Budget> budgets;
};

// The factors of a budget in the section's order, with their names.
std::vector<std::pair<std::string, const FactorError*>> factors_of(const Budget& b);

// A number as the section prints it: 4 significant digits, "—" when not finite.
std::string budget_number(double x);

// For each row of the paper study's validation.json (`validation`) that the budget measures: its
// tolerance (a one-sided row's threshold's distance from zero) against the widest 95 % half-width
// of the factors in the row's units, and the samples a wider factor would need. "" if none.
std::string precision_table(const std::vector<DensityBudgets>& all, const nlohmann::json& validation);

// Each inconsistent row's miss against the sum of the settings' errors: beyond its far end, within
// its near end (each error at the near end of its interval), or between (cannot tell). "" if none.
std::string verdict_reading(const std::vector<DensityBudgets>& all, const nlohmann::json& validation, const std::string& validation_json);

}  // namespace validation
