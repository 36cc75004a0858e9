#pragma once
// The status_glyph_markers node: a glyph of one measured value of the selected examination
// (by default the intracranial pressure) above the avatar's head, as a
// visualization_msgs/MarkerArray for rviz's stock MarkerArray display.
//
// It follows the patient status server's latched ~status (the panel's patient and date),
// reads that examination from the same database (read-only: the encoded status leaves out
// normal values, so it cannot tell a normal ICP from a missing one), asks the glyph server
// (vicc_msgs/RenderGlyph) for the design's picture of the value and its level, and publishes
// it as coloured quads plus a caption. No value: the caption "no data" and no glyph.
//
// Parameters: ~db, ~encoding_config, ~anatomy_config, ~view (as patient_status_server);
// ~status_topic (/patient_status_server/status), ~render_service
// (/glyph_server/render), ~category, ~property, ~design, ~value_variable,
// ~level_variable (GlyphBinding), ~frame_id (avatar), ~width_m (0.2), ~resolution_px (96),
// ~lift_m (0.04: gap between the head's top and the glyph), ~anchor ([x, y, z] of the
// glyph's bottom centre; default: above the highest skin point of the avatar model).
// Publishes ~markers (latched).

#include <memory>
#include <string>

#include <ros/ros.h>
#include <vicc_msgs/EncodedStatus.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Core>

#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/status_glyph/glyph_reading.hpp"

namespace vicc_anatomy_viz::ros_adapter {

struct GlyphMarkerSettings {
  std::string frame_id = "avatar";
  float width_m = 0.2f;
  int resolution_px = 96;
  float lift_m = 0.04f;
  Eigen::Vector3f anchor = Eigen::Vector3f::Zero();  ///< bottom centre of the glyph
};

class StatusGlyphMarkers {
 public:
  /// Throws ConfigError / std::invalid_argument naming the parameter.
  StatusGlyphMarkers(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  void onStatus(const vicc_msgs::EncodedStatus& status);
  status_glyph::GlyphReading read(const vicc_msgs::EncodedStatus& status);
  /// The glyph and its caption; on a render failure only a caption saying so.
  visualization_msgs::MarkerArray markersFor(const status_glyph::GlyphReading& reading,
                                             const ros::Time& stamp);

  std::unique_ptr<PatientStatusService> service_;
  status_glyph::GlyphBinding binding_;
  GlyphMarkerSettings settings_;
  ros::ServiceClient render_client_;
  ros::Publisher markers_pub_;
  ros::Subscriber status_sub_;
};

}  // namespace vicc_anatomy_viz::ros_adapter
