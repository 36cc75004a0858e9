#include "vicc_fusion/ros/fusion_ros.hpp"

#include <algorithm>
#include <stdexcept>

#include "vicc_common/parameter_names.hpp"
#include "vicc_common/ros_parameters.hpp"
#include "vicc_fusion/ros/surfel_cloud.hpp"
#include "vicc_fusion/surfel_io.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/ros/parameters.hpp"

namespace vicc_fusion {
namespace {

constexpr double kWarnPeriod = 5.0;  // s between repeated warnings

}  // namespace

FusionRosSettings readFusionRosSettings(const ros::NodeHandle& private_nh,
                                        std::set<std::string>& read_names) {
  FusionRosSettings settings;
  vicc_common::readRosParameters(private_nh, settings, read_names);
  return settings;
}

FrameToModelConfig readFrameToModelConfig(const ros::NodeHandle& private_nh,
                                          std::set<std::string>& read_names) {
  FrameToModelConfig config;
  vicc_common::readRosParameters(private_nh, config, read_names);
  return config;
}

void FusionRos::warnUnknownParameters(const ros::NodeHandle& private_nh) {
  // The tracker's node settings are known in both modes: track: false loads tracker.yaml too.
  std::set<std::string> node_keys;
  vicc_common::collectParameterNames(vicc_tracking::TrackerNodeSettings{}, node_keys);
  for (const std::string& key : node_keys) parameter_names_.insert(private_nh.resolveName(key));
  vicc_common::warnUnknownRosParameters(private_nh, parameter_names_);
}

FusionRos::FusionRos(ros::NodeHandle& nh, ros::NodeHandle& private_nh)
    : settings_(readFusionRosSettings(private_nh, parameter_names_)),
      model_(readFrameToModelConfig(private_nh, parameter_names_)),
      reconfigure_(std::make_unique<FusionReconfigure>(ros::NodeHandle(private_nh, "fusion"),
                                                       "fusion", model_.config().fusion)) {
  model_pub_ = private_nh.advertise<sensor_msgs::PointCloud2>("model", 1, true);
  if (settings_.publish_rate > 0.0) {
    model_publication_ = std::make_unique<vicc_tracking::LatestStatePublisher>(
        private_nh, model_pub_, 1.0 / settings_.publish_rate, [this](const ros::Time& stamp) {
          model_pub_.publish(
              toPointCloud2(model_.fusion().stableSurfels(), model_to_frame_, frame_id_, stamp));
        });
  }
  save_service_ = private_nh.advertiseService("save_model", &FusionRos::onSaveModel, this);
  vicc_tracking::PreprocessingConfig preprocessing =
      vicc_tracking::readTrackerConfig(private_nh, parameter_names_).preprocessing;
  warnUnknownParameters(private_nh);
  preprocessing.pyramid_levels = 1;
  if (!settings_.track || settings_.use_intensity) {
    preprocessor_ = std::make_unique<vicc_tracking::DepthPreprocessor>(preprocessing);
  }
  if (settings_.use_intensity) {
    intensity_sub_ = nh.subscribe("intensity/image", 5, &FusionRos::onIntensity, this);
    ROS_INFO("fusion: surfel intensity from %s", intensity_sub_.getTopic().c_str());
  }
  if (settings_.track) {
    tracker_ = std::make_unique<vicc_tracking::TrackerRos>(
        nh, private_nh, vicc_tracking::TrackerRos::UnknownParameters::kLeaveToOwner);
    frame_id_ = tracker_->settings().map_frame;
    tracker_->setFrameHook(
        [this](vicc_tracking::Tracker& tracker, const vicc_tracking::FrameReport& report,
               const sensor_msgs::Image& depth, const Eigen::Isometry3d& map_alignment) {
          onTrackedFrame(tracker, report, depth, map_alignment);
        });
    if (settings_.use_intensity) {
      tracker_->setFrameGate([this](const ros::Time& stamp) { return grayImageArrived(stamp); });
    }
    ROS_INFO("fusion: tracking %s against the model, publishing ~model in %s",
             model_.config().track_against_model ? "frame-to-model" : "frame-to-frame",
             frame_id_.c_str());
    return;
  }
  frame_id_ = settings_.map_frame;
  tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_);
  // Paired depth frames wait in the message filter until their pose is on tf.
  depth_pose_filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::Image>>(
      *tf_buffer_, frame_id_, settings_.pose_queue_size, nh);
  depth_pose_filter_->registerCallback(&FusionRos::onDepth, this);
  depth_pose_filter_->registerFailureCallback(
      [](const sensor_msgs::ImageConstPtr& depth,
         tf2_ros::filter_failure_reasons::FilterFailureReason) {
        ROS_WARN_THROTTLE(kWarnPeriod,
                          "fusion: no pose on tf for the depth frame at %.3f (%s); not fused",
                          depth->header.stamp.toSec(), depth->header.frame_id.c_str());
      });
  // Depth through image_transport (raw, or e.g. compressedDepth with ~image_transport).
  camera_sub_ = std::make_unique<vicc_tracking::CameraSubscription>(
      nh, "depth/image", settings_.pose_queue_size,
      image_transport::TransportHints("raw", ros::TransportHints(), private_nh), "fusion",
      [this](const sensor_msgs::ImageConstPtr& depth, const sensor_msgs::CameraInfoConstPtr& info) {
        onCameraFrame(depth, info);
      });
  ROS_INFO("fusion: fusing %s (camera_info on %s) with the poses on tf (%s -> depth frame)",
           camera_sub_->imageTopic().c_str(), camera_sub_->infoTopic().c_str(), frame_id_.c_str());
}

