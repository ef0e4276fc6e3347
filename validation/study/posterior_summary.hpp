#pragma once
// What the report reads of a calibration's posterior.json (calibrate writes it:
// calibration/posterior_report.cpp, rows_consistent in calibration/row_verdicts.cpp), declared
// once: the keys, their types, and a missing one as an absence. calibration/ includes this
// header (a room may include those below it), so the writer can name its keys from here.
#include <optional>
#include <string>
#include <vector>

#include "study/stamp.hpp"

namespace validation {

namespace posterior_keys {
inline constexpr const char* best_set = "best_set";                  // {name, chi2}
inline constexpr const char* name = "name";
inline constexpr const char* stamp = "stamp";                        // study/stamp.hpp
inline constexpr const char* rows_consistent = "rows_consistent";    // {best_set: {name, consistent, judged}, per_row: [...]}
inline constexpr const char* per_row = "per_row";                    // [{name, consistent_at_best_set, ...}]
inline constexpr const char* consistent_at_best_set = "consistent_at_best_set";
inline constexpr const char* consistent = "consistent";
inline constexpr const char* judged = "judged";
inline constexpr const char* sizes = "sizes";                        // [{profile, densities, stamp, confirmed, ...}]
inline constexpr const char* densities = "densities";
inline constexpr const char* confirmed = "confirmed";                // [{set, chosen, predicted_probability, rows: [...]}]
inline constexpr const char* chosen = "chosen";                      // how the set was chosen: choice_names
inline constexpr const char* set = "set";
inline constexpr const char* predicted_probability = "predicted_probability";
inline constexpr const char* rows = "rows";                          // of a confirmed set: [{name, predicted_probability, consistent, mean, sd, samples}]
inline constexpr const char* mean = "mean";                          // a confirmed set's row: its samples' mean at the size, once scored
inline constexpr const char* sd = "sd";
inline constexpr const char* samples = "samples";
inline constexpr const char* largest_size_parts = "largest_size_parts";  // [{densities, rows_consistent}]
inline constexpr const char* scored_sets = "scored_sets";
inline constexpr const char* consistent_sets = "consistent_sets";
inline constexpr const char* judged_sets = "judged_sets";
inline constexpr const char* most_rows_consistent_with_it = "most_rows_consistent_with_it";
inline constexpr const char* set_with_most_rows = "set_with_most_rows";
inline constexpr const char* reach = "reach";                        // {points, largest_probability_all_rows, rows: [{name, largest_probability}]}
inline constexpr const char* points = "points";
inline constexpr const char* largest_probability = "largest_probability";
inline constexpr const char* largest_probability_all_rows = "largest_probability_all_rows";
}  // namespace posterior_keys

// How a set a larger size ran after its budget was chosen: the best of the sets scored (the
// posterior's best prediction among them), a new set at the reach's maximum (a probe), or a set
// of the first size the calibration file names for the size (run once the iterations end).
enum class Choice { best, probe, named };
inline constexpr const char* choice_names[] = {"best", "probe", "named"};  // posterior.json's words, in Choice's order
// The Choice a word of choice_names stands for; none for another word.
std::optional<Choice> choice_from(const std::string& word);
// How a report names a Choice after the set's name: ", the posterior's best prediction among the sets scored".
std::string chosen_words(Choice chosen);

struct PosteriorSummary {
  std::string best_set;  // the best set's name
  Stamp stamp;           // the engine and baseline of the calibration's runs (nothing recorded: none in the file)
  // rows_consistent: each validation row judged on the sets' own samples (absent: the calibration
  // scored no validation rows).
  struct Row {
    std::string name;
    std::optional<bool> consistent_at_best_set;  // none: the best set did not judge it
  };
  std::vector<Row> rows;
  std::optional<int> best_consistent, best_judged;  // rows consistent at the best set, of those it judged

  // A calibration whose largest size runs in parts (each some densities): per part, the stamp of
  // its runs, its rows judged set by set, and the sets it ran to confirm the posterior's best
  // prediction there. Empty for a calibration not in parts.
  struct Part {
    std::vector<std::string> densities;
    Stamp stamp;
    int scored_sets = 0;
    struct Row {
      std::string name;
      int consistent_sets = 0, judged_sets = 0;  // the part's scored sets in which it is consistent, judged
      std::optional<int> most_with;              // the most rows consistent in one of the sets where it is
      std::optional<std::string> set_with_most;  // that set (none: consistent in no set)
    };
    std::vector<Row> rows;
    struct Confirmed {
      std::string set;
      Choice chosen = Choice::best;
      double probability = 0;  // the posterior's, that one sample agrees with every row below
      struct Row {
        std::string name;
        double probability = 0;
        std::optional<bool> consistent;  // on the set's samples (none: not scored yet, or not judged)
        struct Measured {
          double mean = 0, sd = 0;
          int samples = 0;
        };
        std::optional<Measured> measured;  // the set's samples' mean and sd (none: not scored yet)
      };
      std::vector<Row> rows;
    };
    std::vector<Confirmed> confirmed;
    // How far the posterior at the part's size lets its rows be reached: over `points` of its
    // surface's region, each row's largest probability that one sample agrees with it (by name),
    // and that of all the part's rows at once. None before every part has its discrepancy.
    struct Reach {
      int points = 0;
      std::vector<std::pair<std::string, double>> rows;
      double all_rows = 0;
    };
    std::optional<Reach> reach;
  };
  std::vector<Part> parts;
};

// FILE's summary. Throws std::runtime_error naming FILE and the key ("best_set.name: missing") when
// it cannot be read, is not JSON or lacks the best set's name; any other key may be absent.
PosteriorSummary read_posterior_summary(const std::string& file);

}  // namespace validation
