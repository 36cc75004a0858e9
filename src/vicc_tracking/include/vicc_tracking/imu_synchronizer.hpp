#pragma once
// IMU/depth synchronisation of thesis 5.4.5: each depth inter-frame interval consumes exactly
// its length of IMU integration time, measured on the IMU's own clock. When more IMU time is
// available the surplus is carried into the next interval; when less is available the missing
// time is cut off the beginning of the next interval's IMU data.

#include <deque>
#include <vector>

#include "vicc_tracking/imu_types.hpp"

namespace vicc_tracking {

struct SynchronizerConfig {
  double max_gap = 0.1;          ///< s; a longer IMU gap is bridged with at most this much time
  double clock_jump = 1.0;       ///< s; stamps going back further mean a restarted clock (bag loop)
  double max_buffered = 10.0;    ///< s of IMU data kept while no depth frame consumes it
  void validate() const;
};

enum class ImuAddResult { kAccepted, kFirst, kGap, kDuplicate, kOutOfOrder, kClockJump, kInvalid };
const char* toString(ImuAddResult result);

class ImuDepthSynchronizer {
 public:
  explicit ImuDepthSynchronizer(const SynchronizerConfig& config = {});

  /// Adds a reading; rejected readings (duplicate, out of order, non-finite) change nothing.
  /// kClockJump also changes nothing: the caller is expected to reset().
  ImuAddResult add(const ImuSample& sample);

  /// IMU steps covering depth_dt seconds of IMU time (5.4.5). integrated_time receives the
  /// time actually covered (less than depth_dt when the IMU lags).
  std::vector<ImuStep> takeInterval(double depth_dt, double* integrated_time = nullptr);

  /// Drops buffered steps (e.g. those recorded before tracking started).
  void discardBuffered();
  void reset();
  bool hasData() const { return has_previous_; }
  double bufferedTime() const { return buffered_time_; }

 private:
  SynchronizerConfig config_;
  std::deque<ImuStep> steps_;
  bool has_previous_ = false;
  double previous_stamp_ = 0.0;
  double debt_ = 0.0;  ///< IMU time to cut off the beginning of the next interval
  double buffered_time_ = 0.0;  ///< sum of dt over steps_
};

}  // namespace vicc_tracking
