// IMU/depth synchronisation (thesis 5.4.5): what add() accepts, and how takeInterval() hands
// each depth interval exactly its length of IMU time, carrying surplus and debt over.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "vicc_tracking/imu_synchronizer.hpp"

using namespace vicc_tracking;

namespace {

/// A reading whose angular velocity x carries `id`, so a step can be traced to its reading.
ImuSample reading(double stamp, double id) {
  ImuSample sample;
  sample.stamp = stamp;
  sample.angular_velocity = Eigen::Vector3d(id, 0.0, 0.0);
  sample.linear_acceleration = Eigen::Vector3d(0.0, 0.0, 9.81);
  return sample;
}

/// Readings at `rate_dt` from t = 0, reading k carrying id k.
void addReadings(ImuDepthSynchronizer& synchronizer, int count, double rate_dt, int first = 0) {
  for (int k = first; k < first + count; ++k) synchronizer.add(reading(k * rate_dt, k));
}

/// The steps longer than a rounding sliver (cutting at a boundary may leave a ~1e-18 s rest).
std::vector<ImuStep> significant(const std::vector<ImuStep>& steps) {
  std::vector<ImuStep> kept;
  for (const ImuStep& step : steps) {
    if (step.dt > 1e-9) kept.push_back(step);
  }
  return kept;
}

double totalTime(const std::vector<ImuStep>& steps) {
  double total = 0.0;
  for (const ImuStep& step : steps) total += step.dt;
  return total;
}

TEST(ImuSynchronizerTest, ClassifiesEveryKindOfReading) {
  ImuDepthSynchronizer synchronizer;
  EXPECT_FALSE(synchronizer.hasData());
  EXPECT_EQ(synchronizer.add(reading(10.0, 0)), ImuAddResult::kFirst);
  EXPECT_TRUE(synchronizer.hasData());
  EXPECT_DOUBLE_EQ(synchronizer.bufferedTime(), 0.0);  // the first reading starts the clock
  EXPECT_EQ(synchronizer.add(reading(10.01, 1)), ImuAddResult::kAccepted);
  EXPECT_NEAR(synchronizer.bufferedTime(), 0.01, 1e-12);

  // Rejected readings change nothing.
  EXPECT_EQ(synchronizer.add(reading(10.01, 2)), ImuAddResult::kDuplicate);
  EXPECT_EQ(synchronizer.add(reading(10.005, 3)), ImuAddResult::kOutOfOrder);
  EXPECT_EQ(synchronizer.add(reading(5.0, 4)), ImuAddResult::kClockJump);  // > clock_jump back
  ImuSample bad = reading(10.02, 5);
  bad.linear_acceleration.y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(synchronizer.add(bad), ImuAddResult::kInvalid);
  EXPECT_EQ(synchronizer.add(reading(std::numeric_limits<double>::infinity(), 6)),
            ImuAddResult::kInvalid);
  EXPECT_NEAR(synchronizer.bufferedTime(), 0.01, 1e-12);

  // The next good reading is held over the time since the last accepted one.
  EXPECT_EQ(synchronizer.add(reading(10.03, 7)), ImuAddResult::kAccepted);
  const std::vector<ImuStep> steps = synchronizer.takeInterval(1.0);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].angular_velocity.x(), 1);
  EXPECT_NEAR(steps[0].dt, 0.01, 1e-12);
  EXPECT_EQ(steps[1].angular_velocity.x(), 7);
  EXPECT_NEAR(steps[1].dt, 0.02, 1e-12);
}

TEST(ImuSynchronizerTest, AGapIsBridgedWithAtMostMaxGap) {
  SynchronizerConfig config;
  config.max_gap = 0.05;
  ImuDepthSynchronizer synchronizer(config);
  synchronizer.add(reading(0.0, 0));
  EXPECT_EQ(synchronizer.add(reading(0.5, 1)), ImuAddResult::kGap);
  EXPECT_EQ(synchronizer.add(reading(0.51, 2)), ImuAddResult::kAccepted);
  EXPECT_NEAR(synchronizer.bufferedTime(), 0.06, 1e-12);
  double integrated = -1.0;
  const std::vector<ImuStep> steps = synchronizer.takeInterval(0.51, &integrated);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_NEAR(steps[0].dt, 0.05, 1e-12);
  EXPECT_NEAR(integrated, 0.06, 1e-12);  // the IMU could not cover the interval
}

TEST(ImuSynchronizerTest, AnIntervalEndingInsideAReadingCarriesTheRestIntoTheNext) {
  ImuDepthSynchronizer synchronizer;
  addReadings(synchronizer, 11, 0.01);  // 0.1 s of steps, ids 1..10
  double integrated = 0.0;
  const std::vector<ImuStep> first = significant(synchronizer.takeInterval(0.025, &integrated));
  ASSERT_EQ(first.size(), 3u);
  EXPECT_NEAR(totalTime(first), 0.025, 1e-12);
  EXPECT_NEAR(integrated, 0.025, 1e-12);
  EXPECT_EQ(first[2].angular_velocity.x(), 3);
  EXPECT_NEAR(first[2].dt, 0.005, 1e-12);

  const std::vector<ImuStep> second = significant(synchronizer.takeInterval(0.02, &integrated));
  ASSERT_EQ(second.size(), 3u);
  EXPECT_EQ(second[0].angular_velocity.x(), 3);  // the rest of reading 3
  EXPECT_NEAR(second[0].dt, 0.005, 1e-12);
  EXPECT_EQ(second[2].angular_velocity.x(), 5);
  EXPECT_NEAR(second[2].dt, 0.005, 1e-12);
  EXPECT_NEAR(synchronizer.bufferedTime(), 0.1 - 0.045, 1e-12);
}

