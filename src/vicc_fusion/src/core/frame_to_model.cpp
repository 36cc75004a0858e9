#include "vicc_fusion/frame_to_model.hpp"

#include <chrono>
#include <stdexcept>

namespace vicc_fusion {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

void FrameToModelConfig::validate() const {
  fusion.validate();
  prediction.validate();
  if (!(min_prediction_coverage >= 0.0 && min_prediction_coverage <= 1.0)) {
    throw std::invalid_argument("frame-to-model: min_prediction_coverage must be in [0, 1]");
  }
}

FrameToModel::FrameToModel(const FrameToModelConfig& config)
    : config_(config), fusion_(config.fusion) {
  config_.prediction.stable_confidence = config_.fusion.stable_confidence;
  config_.validate();
}

void FrameToModel::setFusionConfig(const SurfelFusionConfig& fusion) {
  FrameToModelConfig candidate = config_;
  candidate.fusion = fusion;
  candidate.prediction.stable_confidence = fusion.stable_confidence;
  candidate.validate();
  fusion_.setConfig(fusion);
  config_ = candidate;
}

FrameToModelStep FrameToModel::afterFrame(vicc_tracking::Tracker& tracker,
                                          const vicc_tracking::FrameReport& report,
                                          const cv::Mat1f* intensity) {
  FrameToModelStep step;
  if (!report.accepted || report.state != vicc_tracking::TrackingState::kOk) return step;
  if (report.frame_index == 0) fusion_.reset();  // tracking (re)started: a new map frame
  const vicc_tracking::DepthPyramid& frame = tracker.currentFrame();
  if (frame.empty()) return step;

  step = fuse(frame.front(), report.camera_pose, intensity);

  if (!config_.track_against_model) return step;
  const auto prediction_start = std::chrono::steady_clock::now();
  vicc_tracking::DepthPyramid prediction =
      predictPyramid(fusion_.surfels(), report.camera_pose, frame, tracker.config().preprocessing,
                     config_.prediction);
  const int frame_normals = frame.front().valid_normals;
  step.prediction_coverage =
      frame_normals > 0 ? static_cast<double>(prediction.front().valid_normals) / frame_normals
                        : 0.0;
  if (step.prediction_coverage >= config_.min_prediction_coverage) {
    step.prediction_used = tracker.useModelPrediction(std::move(prediction));
  }
  step.prediction_ms = millisecondsSince(prediction_start);
  return step;
}

FrameToModelStep FrameToModel::fuse(const vicc_tracking::DepthLevel& frame,
                                    const Eigen::Isometry3d& camera_pose,
                                    const cv::Mat1f* intensity) {
  FrameToModelStep step;
  const auto fusion_start = std::chrono::steady_clock::now();
  step.fusion = fusion_.integrate(frame, camera_pose, intensity);
  step.fused = true;
  step.fusion_ms = millisecondsSince(fusion_start);
  return step;
}

}  // namespace vicc_fusion
