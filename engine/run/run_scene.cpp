#include "run/run_scene.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <numbers>
#include <optional>
#include <omp.h>
#include <sstream>

#include "analysis/measurements.hpp"
#include "dynamics/kernel.hpp"  // chunk_count
#include "control/stress_path.hpp"
#include "analysis/time_series.hpp"
#include "config/yaml_section.hpp"
#include "io/particle_csv.hpp"
#include "io/result_writer.hpp"
#include "io/state_io.hpp"
#include "run/checkpoint.hpp"
#include "run/thread_choice.hpp"

namespace dem {

namespace {
const char* source_key(const ParticleSource& src) {
  return src.kind == ParticleSource::Kind::Lattice ? "particles.lattice/grading"
         : src.kind == ParticleSource::Kind::Csv   ? "particles.csv"
                                                    : "particles.state";
}

// The interruption of a run by the signal `signo` (StageHooks::stop), named.
[[noreturn]] void interrupted(int signo, const std::string& during = "") {
  const char* name = signo == SIGTERM ? "SIGTERM" : signo == SIGINT ? "SIGINT" : signo == SIGHUP ? "SIGHUP" : nullptr;
  throw RunInterrupted(std::string("interrupted by ") + (name ? name : "signal " + std::to_string(signo)) +
                       (during.empty() ? " (a checkpoint, if one was written, lets the run resume)" : " " + during));
}

}  // namespace

std::string read_particle_source(const SceneConfig& scene, const volatile std::sig_atomic_t* stop) {
  const ParticleSource& src = scene.particles;
  if (src.kind == ParticleSource::Kind::Lattice) return "";
  try {
    if (src.kind == ParticleSource::Kind::State) {
      // HDF5 reads the file itself, by seeking: only a regular file. One that cannot be read is
      // left to read_state, whose message says why (not found, not HDF5, ...).
      std::error_code ec;
      const auto type = std::filesystem::status(src.path, ec).type();
      if (type == std::filesystem::file_type::not_found || type == std::filesystem::file_type::directory || ec) return "";
      if (type != std::filesystem::file_type::regular)
        throw std::runtime_error(src.path + ": not a regular file (a FIFO, device or socket): a saved state is an HDF5 file, "
                                 "read by seeking in it; give a regular file");
      try {
        return read_whole_file(src.path, std::numeric_limits<std::size_t>::max());  // a regular file: no cap
      } catch (const std::runtime_error&) {
        return "";
      }
    }
    return read_whole_file(src.path, csv_max_bytes, stop);
  } catch (const ReadStopped&) {
    interrupted(*stop, "while waiting for the bytes of " + std::string(source_key(src)) + " " + src.path + " (a FIFO whose writer has not come?)");
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(scene.file + ": " + source_key(src) + ": " + e.what());
  }
}

Simulation build_simulation(const SceneConfig& scene) { return build_simulation(scene, read_particle_source(scene)); }

Simulation build_simulation(const SceneConfig& scene, const std::string& source_bytes) {
  const ParticleSource& src = scene.particles;
  Particles particles;
  PeriodicCell cell;
  SavedState saved;
  try {  // bad particle input is bad input: reported as a ConfigError naming the scene key
    switch (src.kind) {
      case ParticleSource::Kind::Lattice:
        make_lattice(src.lattice, GradingCurve(src.grading_diameters_m, src.grading_percent_finer, src.grading_basis),
                     scene.material.density_kg_per_m3, particles, cell);
        break;
      case ParticleSource::Kind::Csv:
        cell = PeriodicCell(src.cell_m);
        parse_particle_csv(source_bytes, src.path, cell, scene.material.density_kg_per_m3, particles);
        break;
      case ParticleSource::Kind::State:
        saved = read_state(src.path);
        particles = saved.particles;
        cell = saved.cell;
        break;
    }
  } catch (const std::bad_alloc&) {
    throw;  // not bad input: the run failed (exit 1), "out of memory"
  } catch (const std::exception& e) {
    throw ConfigError(scene.file + ": " + source_key(src) + ": " + e.what());
  }
  const double dt_crit = critical_time_step(scene.material.law, particles, scene.material.density_kg_per_m3);
  if (scene.time_step_s > scene.max_time_step_fraction * dt_crit) {
    std::ostringstream msg;
    msg << scene.file << ": numerics.time_step = " << scene.time_step_s << " s is above the allowed "
        << scene.max_time_step_fraction << " x critical time step = " << scene.max_time_step_fraction * dt_crit
        << " s (critical step " << critical_time_step_formula(scene.material.law) << " = " << dt_crit
        << " s); reduce time_step, or raise numerics.max_time_step_fraction on purpose";
    throw ConfigError(msg.str());
  }
  Simulation sim(std::move(particles), cell, scene.material, scene.damping, scene.time_step_s, scene.verlet_skin_m);
  if (src.kind == ParticleSource::Kind::State) {
    // A new run from a saved state: its own step count starts at zero; the dynamic state continues.
    // A history the scene's law does not keep (a frictional scene from a frictionless sample, a
    // Hertz-Mindlin scene from a linear one) starts unloaded; one the law does not use is dropped.
    sim.restore(0, saved.rates, std::move(saved.contacts), saved.history);
  }
  return sim;
}

HoldStatus hold_status(const Simulation& sim, const StageConfig& st) {
  const Mat3& s = sim.sums().stress_Pa;
  HoldStatus h;
  for (int k = 0; k < 3; ++k) h.stress_error = std::max(h.stress_error, std::abs(s(k, k) - st.target_Pa[k]) / st.target_Pa[k]);
  if (st.zero_shear_stress) {  // a shear stress counts against the mean target, as q/p would
    const double scale = st.target_Pa.mean();
    for (const double shear : {s(0, 1), s(0, 2), s(1, 2)}) h.stress_error = std::max(h.stress_error, std::abs(shear) / scale);
  }
  h.unbalanced_force_ratio = unbalanced_force_ratio(sim);
  h.met = h.stress_error <= st.hold.stress_tolerance && h.unbalanced_force_ratio <= st.hold.unbalanced_force_ratio;
  return h;
}

namespace {

// The servo of a stress stage or path: the scene's settings with the stage's strain-rate cap.
AdaptiveServo stage_servo(const SceneConfig& scene, const StageConfig& st) {
  ServoSettings settings = scene.servo;
  settings.max_strain_rate_per_s = st.max_strain_rate_per_s;
  return AdaptiveServo(settings);
}

bool output_due(const Simulation& sim, const SceneConfig& scene) {
  return sim.step_count() % scene.output.interval_steps == 0;
}

// Particle frames at their own interval, independent of the time-series rows (0: none).
bool frame_due(const Simulation& sim, const SceneConfig& scene) {
  const std::int64_t every = scene.output.frames_interval_steps;
  return every > 0 && sim.step_count() % every == 0;
}

constexpr std::int64_t progress_every = 256;

StageCursor cursor_at(int stage, std::int64_t i) {
  StageCursor c;
  c.stage = stage;
  c.i = i;
  return c;
}

// What a stage type does in the loop all stages share (run_steps), as callables that the loop
// inlines (no virtual call, no std::function): each stage's run_<type>_stage builds one from
// lambdas over its own variables, the loop's iteration `i` among them.
template <class Cursor, class Step, class Where, class Progress, class Done>
struct StageLoop {
  Cursor cursor;      // () -> StageCursor: what a checkpoint before iteration i saves to continue from it
  Step step;          // () -> bool: the targets, sim.step and what the stage tracks per step; true if
                      //    the step's state gets a row even off the output interval (a leg end, a stop)
  Where where;        // () -> RowContext of that row
  Progress progress;  // () -> StageProgress
  Done done;          // () -> bool, after the row: the stage's end criteria (it may throw StageError);
                      //    advances i; true when the loop is over
};
// Spelled out (clang before version 17 deduces no aggregate's arguments); the stages initialise
// the members in order, each named in a comment.
template <class Cursor, class Step, class Where, class Progress, class Done>
StageLoop(Cursor, Step, Where, Progress, Done) -> StageLoop<Cursor, Step, Where, Progress, Done>;

// The loop of every stage (ARCHITECTURE.md, "One time step"): a checkpoint if one is due (never
// at the loop's first iteration), the stage's step, a row at output steps and where the stage asks
// for one, progress at the loop's first step and every progress_every steps after, then the
// stage's end of the step. `i` is the stage's iteration, which its callables advance. The stage
// runs at least one step (the step counts of a scene are checked when it is read).
template <class Loop>
void run_steps(Simulation& sim, const SceneConfig& scene, const StageHooks& hooks, const std::int64_t& i, Loop loop) {
  for (std::int64_t k = 0;; ++k) {
    if (hooks.stop && *hooks.stop) interrupted(*hooks.stop);
    if (i > 0 && hooks.checkpoint_due && hooks.checkpoint_due(sim)) hooks.checkpoint(sim, loop.cursor());
    const bool row = loop.step();
    if (hooks.row && (row || output_due(sim, scene))) hooks.row(sim, loop.where());
    if (hooks.frame && frame_due(sim, scene)) hooks.frame(sim);
    if (hooks.progress && k % progress_every == 0) hooks.progress(sim, loop.progress());
    if (hooks.pace && k % hooks.pace_every == 0) hooks.pace(sim);
    if (loop.done()) return;
  }
}

void run_strain_rate_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks,
                           const StageCursor* resume) {
  const StageConfig& st = scene.stages[static_cast<std::size_t>(index)];
  CellTargets targets;
  for (int k = 0; k < 3; ++k) targets[static_cast<std::size_t>(k)] = {AxisTarget::Mode::StrainRate, st.strain_rate_per_s[k], 0, 0};
  const std::int64_t n = steps_in(st.duration_s, sim.time_step());
  std::int64_t i = resume ? resume->i : 0;
  run_steps(sim, scene, hooks, i, StageLoop{
      /* cursor */ [&] { return cursor_at(index, i); },
      /* step */ [&] {
        sim.step(targets, scene.servo);
        return false;
      },
      /* where */ [&] { return RowContext{index}; },
      /* progress */ [&] { return StageProgress{index, static_cast<double>(i) / static_cast<double>(n), ""}; },
      /* done */ [&] { return ++i >= n; }});
}

void run_stress_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks,
                      const StageCursor* resume) {
  const StageConfig& st = scene.stages[static_cast<std::size_t>(index)];
  const double dt = sim.time_step();
  // Each axis ramps linearly from its stress at the stage start to its target at the stage rate.
  const Vec3 from = resume ? resume->from_Pa : Vec3(count_contacts(sim).stress_Pa.diagonal());
  Vec3 ramp_time;
  for (int k = 0; k < 3; ++k) ramp_time[k] = std::abs(st.target_Pa[k] - from[k]) / st.stress_rate_Pa_per_s;
  const double ramp_end = ramp_time.maxCoeff();
  const std::int64_t max_steps = steps_in(st.hold.max_duration_s, dt);
  AdaptiveServo servo = stage_servo(scene, st);
  CellTargets targets;
  CellControl control;  // zero_shear_stress: the axes' targets, and zero shear stress
  for (std::size_t k = 3; k < 6; ++k) control.component[k] = {AxisTarget::Mode::Stress, 0, 0, 0};
  StageCursor hold = cursor_at(index, 0);  // the hold's measurements so far
  if (resume) servo.restore(resume->servo), hold = *resume;
  const bool creep = st.hold.creep_rate_per_s > 0;
  const std::int64_t creep_window_steps = std::max<std::int64_t>(1, steps_in(st.hold.creep_window_s, dt));
  std::int64_t i = resume ? resume->i : 0;
  bool held = false;  // the hold's criteria met at its last check
  run_steps(sim, scene, hooks, i, StageLoop{
      /* cursor */ [&] {
        hold.i = i, hold.from_Pa = from, hold.servo = servo.state();
        return hold;
      },
      /* step */ [&] {
        const double t = static_cast<double>(i) * dt;
        for (int k = 0; k < 3; ++k) {
          const double sign = st.target_Pa[k] >= from[k] ? 1.0 : -1.0;
          const bool ramping = t < ramp_time[k];
          targets[static_cast<std::size_t>(k)] = {AxisTarget::Mode::Stress, 0,
                                                  ramping ? from[k] + sign * st.stress_rate_Pa_per_s * t : st.target_Pa[k],
                                                  ramping ? sign * st.stress_rate_Pa_per_s : 0.0};
        }
        if (st.zero_shear_stress) {
          for (std::size_t k = 0; k < 3; ++k) control.component[k] = targets[k];
          sim.step(control, servo);
        } else {
          sim.step(targets, servo);
        }
        // The hold, from the state after the step (which the step's row, if any, also reads).
        const std::int64_t done = i + 1;
        const double t_done = static_cast<double>(done) * dt;
        if (creep && t_done >= ramp_end) {  // consecutive windows from the end of the ramp
          if (hold.creep_window_start < 0) {
            hold.creep_window_start = done, hold.creep_volume_at_start = sim.cell().volume();
          } else if (done - hold.creep_window_start >= creep_window_steps) {
            const double elapsed = static_cast<double>(done - hold.creep_window_start) * dt;
            hold.creep_rate = std::abs(std::log(sim.cell().volume() / hold.creep_volume_at_start)) / elapsed;
            hold.creep_window_start = done, hold.creep_volume_at_start = sim.cell().volume();
          }
        }
        if (t_done >= ramp_end && done % st.hold.check_interval_steps == 0) {
          const HoldStatus h = hold_status(sim, st);
          hold.stress_error = h.stress_error;
          hold.unbalanced = h.unbalanced_force_ratio;
          const bool at_rest = !creep || (hold.creep_rate >= 0 && hold.creep_rate <= st.hold.creep_rate_per_s);
          held = h.met && at_rest;
        }
        return false;
      },
      /* where */ [&] { return RowContext{index}; },
      /* progress */ [&] {
        const double t_done = static_cast<double>(i + 1) * dt;
        std::ostringstream status;
        status << "p = " << mean_stress(sim.sums().stress_Pa) / 1e3 << " kPa";
        if (t_done >= ramp_end) status << ", holding: stress error " << 100 * hold.stress_error << " %, unbalanced " << hold.unbalanced;
        if (creep && hold.creep_rate >= 0) status << ", creep " << hold.creep_rate << " 1/s";
        return StageProgress{index, t_done < ramp_end ? t_done / std::max(ramp_end, dt) : -1.0, status.str()};
      },
      /* done */ [&] {
        if (held) return true;
        const double t_done = static_cast<double>(++i) * dt;
        if (i < max_steps) return false;
        // Measured now, at the last step (the hold's last check may be up to check_interval steps
        // old, or, if the ramp never ended, never made).
        const HoldStatus now = hold_status(sim, st);
        const Vec3 reached = sim.sums().stress_Pa.diagonal();
        std::ostringstream msg;
        msg << "stage '" << st.name << "' did not reach equilibrium within hold.max_duration = " << st.hold.max_duration_s
            << " s: stresses " << reached[0] << ", " << reached[1] << ", " << reached[2] << " Pa against targets "
            << st.target_Pa[0] << ", " << st.target_Pa[1] << ", " << st.target_Pa[2] << " Pa, largest stress error "
            << 100 * now.stress_error << " % (allowed " << 100 * st.hold.stress_tolerance << " %), unbalanced force ratio "
            << now.unbalanced_force_ratio << " (allowed " << st.hold.unbalanced_force_ratio << ")";
        if (t_done < ramp_end)
          msg << "; the ramp itself needs " << ramp_end << " s at rate = " << st.stress_rate_Pa_per_s << " Pa/s";
        if (creep) msg << ", creep rate " << hold.creep_rate << " 1/s (allowed " << st.hold.creep_rate_per_s << ")";
        throw StageError(msg.str());
      }});
}


