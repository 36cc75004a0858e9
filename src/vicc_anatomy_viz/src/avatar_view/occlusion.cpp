#include "vicc_anatomy_viz/avatar_view/occlusion.hpp"

#include <Eigen/Geometry>

#include <algorithm>

namespace vicc_anatomy_viz::avatar_view {

Sphere boundingSphere(const avatar::TriangleMesh& mesh) {
  Sphere sphere;
  if (mesh.vertices.empty()) return sphere;
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (const Eigen::Vector3f& vertex : mesh.vertices) sum += vertex;
  sphere.centre = sum / static_cast<float>(mesh.vertices.size());
  for (const Eigen::Vector3f& vertex : mesh.vertices)
    sphere.radius = std::max(sphere.radius, (vertex - sphere.centre).norm());
  return sphere;
}

ImageDisc projectSphere(const Sphere& sphere, const CameraModel& camera) {
  ImageDisc disc;
  const Eigen::Vector4f eye = camera.view * sphere.centre.homogeneous();
  disc.depth = -eye.z();
  disc.in_front = disc.depth > 1e-6f;
  if (!disc.in_front) return disc;
  const Eigen::Vector4f clip = camera.projection * eye;
  disc.centre = clip.head<2>() / clip.w();
  // The image radius of a sphere at this depth (exact at the image centre, close elsewhere).
  const float focal = std::max(camera.projection(0, 0), camera.projection(1, 1));
  disc.radius = focal * sphere.radius / disc.depth;
  return disc;
}

bool projectToPixel(const Eigen::Vector3f& point, const CameraModel& camera, int width, int height,
                    Eigen::Vector2f& pixel) {
  const ImageDisc disc = projectSphere(Sphere{point, 0.f}, camera);
  if (!disc.in_front) return false;
  pixel.x() = (disc.centre.x() + 1.f) * 0.5f * static_cast<float>(width);
  pixel.y() = (1.f - disc.centre.y()) * 0.5f * static_cast<float>(height);
  return true;
}

std::vector<bool> findOccluders(const std::vector<Sphere>& targets,
                                const std::vector<Sphere>& candidates, const CameraModel& camera) {
  std::vector<ImageDisc> target_discs;
  for (const Sphere& target : targets) target_discs.push_back(projectSphere(target, camera));
  std::vector<bool> occludes(candidates.size(), false);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const ImageDisc disc = projectSphere(candidates[c], camera);
    if (!disc.in_front) continue;
    for (std::size_t t = 0; t < targets.size() && !occludes[c]; ++t) {
      const ImageDisc& target = target_discs[t];
      // The candidate's nearest point must lie before the target's centre.
      const bool nearer = disc.depth - candidates[c].radius < target.depth;
      const bool overlap = (disc.centre - target.centre).norm() < disc.radius + target.radius;
      occludes[c] = target.in_front && nearer && overlap;
    }
  }
  return occludes;
}

}  // namespace vicc_anatomy_viz::avatar_view
