#include "vicc_tracking/imu_synchronizer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_tracking {

void SynchronizerConfig::validate() const {
  if (!(max_gap > 0.0) || !(clock_jump > 0.0) || !(max_buffered > 0.0)) {
    throw std::invalid_argument("synchronizer: max_gap, clock_jump and max_buffered must be > 0");
  }
}

const char* toString(ImuAddResult result) {
  switch (result) {
    case ImuAddResult::kAccepted:
      return "accepted";
    case ImuAddResult::kFirst:
      return "first sample";
    case ImuAddResult::kGap:
      return "gap in IMU data";
    case ImuAddResult::kDuplicate:
      return "duplicated stamp";
    case ImuAddResult::kOutOfOrder:
      return "out-of-order stamp";
    case ImuAddResult::kClockJump:
      return "clock jumped backwards";
    case ImuAddResult::kInvalid:
      return "non-finite values";
  }
  return "unknown";
}

ImuDepthSynchronizer::ImuDepthSynchronizer(const SynchronizerConfig& config) : config_(config) {
  config_.validate();
}

ImuAddResult ImuDepthSynchronizer::add(const ImuSample& sample) {
  if (!std::isfinite(sample.stamp) || !sample.angular_velocity.allFinite() ||
      !sample.linear_acceleration.allFinite()) {
    return ImuAddResult::kInvalid;
  }
  if (!has_previous_) {
    has_previous_ = true;
    previous_stamp_ = sample.stamp;
    return ImuAddResult::kFirst;
  }
  const double dt = sample.stamp - previous_stamp_;
  if (dt == 0.0) return ImuAddResult::kDuplicate;
  if (dt < -config_.clock_jump) return ImuAddResult::kClockJump;
  if (dt < 0.0) return ImuAddResult::kOutOfOrder;

  // The reading stands for the interval since the previous one (zero-order hold).
  ImuAddResult result = ImuAddResult::kAccepted;
  ImuStep step{sample.angular_velocity, sample.linear_acceleration, dt};
  if (dt > config_.max_gap) {
    step.dt = config_.max_gap;
    result = ImuAddResult::kGap;
  }
  steps_.push_back(step);
  buffered_time_ += step.dt;
  previous_stamp_ = sample.stamp;

  // Bounded memory when no depth frame arrives for a long time.
  while (buffered_time_ > config_.max_buffered && !steps_.empty()) {
    buffered_time_ -= steps_.front().dt;
    steps_.pop_front();
  }
  return result;
}

std::vector<ImuStep> ImuDepthSynchronizer::takeInterval(double depth_dt, double* integrated_time) {
  // Cut off the IMU time a previous interval could not cover (second rule of 5.4.5).
  while (debt_ > 0.0 && !steps_.empty()) {
    ImuStep& front = steps_.front();
    const double cut = std::min(front.dt, debt_);
    front.dt -= cut;
    debt_ -= cut;
    buffered_time_ -= cut;
    if (front.dt <= 0.0) steps_.pop_front();
  }

  std::vector<ImuStep> interval;
  double budget = std::max(0.0, depth_dt);
  while (budget > 1e-12 && !steps_.empty()) {
    ImuStep& front = steps_.front();
    if (front.dt <= budget) {
      budget -= front.dt;
      buffered_time_ -= front.dt;
      interval.push_back(front);
      steps_.pop_front();
    } else {
      // First rule of 5.4.5: cut the integration at depth_dt, the rest belongs to the next one.
      ImuStep part = front;
      part.dt = budget;
      front.dt -= budget;
      buffered_time_ -= budget;
      budget = 0.0;
      interval.push_back(part);
    }
  }
  debt_ += budget;
  if (integrated_time) *integrated_time = std::max(0.0, depth_dt) - budget;
  return interval;
}

void ImuDepthSynchronizer::discardBuffered() {
  steps_.clear();
  buffered_time_ = 0.0;
  debt_ = 0.0;
}

void ImuDepthSynchronizer::reset() { *this = ImuDepthSynchronizer(config_); }

}  // namespace vicc_tracking