// Straight legs between stress states at constant mean stress (docs/method.md#stress-paths). Each leg moves
// the targets linearly so that the principal stress changing most moves at the stage rate; the
// servo gets the leg's stress rates as feed-forward. Records each leg's tracking error and
// largest inertial number.
void run_stress_path_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks,
                           const StageCursor* resume) {
  const StageConfig& st = scene.stages[static_cast<std::size_t>(index)];
  const double dt = sim.time_step();
  const double p = st.mean_stress_Pa;
  const std::vector<PathLeg> legs = expand_path(st.path, named_state("A", p, st.stress_ratio), st.stress_rate_Pa_per_s);
  AdaptiveServo servo = stage_servo(scene, st);
  const double inertia_scale = mean_diameter(sim.particles()) * std::sqrt(sim.material().density_kg_per_m3);
  std::int64_t total_steps = 0, done_steps = 0;
  for (const PathLeg& leg : legs) total_steps += std::max<std::int64_t>(1, steps_in(leg.duration_s, dt));
  Vec3 strain_at_leg_start = resume ? resume->strain_at_leg_start : sim.cell().strain();
  if (resume) servo.restore(resume->servo), done_steps = resume->done_steps;
  CellTargets targets;
  CellControl control;  // zero_shear_stress: the axes' targets, and zero shear stress
  for (std::size_t k = 3; k < 6; ++k) control.component[k] = {AxisTarget::Mode::Stress, 0, 0, 0};
  for (std::size_t leg_index = resume ? static_cast<std::size_t>(resume->leg) : 0; leg_index < legs.size(); ++leg_index) {
    const PathLeg& leg = legs[leg_index];
    const std::int64_t n = std::max<std::int64_t>(1, steps_in(leg.duration_s, dt));
    const Vec3 rate = (leg.to_Pa - leg.from_Pa) / (static_cast<double>(n) * dt);
    const bool resumed_leg = resume && leg_index == static_cast<std::size_t>(resume->leg);
    LegRecord rec{index, leg.index, leg.cycle, leg.ends_cycle, leg.to_Pa, static_cast<double>(n) * dt, n, 0, Vec3::Zero(),
                  resumed_leg ? resume->max_inertial_number : 0.0};
    Vec3 sum_sq = resumed_leg ? resume->sum_sq : Vec3::Zero();
    std::int64_t i = resumed_leg ? resume->i : 0;  // one loop per leg
    run_steps(sim, scene, hooks, i, StageLoop{
        /* cursor */ [&] {
          StageCursor here = cursor_at(index, i);
          here.servo = servo.state(), here.leg = static_cast<int>(leg_index), here.done_steps = done_steps;
          here.sum_sq = sum_sq, here.max_inertial_number = rec.max_inertial_number, here.strain_at_leg_start = strain_at_leg_start;
          return here;
        },
        /* step */ [&] {
          const Vec3 target = leg.from_Pa + (leg.to_Pa - leg.from_Pa) * (static_cast<double>(i) / static_cast<double>(n));
          for (int k = 0; k < 3; ++k)
            targets[static_cast<std::size_t>(k)] = {AxisTarget::Mode::Stress, 0, target[k], rate[k]};
          if (st.zero_shear_stress) {
            for (std::size_t k = 0; k < 3; ++k) control.component[k] = targets[k];
            sim.step(control, servo);
          } else {
            sim.step(targets, servo);
          }
          const Mat3& s = sim.sums().stress_Pa;  // at this step's positions, i.e. at time t_i
          for (int k = 0; k < 3; ++k) sum_sq[k] += (s(k, k) - target[k]) * (s(k, k) - target[k]);
          const double p_now = s.trace() / 3;
          if (p_now > 0)
            rec.max_inertial_number = std::max(rec.max_inertial_number,
                                               max_strain_rate(sim.rates()) * inertia_scale / std::sqrt(p_now));
          ++done_steps;
          return i + 1 == n;  // a leg ends with a row
        },
        /* where */ [&] {
          const bool last = i + 1 == n;
          return RowContext{index, leg.cycle, leg.index, last, last && leg.ends_cycle, strain_at_leg_start};
        },
        /* progress */ [&] {
          std::ostringstream status;
          status << "cycle " << leg.cycle << ", leg " << leg.index + 1 << "/" << legs.size() << " -> " << leg.to_label;
          return StageProgress{index, static_cast<double>(done_steps) / static_cast<double>(total_steps), status.str()};
        },
        /* done */ [&] { return ++i >= n; }});
    rec.end_step = sim.step_count();
    rec.rms_error = (sum_sq / static_cast<double>(n)).cwiseSqrt() / p;
    if (hooks.leg) hooks.leg(rec);
    if (hooks.warning && rec.max_inertial_number > quasi_static_inertial_number) {
      std::ostringstream msg;
      msg << "stage '" << st.name << "' leg " << leg.index << " (cycle " << leg.cycle << "): inertial number reached "
          << rec.max_inertial_number << " > 1e-3, the loading is not quasi-static";
      hooks.warning(msg.str());
    }
    strain_at_leg_start = sim.cell().strain();
  }
}

