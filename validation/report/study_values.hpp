#pragma once
// The report's values that come from the paper study's results (the figures' notes, the runs and
// their settings, the energy balance, the earlier baseline's table), kept beside the report in
// REPORT/study_values.json with the stamp of the results they came from. `report` writes the file
// whenever the results are here and reads it back when they are not, so every section is written
// again anywhere from committed files; a file from other results than validation.json's shows by
// its stamp (report_main refuses another baseline).
#include <filesystem>
#include <optional>
#include <string>

#include "figures/notes.hpp"
#include "study/stamp.hpp"

namespace validation {

inline constexpr const char* study_values_file = "study_values.json";

struct StudyValues {
  Stamp stamp;          // of the results the values came from (stamp_of_results)
  std::string results;  // the results folder they were read from, as shown
  Values values;
};

// REPORT/study_values.json, written atomically: {"stamp": ..., "results": ..., "values": {key: text}}.
void write_study_values(const std::filesystem::path& report, const StudyValues& s);

// REPORT/study_values.json, or nothing when there is no such file. A file there that is not JSON,
// or not of this shape (a "values" object of strings), throws std::runtime_error naming it.
std::optional<StudyValues> read_study_values(const std::filesystem::path& report);

}  // namespace validation
