#pragma once
// Reading a result file, the counterpart of ResultWriter (io/result_writer.hpp): the one check of
// what a complete result is, and the one reader of its tables. Every tool that reads results
// (dem table and summary, a saved state, the pipeline's reuse, validate, figure-data,
// ensemble-cycles, report, calibrate) asks these, so that none takes a file that another refuses.
#include <map>
#include <string>
#include <vector>

#include "io/hdf5.hpp"

namespace dem {

// Why the open file `f` is not a complete result that this build reads, or "" when it is:
//   * its status is not "complete" (a run that is going on, failed or was killed): "status '...'";
//   * it has no wall_time_s, which ResultWriter::complete writes with that status: a killed run's
//     .partial whose status was set to "complete" by hand;
//   * its schema_version is missing or above this build's (a file of a newer dem, or not dem's).
std::string result_problem(hid_t f);
// Throws h5::Error "<path>: not a complete result (<why>)" unless result_problem(f) is "".
void check_complete_result(hid_t f, const std::string& path);

// The columns of a table of a result (group "timeseries" or "legs"), by name; an empty map when
// the file has no such group. Throws h5::Error naming the file and the column when a column is
// not 1-D, when its length differs from the table's `time` (timeseries) or first column (a column
// cut short or grown: each row has one value in every column), or when it has a `checksum`
// attribute (written by ResultWriter::complete) that its values do not match (a flipped bit).
using Table = std::map<std::string, std::vector<double>>;
Table read_table(hid_t f, const std::string& group, const std::string& path);

// Writes the `checksum` attribute of every column of `group` of an open, writable result: the
// FNV-1a 64 hash (core/content_hash.hpp, as checkpoints use) of its values' bytes, read back from
// the file. ResultWriter::complete calls it once, after the last row.
void write_table_checksums(hid_t f, const std::string& group);

}  // namespace dem
