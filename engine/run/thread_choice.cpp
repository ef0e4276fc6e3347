#include "run/thread_choice.hpp"

#include <algorithm>

namespace dem {

ThreadChoice::ThreadChoice(int requested, const ThreadChoiceSettings& settings)
    : s_(settings), requested_(std::max(1, requested)), kept_(requested_), current_(requested_),
      interval_s_(settings.min_interval_s) {}

void ThreadChoice::begin_window(double now_s, std::int64_t steps) {
  window_start_s_ = now_s;
  window_start_steps_ = steps;
}

void ThreadChoice::start_trial(double now_s, std::int64_t steps) {
  phase_ = Phase::Trying;
  current_ = kept_ == 1 ? requested_ : 1;
  begin_window(now_s, steps);
}

void ThreadChoice::restart(double now_s, std::int64_t steps) {
  if (!started_) return;
  last_s_ = now_s, last_steps_ = steps;
  begin_window(now_s, steps);
}

int ThreadChoice::update(double now_s, std::int64_t steps) {
  if (requested_ == 1) return 1;
  if (!started_) {
    started_ = true;
    last_s_ = now_s, last_steps_ = steps;
    begin_window(now_s, steps);
    next_trial_s_ = now_s + s_.first_trial_s;
    return current_;
  }
  const std::int64_t done = steps - last_steps_;  // run on current_ since the last call
  steps_seen_ += done;
  if (current_ == 1) steps_on_one_ += done;
  last_s_ = now_s, last_steps_ = steps;
  const double span = now_s - window_start_s_;
  if (span < s_.window_s || steps == window_start_steps_) return current_;
  const double rate = static_cast<double>(steps - window_start_steps_) / span;
  begin_window(now_s, steps);
  if (phase_ == Phase::Trying) {  // the trial's window is whole: keep the faster count
    ++trials_;
    if (rate > recent_rate_ * (1 + s_.margin)) {
      kept_ = current_, ++switches_;
      interval_s_ = s_.min_interval_s;
      reference_rate_ = rate;
    } else {
      current_ = kept_;
      interval_s_ = std::min(2 * interval_s_, s_.max_interval_s);
      reference_rate_ = recent_rate_;
    }
    phase_ = Phase::Holding;
    next_trial_s_ = now_s + interval_s_;
    return current_;
  }
  // A whole window of the kept count: a trial when one is due, or at once if it is slower than
  // the count's rate at the last trial by `drop` (other work started beside the run), measured
  // against the window just taken.
  recent_rate_ = rate;
  if (reference_rate_ < 0) reference_rate_ = rate;
  const bool dropped = rate < (1 - s_.drop) * reference_rate_;
  if (dropped) interval_s_ = s_.min_interval_s;
  if (dropped || now_s >= next_trial_s_) start_trial(now_s, steps);
  return current_;
}

}  // namespace dem
