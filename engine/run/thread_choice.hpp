#pragma once
// How many threads a run uses, chosen from its own step rate (docs/performance.md, "Threads
// beside other work").
//
// A run asked for N threads starts on N and, now and then, tries 1 thread for a short window (or,
// on 1, N again) and keeps whichever made more steps per second of wall time. On an idle machine N
// threads win and the trials cost a few tenths of a percent of the run; beside another busy
// process N threads wait at every barrier for a thread the scheduler has taken off its core, and 1
// thread wins. A result is the same bit for bit on any number of threads (dynamics/kernel.hpp),
// so the count may change between any two steps.
//
// Pure: the caller reads the clock and sets the threads (run/run_scene.cpp); the tests drive it
// with a made-up clock and made-up rates.
#include <cstdint>

namespace dem {

struct ThreadChoiceSettings {
  double window_s = 0.25;         // a trial's length, and the window the count in use is measured over
  double first_trial_s = 0.5;     // the first trial starts this long after the run (at a window end)
  double min_interval_s = 4.0;    // from the end of a trial to the next: at first, after a switch, after a drop (below)
  double max_interval_s = 16.0;   // the interval doubles at each trial that keeps the count in use, up to this
  double margin = 0.05;           // the other count is kept only if it made this much more steps per second
  double drop = 0.3;              // a window of the count in use this much slower than its rate at the last trial (its
                                  // first window before any) starts a trial at once
};

class ThreadChoice {
 public:
  // `requested` threads (1: no trials, always 1).
  explicit ThreadChoice(int requested, const ThreadChoiceSettings& settings = {});

  // Given the wall time [s, any origin, never decreasing] and the steps done so far, the count for
  // the steps from now on. Called every few steps; the first call starts the clock.
  int update(double now_s, std::int64_t steps);

  // Starts the current measurement anew from here without judging it (the steps since the last
  // call included work that is not stepping, e.g. writing a checkpoint). Trials and the schedule
  // go on as they were.
  void restart(double now_s, std::int64_t steps);

  int threads() const { return current_; }
  int requested() const { return requested_; }
  int trials() const { return trials_; }      // trials finished
  int switches() const { return switches_; }  // trials that changed the count kept
  std::int64_t steps_on_one() const { return steps_on_one_; }  // steps run on 1 thread (with requested > 1)
  std::int64_t steps_seen() const { return steps_seen_; }      // steps from the first call to the last

 private:
  enum class Phase { Holding, Trying };
  void begin_window(double now_s, std::int64_t steps);
  void start_trial(double now_s, std::int64_t steps);

  ThreadChoiceSettings s_;
  int requested_, kept_, current_;  // kept: the count the run holds; current: the one running (kept or on trial)
  Phase phase_ = Phase::Holding;
  bool started_ = false;
  double last_s_ = 0;
  std::int64_t last_steps_ = 0;
  double window_start_s_ = 0;       // the window being measured
  std::int64_t window_start_steps_ = 0;
  double recent_rate_ = -1;         // steps/s of the kept count's last whole window (< 0: none yet)
  double reference_rate_ = -1;      // of the kept count at the last trial (its first window before any; < 0: none yet)
  double next_trial_s_ = 0;         // when the next trial starts
  double interval_s_ = 0;           // from a trial's end to the next
  int trials_ = 0, switches_ = 0;
  std::int64_t steps_on_one_ = 0, steps_seen_ = 0;
};

}  // namespace dem