void FusionRos::onTrackedFrame(vicc_tracking::Tracker& tracker,
                               const vicc_tracking::FrameReport& report,
                               const sensor_msgs::Image& depth,
                               const Eigen::Isometry3d& map_alignment) {
  if (const auto tuning = reconfigure_->takeChange()) model_.setFusionConfig(*tuning);
  try {
    if (preprocessor_) useCamera(tracker.camera());  // the gray image's undistortion
    const std::optional<cv::Mat1f> intensity = intensityFor(depth.header.stamp);
    const FrameToModelStep step =
        model_.afterFrame(tracker, report, intensity ? &*intensity : nullptr);
    model_to_frame_ = map_alignment;
    if (step.fused) afterFusion(step.fusion, depth.header.stamp);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "fusion: frame not fused: %s", error.what());
  }
}

void FusionRos::useCamera(const vicc_tracking::CameraModel& camera) {
  if (camera_ && *camera_ == camera) return;
  preprocessor_->setCamera(camera);
  camera_ = camera;
}

void FusionRos::onCameraFrame(const sensor_msgs::ImageConstPtr& depth,
                              const sensor_msgs::CameraInfoConstPtr& info) {
  waiting_infos_.push_back(info);
  // The message filter keeps at most pose_queue_size frames; one more covers the newest.
  while (static_cast<int>(waiting_infos_.size()) > settings_.pose_queue_size + 1) {
    waiting_infos_.pop_front();
  }
  depth_pose_filter_->add(depth);
}

void FusionRos::onDepth(const sensor_msgs::ImageConstPtr& depth) {
  if (const auto tuning = reconfigure_->takeChange()) model_.setFusionConfig(*tuning);
  const auto info = std::find_if(waiting_infos_.begin(), waiting_infos_.end(),
                                 [&](const sensor_msgs::CameraInfoConstPtr& info) {
                                   return info->header.stamp == depth->header.stamp;
                                 });
  if (info == waiting_infos_.end()) {  // only if the message filter kept frames longer
    ROS_WARN_THROTTLE(kWarnPeriod, "fusion: the camera_info of the depth frame at %.6f is gone",
                      depth->header.stamp.toSec());
    return;
  }
  try {
    useCamera(vicc_tracking::cameraModelFromInfo(**info));
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "fusion: depth frame at %.6f dropped, its camera_info on %s: %s",
                      depth->header.stamp.toSec(), camera_sub_->infoTopic().c_str(), error.what());
    return;
  }
  waiting_infos_.erase(info);  // those of frames tf never let through age out above
  Eigen::Isometry3d camera_pose;
  try {  // the message filter let the frame through: its pose is on tf now
    camera_pose = vicc_tracking::isometryFromTransform(
        tf_buffer_
            ->lookupTransform(settings_.map_frame, depth->header.frame_id, depth->header.stamp)
            .transform);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "fusion: no pose for the depth frame at %.3f: %s",
                      depth->header.stamp.toSec(), error.what());
    return;
  }
  try {
    const vicc_tracking::DepthPyramid frame =
        preprocessor_->process(vicc_tracking::depthImageView(*depth));
    const std::optional<cv::Mat1f> intensity = intensityFor(depth->header.stamp);
    afterFusion(model_.fuse(frame.front(), camera_pose, intensity ? &*intensity : nullptr).fusion,
                depth->header.stamp);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE(kWarnPeriod, "fusion: depth image dropped: %s", error.what());
  }
}

