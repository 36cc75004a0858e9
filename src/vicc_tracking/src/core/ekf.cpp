#include "vicc_tracking/ekf.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vicc_tracking {
namespace {

constexpr int kQ = 0;    // q   at 0..3
constexpr int kV = 4;    // v   at 4..6
constexpr int kP = 7;    // p   at 7..9
constexpr int kQb = 10;  // q_b at 10..13

Matrix14d blockDiagonal(double rotation, double velocity, double position, double base) {
  Vector14d diagonal;
  diagonal << Eigen::Vector4d::Constant(rotation), Eigen::Vector3d::Constant(velocity),
      Eigen::Vector3d::Constant(position), Eigen::Vector4d::Constant(base);
  return diagonal.asDiagonal();
}

}  // namespace

EkfConfig EkfConfig::thesisNoise() {
  EkfConfig config;
  config.process_noise_rotation = 1e-5;
  config.process_noise_velocity = 1e-2;
  config.process_noise_position = 1e-1;
  config.process_noise_base = 1e-5;
  config.measurement_noise_rotation = 1e-3;
  config.measurement_noise_velocity = 1e-6;
  config.measurement_noise_position = 1e-5;
  config.measurement_noise_base = 1e-13;
  config.initial_covariance = 1e-4;
  config.measurement_noise_interval_exponent = 0.0;
  return config;
}

void EkfConfig::validate() const {
  const double values[] = {
      process_noise_rotation,     process_noise_velocity,     process_noise_position,
      process_noise_base,         measurement_noise_rotation, measurement_noise_velocity,
      measurement_noise_position, measurement_noise_base,     initial_covariance};
  for (double value : values) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw std::invalid_argument(
          "ekf: every noise variance and the initial covariance must be "
          "finite and > 0");
    }
  }
  if (!(measurement_noise_reference_interval > 0.0) ||
      !std::isfinite(measurement_noise_reference_interval)) {
    throw std::invalid_argument("ekf: measurement_noise_reference_interval must be finite and > 0");
  }
  if (!(measurement_noise_interval_exponent >= 0.0 && measurement_noise_interval_exponent <= 8.0)) {
    throw std::invalid_argument("ekf: measurement_noise_interval_exponent must be in [0, 8]");
  }
}

Vector14d EkfState::toVector() const {
  Vector14d x;
  x << q, v, p, q_b;
  return x;
}

EkfState EkfState::fromVector(const Vector14d& x) {
  EkfState state;
  state.q = x.segment<4>(kQ).normalized();
  state.v = x.segment<3>(kV);
  state.p = x.segment<3>(kP);
  state.q_b = x.segment<4>(kQb).normalized();
  return state;
}

InitializationEkf::InitializationEkf(const EkfConfig& config, const ImuCalibration& calibration,
                                     const Eigen::Vector3d& gravity_ref)
    : calibration_(calibration), gravity_ref_(gravity_ref) {
  setConfig(config);
  start(identityQuat());
}

void InitializationEkf::setConfig(const EkfConfig& config) {
  config.validate();
  config_ = config;
  process_noise_ = blockDiagonal(config_.process_noise_rotation, config_.process_noise_velocity,
                                 config_.process_noise_position, config_.process_noise_base);
}

void InitializationEkf::start(const Quat4& base_orientation) {
  state_ = EkfState();
  state_.q_b = base_orientation.normalized();
  covariance_ = Matrix14d::Identity() * config_.initial_covariance;
}

Matrix14d InitializationEkf::processJacobian(const ImuStep& step) const {
  const Eigen::Vector3d omega = step.angular_velocity - calibration_.gyro_bias;
  const double dt = step.dt;
  Matrix14d jacobian = Matrix14d::Identity();
  // Eq. 5.4: q' = q + dt/2 q (x) (0, w) = (I + dt/2 R((0,w))) q
  jacobian.block<4, 4>(kQ, kQ) += 0.5 * dt * rightMultiplicationMatrix(pureQuat(omega));
  // Eq. 5.5: v' = v + dt (qrot(q_b (x) q, a) - g~)
  const Quat4 orientation = multiply(state_.q_b, state_.q);
  const Eigen::Matrix<double, 3, 4> d_rot = qrotJacobian(orientation, step.linear_acceleration);
  jacobian.block<3, 4>(kV, kQ) = dt * d_rot * leftMultiplicationMatrix(state_.q_b);
  jacobian.block<3, 4>(kV, kQb) = dt * d_rot * rightMultiplicationMatrix(state_.q);
  // Eq. 5.6: p' = p + dt v
  jacobian.block<3, 3>(kP, kV) = dt * Eigen::Matrix3d::Identity();
  return jacobian;
}

