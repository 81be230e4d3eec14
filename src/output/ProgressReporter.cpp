#include "argine/output/ProgressReporter.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace argine {

namespace {

std::string formatted(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

double steadySeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

std::string formatWallDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "--";
  const long long total = std::llround(seconds);
  char buffer[48];
  if (total < 60)
    std::snprintf(buffer, sizeof(buffer), "%llds", total);
  else if (total < 3600)
    std::snprintf(buffer, sizeof(buffer), "%lldm%02llds", total / 60, total % 60);
  else if (total < 86400)
    std::snprintf(buffer, sizeof(buffer), "%lldh%02lldm", total / 3600, total % 3600 / 60);
  else
    std::snprintf(buffer, sizeof(buffer), "%lldd%02lldh", total / 86400, total % 86400 / 3600);
  return buffer;
}

ProgressReporter::ProgressReporter(std::ostream& out, bool is_terminal, WallClock clock,
                                   ProgressOptions options)
    : out_(&out), is_terminal_(is_terminal), clock_(std::move(clock)), options_(options) {}

ProgressReporter ProgressReporter::forStandardOutput(const ProgressOptions& options) {
  return ProgressReporter(std::cout, isatty(fileno(stdout)) != 0, steadySeconds, options);
}

void ProgressReporter::beginStage(const std::string& name, Real start_time, Real duration) {
  beginStage(name, start_time, duration, start_time);
}

void ProgressReporter::beginStage(const std::string& name, Real start_time, Real duration,
                                  Real resume_time) {
  stage_ = name;
  start_time_ = start_time;
  duration_ = duration;
  resume_time_ = resume_time;
  point_updates_ = 0;
  drawn_length_ = 0;
  if (options_.quiet) return;
  wall_start_ = clock_();
  next_report_ =
      wall_start_ + (is_terminal_ ? options_.terminal_interval : options_.plain_interval);
}

void ProgressReporter::update(long long step, Real time, Real dt, long long num_points) {
  point_updates_ += num_points;
  if (options_.quiet) return;
  const double now = clock_();
  if (now < next_report_) return;
  next_report_ = now + (is_terminal_ ? options_.terminal_interval : options_.plain_interval);
  print(step, time, dt, now, false);
}

void ProgressReporter::endStage(long long step, Real time, Real dt) {
  if (options_.quiet) return;
  print(step, time, dt, clock_(), true);
}

std::string ProgressReporter::line(long long step, Real time, Real dt, double now) const {
  const Real elapsed_sim = time - start_time_;
  const double fraction = duration_ > 0.0 ? std::clamp(elapsed_sim / duration_, 0.0, 1.0) : 1.0;
  const double wall = now - wall_start_;
  // Remaining wall time if the rest of the stage runs at this run's rate so far (a resumed
  // run's wall clock starts at the checkpoint, not at the stage's start).
  const Real done_here = time - resume_time_;
  const Real remaining = start_time_ + duration_ - time;
  const double eta = done_here > 0.0 ? wall * std::max<Real>(remaining, 0.0) / done_here : -1.0;
  const double rate = wall > 0.0 ? static_cast<double>(point_updates_) / wall : 0.0;
  return stage_ + ": t " + formatted("%.4g", elapsed_sim) + " s / " + formatted("%.4g", duration_) +
         " s (" + formatted("%.1f", 100.0 * fraction) + "%)  step " + std::to_string(step) +
         "  dt " + formatted("%.3g", dt) + " s  ETA " + formatWallDuration(eta) + "  " +
         formatted("%.3g", rate) + " pt-upd/s";
}

void ProgressReporter::print(long long step, Real time, Real dt, double now, bool final_line) {
  std::string text = line(step, time, dt, now);
  if (final_line) {
    // At the end the ETA is replaced by the wall time the stage took.
    const auto eta = text.find("  ETA ");
    const auto rate = text.find("  ", eta + 6);
    text = text.substr(0, eta) + "  wall " + formatWallDuration(now - wall_start_) +
           text.substr(rate) + "  done";
  }
  if (!is_terminal_) {
    *out_ << text << '\n' << std::flush;
    return;
  }
  if (!final_line) {
    // A 20-character bar in front of the line, on the terminal only.
    const Real fraction =
        duration_ > 0.0 ? std::clamp((time - start_time_) / duration_, 0.0, 1.0) : 1.0;
    const auto filled = static_cast<std::size_t>(fraction * 20.0);
    text = "[" + std::string(filled, '#') + std::string(20 - filled, '.') + "] " + text;
  }
  const std::size_t length = text.size();
  if (length < drawn_length_) text += std::string(drawn_length_ - length, ' ');  // clear rest
  drawn_length_ = length;
  *out_ << '\r' << text;
  if (final_line) *out_ << '\n';
  *out_ << std::flush;
}

}  // namespace argine
