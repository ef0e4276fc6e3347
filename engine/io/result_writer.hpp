#pragma once
// Writes one run's result file. The run writes into "<out>.partial" with status "running"; only a
// run that finishes is renamed to <out> with status "complete", so a half-written file can never
// be mistaken for a finished one. The rename comes only after every write, flush and close
// succeeded and the file reached the disk (fsync of the file; fsync of the folder after the
// rename); any failure on the way (a full disk, say) throws with its reason and leaves
// "<out>.partial". A run that fails keeps "<out>.partial" with status "failed: <reason>" when the
// file can still take the attribute; a killed run leaves it at "running".
//
// Particle frames go to /particles after H5MD (io/h5md.hpp); a complete result also gets
// "<out minus .h5>.xdmf" beside it (io/xdmf.hpp), written only after the rename.
#include <memory>
#include <string>
#include <vector>

#include "analysis/columns.hpp"
#include "config/scene_config.hpp"
#include "io/h5md.hpp"
#include "io/failure.hpp"  // describe_failure: the reason in the status "failed: <reason>"
#include "io/hdf5.hpp"

namespace dem {

// A group of equally long, extendable columns, filled row by row and flushed in batches.
class ColumnTable {
 public:
  ColumnTable(hid_t file, const std::string& group, const std::vector<SeriesColumn>& columns);
  struct Reopen {};
  ColumnTable(hid_t file, const std::string& group, const std::vector<SeriesColumn>& columns, Reopen);
  void append(const std::vector<double>& row);  // one value per column (std::logic_error otherwise)
  std::size_t pending_rows() const { return pending_.empty() ? 0 : pending_[0].size(); }
  void flush();  // writes pending rows (the caller flushes the file)

 private:
  h5::Handle group_;
  std::vector<h5::Column> columns_;
  std::vector<std::vector<double>> pending_;  // per column
};

class ResultWriter {
 public:
  ResultWriter(std::string out_path, const SceneConfig& scene);
  // Continues from a checkpoint (run/checkpoint.hpp): <out>.partial becomes a copy of it, without
  // its /checkpoint group, and the run appends to its rows and frames.
  ResultWriter(std::string out_path, const SceneConfig& scene, const std::string& checkpoint_file);
  ~ResultWriter();

  void append_row(const std::vector<double>& row);  // /timeseries; flushed every `flush_rows` rows
  void append_leg(const std::vector<double>& row);  // /legs (stress-path stages)
  void add_warning(const std::string& warning);     // appended to the dataset /warnings (one string each)
  void set_attribute(const std::string& name, const std::string& value);  // a root attribute
  void flush();  // everything so far is written to the file (checked; not fsync'd) when it returns
  void write_state(const class Simulation& sim);
  // One H5MD particle frame at the simulation's current step (the first call creates /h5md
  // and /particles, taking radius and mass from `sim`); none if the last frame is of this step.
  void append_frame(const Simulation& sim);
  // Marks the file complete, closes it, fsyncs it and moves it to its final name; throws
  // (h5::Error, std::runtime_error) with the reason if any of that fails, leaving <out>.partial.
  // Returns a warning for the caller to report if the XDMF view could not be written ("" if it was).
  std::string complete(double wall_time_s);
  // Marks the partial file "failed: <reason>" (best effort; never throws).
  void fail(const std::string& reason) noexcept;
  const std::string& partial_path() const { return partial_; }

 private:
  void write_pending();  // rows and warnings into the file
  void close();          // checked; file_ is empty afterwards either way
  std::string out_, partial_;
  std::size_t flush_rows_;
  bool frame_contacts_;
  h5::Handle file_;
  std::vector<ColumnTable> tables_;  // [0] time series, [1] legs
  std::unique_ptr<H5mdWriter> frames_;  // created by the first frame
  std::vector<std::string> warnings_;  // not yet written
  bool done_ = false;
  bool closed_cleanly_ = false;  // the file was closed without error (fail() may reopen it)
};

}  // namespace dem
