#include "vicc_tracking/icp.hpp"

#include <algorithm>
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
using simd::Mask4;
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

namespace {

/// The source pixels that have a normal, as planes of four-aligned length (the padding has a
/// zero normal, so it never passes the normal test). Built once per level and frame: every
/// ICP iteration then reads only valid points, four at a time.
struct SourcePoints {
  std::vector<float> x, y, z, nx, ny, nz;
  size_t size() const { return x.size(); }
};

SourcePoints compactSource(const DepthLevel& source) {
  const size_t pixels = source.normals.size();
  SourcePoints points;
  for (auto* plane : {&points.x, &points.y, &points.z, &points.nx, &points.ny, &points.nz}) {
    plane->assign(pixels + 3, 0.f);
  }
  // Every pixel is written at the next free slot, which only advances for valid ones: no
  // branch on validity (it changes pixel by pixel at every hole and edge).
  size_t n = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const Eigen::Vector3f& vertex = source.vertices[i];
    const Eigen::Vector3f& normal = source.normals[i];
    points.x[n] = vertex.x();
    points.y[n] = vertex.y();
    points.z[n] = vertex.z();
    points.nx[n] = normal.x();
    points.ny[n] = normal.y();
    points.nz[n] = normal.z();
    n += (normal.z() != 0.f) | (normal.x() != 0.f);
  }
  const size_t padded = (n + 3) / 4 * 4;
  for (auto* plane : {&points.x, &points.y, &points.z, &points.nx, &points.ny, &points.nz}) {
    std::fill(plane->begin() + n, plane->begin() + padded, 0.f);  // zero normal: never valid
    plane->resize(padded);
  }
  return points;
}

/// Eq. 2.6 (projective data association, nearest reference pixel) and Eq. 2.7 linearised,
/// r + (p x n) . w + n . t, summed into the normal equations four points at a time: the 21
/// upper-triangle entries of J^T J and J^T r in float lanes, flushed to double every few
/// hundred points.
PointToPlaneSystem sumSystem(const SourcePoints& source, const DepthLevel& reference,
                             const Eigen::Isometry3d& pose, double max_distance,
                             float min_normal_cosine) {
  const Eigen::Matrix3f r = pose.linear().cast<float>();
  const Eigen::Vector3f t = pose.translation().cast<float>();
  const PinholeIntrinsics& k = reference.intrinsics;
  const float max_distance_sq = static_cast<float>(max_distance * max_distance);
  const float max_u = static_cast<float>(k.width) - 0.5f;
  const float max_v = static_cast<float>(k.height) - 0.5f;
  const Eigen::Vector3f* reference_vertices = reference.vertices.data();
  const Eigen::Vector3f* reference_normals = reference.normals.data();

  PointToPlaneSystem system;
  constexpr size_t kFlushEvery = 256;
  for (size_t block = 0; block < source.size(); block += kFlushEvery) {
    Float4 ata[21] = {};
    Float4 atb[6] = {};
    Float4 error = {};
    Mask4 count = {};
    const size_t block_end = std::min(source.size(), block + kFlushEvery);
    for (size_t c = block; c < block_end; c += 4) {
      const Float4 sx = load4(&source.x[c]), sy = load4(&source.y[c]), sz = load4(&source.z[c]);
      const Float4 x = r(0, 0) * sx + r(0, 1) * sy + r(0, 2) * sz + t.x();
      const Float4 y = r(1, 0) * sx + r(1, 1) * sy + r(1, 2) * sz + t.y();
      const Float4 z = r(2, 0) * sx + r(2, 1) * sy + r(2, 2) * sz + t.z();
      const Mask4 in_front = z > 0.f;
      const Float4 inverse_z = in_front ? 1.f / z : Float4{};
      const Float4 pu = k.fx * x * inverse_z + k.cx;
      const Float4 pv = k.fy * y * inverse_z + k.cy;
      const Mask4 inside = in_front & (pu >= -0.5f) & (pv >= -0.5f) & (pu < max_u) & (pv < max_v);
      if (!(inside[0] | inside[1] | inside[2] | inside[3])) continue;
      const Mask4 index = inside ? __builtin_convertvector(pv + 0.5f, Mask4) * k.width +
                                       __builtin_convertvector(pu + 0.5f, Mask4)
                                 : Mask4{};
      Float4 rx, ry, rz, nx, ny, nz;  // reference vertex and normal per lane (a gather)
      for (int lane = 0; lane < 4; ++lane) {
        const Eigen::Vector3f& vertex = reference_vertices[index[lane]];
        const Eigen::Vector3f& normal = reference_normals[index[lane]];
        rx[lane] = vertex.x();
        ry[lane] = vertex.y();
        rz[lane] = vertex.z();
        nx[lane] = normal.x();
        ny[lane] = normal.y();
        nz[lane] = normal.z();
      }
      const Float4 dx = x - rx, dy = y - ry, dz = z - rz;
      const Float4 snx = load4(&source.nx[c]), sny = load4(&source.ny[c]),
                   snz = load4(&source.nz[c]);
      const Float4 rotated_x = r(0, 0) * snx + r(0, 1) * sny + r(0, 2) * snz;
      const Float4 rotated_y = r(1, 0) * snx + r(1, 1) * sny + r(1, 2) * snz;
      const Float4 rotated_z = r(2, 0) * snx + r(2, 1) * sny + r(2, 2) * snz;
      const Mask4 valid = inside & ((nz != 0.f) | (nx != 0.f)) &
                          (dx * dx + dy * dy + dz * dz <= max_distance_sq) &
                          (rotated_x * nx + rotated_y * ny + rotated_z * nz >= min_normal_cosine);
      // Rejected lanes get a zero normal and residual: they add nothing.
      const Float4 a = valid ? nx : Float4{}, b = valid ? ny : Float4{}, d = valid ? nz : Float4{};
      const Float4 residual = a * dx + b * dy + d * dz;
      const Float4 j[6] = {y * d - z * b, z * a - x * d, x * b - y * a, a, b, d};
      int entry = 0;
      for (int row = 0; row < 6; ++row) {
        for (int col = row; col < 6; ++col) ata[entry++] += j[row] * j[col];
        atb[row] += j[row] * residual;
      }
      error += residual * residual;
      count -= valid;  // true lanes are -1
    }
    int entry = 0;
    for (int row = 0; row < 6; ++row) {
      for (int col = row; col < 6; ++col) system.ata(row, col) += sum4(ata[entry++]);
      system.atb(row) += sum4(atb[row]);
    }
    system.squared_error += sum4(error);
    system.count += count[0] + count[1] + count[2] + count[3];
  }
  system.ata = system.ata.selfadjointView<Eigen::Upper>();
  return system;
}

}  // namespace

PointToPlaneSystem ProjectiveIcp::buildSystem(const DepthLevel& source, const DepthLevel& reference,
                                              const Eigen::Isometry3d& pose,
                                              double max_distance) const {
  return sumSystem(compactSource(source), reference, pose, max_distance, min_normal_cosine_);
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
    const SourcePoints points = max_iterations > 0 ? compactSource(source[level]) : SourcePoints{};
    for (int iteration = 0; iteration < max_iterations; ++iteration) {
      PointToPlaneSystem system =
          sumSystem(points, reference[level], result.pose, max_distance, min_normal_cosine_);
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
