#include "vicc_tracking/sim/visible_surface.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace vicc_tracking::sim {

std::vector<SurfacePoint> visibleSurface(const RigSimulator& rig,
                                         const VisibleSurfaceConfig& config,
                                         void (*progress)(size_t, size_t)) {
  if (!(config.spacing > 0.0) || config.frame_stride < 1 || !(config.occlusion_tolerance > 0.0)) {
    throw std::invalid_argument("visible surface: spacing, frame_stride and tolerance must be > 0");
  }
  const std::vector<SurfacePoint> samples = rig.sampleSurface(config.spacing);
  const CameraModel& camera = rig.scenario().camera;
  const double min_range = rig.scenario().tof.min_range;
  const double max_range = std::min(rig.scenario().tof.max_range, config.max_distance);
  const double min_cosine = std::cos(config.max_view_angle_deg * M_PI / 180.0);
  std::vector<char> seen(samples.size(), 0);
  const std::vector<double>& times = rig.depthTimes();
  for (size_t k = 0; k < times.size(); k += config.frame_stride) {
    const Eigen::Isometry3d camera_pose = rig.cameraPose(times[k]);
    const Eigen::Isometry3d map_to_camera = camera_pose.inverse();
    const cv::Mat depth = rig.renderDepthNoiseFree(times[k]);
    for (size_t i = 0; i < samples.size(); ++i) {
      if (seen[i]) continue;
      const Eigen::Vector3d p = map_to_camera * samples[i].position;
      if (p.z() < min_range || p.norm() > max_range) continue;
      const Eigen::Vector3d n = map_to_camera.linear() * samples[i].normal;
      if (-n.dot(p.normalized()) < min_cosine) continue;  // back side or too grazing
      const Eigen::Vector2d pixel = camera.project(p);
      const int u = static_cast<int>(std::lround(pixel.x()));
      const int v = static_cast<int>(std::lround(pixel.y()));
      if (u < 0 || v < 0 || u >= depth.cols || v >= depth.rows) continue;
      const float rendered = depth.at<float>(v, u);
      if (rendered > 0.f && std::abs(rendered - p.z()) < config.occlusion_tolerance) seen[i] = 1;
    }
    if (progress) progress(k + 1, times.size());
  }
  std::vector<SurfacePoint> visible;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (seen[i]) visible.push_back(samples[i]);
  }
  return visible;
}

void writeSurfacePly(const std::string& path, const std::vector<SurfacePoint>& points) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "ply\nformat binary_little_endian 1.0\ncomment VICC simulator: true visible surface\n"
      << "element vertex " << points.size() << "\n"
      << "property float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n"
      << "property float curvature\nend_header\n";  // PCL's PointNormal layout: loads quietly
  for (const SurfacePoint& point : points) {
    const float values[7] = {static_cast<float>(point.position.x()),
                             static_cast<float>(point.position.y()),
                             static_cast<float>(point.position.z()),
                             static_cast<float>(point.normal.x()),
                             static_cast<float>(point.normal.y()),
                             static_cast<float>(point.normal.z()),
                             0.f};
    out.write(reinterpret_cast<const char*>(values), sizeof(values));  // x86/ARM: little endian
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace vicc_tracking::sim
