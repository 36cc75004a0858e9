// rostest: the fusion node (tracker inside, frame-to-model) publishes a model that lies on the
// simulator's true surface, tracks the ground truth, and saves the model on request.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <unistd.h>

#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <vicc_msgs/SaveModel.h>
#include <vicc_msgs/TrackingStatus.h>

#include "vicc_fusion/model_accuracy.hpp"
#include "vicc_fusion/surfel_io.hpp"
#include "vicc_tracking/ros/conversions.hpp"
#include "vicc_tracking/tracker.hpp"
#include "wait_for_recording_end.hpp"

namespace {

std::string g_surface_path;
// The tracker's topics: the fusion node's own (track: true) or an external tracker node's.
std::string g_tracker_namespace = "/fusion";
bool g_expect_intensity = false;

/// The message a new subscriber to the latched `topic` receives within a few seconds.
template <class Message>
boost::shared_ptr<const Message> latchedMessage(const std::string& topic) {
  ros::NodeHandle nh;
  return ros::topic::waitForMessage<Message>(topic, nh, ros::Duration(5.0));
}

class FusionNodeTest : public ::testing::Test {
 protected:
  FusionNodeTest() : listener_(buffer_) {
    model_sub_ = nh_.subscribe("/fusion/model", 5, &FusionNodeTest::onModel, this);
    status_sub_ =
        nh_.subscribe(g_tracker_namespace + "/status", 1000, &FusionNodeTest::onStatus, this);
    odom_sub_ = nh_.subscribe(g_tracker_namespace + "/odom", 1000, &FusionNodeTest::onOdom, this);
  }

  void onModel(const sensor_msgs::PointCloud2& cloud) {
    ++clouds_;
    last_cloud_ = cloud;
  }
  void onStatus(const vicc_msgs::TrackingStatus& status) { statuses_.push_back(status); }
  void onOdom(const nav_msgs::Odometry& odom) { odometry_.push_back(odom); }

  vicc_fusion::SurfelVector surfelsOf(const sensor_msgs::PointCloud2& cloud) const {
    vicc_fusion::SurfelVector surfels;
    sensor_msgs::PointCloud2ConstIterator<float> position(cloud, "x");
    sensor_msgs::PointCloud2ConstIterator<float> normal(cloud, "normal_x");
    sensor_msgs::PointCloud2ConstIterator<float> radius(cloud, "radius");
    sensor_msgs::PointCloud2ConstIterator<float> confidence(cloud, "confidence");
    for (; position != position.end(); ++position, ++normal, ++radius, ++confidence) {
      vicc_fusion::Surfel surfel;
      surfel.position = Eigen::Vector3f(position[0], position[1], position[2]);
      surfel.normal = Eigen::Vector3f(normal[0], normal[1], normal[2]);
      surfel.radius = *radius;
      surfel.confidence = *confidence;
      surfels.push_back(surfel);
    }
    return surfels;
  }

