#include "vicc_tracking/init_strategy.hpp"

#include <stdexcept>

#include "vicc_tracking/strapdown.hpp"

namespace vicc_tracking {

InitStrategyType initStrategyFromString(const std::string& name) {
  if (name == "ekf") return InitStrategyType::kEkf;
  if (name == "identity") return InitStrategyType::kIdentity;
  if (name == "constant_velocity") return InitStrategyType::kConstantVelocity;
  if (name == "imu") return InitStrategyType::kImu;
  throw std::invalid_argument("unknown init strategy '" + name +
                              "' (choose ekf, identity, constant_velocity or imu)");
}

std::string toString(InitStrategyType type) {
  switch (type) {
    case InitStrategyType::kEkf:
      return "ekf";
    case InitStrategyType::kIdentity:
      return "identity";
    case InitStrategyType::kConstantVelocity:
      return "constant_velocity";
    case InitStrategyType::kImu:
      return "imu";
  }
  return "unknown";
}

bool needsImu(InitStrategyType type) {
  return type == InitStrategyType::kEkf || type == InitStrategyType::kImu;
}

void InitStrategy::start(double stamp, const Eigen::Isometry3d& imu_pose) {
  history_.clear();
  history_.push(StampedPose::fromIsometry(stamp, imu_pose));
}

void InitStrategy::update(double stamp, const Eigen::Isometry3d& imu_pose) {
  history_.push(StampedPose::fromIsometry(stamp, imu_pose));
}

namespace {

class IdentityInit : public InitStrategy {
 public:
  InitStrategyType type() const override { return InitStrategyType::kIdentity; }
  Eigen::Isometry3d predict(double, const std::vector<ImuStep>&) override {
    return history_.back().toIsometry();
  }
};

class ConstantVelocityInit : public InitStrategy {
 public:
  InitStrategyType type() const override { return InitStrategyType::kConstantVelocity; }
  Eigen::Isometry3d predict(double stamp, const std::vector<ImuStep>&) override {
    const Eigen::Isometry3d last = history_.back().toIsometry();
    if (history_.size() < 2) return last;
    const double previous_dt = history_.back().stamp - history_.back(1).stamp;
    if (previous_dt <= 0.0) return last;
    // Repeat the last body-frame motion, scaled to this interval's length.
    const Eigen::Isometry3d motion = history_.back(1).toIsometry().inverse() * last;
    const double scale = (stamp - history_.back().stamp) / previous_dt;
    const Eigen::AngleAxisd rotation(motion.linear());
    Eigen::Isometry3d scaled = Eigen::Isometry3d::Identity();
    scaled.linear() =
        Eigen::AngleAxisd(rotation.angle() * scale, rotation.axis()).toRotationMatrix();
    scaled.translation() = motion.translation() * scale;
    return last * scaled;
  }
};

/// Niessner et al. 2014: integrate the IMU from the last tracked pose, no fusion.
class ImuIntegrationInit : public InitStrategy {
 public:
  explicit ImuIntegrationInit(const InitContext& context) : context_(context) {}
  InitStrategyType type() const override { return InitStrategyType::kImu; }
  void start(double stamp, const Eigen::Isometry3d& imu_pose) override {
    InitStrategy::start(stamp, imu_pose);
    previous_steps_.clear();
  }

  Eigen::Isometry3d predict(double stamp, const std::vector<ImuStep>& steps) override {
    StrapdownState state;
    state.orientation = toEigen(history_.back().orientation);
    state.position = history_.back().position;
    // The IMU alone cannot know the velocity. The last two tracked positions and the IMU
    // steps recorded between them do: the backward difference of the positions alone is the
    // velocity half an interval ago, which under hand-held accelerations misses by centimetres.
    if (history_.size() >= 2) {
      const StampedPose& older = history_.back(1);
      const StampedPose& newer = history_.back();
      const bool steps_cover_it = previous_interval_end_ == newer.stamp;
      state.velocity = velocityAtIntervalEnd(
          toEigen(older.orientation), older.position, newer.position, newer.stamp - older.stamp,
          steps_cover_it ? previous_steps_ : std::vector<ImuStep>{}, context_.calibration,
          context_.gravity_map);
    }
    for (const ImuStep& step : steps) {
      state = strapdownStep(state, step, context_.calibration, context_.gravity_map);
    }
    previous_steps_ = steps;
    previous_interval_end_ = stamp;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = state.orientation.toRotationMatrix();
    pose.translation() = state.position;
    return pose;
  }

