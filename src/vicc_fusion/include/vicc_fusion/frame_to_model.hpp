#pragma once
// The hand-over between tracking and fusion that the offline tool and the fusion node share:
// fuse each tracked frame into the surfel model, render the model at the new pose and give
// the prediction to the tracker as the next ICP reference (frame-to-model, thesis 2.2.2).
// Before the model covers enough of the view, the tracker stays frame-to-frame.

#include "vicc_fusion/model_prediction.hpp"
#include "vicc_fusion/surfel_fusion.hpp"
#include "vicc_tracking/tracker.hpp"

namespace vicc_fusion {

struct FrameToModelConfig {
  SurfelFusionConfig fusion;
  /// Its stable_confidence is taken from `fusion`: the tracker aligns to the stable model.
  ModelPredictionConfig prediction;
  bool track_against_model = true;  ///< false: fuse only, track frame-to-frame
  /// The prediction replaces the last frame only if it has at least this share of the
  /// frame's valid normals.
  double min_prediction_coverage = 0.5;
  void validate() const;
};

struct FrameToModelStep {
  bool fused = false;            ///< false for lost or untracked frames
  bool prediction_used = false;  ///< the next frame aligns to the model
  double prediction_coverage = 0.0;
  FusionFrameStats fusion;
  double fusion_ms = 0.0;
  double prediction_ms = 0.0;
};

class FrameToModel {
 public:
  explicit FrameToModel(const FrameToModelConfig& config);

  /// Call after every tracker.addDepth(): fuses tracker.currentFrame() at report.camera_pose
  /// and hands the model prediction to the tracker. Resets the model when tracking restarts
  /// (a new map, e.g. after a clock jump).
  FrameToModelStep afterFrame(vicc_tracking::Tracker& tracker,
                              const vicc_tracking::FrameReport& report,
                              const cv::Mat1f* intensity = nullptr);

  /// Fusion alone, for poses from elsewhere (an external tracker): no prediction.
  FrameToModelStep fuse(const vicc_tracking::DepthLevel& frame,
                        const Eigen::Isometry3d& camera_pose, const cv::Mat1f* intensity = nullptr);

  const SurfelFusion& fusion() const { return fusion_; }
  const FrameToModelConfig& config() const { return config_; }
  void reset() { fusion_.reset(); }
  /// New fusion thresholds while running (the prediction's stable_confidence follows).
  /// Throws std::invalid_argument; nothing changes then.
  void setFusionConfig(const SurfelFusionConfig& fusion);

 private:
  FrameToModelConfig config_;
  SurfelFusion fusion_;
};

}  // namespace vicc_fusion