TEST(ImuSynchronizerTest, MissingImuTimeIsCutOffTheNextInterval) {
  ImuDepthSynchronizer synchronizer;
  addReadings(synchronizer, 3, 0.01);  // 0.02 s of steps
  double integrated = 0.0;
  const std::vector<ImuStep> lagging = synchronizer.takeInterval(0.05, &integrated);
  EXPECT_NEAR(totalTime(lagging), 0.02, 1e-12);
  EXPECT_NEAR(integrated, 0.02, 1e-12);  // 0.03 s owed

  addReadings(synchronizer, 8, 0.01, 3);  // readings 3..10: steps of 0.01 s, ids 3..10
  const std::vector<ImuStep> next = significant(synchronizer.takeInterval(0.02, &integrated));
  EXPECT_NEAR(integrated, 0.02, 1e-12);
  ASSERT_EQ(next.size(), 2u);
  // Readings 3, 4 and 5 (0.03 s) went to pay the debt: this interval starts at reading 6.
  EXPECT_EQ(next[0].angular_velocity.x(), 6);
  EXPECT_EQ(next[1].angular_velocity.x(), 7);
  EXPECT_NEAR(synchronizer.bufferedTime(), 0.03, 1e-12);
}

TEST(ImuSynchronizerTest, OverManyIntervalsTheImuTimeEqualsTheDepthTime) {
  // A 400 Hz IMU against depth intervals that are no multiple of its period.
  ImuDepthSynchronizer synchronizer;
  synchronizer.add(reading(0.0, 0));
  double imu_time = 0.0, depth_time = 0.0, stamp = 0.0;
  int id = 1;
  for (int frame = 0; frame < 40; ++frame) {
    const double depth_dt = frame % 3 == 0 ? 0.0667 : 0.0333;
    while (stamp < depth_time + depth_dt + 1e-9) {
      stamp += 0.0025;
      synchronizer.add(reading(stamp, id++));
    }
    depth_time += depth_dt;
    double integrated = 0.0;
    imu_time += totalTime(synchronizer.takeInterval(depth_dt, &integrated));
    EXPECT_NEAR(integrated, depth_dt, 1e-9) << "frame " << frame;
  }
  EXPECT_NEAR(imu_time, depth_time, 1e-9);
}

TEST(ImuSynchronizerTest, KeepsAtMostMaxBufferedSecondsWithoutDepthFrames) {
  SynchronizerConfig config;
  config.max_buffered = 0.5;
  ImuDepthSynchronizer synchronizer(config);
  addReadings(synchronizer, 201, 0.01);  // 2 s of readings
  EXPECT_LE(synchronizer.bufferedTime(), 0.5 + 1e-9);
  EXPECT_GT(synchronizer.bufferedTime(), 0.49);
  const std::vector<ImuStep> steps = synchronizer.takeInterval(10.0);
  ASSERT_FALSE(steps.empty());
  EXPECT_EQ(steps.back().angular_velocity.x(), 200);  // the newest are kept
  EXPECT_GE(steps.front().angular_velocity.x(), 150);
}

TEST(ImuSynchronizerTest, DiscardAndResetForgetDataAndDebt) {
  ImuDepthSynchronizer synchronizer;
  addReadings(synchronizer, 3, 0.01);
  synchronizer.takeInterval(0.1);  // 0.08 s owed
  synchronizer.discardBuffered();
  EXPECT_DOUBLE_EQ(synchronizer.bufferedTime(), 0.0);
  addReadings(synchronizer, 2, 0.01, 3);
  EXPECT_NEAR(totalTime(synchronizer.takeInterval(0.02)), 0.02, 1e-12);  // no debt left

  synchronizer.reset();
  EXPECT_FALSE(synchronizer.hasData());
  EXPECT_EQ(synchronizer.add(reading(0.0, 0)), ImuAddResult::kFirst);  // even an older stamp

  EXPECT_TRUE(synchronizer.takeInterval(-0.1).empty());  // a negative interval takes nothing
}

TEST(ImuSynchronizerTest, RejectsNonPositiveConfiguration) {
  for (double SynchronizerConfig::*field :
       {&SynchronizerConfig::max_gap, &SynchronizerConfig::clock_jump,
        &SynchronizerConfig::max_buffered}) {
    for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
      SynchronizerConfig config;
      config.*field = bad;
      EXPECT_THROW(ImuDepthSynchronizer{config}, std::invalid_argument);
    }
  }
}

}  // namespace