// The strain of component k since the reference: axial true strain or engineering shear strain.
double component_strain(const PeriodicCell& cell, int k) { return k < 3 ? cell.strain()[k] : cell.shear_strain()[k - 3]; }

// The mean stress of the two axes other than k.
double lateral_stress(const Mat3& s, int k) { return 0.5 * (s((k + 1) % 3, (k + 1) % 3) + s((k + 2) % 3, (k + 2) % 3)); }

// The stress targets of a control stage that its end stress `s` misses by more than
// control_target_tolerance of their scale (the largest of |target|, the mean stress at the end
// and at the stage start p0, so that a zero shear target is judged against p): "" when none does. The cycled component (`cycled`)
// moves by design and is not judged.
constexpr double control_target_tolerance = 0.25;
std::string missed_targets(const Mat3& s, double p0, const StageConfig& st, int cycled) {
  static const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  const double p = s.trace() / 3;
  std::ostringstream msg;
  const auto judge = [&](const std::string& what, double reached, double target) {
    const double scale = std::max({std::abs(target), std::abs(p), std::abs(p0)});
    if (std::abs(reached - target) > control_target_tolerance * scale)
      msg << (msg.tellp() > 0 ? "; " : "") << what << " reached " << reached << " Pa against its target " << target << " Pa";
  };
  for (int k = 0; k < 6; ++k) {
    const AxisTarget& t = st.control.component[static_cast<std::size_t>(k)];
    if (t.mode == AxisTarget::Mode::Stress && k != cycled)
      judge(std::string("stress ") + component_names[static_cast<std::size_t>(k)], s(row[k], col[k]), t.stress_Pa);
  }
  if (st.control.constraint.kind == CellConstraint::Kind::ConstantMeanStress)
    judge("the mean stress (constant_mean_stress)", p, st.control.constraint.mean_stress_Pa);
  if (msg.tellp() == 0) return "";
  std::ostringstream out;
  out << msg.str() << ": the stage did not reach what it was asked (more than " << control_target_tolerance * 100
      << " % off); a target beyond what max_strain_rate = " << st.max_strain_rate_per_s
      << " 1/s reaches in the stage's duration, or a loading too fast for the servo";
  return out.str();
}

