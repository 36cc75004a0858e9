#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "vicc_tracking/depth_preprocessing.hpp"
#include "vicc_tracking/sim/rig_simulator.hpp"

using namespace vicc_tracking;

namespace {

TEST(DepthPreprocessingTest, MillimetresAndMetresGiveTheSameDepthAndInvalidBecomesZero) {
  cv::Mat1w millimetres(2, 3, static_cast<uint16_t>(1234));
  millimetres(0, 1) = 0;
  const cv::Mat1f from_mm = toMetricDepth(millimetres);
  EXPECT_FLOAT_EQ(from_mm(0, 0), 1.234f);
  EXPECT_FLOAT_EQ(from_mm(0, 1), 0.f);
  cv::Mat1f metres(2, 3, 1.234f);
  metres(0, 0) = std::numeric_limits<float>::quiet_NaN();
  metres(0, 1) = std::numeric_limits<float>::infinity();
  metres(0, 2) = -std::numeric_limits<float>::infinity();
  const cv::Mat1f cleaned = toMetricDepth(metres);
  EXPECT_FLOAT_EQ(cleaned(0, 0), 0.f);
  EXPECT_FLOAT_EQ(cleaned(0, 1), 0.f);
  EXPECT_FLOAT_EQ(cleaned(0, 2), 0.f);
  EXPECT_FLOAT_EQ(cleaned(1, 1), 1.234f);
  EXPECT_THROW(toMetricDepth(cv::Mat3b(2, 2)), std::invalid_argument);
}

/// Undistortion round trip: a distorted rendering of a known scene, preprocessed, gives
/// vertices on the true surface.
TEST(DepthPreprocessingTest, DistortedRenderingUndistortsOntoTheTrueSurface) {
  const sim::RigSimulator rig(sim::loadScenario("short_test"));
  for (const auto model : {DistortionModel::kPlumbBob, DistortionModel::kEquidistant}) {
    sim::Scenario scenario = rig.scenario();
    scenario.camera.model = model;
    if (model == DistortionModel::kEquidistant)
      scenario.camera.distortion = {0.05, -0.01, 0.002, 0.0};
    const sim::RigSimulator distorted_rig(scenario);
    PreprocessingConfig config;
    config.bilateral_filter = false;
    config.pyramid_levels = 3;
    DepthPreprocessor preprocessor(config);
    preprocessor.setCamera(scenario.camera);
    const double t = 3.2;
    const DepthPyramid pyramid = preprocessor.process(distorted_rig.renderDepthNoiseFree(t));
    ASSERT_EQ(pyramid.size(), 3u);
    EXPECT_EQ(pyramid[1].intrinsics.width, 112);
    EXPECT_EQ(pyramid[2].intrinsics.height, 42);
    const Eigen::Isometry3d pose = distorted_rig.cameraPose(t);
    const DepthLevel& level = pyramid[0];
    int checked = 0;
    double worst = 0.0;
    for (size_t i = 0; i < level.vertices.size(); i += 7) {
      if (!level.hasVertex(static_cast<int>(i))) continue;
      const Eigen::Vector3d point = pose * level.vertices[i].cast<double>();
      const Eigen::Vector3d direction = point - pose.translation();
      const auto hit = distorted_rig.scene().raycast(pose.translation(), direction);
      ASSERT_TRUE(hit.has_value());
      worst = std::max(worst, std::abs(1.0 - *hit) * direction.norm());
      ++checked;
    }
    EXPECT_GT(checked, 2000);
    EXPECT_LT(worst, 1e-4) << "metres off the surface, model " << toString(model);
    EXPECT_GT(level.valid_normals, level.valid_vertices * 8 / 10);
  }
}

TEST(DepthPreprocessingTest, NormalsOfATiltedPlaneEverywhereInsideAndNoneOnEdgesOrBorders) {
  // The plane n.X = d seen by a pinhole camera: depth z(u, v) = d / (n . ray(u, v)). Its
  // normal (facing the camera) must come out at every interior pixel, including the last
  // columns (the normals are computed four pixels at a time), and nowhere on the border,
  // at holes or across a depth edge.
  PinholeIntrinsics k;
  k.width = 37;  // not a multiple of four
  k.height = 11;
  k.fx = k.fy = 30.f;
  k.cx = 18.f;
  k.cy = 5.f;
  const Eigen::Vector3f plane_normal = Eigen::Vector3f(0.3f, -0.2f, -1.f).normalized();
  const float plane_distance = -0.8f;  // n . X = d with X at about 0.8 m
  cv::Mat1f depth(k.height, k.width);
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const Eigen::Vector3f ray((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.f);
      depth(v, u) = plane_distance / plane_normal.dot(ray);
    }
  }
  depth(5, 10) = 0.f;    // a hole: it and its four neighbours have no normal
  depth(2, 30) += 0.5f;  // a jump: pixels whose differences span it have none
  const DepthLevel level = computeDepthLevel(depth, k, 0.05);
  int normals = 0;
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const int i = v * k.width + u;
      const bool border = u == 0 || v == 0 || u == k.width - 1 || v == k.height - 1;
      const bool near_hole = std::abs(u - 10) + std::abs(v - 5) <= 1;
      const bool across_jump =
          (v == 2 && std::abs(u - 30) == 1) || (u == 30 && std::abs(v - 2) == 1);
      if (border || near_hole || across_jump) {
        EXPECT_FALSE(level.hasNormal(i)) << u << "," << v;
        continue;
      }
      if (u == 30 && v == 2) continue;  // the jump pixel itself: a normal of its own level
      ASSERT_TRUE(level.hasNormal(i)) << u << "," << v;
      EXPECT_NEAR(level.normals[i].dot(plane_normal), 1.f, 1e-4f) << u << "," << v;
      EXPECT_GT(level.radii[i], 0.f);
      ++normals;
    }
  }
  EXPECT_EQ(level.valid_normals, normals + (level.hasNormal(2 * k.width + 30) ? 1 : 0));
}