  ros::NodeHandle nh_;
  tf2_ros::Buffer buffer_{ros::Duration(60.0)};
  tf2_ros::TransformListener listener_;
  ros::Subscriber model_sub_, status_sub_, odom_sub_;
  int clouds_ = 0;
  sensor_msgs::PointCloud2 last_cloud_;
  std::vector<vicc_msgs::TrackingStatus> statuses_;
  std::vector<nav_msgs::Odometry> odometry_;
};

TEST_F(FusionNodeTest, ModelLiesOnTheTrueSurface) {
  // Wait for the recording to end: no new status for 3 s after the last one.
  vicc_test::waitForRecordingEnd([this] { return statuses_.size(); });
  ASSERT_GT(odometry_.size(), 40u) << "too few tracked poses";
  ASSERT_GT(clouds_, 1) << "the model was not published";

  // The poses follow the truth (frame-to-model inside the fusion node, or the external
  // tracker's), and no frame was lost.
  int lost = 0;
  for (const auto& status : statuses_)
    lost += status.state == vicc_msgs::TrackingStatus::STATE_LOST;
  EXPECT_EQ(lost, 0);
  double max_error = 0.0;
  for (const auto& odom : odometry_) {
    try {
      const auto truth =
          buffer_.lookupTransform("map", "pico_flexx_optical_frame_gt", odom.header.stamp);
      const auto& p = odom.pose.pose.position;
      max_error =
          std::max(max_error, (vicc_tracking::isometryFromTransform(truth.transform).translation() -
                               Eigen::Vector3d(p.x, p.y, p.z))
                                  .norm());
    } catch (const std::exception&) {
    }
  }
  EXPECT_LT(max_error, 0.01) << "metres";

  // The published model (map aligned to the ground truth at the first frame) against the
  // true surface the recording saw.
  EXPECT_EQ(last_cloud_.header.frame_id, "map");
  const vicc_fusion::SurfelVector surfels = surfelsOf(last_cloud_);
  ASSERT_GT(surfels.size(), 5000u);
  const auto truth = vicc_fusion::loadTruthSurface(g_surface_path);
  const vicc_fusion::ModelAccuracy accuracy =
      vicc_fusion::evaluateModel(surfels, truth, Eigen::Isometry3d::Identity());
  EXPECT_LT(accuracy.mean_distance, 0.003) << "metres";
  EXPECT_LT(accuracy.p95_distance, 0.01) << "metres";
  EXPECT_GT(accuracy.completeness, 0.6);
  EXPECT_LT(accuracy.surfels_outside, surfels.size() / 10);

  // Gray values: with use_intensity most stable surfels carry the simulated amplitude (a
  // fraction in [0, 1] of the mono16 range), otherwise none does.
  size_t with_intensity = 0;
  for (sensor_msgs::PointCloud2ConstIterator<float> gray(last_cloud_, "intensity");
       gray != gray.end(); ++gray) {
    if (std::isnan(*gray)) continue;
    ++with_intensity;
    EXPECT_GE(*gray, 0.f);
    EXPECT_LE(*gray, 1.f);
  }
  if (g_expect_intensity) {
    EXPECT_GT(with_intensity, surfels.size() * 9 / 10);
  } else {
    EXPECT_EQ(with_intensity, 0u);
  }

  // The last model published is the final one, stamped with the last frame, even though
  // publish_rate (0.3 Hz here) throttled it while the frames came; a subscriber that connects
  // only now (rviz opened after the replay) gets it too, and the tracked path with it.
  ASSERT_FALSE(statuses_.empty());
  const ros::Time last_frame = statuses_.back().header.stamp;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  while (last_cloud_.header.stamp != last_frame && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.05).sleep();
  }
  EXPECT_EQ(last_cloud_.header.stamp, last_frame) << "the final model was not published";
  const auto late_cloud = latchedMessage<sensor_msgs::PointCloud2>("/fusion/model");
  ASSERT_TRUE(late_cloud) << "no latched model for a late subscriber";
  EXPECT_EQ(late_cloud->header.stamp, last_frame);
  EXPECT_EQ(late_cloud->width * late_cloud->height, last_cloud_.width * last_cloud_.height);
  const auto late_path = latchedMessage<nav_msgs::Path>(g_tracker_namespace + "/path");
  ASSERT_TRUE(late_path) << "no latched path for a late subscriber";
  ASSERT_FALSE(late_path->poses.empty());
  EXPECT_EQ(late_path->poses.back().header.stamp, last_frame);

  // ~save_model writes the model ~model showed: the final one.
  vicc_msgs::SaveModel save;
  // One file per test process: make runs the fusion rostests in parallel.
  save.request.path =
      ::testing::TempDir() + "/vicc_fusion_rostest_model_" + std::to_string(getpid()) + ".ply";
  ASSERT_TRUE(ros::service::call("/fusion/save_model", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  EXPECT_EQ(save.response.surfels, surfels.size());
  EXPECT_EQ(vicc_fusion::loadSurfelsPly(save.request.path).size(), save.response.surfels);
  std::remove(save.request.path.c_str());
  save.request.path = "/nonexistent/dir/model.ply";
  ASSERT_TRUE(ros::service::call("/fusion/save_model", save));
  EXPECT_FALSE(save.response.success);
  EXPECT_FALSE(save.response.message.empty());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "fusion_rostest");
  if (argc < 2) {
    std::fprintf(stderr, "usage: fusion_rostest TRUE_SURFACE.ply\n");
    return 2;
  }
  g_surface_path = argv[1];
  ros::NodeHandle("~").param<std::string>("tracker_namespace", g_tracker_namespace, "/fusion");
  ros::NodeHandle("~").param<bool>("expect_intensity", g_expect_intensity, false);
  return RUN_ALL_TESTS();
}