void run_control_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks,
                       const StageCursor* resume) {
  const StageConfig& st = scene.stages[static_cast<std::size_t>(index)];
  const double dt = sim.time_step();
  const std::int64_t n = steps_in(st.duration_s, dt);
  AdaptiveServo servo = stage_servo(scene, st);
  const CyclicLoading& cyc = st.cyclic;
  const bool cyclic = cyc.component >= 0;
  const int kc = std::max(cyc.component, 0);
  // What the stage measures from its start (p0 for r_u, q0 of a cyclic deviator, the strains),
  // and the range of the cyclic strain in the current cycle: from the checkpoint when resuming.
  StageCursor start;
  if (resume) {
    start = *resume;
    servo.restore(resume->servo);
  } else {
    const Mat3 s0 = count_contacts(sim).stress_Pa;
    start.mean_stress_at_start = s0.trace() / 3;
    start.deviator_at_start = s0(kc, kc) - lateral_stress(s0, kc);
    for (int k = 0; k < 6; ++k) start.strain_at_start[static_cast<std::size_t>(k)] = component_strain(sim.cell(), k);
  }
  const double p0 = start.mean_stress_at_start;
  const auto strain_since_start = [&](int k) {
    return component_strain(sim.cell(), k) - start.strain_at_start[static_cast<std::size_t>(k)];
  };
  double low = start.cycle_low, high = start.cycle_high;
  // The largest inertial number of the stage (every rate component), carried by a checkpoint.
  const double inertia_scale = mean_diameter(sim.particles()) * std::sqrt(sim.material().density_kg_per_m3);
  double max_inertial = resume ? resume->max_inertial_number : 0.0;
  const double omega = cyclic ? 2 * std::numbers::pi / cyc.period_s : 0;
  const auto cycle_of = [&](std::int64_t step) { return static_cast<int>(std::floor(static_cast<double>(step) * dt / cyc.period_s)) + 1; };
  std::string ended = "duration reached";
  bool liquefied = false, stopped = false;
  int cycle = 0;       // of the step
  RowContext where;    // of the step's row
  std::int64_t i = resume ? resume->i : 0;
  run_steps(sim, scene, hooks, i, StageLoop{
      /* cursor */ [&] {
        StageCursor here = start;
        here.stage = index, here.i = i, here.servo = servo.state(), here.cycle_low = low, here.cycle_high = high;
        here.max_inertial_number = max_inertial;
        return here;
      },
      /* step */ [&] {
        CellControl control = st.control;
        cycle = cyclic ? cycle_of(i) : 0;
        if (cyclic) {
          const double t = static_cast<double>(i) * dt;
          const double wave = cyc.amplitude * std::sin(omega * t), wave_rate = cyc.amplitude * omega * std::cos(omega * t);
          AxisTarget& c = control.component[static_cast<std::size_t>(kc)];
          switch (cyc.quantity) {
            case CyclicLoading::Quantity::Stress: c.stress_Pa += wave, c.stress_rate_Pa_per_s = wave_rate; break;
            case CyclicLoading::Quantity::Deviator:  // about the other axes' stress at the last evaluation
              c.stress_Pa = lateral_stress(sim.sums().stress_Pa, kc) + start.deviator_at_start + wave;
              c.stress_rate_Pa_per_s = wave_rate;
              break;
            case CyclicLoading::Quantity::Strain: c.strain_rate_per_s += wave_rate; break;
          }
        }
        sim.step(control, servo);
        where = RowContext{index, cycle};
        where.mean_stress_at_stage_start = p0;
        std::string stop;
        if (cyclic) {
          const double e = strain_since_start(kc);
          low = std::min(low, e), high = std::max(high, e);
          where.double_amplitude_strain = high - low;
          if (st.until.double_amplitude_strain > 0 && high - low >= st.until.double_amplitude_strain) stop = "double_amplitude_strain";
          if (cycle_of(i + 1) > cycle) low = high = e;  // the next step starts a cycle
        }
        const double p = sim.sums().stress_Pa.trace() / 3;
        if (p > 0) max_inertial = std::max(max_inertial, max_strain_rate(sim.rates()) * inertia_scale / std::sqrt(p));
        if (st.until.pore_pressure_ratio > 0 && p0 > 0 && 1 - p / p0 >= st.until.pore_pressure_ratio) stop = "pore_pressure_ratio";
        if (st.until.strain > 0 && std::abs(strain_since_start(st.until.component)) >= st.until.strain) stop = "strain";
        if (!stop.empty()) {
          std::ostringstream why;
          why << "until." << stop << " met at time " << sim.time() << " s";
          if (cyclic) why << " after " << static_cast<double>(i + 1) * dt / cyc.period_s << " cycles";
          ended = why.str();
          liquefied = stop == "pore_pressure_ratio" || stop == "double_amplitude_strain";
          stopped = true;
        }
        return stopped || i + 1 == n;  // the stage's last row is its end
      },
      /* where */ [&] { return where; },
      /* progress */ [&] {
        const double p = sim.sums().stress_Pa.trace() / 3;
        std::ostringstream status;
        if (cyclic) status << "cycle " << cycle << ", ";
        status << "r_u " << (p0 > 0 ? 1 - p / p0 : 0.0);
        return StageProgress{index, static_cast<double>(i) / static_cast<double>(n), status.str()};
      },
      /* done */ [&] { return stopped || ++i >= n; }});
  if (hooks.attribute) hooks.attribute("stage_end_" + st.name, ended);
  if (hooks.warning && max_inertial > quasi_static_inertial_number) {
    std::ostringstream msg;
    msg << "stage '" << st.name << "': inertial number reached " << max_inertial << " > 1e-3, the loading is not quasi-static";
    hooks.warning(msg.str());
  }
  // Were the stress targets reached? A target the stage never got near (beyond the cell's
  // strain-rate cap in its duration, or a mean stress that ran away) fails the stage instead of
  // ending it as if done. A liquefied sample (until.pore_pressure_ratio, double_amplitude_strain)
  // cannot hold its targets: that end is the outcome asked for.
  if (!liquefied) {
    const std::string miss = missed_targets(sim.sums().stress_Pa, p0, st, cyclic ? kc : -1);
    if (!miss.empty()) throw StageError("stage '" + st.name + "' (" + ended + "): " + miss);
  }
}

}  // namespace

