#pragma once
// Quaternion algebra on plain 4-vectors (s, vx, vy, vz), as the thesis writes its EKF
// (Eq. 5.4-5.15 add and scale quaternions, which Eigen::Quaterniond does not allow).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vicc_tracking {

using Quat4 = Eigen::Vector4d;  // (s, x, y, z), scalar first as in the thesis

inline Quat4 identityQuat() { return Quat4(1.0, 0.0, 0.0, 0.0); }

inline Quat4 toQuat4(const Eigen::Quaterniond& q) { return Quat4(q.w(), q.x(), q.y(), q.z()); }

inline Eigen::Quaterniond toEigen(const Quat4& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
}

inline Quat4 conjugate(const Quat4& q) { return Quat4(q[0], -q[1], -q[2], -q[3]); }

/// L(p) with p (x) q = L(p) q.
inline Eigen::Matrix4d leftMultiplicationMatrix(const Quat4& p) {
  Eigen::Matrix4d m;
  m << p[0], -p[1], -p[2], -p[3],  //
      p[1], p[0], -p[3], p[2],     //
      p[2], p[3], p[0], -p[1],     //
      p[3], -p[2], p[1], p[0];
  return m;
}

/// R(q) with p (x) q = R(q) p.
inline Eigen::Matrix4d rightMultiplicationMatrix(const Quat4& q) {
  Eigen::Matrix4d m;
  m << q[0], -q[1], -q[2], -q[3],  //
      q[1], q[0], q[3], -q[2],     //
      q[2], -q[3], q[0], q[1],     //
      q[3], q[2], -q[1], q[0];
  return m;
}

inline Quat4 multiply(const Quat4& p, const Quat4& q) { return leftMultiplicationMatrix(p) * q; }

inline Quat4 pureQuat(const Eigen::Vector3d& v) { return Quat4(0.0, v.x(), v.y(), v.z()); }

/// Rotates s by the (not necessarily unit) quaternion r: r (x) (0,s) (x) r*, valid for unit r.
inline Eigen::Vector3d qrot(const Quat4& r, const Eigen::Vector3d& s) {
  const double w = r[0];
  const Eigen::Vector3d v = r.tail<3>();
  return (w * w - v.squaredNorm()) * s + 2.0 * v.dot(s) * v + 2.0 * w * v.cross(s);
}

/// d qrot(r, s) / d r, the 3x4 Jacobian of the expression above.
inline Eigen::Matrix<double, 3, 4> qrotJacobian(const Quat4& r, const Eigen::Vector3d& s) {
  const double w = r[0];
  const Eigen::Vector3d v = r.tail<3>();
  Eigen::Matrix3d s_cross;
  s_cross << 0.0, -s.z(), s.y(), s.z(), 0.0, -s.x(), -s.y(), s.x(), 0.0;
  Eigen::Matrix<double, 3, 4> jacobian;
  jacobian.col(0) = 2.0 * w * s + 2.0 * v.cross(s);
  jacobian.rightCols<3>() = 2.0 * (v.dot(s) * Eigen::Matrix3d::Identity() + v * s.transpose() -
                                   s * v.transpose() - w * s_cross);
  return jacobian;
}

/// Flips q to the hemisphere of reference (q and -q are the same rotation).
inline Quat4 alignedTo(const Quat4& q, const Quat4& reference) {
  return q.dot(reference) < 0.0 ? Quat4(-q) : q;
}

/// Angle in radians of the rotation between two orientations.
inline double rotationAngle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

}  // namespace vicc_tracking