void FusionRos::onIntensity(const sensor_msgs::ImageConstPtr& gray) {
  constexpr size_t kKept = 10;  // the depth of the same stamp may be a few frames behind
  recent_gray_.push_back(gray);
  while (recent_gray_.size() > kKept) recent_gray_.pop_front();
  latest_gray_ = gray->header.stamp;
  if (!first_gray_) first_gray_ = latest_gray_;
  if (tracker_) tracker_->processPending();  // a frame may have waited for this image
}

bool FusionRos::grayImageArrived(const ros::Time& stamp) const {
  constexpr double kGiveUp = 0.5;  // s without gray images: they stopped, do not hold frames back
  return !latest_gray_ || *latest_gray_ >= stamp || (stamp - *latest_gray_).toSec() > kGiveUp;
}

std::optional<cv::Mat1f> FusionRos::intensityFor(const ros::Time& stamp) {
  if (!settings_.use_intensity) return std::nullopt;
  for (const sensor_msgs::ImageConstPtr& gray : recent_gray_) {
    if (gray->header.stamp != stamp) continue;
    try {
      if (!camera_) throw std::runtime_error("no valid camera_info yet");
      return preprocessor_->undistortIntensity(vicc_tracking::intensityImageView(*gray));
    } catch (const std::exception& error) {
      ROS_WARN_THROTTLE(kWarnPeriod, "fusion: gray image at %.3f not used: %s", stamp.toSec(),
                        error.what());
      return std::nullopt;
    }
  }
  warnNoGrayImage(stamp);
  return std::nullopt;
}

void FusionRos::warnNoGrayImage(const ros::Time& stamp) {
  constexpr int kStartupFrames = 15;  // the gray image's connection may come up a second later
  if (!latest_gray_) {
    if (++frames_before_any_gray_ == kStartupFrames) {
      ROS_WARN(
          "fusion: use_intensity, but no gray image on %s yet; depth frames on %s are "
          "fused without intensity",
          intensity_sub_.getTopic().c_str(), depthTopic().c_str());
    }
    return;
  }
  // Frames older than the first gray image came before its connection (unless a looping
  // recording went back in time since).
  if (stamp < *first_gray_ && *latest_gray_ >= *first_gray_) return;
  ROS_WARN_THROTTLE(kWarnPeriod,
                    "fusion: no gray image with the stamp %.6f of the depth frame on %s arrived "
                    "on %s (its latest at %.6f); fused without intensity. Depth and gray image "
                    "are paired by exact stamp.",
                    stamp.toSec(), depthTopic().c_str(), intensity_sub_.getTopic().c_str(),
                    latest_gray_->toSec());
}

std::string FusionRos::depthTopic() const {
  return tracker_ ? tracker_->depthTopic() : camera_sub_->imageTopic();
}

void FusionRos::afterFusion(const FusionFrameStats& stats, const ros::Time& stamp) {
  if (stats.refused > 0 && !warned_full_) {
    ROS_WARN("fusion: the model reached max_surfels (%d): new surface is no longer added",
             model_.config().fusion.max_surfels);
    warned_full_ = true;
  }
  if (model_publication_) model_publication_->changed(stamp);
}

bool FusionRos::onSaveModel(vicc_msgs::SaveModel::Request& request,
                            vicc_msgs::SaveModel::Response& response) {
  try {
    if (request.path.empty()) throw std::invalid_argument("no path given");
    SurfelVector surfels = model_.fusion().stableSurfels();
    const Eigen::Isometry3f transform = model_to_frame_.cast<float>();
    for (Surfel& surfel : surfels) {  // in the published frame, as on ~model
      surfel.position = transform * surfel.position;
      surfel.normal = transform.linear() * surfel.normal;
    }
    saveSurfelsPly(request.path, surfels);
    response.success = true;
    response.surfels = static_cast<uint32_t>(surfels.size());
    response.message = "wrote " + std::to_string(surfels.size()) + " stable surfels to " +
                       request.path + " (" + frame_id_ + " frame)";
    ROS_INFO("fusion: %s", response.message.c_str());
  } catch (const std::exception& error) {
    response.success = false;
    response.message = error.what();
    ROS_WARN("fusion: save_model failed: %s", error.what());
  }
  return true;  // the outcome is in the response
}

}  // namespace vicc_fusion