void run_stage(Simulation& sim, const SceneConfig& scene, int index, const StageHooks& hooks, const StageCursor* resume) {
  const StageConfig& st = scene.stages[static_cast<std::size_t>(index)];
  if (!resume) {  // a resumed stage has had its start
    if (st.reset_strain) sim.cell().set_reference_lengths(sim.cell().lengths());
    if (hooks.row) hooks.row(sim, {index});  // every stage starts and ends with a row
  }
  switch (st.type) {
    case StageConfig::Type::StrainRate: run_strain_rate_stage(sim, scene, index, hooks, resume); break;
    case StageConfig::Type::Stress: run_stress_stage(sim, scene, index, hooks, resume); break;
    case StageConfig::Type::StressPath: run_stress_path_stage(sim, scene, index, hooks, resume); return;  // rows at every leg end
    case StageConfig::Type::Control: run_control_stage(sim, scene, index, hooks, resume); return;  // its last row is its end
  }
  if (hooks.row && !output_due(sim, scene)) hooks.row(sim, {index});  // the stage end is always recorded
}

std::string energy_error_cause(const Simulation& sim) {
  const double safe_fraction = SceneConfig{}.max_time_step_fraction;
  const AnyContactLaw& law = sim.material().law;
  const double fraction = sim.time_step() / critical_time_step(law, sim.particles(), sim.material().density_kg_per_m3);
  std::ostringstream step;
  step << "the time step (" << sim.time_step() << " s = " << fraction << " x critical, " << critical_time_step_formula(law) << ")";
  std::ostringstream msg;
  if (const double d = dashpot_step_number(sim); d >= 0.5) {
    msg << "the contact dashpots are past their explicit limit: dt sum_c c / m = " << d
        << " on the most damped sphere (unstable from about 1; c = 2 zeta sqrt(m* k) per contact, so it grows with the "
           "contacts a sphere has, which the one-contact critical step does not count): lower material.contact_damping = "
        << contact_damping_ratio(law) << " or the time step (" << sim.time_step() << " s = " << fraction << " x critical)";
  } else if (fraction > safe_fraction * (1 + 1e-9)) {  // a step set to exactly the limit reads back a rounding above it
    msg << step.str() << " is too large for this stiffness and loading";
  } else if (tangential_history_name(law) == MindlinCoulomb::history_name) {
    msg << "Hertz-Mindlin's tangential spring is incremental (k_t grows with the overlap) and not conservative: the "
           "balance stays open by a term that does not fall with the time step, bounded by the Coulomb cap "
           "(engine/README.md); "
        << step.str() << " is within the " << safe_fraction
        << " x critical allowed by default: raise numerics.max_energy_error for this law";
  } else {
    msg << step.str() << " may be too large for this stiffness and loading (it is within the " << safe_fraction
        << " x critical allowed by default)";
  }
  return msg.str();
}