 private:
  InitContext context_;
  std::vector<ImuStep> previous_steps_;  ///< the IMU steps of the interval predicted last
  double previous_interval_end_ = -1.0;  ///< stamp that interval ended at
};

/// The thesis's method (5.4): EKF prediction over the interval, correction with the virtual
/// measurements, initial pose from Eq. 5.23-5.24, then the reset of Eq. 5.25-5.30.
class EkfInit : public InitStrategy {
 public:
  explicit EkfInit(const InitContext& context)
      : context_(context), ekf_(context.ekf, context.calibration, context.gravity_map) {}
  InitStrategyType type() const override { return InitStrategyType::kEkf; }

  void start(double stamp, const Eigen::Isometry3d& imu_pose) override {
    InitStrategy::start(stamp, imu_pose);
    ekf_.start(history_.back().orientation);
    previous_steps_.clear();
    previous_interval_end_ = -1.0;
    velocities_.clear();
  }

  Eigen::Isometry3d predict(double stamp, const std::vector<ImuStep>& steps) override {
    for (const ImuStep& step : steps) ekf_.predict(step);
    const StampedPose& previous = history_.back();
    // Eq. 5.10 takes the backward difference of the last two ICP positions for the velocity
    // at the newest pose, but that is the mean velocity over the last interval: it lags half
    // an interval, and Eq. 5.14-5.15 extrapolate the lag over the next interval. The IMU steps
    // recorded between the two poses give the velocity at the newest pose itself.
    if (context_.ekf.imu_aided_virtual_velocity && history_.size() >= 2 &&
        previous_interval_end_ == previous.stamp) {
      const StampedPose& older = history_.back(1);
      velocities_.insert(
          velocities_.begin(),
          velocityAtIntervalEnd(toEigen(older.orientation), older.position, previous.position,
                                previous.stamp - older.stamp, previous_steps_, context_.calibration,
                                context_.gravity_map));
      if (velocities_.size() > 2) velocities_.pop_back();
    } else {
      velocities_.clear();
    }
    const double interval = stamp - previous.stamp;
    ekf_.correct(virtualMeasurement(history_, interval, velocities_), interval);
    previous_steps_ = steps;
    previous_interval_end_ = stamp;
    const EkfState& state = ekf_.state();
    StampedPose guess;
    guess.stamp = stamp;
    guess.position = previous.position + state.p;                              // Eq. 5.23
    guess.orientation = multiply(previous.orientation, state.q).normalized();  // Eq. 5.24
    ekf_.reset(previous.orientation);
    return guess.toIsometry();
  }

  void setEkfConfig(const EkfConfig& config) override {
    ekf_.setConfig(config);
    context_.ekf = config;
  }

  const InitializationEkf& filter() const { return ekf_; }

 private:
  InitContext context_;
  InitializationEkf ekf_;
  std::vector<ImuStep> previous_steps_;      ///< the IMU steps of the interval predicted last
  double previous_interval_end_ = -1.0;      ///< stamp that interval ended at
  std::vector<Eigen::Vector3d> velocities_;  ///< at the newest and the one-older pose
};

}  // namespace

std::unique_ptr<InitStrategy> makeInitStrategy(InitStrategyType type, const InitContext& context) {
  switch (type) {
    case InitStrategyType::kEkf:
      return std::make_unique<EkfInit>(context);
    case InitStrategyType::kIdentity:
      return std::make_unique<IdentityInit>();
    case InitStrategyType::kConstantVelocity:
      return std::make_unique<ConstantVelocityInit>();
    case InitStrategyType::kImu:
      return std::make_unique<ImuIntegrationInit>(context);
  }
  throw std::invalid_argument("unknown init strategy");
}

}  // namespace vicc_tracking
