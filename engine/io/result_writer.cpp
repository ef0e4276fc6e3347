#include "io/result_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <new>
#include <stdexcept>

#include "analysis/legs.hpp"
#include "analysis/time_series.hpp"
#include "io/atomic_file.hpp"
#include "io/result_file.hpp"
#include "io/state_io.hpp"
#include "io/xdmf.hpp"
#include "version.hpp"

namespace dem {

ColumnTable::ColumnTable(hid_t file, const std::string& group, const std::vector<SeriesColumn>& columns)
    : group_(h5::create_group(file, group)), pending_(columns.size()) {
  for (const SeriesColumn& c : columns) {
    columns_.emplace_back(group_, c.name, c.units);
    if (!c.doc.empty()) h5::set_attribute(columns_.back().id(), "doc", c.doc);
  }
}

ColumnTable::ColumnTable(hid_t file, const std::string& group, const std::vector<SeriesColumn>& columns, Reopen)
    : group_(h5::open_group(file, group)), pending_(columns.size()) {
  for (const SeriesColumn& c : columns) columns_.emplace_back(group_, c.name);
}

void ColumnTable::append(const std::vector<double>& row) {
  if (row.size() != columns_.size())  // a row measured for another table: a bug, never bad input
    throw std::logic_error("a row of " + std::to_string(row.size()) + " values for a table of " +
                           std::to_string(columns_.size()) + " columns");
  for (std::size_t c = 0; c < columns_.size(); ++c) pending_[c].push_back(row[c]);
}

void ColumnTable::flush() {
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    columns_[c].append(pending_[c]);
    pending_[c].clear();
  }
}

ResultWriter::ResultWriter(std::string out_path, const SceneConfig& scene)
    : out_(std::move(out_path)), partial_(out_ + ".partial"), flush_rows_(static_cast<std::size_t>(scene.output.flush_rows)),
      frame_contacts_(scene.output.frames_contacts) {
  file_ = h5::create_file(partial_);
  try {  // the file exists from here on: a failure goes into its status
    h5::set_attribute(file_, "status", std::string("running"));
    h5::set_attribute(file_, "software_version", std::string(software_version));
    h5::set_attribute(file_, "schema_version", static_cast<std::int64_t>(schema_version));
    h5::set_attribute(file_, "scene_file", scene.file);
    h5::write_text(file_, "scene_yaml", scene.resolved_yaml);  // a dataset: no size limit
    h5::set_attribute(file_, "damping_form", std::string(scene.damping.form == Damping::Form::Viscous ? "viscous" : "local"));
    tables_.emplace_back(file_, "timeseries", series_columns());
    tables_.emplace_back(file_, "legs", leg_columns());
    h5::flush_file(file_, partial_);
  } catch (const std::exception& e) {
    fail(describe_failure(e));
    throw;
  }
}

ResultWriter::ResultWriter(std::string out_path, const SceneConfig& scene, const std::string& checkpoint_file)
    : out_(std::move(out_path)), partial_(out_ + ".partial"), flush_rows_(static_cast<std::size_t>(scene.output.flush_rows)),
      frame_contacts_(scene.output.frames_contacts) {
  copy_file_contents(checkpoint_file, partial_);
  file_ = h5::open_file_write(partial_);
  try {
    if (H5Ldelete(file_, "checkpoint", H5P_DEFAULT) < 0) throw h5::Error(partial_ + ": cannot remove /checkpoint");
    tables_.emplace_back(file_, "timeseries", series_columns(), ColumnTable::Reopen{});
    tables_.emplace_back(file_, "legs", leg_columns(), ColumnTable::Reopen{});
    if (h5::exists(file_, "particles/all")) frames_ = std::make_unique<H5mdWriter>(file_);
    h5::flush_file(file_, partial_);
  } catch (const std::exception& e) {
    fail(describe_failure(e));
    throw;
  }
}

