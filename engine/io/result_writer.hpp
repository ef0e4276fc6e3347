#pragma once
// Writes one run's result file. The run writes into "<out>.partial" with status "running"; only a
// run that finishes is renamed to <out> with status "complete", so a half-written file can never
// be mistaken for a finished one. A run that fails keeps "<out>.partial" with status
// "failed: <reason>"; a killed run leaves it at "running".
#include <memory>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "io/hdf5.hpp"

namespace dem {

class ResultWriter {
 public:
  ResultWriter(std::string out_path, const SceneConfig& scene);
  ~ResultWriter();

  void append_row(const std::vector<double>& row);  // buffered; flushed every `flush_rows` rows
  void flush();
  hid_t file() const { return file_; }
  void write_state(const class Simulation& sim);
  // Marks the file complete and moves it to its final name.
  void complete(double wall_time_s);
  // Marks the partial file failed (best effort; never throws).
  void fail(const std::string& reason) noexcept;
  const std::string& partial_path() const { return partial_; }

 private:
  std::string out_, partial_;
  std::size_t flush_rows_;
  h5::Handle file_, series_;
  std::vector<h5::Column> columns_;
  std::vector<std::vector<double>> pending_;  // per column
  bool done_ = false;
};

}  // namespace dem
