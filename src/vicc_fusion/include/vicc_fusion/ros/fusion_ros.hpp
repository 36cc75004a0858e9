#pragma once
// ROS interface of the surfel fusion, shared by the `fusion` node and nodelet. Two modes:
// - track: true (default): the node runs the vicc_tracking tracker itself (same topics and
//   parameters as the tracker node) and fuses every tracked frame in the depth callback; the
//   model prediction goes straight back to the tracker (frame-to-model) without copying a
//   frame. Where the model does not cover the view yet, the tracker stays frame-to-frame.
// - track: false: an external tracker publishes the camera pose on tf (map_frame -> depth
//   frame); the node only fuses, with that pose at each depth stamp.
// Depth comes with the camera_info of its stamp (CameraSubscription: image_transport's
// pairing, unpaired frames warned). With use_intensity each frame takes the gray image of its
// stamp; with track: true a frame waits for it (a few frames at most), and a frame fused
// without its gray image is warned about.
// Both publish the stable model on ~model (PointCloud2, latched, throttled, only with
// subscribers; the final model once the frames stop) and serve ~save_model (binary PLY).

#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>
#include <vicc_msgs/SaveModel.h>

#include "vicc_fusion/frame_to_model.hpp"
#include "vicc_fusion/fusion_parameters.hpp"
#include "vicc_fusion/ros/fusion_reconfigure.hpp"
#include "vicc_tracking/ros/camera_subscription.hpp"
#include "vicc_tracking/ros/latest_state_publisher.hpp"
#include "vicc_tracking/ros/tracker_ros.hpp"

namespace vicc_fusion {

/// Private parameters (the tables of fusion_parameters.hpp, config/fusion.yaml): track,
/// map_frame, publish_rate, pose_queue_size, use_intensity, frame_to_model,
/// min_prediction_coverage, fusion/* (SurfelFusionConfig) and prediction/*
/// (ModelPredictionConfig). Wrong types and invalid values throw naming the parameter; the
/// names read are added to `read_names`.
FusionRosSettings readFusionRosSettings(const ros::NodeHandle& private_nh,
                                        std::set<std::string>& read_names);
FrameToModelConfig readFrameToModelConfig(const ros::NodeHandle& private_nh,
                                          std::set<std::string>& read_names);

class FusionRos {
 public:
  /// Throws std::invalid_argument when a parameter is invalid.
  FusionRos(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  /// Warns about private parameters neither the fusion's nor the tracker's tables know.
  void warnUnknownParameters(const ros::NodeHandle& private_nh);
  void onTrackedFrame(vicc_tracking::Tracker& tracker, const vicc_tracking::FrameReport& report,
                      const sensor_msgs::Image& depth, const Eigen::Isometry3d& map_alignment);
  /// The preprocessor's calibration: the undistortion of the gray image (track: false: of the
  /// depth too).
  void useCamera(const vicc_tracking::CameraModel& camera);
  void onCameraFrame(const sensor_msgs::ImageConstPtr& depth,
                     const sensor_msgs::CameraInfoConstPtr& info);
  void onDepth(const sensor_msgs::ImageConstPtr& depth);
  void onIntensity(const sensor_msgs::ImageConstPtr& gray);
  /// track: true: whether the frame at `stamp` may go: its gray image (or a later one) arrived,
  /// or none is coming (no gray image yet, or none for half a second).
  bool grayImageArrived(const ros::Time& stamp) const;
  /// The gray image with the depth's stamp on the depth's undistorted grid; nullopt if none
  /// arrived (the frame is then fused without intensity) or it is unusable (both warned).
  std::optional<cv::Mat1f> intensityFor(const ros::Time& stamp);
  void warnNoGrayImage(const ros::Time& stamp);
  std::string depthTopic() const;
  void afterFusion(const FusionFrameStats& stats, const ros::Time& stamp);
  bool onSaveModel(vicc_msgs::SaveModel::Request& request,
                   vicc_msgs::SaveModel::Response& response);

  std::set<std::string> parameter_names_;  // every parameter read in the private namespace
  FusionRosSettings settings_;
  FrameToModel model_;
  std::unique_ptr<FusionReconfigure> reconfigure_;  ///< ~fusion thresholds while running
  std::string frame_id_;                            ///< frame of the published model
  Eigen::Isometry3d model_to_frame_ = Eigen::Isometry3d::Identity();
  bool warned_full_ = false;

  // track: true
  std::unique_ptr<vicc_tracking::TrackerRos> tracker_;
  // use_intensity: recent gray images (a few frames), and the preprocessor that undistorts
  // them (track: false uses it for the depth too)
  std::deque<sensor_msgs::ImageConstPtr> recent_gray_;
  std::optional<ros::Time> first_gray_, latest_gray_;
  int frames_before_any_gray_ = 0;
  ros::Subscriber intensity_sub_;
  std::unique_ptr<vicc_tracking::DepthPreprocessor> preprocessor_;
  std::optional<vicc_tracking::CameraModel> camera_;
  // track: false
  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  /// depth/image (~image_transport selects the transport) + the camera_info beside it
  std::unique_ptr<vicc_tracking::CameraSubscription> camera_sub_;
  /// Paired depth frames wait here for their pose on tf; their camera_info beside them.
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::Image>> depth_pose_filter_;
  std::deque<sensor_msgs::CameraInfoConstPtr> waiting_infos_;

  ros::Publisher model_pub_;
  /// The stable model on model_pub_: throttled to publish_rate while frames arrive, the final
  /// one once they stop (also to a subscriber that connects after the replay); null if
  /// publish_rate <= 0.
  std::unique_ptr<vicc_tracking::LatestStatePublisher> model_publication_;
  ros::ServiceServer save_service_;
};

}  // namespace vicc_fusion
