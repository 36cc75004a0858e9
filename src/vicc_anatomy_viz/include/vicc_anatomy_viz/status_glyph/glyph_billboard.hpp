#pragma once
// A glyph image as flat-coloured quads for a visualization_msgs TRIANGLE_LIST marker: rviz's
// stock markers cannot texture a quad, so each run of equal pixels in a row becomes one
// rectangle. Background pixels are left out (the glyph floats). ROS- and Qt-free.

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace vicc_anatomy_viz::status_glyph {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< row-major, 3 bytes per pixel
};

struct ColouredQuad {
  /// Corners in the billboard plane, metres: u to the viewer's right, v up; centre at 0.
  Eigen::Vector2f min_corner, max_corner;
  Eigen::Vector3f colour;  ///< linear 0..1 RGB as stored in the image
};

struct BillboardOptions {
  float width_m = 0.2f;                 ///< the image's width in the scene (height keeps aspect)
  Eigen::Vector3f background{1, 1, 1};  ///< this colour is left out ...
  float background_tolerance = 0.04f;   ///< ... within this per-channel distance
};

/// Throws std::invalid_argument for an empty image or a buffer of the wrong size.
std::vector<ColouredQuad> billboardQuads(const RgbImage& image, const BillboardOptions& options);

/// Two triangles per quad in the plane through `centre` spanned by `right` and `up` (unit
/// vectors): 6 points and 6 colours per quad, counter-clockwise seen from right x up.
struct TriangleSoup {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> colours;
};
TriangleSoup billboardTriangles(const std::vector<ColouredQuad>& quads,
                                const Eigen::Vector3f& centre, const Eigen::Vector3f& right,
                                const Eigen::Vector3f& up);

}  // namespace vicc_anatomy_viz::status_glyph