ResultWriter::~ResultWriter() {
  // run_scene writes every std::exception's reason (out of memory included) before this; only a
  // writer dropped without complete() or fail() gets here.
  if (!done_) fail("the run was interrupted");
}

void ResultWriter::append_row(const std::vector<double>& row) {
  tables_[0].append(row);
  if (tables_[0].pending_rows() >= flush_rows_) flush();
}

void ResultWriter::append_leg(const std::vector<double>& row) { tables_[1].append(row); }

void ResultWriter::set_attribute(const std::string& name, const std::string& value) {
  h5::set_attribute(file_, name, value);
}

void ResultWriter::add_warning(const std::string& warning) { warnings_.push_back(warning); }

void ResultWriter::write_pending() {
  for (ColumnTable& t : tables_) t.flush();
  // Appended, never rewritten: any number of warnings of any length (an attribute stopped a run
  // at 64 KiB of them).
  h5::append_texts(file_, "warnings", warnings_);
  warnings_.clear();
}

void ResultWriter::flush() {
  write_pending();
  h5::flush_file(file_, partial_);
}

void ResultWriter::write_state(const Simulation& sim) {
  h5::Handle g = h5::create_group(file_, "state");
  dem::write_state(g, sim);
}

void ResultWriter::append_frame(const Simulation& sim) {
  if (!frames_) frames_ = std::make_unique<H5mdWriter>(file_, sim);
  if (frames_->frames() > 0 && frames_->last_step() == sim.step_count()) return;
  frames_->append_frame(sim, frame_contacts_);
  h5::flush_file(file_, partial_);
}

void ResultWriter::close() {
  // Everything is written first (checked), so that closing datasets and groups, whose errors
  // HDF5 would not report, has nothing left to write; then the file's own close is checked.
  if (file_.id() >= 0) h5::flush_file(file_, partial_);
  frames_.reset();
  tables_.clear();
  h5::close_file(file_, partial_);
  closed_cleanly_ = true;
}

std::string ResultWriter::complete(double wall_time_s) {
  write_pending();
  for (const char* table : {"timeseries", "legs"}) write_table_checksums(file_, table);  // once, after the last row
  h5::set_attribute(file_, "wall_time_s", wall_time_s);
  h5::set_attribute(file_, "status", std::string("complete"));
  const bool has_frames = frames_ && frames_->frames() > 0;
  close();  // the file is closed before it gets its final name
  sync_file(partial_);  // and on the disk
  // An XDMF left by an earlier result at this path would describe the wrong frames: it goes first.
  const std::string xdmf = xdmf_path_for(out_);
  std::filesystem::remove(xdmf);
  std::filesystem::rename(partial_, out_);
  try {
    sync_folder_of(out_);  // the new name on the disk too
  } catch (...) {
    std::error_code back;  // not known to be on the disk: not complete
    std::filesystem::rename(out_, partial_, back);
    throw;
  }
  done_ = true;
  // The XDMF is a convenience view of a result that is already complete: failing to write it is
  // reported but does not fail the run.
  if (!has_frames) return "";
  try {
    write_xdmf(out_);
  } catch (const std::exception& e) {
    return xdmf + ": no XDMF file written: " + e.what();
  }
  return "";
}

void ResultWriter::fail(const std::string& reason) noexcept {
  if (done_) return;
  done_ = true;
  // Each step on its own: on a full disk the rows may not fit while the status still does.
  try {
    if (file_.id() < 0 && closed_cleanly_ && std::filesystem::is_regular_file(partial_))
      file_ = h5::open_file_write(partial_);  // closed, then complete() failed (fsync, rename)
  } catch (...) {
  }
  if (file_.id() < 0) return;  // never opened, or its close failed: HDF5 cannot touch it again
  try {
    write_pending();
  } catch (...) {
  }
  try {
    h5::set_attribute(file_, "status", std::string("failed: ") + reason);
  } catch (...) {
  }
  try {
    close();
  } catch (...) {
  }
}

}  // namespace dem
