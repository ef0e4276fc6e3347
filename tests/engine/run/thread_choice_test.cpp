// The thread count a run keeps (run/thread_choice.hpp), driven by a made-up clock: a "machine"
// whose step rate on 1 and on 2 threads is given as a function of time, stepped 16 steps between
// two calls as the run loop does. No test here times anything: speed targets live in `make bench`.
//
// The expectations follow from the default settings: a trial of the other count lasts one 0.25 s
// window; the first starts 0.5 s into the run; after a trial that keeps the count in use the next
// starts twice the interval before it later (4 s at first: 8, 16, 16, ... s; 16 s at most), after a
// switch 4 s later, each at the end of a
// window of the count in use; a window of that count more than 30 % slower than its rate at the
// last trial starts a trial at once; the other count must be more than 5 % faster to be kept.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <functional>

#include "run/thread_choice.hpp"

using dem::ThreadChoice;

namespace {

constexpr std::int64_t steps_per_call = 16;

struct FakeMachine {
  std::function<double(int threads, double t)> rate;  // steps per second of wall time
  double t = 0;
  std::int64_t steps = 0;
  std::int64_t steps_on_two = 0;
  // Steps with `choice` deciding until the clock passes `until` [s].
  void run(ThreadChoice& choice, double until) {
    int threads = choice.update(t, steps);
    while (t < until) {
      t += static_cast<double>(steps_per_call) / rate(threads, t);
      steps += steps_per_call;
      if (threads == 2) steps_on_two += steps_per_call;
      threads = choice.update(t, steps);
    }
  }
};

// Steps until the next trial has ended.
void to_end_of_next_trial(ThreadChoice& choice, FakeMachine& m) {
  const int trials = choice.trials();
  while (choice.trials() == trials) m.run(choice, m.t + 0.01);
}

double idle(int threads, double) { return threads == 2 ? 1600.0 : 1000.0; }  // 2 threads 1.6 x faster
double busy(int threads, double) { return threads == 2 ? 700.0 : 1000.0; }   // 1 thread 1.43 x faster

}  // namespace

TEST_CASE("a run asked for 1 thread never tries another count", "[thread_choice][threads]") {
  ThreadChoice choice(1);
  FakeMachine m{busy};
  m.run(choice, 60);
  REQUIRE(choice.threads() == 1);
  REQUIRE(choice.trials() == 0);
  REQUIRE(m.steps_on_two == 0);
}

TEST_CASE("idle, the run keeps 2 threads and its trials of 1 cost under 1 % of its steps", "[thread_choice][threads]") {
  ThreadChoice choice(2);
  FakeMachine m{idle};
  m.run(choice, 300);
  REQUIRE(choice.threads() == 2);
  REQUIRE(choice.switches() == 0);
  // Trials start near 0.5, 8.75 and 25 s, then every 16.25 s (each up to a window later, at the
  // end of a window of 2 threads): 3 + 16 up to 300 s, one fewer if they come late.
  REQUIRE(choice.trials() >= 18);
  REQUIRE(choice.trials() <= 19);
  // Each trial is one window of 0.25 s (plus the last call's 10 ms at most) at 1,000 instead of
  // 1,600 steps/s: about 19 x 0.25 x 600 = 2,850 steps fewer than 2 threads throughout.
  const double all_on_two = 1600.0 * m.t;
  REQUIRE(static_cast<double>(m.steps) > 0.99 * all_on_two);
  REQUIRE(static_cast<double>(m.steps) < all_on_two);
  REQUIRE(choice.steps_on_one() == m.steps - m.steps_on_two);
}

TEST_CASE("beside a busy process, the run moves to 1 thread at its first trial and stays", "[thread_choice][threads]") {
  ThreadChoice choice(2);
  FakeMachine m{busy};
  m.run(choice, 1.1);  // the first trial: from the first window end after 0.5 s, 0.25 s long
  REQUIRE(choice.threads() == 1);
  REQUIRE(choice.switches() == 1);
  m.run(choice, 300);
  REQUIRE(choice.threads() == 1);
  REQUIRE(choice.switches() == 1);  // every trial of 2 threads after it lost
  // 2 threads: the first 0.5 s and a 0.25 s trial after 4 s, then 8, 16, 16, ... s (19 of them),
  // 5.3 s in all at 700 instead of 1,000 steps/s: about 1,600 steps fewer than 1 thread throughout.
  REQUIRE(static_cast<double>(m.steps) > 0.99 * 1000.0 * m.t);
}

TEST_CASE("a busy process starting beside the run moves it to 1 thread within a window or two", "[thread_choice][threads]") {
  ThreadChoice choice(2);
  double busy_from = 1e9;
  FakeMachine m{[&](int threads, double t) { return t < busy_from ? idle(threads, t) : busy(threads, t); }};
  m.run(choice, 100);
  to_end_of_next_trial(choice, m);  // the next scheduled trial is 16 s away
  REQUIRE(choice.threads() == 2);
  const int trials = choice.trials();
  busy_from = m.t + 1;
  // Only the drop (2 threads from 1,600 to 700 steps/s) starts a trial that soon, at the end of
  // the first window wholly after busy_from, 0.3 s later at most; the trial ends 0.25 s later
  // (and a call's 16 ms).
  m.run(choice, busy_from + 0.6);
  REQUIRE(choice.trials() == trials + 1);
  REQUIRE(choice.threads() == 1);
}

TEST_CASE("when the busy process ends, the run is back on 2 threads within the longest interval", "[thread_choice][threads]") {
  ThreadChoice choice(2);
  FakeMachine m{[](int threads, double t) { return t < 200 ? busy(threads, t) : idle(threads, t); }};
  m.run(choice, 200);
  REQUIRE(choice.threads() == 1);
  // 1 thread does not slow down when the process ends: only a scheduled trial finds 2 threads
  // faster, at most 16 s later (and up to a window more), and it lasts 0.25 s.
  m.run(choice, 216.8);
  REQUIRE(choice.threads() == 2);
  REQUIRE(choice.switches() == 2);
}

TEST_CASE("counts within the margin of each other: the run keeps the one it has", "[thread_choice][threads]") {
  ThreadChoice choice(2);
  FakeMachine m{[](int threads, double) { return threads == 2 ? 1000.0 : 1040.0; }};  // 1 thread 4 % faster
  m.run(choice, 120);
  REQUIRE(choice.trials() > 5);
  REQUIRE(choice.switches() == 0);
  REQUIRE(choice.threads() == 2);
}

TEST_CASE("a pause the run reports (restart) is not taken for a slower count", "[thread_choice][threads]") {
  // Idle on 2 threads, just after a trial (the next is 16 s away); then 0.2 s without a step (a
  // checkpoint written) in the middle of a window. Unreported, that window shows at most
  // 0.25 / (0.25 + 0.2) of the rate (889 steps/s), a drop of 44 %: a trial at once, and 1 thread's
  // 1,000 steps/s beat it by more than 5 %, a wrong switch. Reported with restart(), the window
  // starts again after the pause: no trial.
  for (const bool reported : {false, true}) {
    ThreadChoice choice(2);
    FakeMachine m{idle};
    m.run(choice, 100);
    to_end_of_next_trial(choice, m);
    const int trials = choice.trials();
    m.run(choice, m.t + 0.1);
    m.t += 0.2;
    if (reported) choice.restart(m.t, m.steps);
    m.run(choice, m.t + 1.0);
    INFO("pause reported: " << reported);
    REQUIRE(choice.trials() == trials + (reported ? 0 : 1));
    REQUIRE(choice.threads() == (reported ? 2 : 1));
  }
}
