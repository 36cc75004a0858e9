// The pain trigger's normal-perturbation relief (the formulas the display's fragment program
// runs): which states get it, the bump field, the tilt per level, that it reads as relief at
// whole-body scale under rviz's head light, and that the category's hue survives it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"

namespace vicc_anatomy_viz::avatar_view {
namespace {

constexpr float kPi = 3.14159265f;

/// The encoding's pain trigger (config/encoding: frequency 6, amplitude 0.6, one level).
TextureState trigger() { return {TextureKind::kNormalPerturbation, 1, 1, 6.f, 0.6f}; }

float hueDegrees(const Eigen::Vector3f& rgb) {
  const float max = rgb.maxCoeff(), min = rgb.minCoeff(), range = max - min;
  if (range <= 0.f) return 0.f;
  float hue = 0.f;
  if (max == rgb.x())
    hue = std::fmod((rgb.y() - rgb.z()) / range, 6.f);
  else if (max == rgb.y())
    hue = (rgb.z() - rgb.x()) / range + 2.f;
  else
    hue = (rgb.x() - rgb.y()) / range + 4.f;
  hue *= 60.f;
  return hue < 0.f ? hue + 360.f : hue;
}

float saturation(const Eigen::Vector3f& rgb) {
  return rgb.maxCoeff() > 0.f ? (rgb.maxCoeff() - rgb.minCoeff()) / rgb.maxCoeff() : 0.f;
}

float hueDistance(float a, float b) {
  const float d = std::fabs(a - b);
  return std::min(d, 360.f - d);
}

/// The front of a shank (a vertical cylinder of 5 cm radius at x = 0, y = 0), sampled every
/// 2 mm (one pixel of the whole-body snapshot) over 6 x 6 cm, lit by rviz's head light from
/// the camera in front (+x), shaded in a category colour; the luminances, row by row.
std::vector<std::vector<float>> frontOfShank(const ReliefParameters& relief,
                                             const Eigen::Vector3f& colour) {
  ReliefLighting lighting;
  lighting.ambient_light = Eigen::Vector3f::Constant(0.3f);
  lighting.to_light = lighting.to_eye = Eigen::Vector3f::UnitX();
  std::vector<std::vector<float>> rows;
  for (float z = 0.20f; z < 0.26f; z += 0.002f) {
    rows.emplace_back();
    for (float y = -0.03f; y < 0.03f; y += 0.002f) {
      const Eigen::Vector3f point(std::sqrt(0.05f * 0.05f - y * y), y, z);
      const Eigen::Vector3f normal = Eigen::Vector3f(point.x(), point.y(), 0.f).normalized();
      const Eigen::Vector3f shaded = shadeRelief(
          colour, 0.6f * colour, perturbedNormal(point, normal, relief), lighting, relief);
      rows.back().push_back(shaded.dot(Eigen::Vector3f(0.299f, 0.587f, 0.114f)));
    }
  }
  return rows;
}

/// Mean absolute luminance step between neighbouring pixels: what the eye reads as texture.
float pixelContrast(const std::vector<std::vector<float>>& rows) {
  float sum = 0.f;
  int count = 0;
  for (std::size_t r = 0; r + 1 < rows.size(); ++r)
    for (std::size_t c = 0; c + 1 < rows[r].size(); ++c) {
      sum += std::fabs(rows[r][c + 1] - rows[r][c]) + std::fabs(rows[r + 1][c] - rows[r][c]);
      count += 2;
    }
  return sum / static_cast<float>(count);
}

TEST(ReliefShadingTest, OnlyTheNormalPerturbationIsARelief) {
  EXPECT_FALSE(reliefParameters({}).active());
  EXPECT_FALSE(reliefParameters({TextureKind::kNoise, 3, 3, 16.f, 1.f}).active());
  EXPECT_FALSE(reliefParameters({TextureKind::kNormalPerturbation, 0, 1, 6.f, 0.6f}).active());
  EXPECT_FALSE(reliefParameters({TextureKind::kNormalPerturbation, 1, 1, NAN, 0.6f}).active());
  const ReliefParameters relief = reliefParameters(trigger());
  ASSERT_TRUE(relief.active());
  // Six bumps per decimetre: one bump (half a sine period) every 1/60 m.
  EXPECT_NEAR(kPi / relief.wavenumber, 1.f / 60.f, 1e-6f);
}

TEST(ReliefShadingTest, TheGradientIsThatOfTheBumpField) {
  const float k = reliefParameters(trigger()).wavenumber;
  const float h = 1e-5f;
  for (const Eigen::Vector3f& point :
       {Eigen::Vector3f(0.01f, 0.02f, 0.7f), Eigen::Vector3f(0.13f, -0.2f, 0.31f),
        Eigen::Vector3f(-0.05f, 0.011f, 1.2f)}) {
    const Eigen::Vector3f gradient = normalisedBumpGradient(point, k);
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3f step = h * Eigen::Vector3f::Unit(axis);
      const float numeric = (bumpHeight(point + step, k) - bumpHeight(point - step, k)) / (2 * h);
      EXPECT_NEAR(gradient[axis] * k, numeric, 0.02f * k) << axis;
    }
    EXPECT_LE(gradient.norm(), 2.f + 1e-4f);
  }
}

TEST(ReliefShadingTest, TheTiltGrowsWithTheLevelAndStaysBelowSixtyDegrees) {
  float previous_mean = 0.f;
  for (int level = 1; level <= 3; ++level) {
    const ReliefParameters relief =
        reliefParameters({TextureKind::kNormalPerturbation, level, 3, 6.f, 1.f});
    float sum = 0.f, steepest = 0.f;
    int count = 0;
    const Eigen::Vector3f normal = Eigen::Vector3f(1.f, 0.3f, 0.1f).normalized();
    for (float a = 0.f; a < 0.1f; a += 0.0013f)
      for (float b = 0.f; b < 0.1f; b += 0.0017f) {
        const Eigen::Vector3f point = Eigen::Vector3f(0.2f, 0.f, 0.5f) +
                                      a * normal.unitOrthogonal() +
                                      b * normal.cross(normal.unitOrthogonal());
        const float tilt =
            std::acos(std::clamp(perturbedNormal(point, normal, relief).dot(normal), -1.f, 1.f));
        sum += tilt;
        steepest = std::max(steepest, tilt);
        ++count;
      }
    const float mean_deg = sum / count * 180.f / kPi;
    EXPECT_GT(mean_deg, previous_mean + 3.f) << "level " << level;
    EXPECT_LT(steepest * 180.f / kPi, 60.f) << "level " << level;
    previous_mean = mean_deg;
  }
  EXPECT_GT(previous_mean, 15.f);
}

TEST(ReliefShadingTest, TheReliefReadsAtWholeBodyScaleUnderTheHeadLight) {
  const Eigen::Vector3f red(0.8f, 0.1f, 0.1f);
  const float flat = pixelContrast(frontOfShank({}, red));
  const float relief = pixelContrast(frontOfShank(reliefParameters(trigger()), red));
  // A smooth cylinder changes by well under a grey level per pixel; the bumps by several.
  EXPECT_LT(flat, 0.005f);
  EXPECT_GT(relief, 0.03f);
}

TEST(ReliefShadingTest, TheCategoryHueSurvivesTheRelief) {
  const ReliefParameters relief = reliefParameters(trigger());
  ReliefLighting lighting;
  lighting.ambient_light = Eigen::Vector3f::Constant(0.3f);
  lighting.to_eye = Eigen::Vector3f::UnitX();
  lighting.to_light = Eigen::Vector3f(1.f, 0.2f, 0.3f).normalized();
  // Pain red, paresis purple, sensory cyan (the encoding's hues, strong levels).
  for (const Eigen::Vector3f& colour :
       {Eigen::Vector3f(0.62f, 0.05f, 0.05f), Eigen::Vector3f(0.45f, 0.1f, 0.62f),
        Eigen::Vector3f(0.05f, 0.55f, 0.6f)}) {
    for (float y = -0.03f; y < 0.03f; y += 0.0011f)
      for (float z = 0.2f; z < 0.26f; z += 0.0013f) {
        const Eigen::Vector3f point(0.05f, y, z);
        const Eigen::Vector3f shaded =
            shadeRelief(colour, 0.6f * colour,
                        perturbedNormal(point, Eigen::Vector3f::UnitX(), relief), lighting, relief);
        ASSERT_LE(shaded.maxCoeff(), 1.f);  // no clipping that would shift the hue
        EXPECT_LT(hueDistance(hueDegrees(shaded), hueDegrees(colour)), 2.f);
        EXPECT_GT(saturation(shaded), 0.5f * saturation(colour));
      }
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar_view
