#include "io/result_writer.hpp"

#include <filesystem>

#include "analysis/time_series.hpp"
#include "io/state_io.hpp"
#include "version.hpp"

namespace dem {

ResultWriter::ResultWriter(std::string out_path, const SceneConfig& scene)
    : out_(std::move(out_path)), partial_(out_ + ".partial"), flush_rows_(static_cast<std::size_t>(scene.output.flush_rows)) {
  file_ = h5::create_file(partial_);
  h5::set_attribute(file_, "status", std::string("running"));
  h5::set_attribute(file_, "software_version", std::string(software_version));
  h5::set_attribute(file_, "schema_version", static_cast<std::int64_t>(schema_version));
  h5::set_attribute(file_, "scene_file", scene.file);
  h5::set_attribute(file_, "scene_yaml", scene.resolved_yaml);
  h5::set_attribute(file_, "damping_form", std::string(scene.damping.form == Damping::Form::Viscous ? "viscous" : "local"));
  series_ = h5::create_group(file_, "timeseries");
  for (const SeriesColumn& c : series_columns()) {
    columns_.emplace_back(series_, c.name, c.units);
    if (!c.doc.empty()) h5::set_attribute(columns_.back().id(), "doc", c.doc);
  }
  pending_.resize(columns_.size());
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

ResultWriter::~ResultWriter() {
  if (!done_) fail("the run was interrupted");
}

void ResultWriter::append_row(const std::vector<double>& row) {
  for (std::size_t c = 0; c < columns_.size(); ++c) pending_[c].push_back(row[c]);
  if (pending_[0].size() >= flush_rows_) flush();
}

void ResultWriter::flush() {
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    columns_[c].append(pending_[c]);
    pending_[c].clear();
  }
  H5Fflush(file_, H5F_SCOPE_GLOBAL);
}

void ResultWriter::write_state(const Simulation& sim) {
  h5::Handle g = h5::create_group(file_, "state");
  dem::write_state(g, sim);
}

void ResultWriter::complete(double wall_time_s) {
  flush();
  h5::set_attribute(file_, "wall_time_s", wall_time_s);
  h5::set_attribute(file_, "status", std::string("complete"));
  columns_.clear();
  series_.reset();
  file_.reset();  // closes the file before it gets its final name
  std::filesystem::rename(partial_, out_);
  done_ = true;
}

void ResultWriter::fail(const std::string& reason) noexcept {
  if (done_) return;
  done_ = true;
  try {
    flush();
    h5::set_attribute(file_, "status", std::string("failed: ") + reason);
    columns_.clear();
    series_.reset();
    file_.reset();
  } catch (...) {
  }
}

}  // namespace dem
