#pragma once
// Projective point-to-plane ICP, coarse to fine over a depth pyramid (thesis 2.2.2, Eq. 2.6-2.7).

#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "vicc_tracking/depth_preprocessing.hpp"

namespace vicc_tracking {

struct IcpConfig {
  /// Maximum iterations per pyramid level, index 0 = finest.
  std::vector<int> iterations_per_level{10, 5, 4};
  double max_correspondence_distance = 0.05;   ///< m, at the finest level (doubles per level)
  double max_normal_angle_deg = 30.0;
  double convergence_translation = 1e-4;       ///< m; increment below this = converged
  double convergence_rotation_deg = 0.01;
  int min_inliers = 200;                       ///< on the finest level
  double min_inlier_ratio = 0.15;              ///< of the valid source normals, finest level
  double max_condition_number = 1e5;           ///< of the 6x6 system, finest level
  double max_jump_translation = 0.15;          ///< m away from the initial guess = failure
  double max_jump_rotation_deg = 20.0;
  void validate() const;
};

struct IcpResult {
  bool ok = false;
  std::string failure_reason;       ///< set when !ok
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< T_reference_source
  int iterations = 0;
  std::vector<int> iterations_per_level;
  int inliers = 0;
  double inlier_ratio = 0.0;
  double residual_rms = 0.0;
  double condition_number = 0.0;
};

/// One linearised point-to-plane system: J^T J x = -J^T r over all correspondences.
struct PointToPlaneSystem {
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
  double squared_error = 0.0;
  int count = 0;
};

class ProjectiveIcp {
 public:
  explicit ProjectiveIcp(const IcpConfig& config);

  /// Aligns source (the new frame) to reference (previous frame or model prediction, in the
  /// reference camera's coordinates), starting from initial_guess = T_reference_source.
  /// Both pyramids need the same number of levels and matching intrinsics.
  IcpResult align(const DepthPyramid& source, const DepthPyramid& reference,
                  const Eigen::Isometry3d& initial_guess) const;

  /// Builds the linear system of one iteration (exposed for tests).
  PointToPlaneSystem buildSystem(const DepthLevel& source, const DepthLevel& reference,
                                 const Eigen::Isometry3d& pose, double max_distance) const;

  const IcpConfig& config() const { return config_; }

 private:
  IcpConfig config_;
  float min_normal_cosine_;
};

/// Exponential map of a twist (rotation vector, translation) to a rigid transform.
Eigen::Isometry3d twistToIsometry(const Eigen::Matrix<double, 6, 1>& twist);

}  // namespace vicc_tracking
