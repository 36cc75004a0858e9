#pragma once
// Which unencoded structures hide an encoded one from the current camera (thesis 4.4.2.2,
// Fig. 4.3), decided per frame on bounding spheres projected to the image: a candidate in
// front of a target whose image disc overlaps the target's disc occludes it. The skin is
// handled per pixel by the renderer (see AvatarVisual); this test picks the inner structures
// that are faded.

#include <Eigen/Core>

#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar_view {

struct Sphere {
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float radius = 0.f;
};

/// Centre of the vertices and the largest distance to it; radius 0 for an empty mesh.
Sphere boundingSphere(const avatar::TriangleMesh& mesh);

/// A camera as the renderer has it: world -> eye (OpenGL convention, looking down -z) and
/// eye -> clip.
struct CameraModel {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
};

/// A sphere's image: centre and radius in normalised device coordinates, distance along the
/// viewing direction of its centre; in_front false when the centre is behind the camera.
struct ImageDisc {
  Eigen::Vector2f centre = Eigen::Vector2f::Zero();
  float radius = 0.f;
  float depth = 0.f;
  bool in_front = false;
};

ImageDisc projectSphere(const Sphere& sphere, const CameraModel& camera);

/// Pixel position (x right, y down, origin top-left) of a world point, false when behind.
bool projectToPixel(const Eigen::Vector3f& point, const CameraModel& camera, int width, int height,
                    Eigen::Vector2f& pixel);

/// For every candidate: does it occlude at least one target?
std::vector<bool> findOccluders(const std::vector<Sphere>& targets,
                                const std::vector<Sphere>& candidates, const CameraModel& camera);

}  // namespace vicc_anatomy_viz::avatar_view