TEST(DepthPreprocessingTest, WrongSizeOrTypeThrows) {
  DepthPreprocessor preprocessor{PreprocessingConfig{}};
  preprocessor.setCamera(sim::picoFlexxCamera());
  EXPECT_THROW(preprocessor.process(cv::Mat1f(10, 10, 1.f)), std::invalid_argument);
  EXPECT_THROW(preprocessor.process(cv::Mat3b(171, 224)), std::invalid_argument);
}

/// The gray image follows the depth: a depth and a gray image both encoding their sensor
/// pixel's index land on the same pinhole pixels, for both distortion models and all types.
TEST(DepthPreprocessingTest, IntensityLandsWhereTheDepthOfTheSameSensorPixelLands) {
  for (const auto model : {DistortionModel::kPlumbBob, DistortionModel::kEquidistant}) {
    CameraModel camera = sim::picoFlexxCamera();
    camera.model = model;
    camera.distortion = model == DistortionModel::kEquidistant
                            ? std::vector<double>{0.05, -0.01, 0.002, 0.0}
                            : std::vector<double>{-0.1, 0.05, 0.001, -0.001, 0.0};
    ASSERT_TRUE(camera.hasDistortion());
    PreprocessingConfig config;
    config.bilateral_filter = false;
    config.pyramid_levels = 1;
    DepthPreprocessor preprocessor(config);
    preprocessor.setCamera(camera);
    const int width = camera.width, height = camera.height;
    cv::Mat1f depth(height, width);
    cv::Mat1w gray16(height, width);
    cv::Mat1b gray8(height, width);
    cv::Mat1f gray32(height, width);
    for (int v = 0; v < height; ++v) {
      for (int u = 0; u < width; ++u) {
        const int index = v * width + u;
        depth(v, u) = 0.5f + 1e-5f * static_cast<float>(index);
        gray16(v, u) = static_cast<uint16_t>(index);
        gray8(v, u) = static_cast<uint8_t>((u + 3 * v) % 256);
        gray32(v, u) = static_cast<float>(index);
      }
    }
    gray32(0, 0) = std::numeric_limits<float>::infinity();
    const DepthLevel level = preprocessor.process(depth).front();
    const cv::Mat1f undistorted16 = preprocessor.undistortIntensity(gray16);
    const cv::Mat1f undistorted8 = preprocessor.undistortIntensity(gray8);
    const cv::Mat1f undistorted32 = preprocessor.undistortIntensity(gray32);
    ASSERT_EQ(undistorted16.rows, level.depth.rows);
    ASSERT_EQ(undistorted16.cols, level.depth.cols);
    int valid = 0, moved = 0;
    for (int v = 0; v < height; ++v) {
      for (int u = 0; u < width; ++u) {
        const float d = level.depth(v, u);
        if (d <= 0.f) {  // unmapped: no sensor pixel, no gray
          EXPECT_TRUE(std::isnan(undistorted16(v, u))) << u << "," << v;
          EXPECT_TRUE(std::isnan(undistorted8(v, u))) << u << "," << v;
          continue;
        }
        const int index = static_cast<int>(std::lround((d - 0.5f) / 1e-5f));
        const int su = index % width, sv = index / width;
        ASSERT_NEAR(undistorted16(v, u) * 65535.f, static_cast<float>(index), 0.02f)
            << u << "," << v;
        EXPECT_NEAR(undistorted8(v, u) * 255.f, static_cast<float>((su + 3 * sv) % 256), 1e-3f);
        if (index == 0) {
          EXPECT_TRUE(std::isnan(undistorted32(v, u)));
        } else {
          EXPECT_EQ(undistorted32(v, u), static_cast<float>(index));
        }
        ++valid;
        if (su != u || sv != v) ++moved;
      }
    }
    EXPECT_GT(valid, width * height * 8 / 10);
    EXPECT_GT(moved, valid / 2) << "the distortion should move most pixels";
  }
}

