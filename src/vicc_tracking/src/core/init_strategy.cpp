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
    scaled.linear() = Eigen::AngleAxisd(rotation.angle() * scale, rotation.axis()).toRotationMatrix();
    scaled.translation() = motion.translation() * scale;
    return last * scaled;
  }
};

/// Niessner et al. 2014: integrate the IMU from the last tracked pose, no fusion.
class ImuIntegrationInit : public InitStrategy {
 public:
  explicit ImuIntegrationInit(const InitContext& context) : context_(context) {}
  InitStrategyType type() const override { return InitStrategyType::kImu; }
  Eigen::Isometry3d predict(double, const std::vector<ImuStep>& steps) override {
    StrapdownState state;
    state.orientation = toEigen(history_.back().orientation);
    state.position = history_.back().position;
    // The IMU alone cannot know the velocity: take it from the last two tracked positions.
    if (history_.size() >= 2) {
      const double dt = history_.back().stamp - history_.back(1).stamp;
      if (dt > 0.0) state.velocity = (history_.back().position - history_.back(1).position) / dt;
    }
    for (const ImuStep& step : steps) {
      state = strapdownStep(state, step, context_.calibration, context_.gravity_map);
    }
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = state.orientation.toRotationMatrix();
    pose.translation() = state.position;
    return pose;
  }

 private:
  InitContext context_;
};

/// The thesis's method (5.4): EKF prediction over the interval, correction with the virtual
/// measurements, initial pose from Eq. 5.23-5.24, then the reset of Eq. 5.25-5.30.
class EkfInit : public InitStrategy {
 public:
  explicit EkfInit(const InitContext& context)
      : ekf_(context.ekf, context.calibration, context.gravity_map) {}
  InitStrategyType type() const override { return InitStrategyType::kEkf; }

  void start(double stamp, const Eigen::Isometry3d& imu_pose) override {
    InitStrategy::start(stamp, imu_pose);
    ekf_.start(history_.back().orientation);
  }

  Eigen::Isometry3d predict(double stamp, const std::vector<ImuStep>& steps) override {
    for (const ImuStep& step : steps) ekf_.predict(step);
    const StampedPose& previous = history_.back();
    ekf_.correct(virtualMeasurement(history_, stamp - previous.stamp));
    const EkfState& state = ekf_.state();
    StampedPose guess;
    guess.stamp = stamp;
    guess.position = previous.position + state.p;                              // Eq. 5.23
    guess.orientation = multiply(previous.orientation, state.q).normalized();  // Eq. 5.24
    ekf_.reset(previous.orientation);
    return guess.toIsometry();
  }

  const InitializationEkf& filter() const { return ekf_; }

 private:
  InitializationEkf ekf_;
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