namespace {

// The checkpoint this run continues from, if any (see Resume).
std::optional<Checkpoint> checkpoint_to_resume(const SceneConfig& scene, const std::string& out_path,
                                               const std::string& identity, Resume resume, const RunObserver& observer) {
  const std::string path = checkpoint_path(out_path);
  if (resume == Resume::Never) return std::nullopt;
  if (!std::filesystem::exists(path)) {
    if (resume == Resume::Always) throw ConfigError(path + ": no checkpoint to resume from");
    return std::nullopt;
  }
  try {
    Checkpoint c = read_checkpoint(path);
    if (c.identity != identity)
      throw h5::Error(path + ": written by a run of other inputs (identity " + c.identity + ", this run " + identity +
                      "): the scene, its particle file or the engine changed");
    if (c.cursor.stage >= static_cast<int>(scene.stages.size()))
      throw h5::Error(path + ": stage " + std::to_string(c.cursor.stage) + " does not exist in the scene");
    return c;
  } catch (const h5::Error& e) {
    if (resume == Resume::Always) throw ConfigError(std::string("cannot resume: ") + e.what());
    if (observer.warning) observer.warning(std::string("not resuming: ") + e.what() + "; starting from the beginning");
    return std::nullopt;
  }
}

// The stages of a run whose result file `out` is open, from the start or from checkpoint `from`;
// completes the result. Throws whatever stops the run (the caller marks the result failed).
RunSummary run_stages(Simulation& sim, const SceneConfig& scene, const Checkpoint* from, const std::string& out_path,
                      const std::string& identity, const RunObserver& observer, std::chrono::steady_clock::time_point start,
                      ResultWriter& out) {
  using clock = std::chrono::steady_clock;
  StageHooks hooks;
  const auto seconds_since = [](clock::time_point t0) { return std::chrono::duration<double>(clock::now() - t0).count(); };
  // The threads (run/thread_choice.hpp): those asked (omp_set_num_threads), at most one per chunk
  // of particles (a second thread has no chunk of its own below two); on more than one, the run
  // measures its step rate and keeps 1 thread or all of them, whichever steps faster. The clock is
  // read every pace_every steps: about every 8,000 particle-steps.
  const std::size_t particles = sim.particles().size();
  const int usable = static_cast<int>(std::min<std::ptrdiff_t>(omp_get_max_threads(), std::max<std::ptrdiff_t>(1, chunk_count(particles))));
  ThreadChoice threads(usable);
  int running = usable;
  omp_set_num_threads(usable);
  if (usable > 1) {
    hooks.pace_every = std::max<std::int64_t>(1, 8192 / static_cast<std::int64_t>(std::max<std::size_t>(1, particles)));
    hooks.pace = [&](const Simulation& s) {
      const int next = threads.update(seconds_since(start), s.step_count());
      if (next != running) omp_set_num_threads(running = next);
    };
  }
  // Rows are where the energy balance is looked at: a run whose balance no longer closes (an
  // unstable or too coarse time step) stops, after the row that shows it is written.
  const std::int64_t frame_every = scene.output.frames_interval_steps;
  hooks.row = [&](const Simulation& s, const RowContext& where) {
    out.append_row(measure_row(s, where));
    const double error = s.energy().closure_error();
    if (error > scene.max_energy_error) {
      std::ostringstream msg;
      msg << "the energy balance no longer closes at step " << s.step_count() << " (time " << s.time()
          << " s): closure error " << error << " > numerics.max_energy_error = " << scene.max_energy_error
          << "; " << energy_error_cause(s);
      throw StageError(msg.str());
    }
  };
  if (frame_every > 0) hooks.frame = [&](const Simulation& s) { out.append_frame(s); };
  hooks.leg = [&](const LegRecord& r) { out.append_leg(leg_row(r)); };
  hooks.attribute = [&](const std::string& name, const std::string& value) { out.set_attribute(name, value); };
  // Checkpoints by steps and by wall time (the clock is read every 256 steps); never twice at
  // one step, so a resumed run does not write again the checkpoint it started from.
  std::int64_t last_checkpoint_step = sim.step_count();
  auto last_checkpoint_wall = clock::now();
  const bool checkpoints = scene.output.checkpoint_interval_steps > 0 || scene.output.checkpoint_wall_time_s > 0;
  if (checkpoints) hooks.checkpoint_due = [&](const Simulation& s) {
    const std::int64_t step = s.step_count();
    if (step == last_checkpoint_step) return false;
    if (scene.output.checkpoint_interval_steps > 0 && step % scene.output.checkpoint_interval_steps == 0) return true;
    return scene.output.checkpoint_wall_time_s > 0 && step % 256 == 0 &&
           std::chrono::duration<double>(clock::now() - last_checkpoint_wall).count() >= scene.output.checkpoint_wall_time_s;
  };
  hooks.checkpoint = [&](const Simulation& s, const StageCursor& where) {
    if (frame_every == 0) out.append_frame(s);  // frames at regular steps only, when asked for
    out.flush();
    write_checkpoint(out.partial_path(), out_path, identity, std::chrono::duration<double>(clock::now() - start).count(), s,
                     where);
    last_checkpoint_step = s.step_count();
    last_checkpoint_wall = clock::now();
    threads.restart(seconds_since(start), s.step_count());  // the writing is not stepping
  };
  hooks.stop = observer.stop;
  hooks.warning = [&](const std::string& w) {
    if (observer.warning) observer.warning(w);
    out.add_warning(w);
  };
  if (observer.progress)
    hooks.progress = [&](const Simulation& s, const StageProgress& pr) {
      RunProgress r;
      r.scene = scene.name;
      r.stage = pr.stage;
      r.stages = static_cast<int>(scene.stages.size());
      r.stage_name = scene.stages[static_cast<std::size_t>(pr.stage)].name;
      r.step = s.step_count();
      r.time_s = s.time();
      r.elapsed_s = std::chrono::duration<double>(clock::now() - start).count();
      r.stage_fraction = pr.fraction;
      r.status = pr.status;
      observer.progress(r);
    };
  const int first = from ? from->cursor.stage : 0;
  for (int i = first; i < static_cast<int>(scene.stages.size()); ++i)
    run_stage(sim, scene, i, hooks, from && i == first ? &from->cursor : nullptr);
  out.append_frame(sim);
  out.write_state(sim);
  const double wall = std::chrono::duration<double>(clock::now() - start).count();
  const std::string view_warning = out.complete(wall);
  if (!view_warning.empty() && observer.warning) observer.warning(view_warning);
  std::error_code gone;  // the result supersedes the checkpoint (a stale one would only be resumed to the same end)
  if (std::filesystem::remove(checkpoint_path(out_path), gone); gone && observer.warning)
    observer.warning(checkpoint_path(out_path) + ": not removed: " + gone.message());
  RunSummary summary{scene.name, sim.step_count(), wall};
  summary.threads = usable;
  summary.steps_on_one_thread = threads.steps_on_one();
  summary.thread_trials = threads.trials();
  summary.thread_switches = threads.switches();
  return summary;
}

}  // namespace