void InitializationEkf::predict(const ImuStep& step) {
  const Matrix14d jacobian = processJacobian(step);
  const Eigen::Vector3d omega = step.angular_velocity - calibration_.gyro_bias;
  const double dt = step.dt;

  EkfState next = state_;
  // Eq. 5.4 with the first term the thesis's footnote 1 restores.
  next.q = (state_.q + 0.5 * dt * multiply(state_.q, pureQuat(omega))).normalized();
  // Eq. 5.5 in the form of 5.4.1: the still-phase gravity absorbs the accelerometer bias.
  next.v = state_.v +
           dt * (qrot(multiply(state_.q_b, state_.q), step.linear_acceleration) - gravity_ref_);
  next.p = state_.p + dt * state_.v;  // Eq. 5.6
  next.q_b = state_.q_b;              // Eq. 5.7
  state_ = next;

  covariance_ = jacobian * covariance_ * jacobian.transpose() + process_noise_;
}

Matrix14d InitializationEkf::measurementNoise(double interval_dt) const {
  // The extrapolation error grows as a power of the interval (docs/imu_noise.md). A zero or
  // negative interval (never passed by the tracker, which rejects such stamps) counts as the
  // shortest one so that R stays positive.
  constexpr double kShortestInterval = 1e-4;
  const double ratio =
      std::max(interval_dt, kShortestInterval) / config_.measurement_noise_reference_interval;
  const double scale = std::pow(ratio, config_.measurement_noise_interval_exponent);
  return blockDiagonal(scale * config_.measurement_noise_rotation,
                       scale * config_.measurement_noise_velocity,
                       scale * config_.measurement_noise_position, config_.measurement_noise_base);
}

void InitializationEkf::correct(const Vector14d& measurement, double interval_dt) {
  Vector14d z = measurement;
  // q and -q are the same rotation: compare like with like.
  z.segment<4>(kQ) = alignedTo(z.segment<4>(kQ), state_.q);
  z.segment<4>(kQb) = alignedTo(z.segment<4>(kQb), state_.q_b);

  // Eq. 5.20: with h(x) = x the gain is K = P (P + R)^-1.
  const Matrix14d innovation_covariance = covariance_ + measurementNoise(interval_dt);
  const Matrix14d gain = innovation_covariance.ldlt().solve(covariance_.transpose()).transpose();
  const Vector14d x = state_.toVector();
  state_ = EkfState::fromVector(x + gain * (z - x));            // Eq. 5.21
  covariance_ = (Matrix14d::Identity() - gain) * covariance_;   // Eq. 5.22
  covariance_ = 0.5 * (covariance_ + covariance_.transpose());  // keep it symmetric
}

Matrix14d InitializationEkf::resetJacobian(const Quat4& previous_icp_orientation) const {
  Matrix14d jacobian = Matrix14d::Zero();
  jacobian.block<3, 3>(kV, kV) = Eigen::Matrix3d::Identity();                          // Eq. 5.27
  jacobian.block<4, 4>(kQb, kQ) = leftMultiplicationMatrix(previous_icp_orientation);  // 5.29
  return jacobian;
}

void InitializationEkf::reset(const Quat4& previous_icp_orientation) {
  const Matrix14d jacobian = resetJacobian(previous_icp_orientation);
  EkfState next;
  next.q = identityQuat();                                               // Eq. 5.26
  next.v = state_.v;                                                     // Eq. 5.27
  next.p = Eigen::Vector3d::Zero();                                      // Eq. 5.28
  next.q_b = multiply(previous_icp_orientation, state_.q).normalized();  // Eq. 5.29
  state_ = next;

  // Eq. 5.30; the cleared frame-to-frame parts restart with the P0 diagonal of Eq. 5.8.
  covariance_ = jacobian * covariance_ * jacobian.transpose();
  covariance_.block<4, 4>(kQ, kQ) = Eigen::Matrix4d::Identity() * config_.initial_covariance;
  covariance_.block<3, 3>(kP, kP) = Eigen::Matrix3d::Identity() * config_.initial_covariance;
}

}  // namespace vicc_tracking