TEST(DepthPreprocessingTest, IntensityOfWrongSizeOrTypeThrowsAndWithoutDistortionIsScaledOnly) {
  DepthPreprocessor preprocessor{PreprocessingConfig{}};
  EXPECT_THROW(preprocessor.undistortIntensity(cv::Mat1w(171, 224)), std::logic_error);
  CameraModel camera = sim::picoFlexxCamera();
  camera.distortion.assign(camera.distortion.size(), 0.0);
  ASSERT_FALSE(camera.hasDistortion());
  preprocessor.setCamera(camera);
  EXPECT_THROW(preprocessor.undistortIntensity(cv::Mat1w(10, 10)), std::invalid_argument);
  EXPECT_THROW(preprocessor.undistortIntensity(cv::Mat1w(224, 171)), std::invalid_argument);
  EXPECT_THROW(preprocessor.undistortIntensity(cv::Mat3b(171, 224)), std::invalid_argument);
  EXPECT_THROW(preprocessor.undistortIntensity(cv::Mat1d(171, 224)), std::invalid_argument);
  cv::Mat1w gray(171, 224, static_cast<uint16_t>(65535));
  gray(5, 7) = 0;
  const cv::Mat1f scaled = preprocessor.undistortIntensity(gray);
  EXPECT_FLOAT_EQ(scaled(0, 0), 1.f);
  EXPECT_FLOAT_EQ(scaled(5, 7), 0.f);
}

TEST(CameraModelTest, ProjectUnprojectRoundTripOverTheWholeImage) {
  for (const auto model : {DistortionModel::kPlumbBob, DistortionModel::kEquidistant}) {
    CameraModel camera = sim::picoFlexxCamera();
    camera.model = model;
    if (model == DistortionModel::kEquidistant) camera.distortion = {0.05, -0.01, 0.002, 0.0};
    double worst = 0.0;
    for (int v = 0; v < camera.height; v += 5) {
      for (int u = 0; u < camera.width; u += 5) {
        const Eigen::Vector2d ray = camera.unprojectToNormalized(Eigen::Vector2d(u, v));
        const Eigen::Vector2d back = camera.project(Eigen::Vector3d(ray.x(), ray.y(), 1.0));
        worst = std::max(worst, (back - Eigen::Vector2d(u, v)).norm());
      }
    }
    EXPECT_LT(worst, 1e-3) << toString(model);
  }
}

TEST(CameraModelTest, ValidateNamesTheBadField) {
  CameraModel camera = sim::picoFlexxCamera();
  camera.fy = -1.0;
  try {
    camera.validate();
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("fy"), std::string::npos) << error.what();
  }
}

}  // namespace
