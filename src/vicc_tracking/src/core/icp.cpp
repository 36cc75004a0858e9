#include "vicc_tracking/icp.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "vicc_tracking/simd4.hpp"

namespace vicc_tracking {
namespace {
constexpr double kDegToRad = M_PI / 180.0;
using simd::Float4;
using simd::load4;
using simd::sum4;
}  // namespace

void IcpConfig::validate() const {
  if (iterations_per_level.empty()) {
    throw std::invalid_argument("icp.iterations_per_level must not be empty");
  }
  for (int iterations : iterations_per_level) {
    if (iterations < 0 || iterations > 1000) {
      throw std::invalid_argument("icp.iterations_per_level entries must be in 0..1000");
    }
  }
  if (!(max_correspondence_distance > 0.0) || !(max_normal_angle_deg > 0.0) ||
      max_normal_angle_deg > 90.0) {
    throw std::invalid_argument(
        "icp: max_correspondence_distance must be > 0 and "
        "max_normal_angle_deg in (0, 90]");
  }
  if (!(convergence_translation >= 0.0) || !(convergence_rotation_deg >= 0.0)) {
    throw std::invalid_argument("icp: convergence thresholds must be >= 0");
  }
  if (min_inliers < 6 || !(min_inlier_ratio >= 0.0) || min_inlier_ratio > 1.0) {
    throw std::invalid_argument("icp: min_inliers must be >= 6 and min_inlier_ratio in [0, 1]");
  }
  if (!(max_condition_number > 1.0) || !(max_jump_translation > 0.0) ||
      !(max_jump_rotation_deg > 0.0)) {
    throw std::invalid_argument("icp: max_condition_number must be > 1 and jump limits > 0");
  }
}

Eigen::Isometry3d twistToIsometry(const Eigen::Matrix<double, 6, 1>& twist) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d rotation = twist.head<3>();
  const double angle = rotation.norm();
  if (angle > 1e-12) {
    transform.linear() = Eigen::AngleAxisd(angle, rotation / angle).toRotationMatrix();
  }
  transform.translation() = twist.tail<3>();
  return transform;
}

ProjectiveIcp::ProjectiveIcp(const IcpConfig& config) : config_(config) {
  config_.validate();
  min_normal_cosine_ = static_cast<float>(std::cos(config_.max_normal_angle_deg * kDegToRad));
}

PointToPlaneSystem ProjectiveIcp::buildSystem(const DepthLevel& source, const DepthLevel& reference,
                                              const Eigen::Isometry3d& pose,
                                              double max_distance) const {
  const Eigen::Matrix3f rotation = pose.linear().cast<float>();
  const Eigen::Vector3f translation = pose.translation().cast<float>();
  const PinholeIntrinsics& k = reference.intrinsics;
  const float max_distance_sq = static_cast<float>(max_distance * max_distance);
  const int width = source.intrinsics.width;
  const int height = source.intrinsics.height;

  // Per row: find the correspondences (scalar: projection and lookups), keep them in planes,
  // then accumulate the 21 upper-triangle entries of J^T J and J^T r four at a time in float,
  // and in double across rows.
  PointToPlaneSystem system;
  const float max_u = static_cast<float>(k.width) - 0.5f;
  const float max_v = static_cast<float>(k.height) - 0.5f;
  const size_t padded = static_cast<size_t>(width) + 4;
  std::vector<float> planes(7 * padded);
  float* const px = planes.data();
  float* const py = px + padded;
  float* const pz = py + padded;
  float* const nx = pz + padded;
  float* const ny = nx + padded;
  float* const nz = ny + padded;
  float* const residuals = nz + padded;
  for (int v = 0; v < height; ++v) {
    int n = 0;
    for (int u = 0; u < width; ++u) {
      const int index = v * width + u;
      const Eigen::Vector3f& source_normal = source.normals[index];
      if (source_normal.z() == 0.f && source_normal.x() == 0.f) continue;
      const Eigen::Vector3f point = rotation * source.vertices[index] + translation;
      if (point.z() <= 0.f) continue;
      // Eq. 2.6: projective data association (rounding to the nearest reference pixel).
      const float inverse_z = 1.f / point.z();
      const float pu = k.fx * point.x() * inverse_z + k.cx;
      const float pv = k.fy * point.y() * inverse_z + k.cy;
      if (!(pu >= -0.5f && pv >= -0.5f && pu < max_u && pv < max_v)) continue;
      const int reference_index =
          static_cast<int>(pv + 0.5f) * k.width + static_cast<int>(pu + 0.5f);
      const Eigen::Vector3f& normal = reference.normals[reference_index];
      if (normal.z() == 0.f && normal.x() == 0.f) continue;
      const Eigen::Vector3f difference = point - reference.vertices[reference_index];
      if (difference.squaredNorm() > max_distance_sq) continue;
      if ((rotation * source_normal).dot(normal) < min_normal_cosine_) continue;
      px[n] = point.x();
      py[n] = point.y();
      pz[n] = point.z();
      nx[n] = normal.x();
      ny[n] = normal.y();
      nz[n] = normal.z();
      residuals[n] = normal.dot(difference);
      ++n;
    }
    if (n == 0) continue;
    for (int pad = n; pad % 4 != 0; ++pad) {  // zero normal and residual: adds nothing
      px[pad] = py[pad] = pz[pad] = nx[pad] = ny[pad] = nz[pad] = residuals[pad] = 0.f;
    }

    // Eq. 2.7 linearised: r + (p x n) . w + n . t.
    Float4 ata[21] = {};
    Float4 atb[6] = {};
    Float4 error = {};
    for (int c = 0; c < n; c += 4) {
      const Float4 x = load4(px + c), y = load4(py + c), z = load4(pz + c);
      const Float4 a = load4(nx + c), b = load4(ny + c), d = load4(nz + c);
      const Float4 r = load4(residuals + c);
      const Float4 j[6] = {y * d - z * b, z * a - x * d, x * b - y * a, a, b, d};
      int entry = 0;
      for (int row = 0; row < 6; ++row) {
        for (int col = row; col < 6; ++col) ata[entry++] += j[row] * j[col];
        atb[row] += j[row] * r;
      }
      error += r * r;
    }
    int entry = 0;
    for (int row = 0; row < 6; ++row) {
      for (int col = row; col < 6; ++col) system.ata(row, col) += sum4(ata[entry++]);
      system.atb(row) += sum4(atb[row]);
    }
    system.squared_error += sum4(error);
    system.count += n;
  }
  system.ata = system.ata.selfadjointView<Eigen::Upper>();
  return system;
}

