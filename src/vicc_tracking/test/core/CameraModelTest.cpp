#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "vicc_tracking/camera_model.hpp"
#include "vicc_tracking/depth_preprocessing.hpp"

using namespace vicc_tracking;

namespace {

CameraModel picoFlexx() {
  CameraModel camera;
  camera.width = 224;
  camera.height = 171;
  camera.fx = 210.0;
  camera.fy = 210.0;
  camera.cx = 111.5;
  camera.cy = 85.5;
  camera.model = DistortionModel::kPlumbBob;
  camera.distortion = {-0.12, 0.03, 0.0005, -0.0003, 0.0};
  return camera;
}

/// One recalibration per field: the camera-change test of every node must see each of them.
std::vector<std::pair<std::string, std::function<void(CameraModel&)>>> recalibrations() {
  return {
      {"width", [](CameraModel& c) { c.width = 112; }},
      {"height", [](CameraModel& c) { c.height = 86; }},
      {"fx", [](CameraModel& c) { c.fx += 0.5; }},
      {"fy", [](CameraModel& c) { c.fy += 0.5; }},
      {"cx", [](CameraModel& c) { c.cx += 0.25; }},
      {"cy", [](CameraModel& c) { c.cy -= 0.25; }},
      {"D", [](CameraModel& c) { c.distortion[1] = 0.031; }},
      {"D length", [](CameraModel& c) { c.distortion.pop_back(); }},
      {"distortion model",
       [](CameraModel& c) {
         c.model = DistortionModel::kEquidistant;
         c.distortion = {-0.12, 0.03, 0.0005, -0.0003};
       }},
  };
}

TEST(CameraModelTest, EqualityDetectsAChangeOfEveryCalibrationValue) {
  const CameraModel reference = picoFlexx();
  EXPECT_TRUE(reference == picoFlexx());
  EXPECT_FALSE(reference != picoFlexx());
  for (const auto& [field, change] : recalibrations()) {
    CameraModel changed = picoFlexx();
    change(changed);
    EXPECT_FALSE(reference == changed) << field;
    EXPECT_TRUE(reference != changed) << field;
  }
}

TEST(CameraModelTest, PreprocessorTakesEveryRecalibration) {
  PreprocessingConfig config;
  config.pyramid_levels = 1;
  for (const auto& [field, change] : recalibrations()) {
    DepthPreprocessor preprocessor(config);
    preprocessor.setCamera(picoFlexx());
    CameraModel changed = picoFlexx();
    change(changed);
    preprocessor.setCamera(changed);
    EXPECT_TRUE(preprocessor.camera() == changed) << field;
  }
}

}  // namespace
