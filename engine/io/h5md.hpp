#pragma once
// Particle frames in the result file after the H5MD 1.1 convention (https://www.nongnu.org/h5md/),
// so that generic readers find positions, velocities and the cell over time without knowing our
// own layout. Frames are a *view*: the continuation state stays in /state (io/state_io.hpp).
//
//   /h5md                       version = [1, 1]; author/name, creator/{name, version}
//   /particles/all/position     step [F], time [F] (s), value [F x N x 3] (m), x = L o s
//   /particles/all/velocity     value [F x N x 3] (m s-1), the *fluctuating* velocity v
//   /particles/all/angular_velocity  value [F x N x 3] (rad s-1)
//   /particles/all/box          dimension = 3, boundary = periodic x 3; edges/value [F x 3] (m)
//   /particles/all/radius, mass [N] (m, kg), time-independent
//
// The step and time datasets live in position/ and are hard-linked into the other elements, as
// H5MD allows: one append extends them for all, so the elements can never disagree on frames.
//
// Beside them, our own (not H5MD) per-frame views, for ParaView through the XDMF (io/xdmf.hpp):
//   /frames/cell_corners        [F x 8 x 3] (m): the cell's corners (a tilted cell is drawn tilted)
//   /frames/contacts (output.frames.contacts only): the contact network of every frame, its rows
//     frame after frame: count [F] (contacts in each frame), pairs [M x 2] (particle indices),
//     normal_force, tangential_force [M] (N, |f_t|), branch [M x 3] (m, from the first
//     particle's centre to the nearest image of the second's), ends [M x 2 x 3] (m, the two
//     centres, the second unwrapped: what ParaView draws as a line)
#include <cstdint>
#include <string>
#include <vector>

#include "dynamics/simulation.hpp"
#include "io/hdf5.hpp"

namespace dem {

class H5mdWriter {
 public:
  // Creates /h5md and /particles/all in `file`, with the (fixed) radius and mass of `sim`.
  H5mdWriter(hid_t file, const Simulation& sim);
  // Reopens the frames of `file` (written by the constructor above) for appending.
  explicit H5mdWriter(hid_t file);
  // Appends the current positions, velocities and cell edges as one frame at sim's step, with
  // the contact network if `contacts` (the first frame decides: all frames have it or none).
  void append_frame(const Simulation& sim, bool contacts = false);
  std::size_t frames() const { return step_.frames(); }
  std::int64_t last_step() const { return last_step_; }

 private:
  void create_views(hid_t file, bool contacts);
  void append_contacts(const Simulation& sim);
  h5::FrameSeries<std::int64_t> step_;
  h5::FrameSeries<double> time_, position_, velocity_, angular_velocity_, edges_;
  h5::FrameSeries<double> corners_;
  bool views_ = false, contacts_ = false;
  h5::FrameSeries<std::int64_t> contact_count_, pairs_;
  h5::FrameSeries<double> normal_force_, tangential_force_, branch_, ends_;
  std::int64_t last_step_ = -1;
  hid_t file_ = -1;
};

// One frame of a result's /particles/all (and /frames/contacts if it has them), as written above.
struct Frame {
  std::int64_t step = 0;
  double time_s = 0;
  std::vector<double> position, velocity, angular_velocity;  // N x 3, row-major [m, m/s, rad/s]
  std::vector<double> radius, mass;                          // N [m, kg]
  double edges[3] = {0, 0, 0};                               // the cell's edges [m]
  bool has_contacts = false;                                 // written with output.frames.contacts
  std::vector<std::int64_t> pairs;                           // M x 2 particle indices
  std::vector<double> normal_force, tangential_force;        // M [N]
  std::vector<double> branch;                                // M x 3 [m]
};
// The number of frames in `file` (0 if it has none).
std::size_t frame_count(const std::string& file);
// Frame `index` (from 0) of `file`, read row by row (not the whole series); throws h5::Error
// naming the file and the range of frames it has when there is no such frame.
Frame read_frame(const std::string& file, std::size_t index);

}  // namespace dem