IcpResult ProjectiveIcp::align(const DepthPyramid& source, const DepthPyramid& reference,
                               const Eigen::Isometry3d& initial_guess) const {
  if (source.empty() || source.size() != reference.size()) {
    throw std::invalid_argument("ICP: source and reference pyramids differ in depth");
  }
  IcpResult result;
  result.pose = initial_guess;
  const int levels = static_cast<int>(source.size());
  result.iterations_per_level.assign(levels, 0);

  PointToPlaneSystem last_system;
  for (int level = levels - 1; level >= 0; --level) {
    const int max_iterations =
        config_
            .iterations_per_level[std::min<size_t>(level, config_.iterations_per_level.size() - 1)];
    const double max_distance = config_.max_correspondence_distance * std::pow(2.0, level);
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      PointToPlaneSystem system =
          buildSystem(source[level], reference[level], result.pose, max_distance);
      last_system = system;
      if (system.count < 6) break;  // nothing to solve on this level; try the finer one
      const Eigen::Matrix<double, 6, 1> twist = system.ata.ldlt().solve(-system.atb);
      if (!twist.allFinite()) break;
      result.pose = twistToIsometry(twist) * result.pose;
      ++result.iterations_per_level[level];
      ++result.iterations;
      if (twist.tail<3>().norm() < config_.convergence_translation &&
          twist.head<3>().norm() < config_.convergence_rotation_deg * kDegToRad) {
        break;
      }
    }
  }

  // Quality of the final (finest-level) alignment: the last iteration's system, built one
  // (converged, hence tiny) step before the final pose, saves a full pass over the image.
  if (result.iterations_per_level[0] == 0) {
    last_system =
        buildSystem(source[0], reference[0], result.pose, config_.max_correspondence_distance);
  }
  result.inliers = last_system.count;
  result.inlier_ratio = source[0].valid_normals > 0
                            ? static_cast<double>(last_system.count) / source[0].valid_normals
                            : 0.0;
  result.residual_rms =
      last_system.count > 0 ? std::sqrt(last_system.squared_error / last_system.count) : 0.0;
  if (last_system.count >= 6) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(last_system.ata,
                                                                           Eigen::EigenvaluesOnly);
    const double smallest = eigen.eigenvalues()(0);
    result.condition_number = smallest > 0.0 ? eigen.eigenvalues()(5) / smallest
                                             : std::numeric_limits<double>::infinity();
  }

  const Eigen::Isometry3d jump = initial_guess.inverse() * result.pose;
  const double jump_translation = jump.translation().norm();
  const double jump_rotation_deg = Eigen::AngleAxisd(jump.linear()).angle() / kDegToRad;
  std::ostringstream reason;
  if (result.inliers < config_.min_inliers || result.inlier_ratio < config_.min_inlier_ratio) {
    reason << "too few correspondences (" << result.inliers << ", "
           << static_cast<int>(100.0 * result.inlier_ratio) << "% of valid pixels)";
  } else if (!(result.condition_number <= config_.max_condition_number)) {
    reason << "ill-conditioned system (condition " << result.condition_number
           << "): geometry does not constrain all 6 degrees of freedom";
  } else if (jump_translation > config_.max_jump_translation ||
             jump_rotation_deg > config_.max_jump_rotation_deg) {
    reason << "result jumped " << jump_translation << " m / " << jump_rotation_deg
           << " deg away from the initial guess";
  }
  result.failure_reason = reason.str();
  result.ok = result.failure_reason.empty();
  return result;
}

}  // namespace vicc_tracking
