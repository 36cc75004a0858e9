#include "vicc_anatomy_viz/status_glyph/glyph_billboard.hpp"

#include <stdexcept>
#include <string>

namespace vicc_anatomy_viz::status_glyph {

namespace {

Eigen::Vector3f pixelColour(const RgbImage& image, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 3;
  return Eigen::Vector3f(image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]) / 255.f;
}

bool isBackground(const Eigen::Vector3f& colour, const BillboardOptions& options) {
  return (colour - options.background).cwiseAbs().maxCoeff() <= options.background_tolerance;
}

}  // namespace

std::vector<ColouredQuad> billboardQuads(const RgbImage& image, const BillboardOptions& options) {
  if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("glyph image is empty");
  if (image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw std::invalid_argument("glyph image buffer has " + std::to_string(image.rgb.size()) +
                                " bytes, not 3 x " + std::to_string(image.width) + " x " +
                                std::to_string(image.height));
  }
  if (!(options.width_m > 0.f)) throw std::invalid_argument("billboard width must be positive");
  const float pixel = options.width_m / static_cast<float>(image.width);
  const Eigen::Vector2f origin(-0.5f * options.width_m, 0.5f * pixel * image.height);
  std::vector<ColouredQuad> quads;
  for (int y = 0; y < image.height; ++y) {
    int x = 0;
    while (x < image.width) {
      const Eigen::Vector3f colour = pixelColour(image, x, y);
      int end = x + 1;
      while (end < image.width && pixelColour(image, end, y) == colour) ++end;
      if (!isBackground(colour, options)) {
        ColouredQuad quad;
        quad.min_corner = origin + Eigen::Vector2f(pixel * x, -pixel * (y + 1));
        quad.max_corner = origin + Eigen::Vector2f(pixel * end, -pixel * y);
        quad.colour = colour;
        quads.push_back(quad);
      }
      x = end;
    }
  }
  return quads;
}

TriangleSoup billboardTriangles(const std::vector<ColouredQuad>& quads,
                                const Eigen::Vector3f& centre, const Eigen::Vector3f& right,
                                const Eigen::Vector3f& up) {
  TriangleSoup soup;
  soup.points.reserve(quads.size() * 6);
  soup.colours.reserve(quads.size() * 6);
  auto at = [&](float u, float v) -> Eigen::Vector3f { return centre + u * right + v * up; };
  for (const auto& quad : quads) {
    const Eigen::Vector3f a = at(quad.min_corner.x(), quad.min_corner.y());
    const Eigen::Vector3f b = at(quad.max_corner.x(), quad.min_corner.y());
    const Eigen::Vector3f c = at(quad.max_corner.x(), quad.max_corner.y());
    const Eigen::Vector3f d = at(quad.min_corner.x(), quad.max_corner.y());
    for (const Eigen::Vector3f& point : {a, b, c, a, c, d}) {
      soup.points.push_back(point);
      soup.colours.push_back(quad.colour);
    }
  }
  return soup;
}

}  // namespace vicc_anatomy_viz::status_glyph