RunSummary run_scene(const SceneConfig& scene, const std::string& out_path, const RunObserver& observer,
                     const std::string& input_hash, Resume resume) {
  using clock = std::chrono::steady_clock;
  auto start = clock::now();
  // run_stages picks the thread count as it goes; the caller's count is set again however the run ends.
  struct ThreadsAsAsked {
    int n = omp_get_max_threads();
    ~ThreadsAsAsked() { omp_set_num_threads(n); }
  } threads_as_asked;
  const std::string source_bytes = read_particle_source(scene, observer.stop);  // the particle file, read once
  Simulation sim = build_simulation(scene, source_bytes);       // all input checks happen before the output file exists
  const std::string identity = run_identity(scene, input_hash, source_bytes);
  std::optional<Checkpoint> from = checkpoint_to_resume(scene, out_path, identity, resume, observer);
  std::unique_ptr<ResultWriter> writer;
  // From here on every failure, whatever it is (a stage, a full disk, memory), is written into the
  // partial result's status with its reason before it goes on to the caller.
  try {
    if (from) {
      writer = std::make_unique<ResultWriter>(out_path, scene, checkpoint_path(out_path));
      sim = restore_simulation(scene, *from);
      start -= std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(from->wall_time_s));
      if (observer.note)
        observer.note(scene.name + ": resuming from " + checkpoint_path(out_path) + " at step " + std::to_string(sim.step_count()));
    } else {
      writer = std::make_unique<ResultWriter>(out_path, scene);
      if (!input_hash.empty()) writer->set_attribute("input_hash", input_hash);
      writer->append_frame(sim);  // particle frames: the start, each checkpoint and the end of the run
    }
    return run_stages(sim, scene, from ? &*from : nullptr, out_path, identity, observer, start, *writer);
  } catch (const std::exception& e) {
    if (writer) writer->fail(describe_failure(e));
    throw;
  }
}

}  // namespace dem
