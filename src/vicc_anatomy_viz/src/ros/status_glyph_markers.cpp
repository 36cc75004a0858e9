#include "vicc_anatomy_viz/ros/status_glyph_markers.hpp"

#include <vicc_msgs/RenderGlyph.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/ros/patient_status_server.hpp"
#include "vicc_anatomy_viz/ros/patient_status_server_settings.hpp"
#include "vicc_anatomy_viz/status_glyph/glyph_billboard.hpp"
#include "vicc_common/ros_parameters.hpp"
#include "vicc_common/ros_service_call.hpp"

namespace vicc_anatomy_viz::ros_adapter {

using status_glyph::GlyphReading;
using status_glyph::ReadingKind;

namespace {

constexpr const char* kNamespace = "status_glyph";
constexpr float kCaptionHeightM = 0.035f;

/// Bottom centre of the glyph: above the highest point of the avatar's skin.
Eigen::Vector3f anchorAboveHead(const AnatomyCatalog& catalog, float lift_m) {
  const avatar::AvatarModel model =
      avatar::buildAvatarModel(avatar::defaultAvatarManifestPath(), catalog);
  const auto& vertices = model.skin.vertices;
  if (vertices.empty()) throw ConfigError("the avatar model has no skin vertices");
  const auto top = std::max_element(vertices.begin(), vertices.end(),
                                    [](const auto& a, const auto& b) { return a.z() < b.z(); });
  return *top + Eigen::Vector3f(0.f, 0.f, lift_m);
}

/// The node's own parameters, read beside the patient server's table (db, configs, view) by
/// the same reader, so a wrong type or a typo is named (one parameter style for every node).
struct MarkerNodeParameters {
  status_glyph::GlyphBinding binding;
  std::string status_topic = "/patient_status_server/status";
  std::string render_service = "/glyph_server/render";
  std::string frame_id = GlyphMarkerSettings{}.frame_id;
  double width_m = GlyphMarkerSettings{}.width_m;
  int resolution_px = GlyphMarkerSettings{}.resolution_px;
  double lift_m = GlyphMarkerSettings{}.lift_m;
  std::vector<double> anchor;  ///< empty: above the highest skin point

  /// Throws std::invalid_argument naming the parameter.
  void validate() const {
    if (status_topic.empty()) throw std::invalid_argument("status_topic is empty");
    if (render_service.empty()) throw std::invalid_argument("render_service is empty");
    if (frame_id.empty()) throw std::invalid_argument("frame_id is empty");
    if (!(width_m > 0.0 && width_m < 5.0)) {
      throw std::invalid_argument("width_m must be within (0, 5) m");
    }
    if (resolution_px < 8 || resolution_px > 512) {
      throw std::invalid_argument("resolution_px must be within 8..512");
    }
    if (!(lift_m >= 0.0 && lift_m < 1.0))
      throw std::invalid_argument("lift_m must be within [0, 1) m");
    if (!anchor.empty() && anchor.size() != 3) {
      throw std::invalid_argument("anchor must be [x, y, z] in metres");
    }
  }
};

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, MarkerNodeParameters>> visitParameters(
    Config& config, Visitor& visit) {
  visit("category", config.binding.category);
  visit("property", config.binding.property);
  visit("design", config.binding.design);
  visit("value_variable", config.binding.value_variable);
  visit("level_variable", config.binding.level_variable);
  visit("status_topic", config.status_topic);
  visit("render_service", config.render_service);
  visit("frame_id", config.frame_id);
  visit("width_m", config.width_m);
  visit("resolution_px", config.resolution_px);
  visit("lift_m", config.lift_m);
  visit("anchor", config.anchor);
}

GlyphMarkerSettings markerSettings(const MarkerNodeParameters& parameters,
                                   const AnatomyCatalog& catalog) {
  GlyphMarkerSettings settings;
  settings.frame_id = parameters.frame_id;
  settings.width_m = static_cast<float>(parameters.width_m);
  settings.resolution_px = parameters.resolution_px;
  settings.lift_m = static_cast<float>(parameters.lift_m);
  settings.anchor =
      parameters.anchor.empty()
          ? anchorAboveHead(catalog, settings.lift_m)
          : Eigen::Vector3d(parameters.anchor[0], parameters.anchor[1], parameters.anchor[2])
                .cast<float>();
  return settings;
}

visualization_msgs::Marker baseMarker(const GlyphMarkerSettings& settings, const ros::Time& stamp,
                                      int id, int type) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = settings.frame_id;
  marker.header.stamp = stamp;
  marker.ns = kNamespace;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = marker.scale.y = marker.scale.z = 1.0;
  marker.color.r = marker.color.g = marker.color.b = marker.color.a = 1.f;
  return marker;
}

geometry_msgs::Point toPoint(const Eigen::Vector3f& p) {
  geometry_msgs::Point point;
  point.x = p.x();
  point.y = p.y();
  point.z = p.z();
  return point;
}

/// The glyph in the y-z plane facing +x (the avatar's front, REP-103), upright.
visualization_msgs::Marker glyphMarker(const vicc_msgs::RenderGlyph::Response& rendered,
                                       const GlyphMarkerSettings& settings,
                                       const ros::Time& stamp) {
  const sensor_msgs::Image& image = rendered.image;
  if (image.encoding != "rgb8" || image.step != image.width * 3) {
    throw std::runtime_error("glyph server image is '" + image.encoding + "' with step " +
                             std::to_string(image.step) + ", not packed rgb8");
  }
  status_glyph::RgbImage rgb{static_cast<int>(image.width), static_cast<int>(image.height),
                             image.data};
  status_glyph::BillboardOptions options;
  options.width_m = settings.width_m;
  const auto quads = status_glyph::billboardQuads(rgb, options);
  const float half_height = 0.5f * settings.width_m * rgb.height / rgb.width;
  const auto soup = status_glyph::billboardTriangles(
      quads, settings.anchor + Eigen::Vector3f(0.f, 0.f, half_height), Eigen::Vector3f::UnitY(),
      Eigen::Vector3f::UnitZ());
  visualization_msgs::Marker marker =
      baseMarker(settings, stamp, 0, visualization_msgs::Marker::TRIANGLE_LIST);
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    marker.points.push_back(toPoint(soup.points[i]));
    std_msgs::ColorRGBA colour;
    colour.r = soup.colours[i].x();
    colour.g = soup.colours[i].y();
    colour.b = soup.colours[i].z();
    colour.a = 1.f;
    marker.colors.push_back(colour);
  }
  return marker;
}

}  // namespace

StatusGlyphMarkers::StatusGlyphMarkers(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  PatientStatusServerSettings server_settings = PatientStatusServerSettings::withDefaultPaths();
  MarkerNodeParameters parameters;
  std::set<std::string> read_names;
  vicc_common::readRosParameters(private_nh, server_settings, read_names);
  vicc_common::readRosParameters(private_nh, parameters, read_names);
  vicc_common::warnUnknownRosParameters(private_nh, read_names);
  PatientStatusConfig config = server_settings.serviceConfig();
  config.store.read_only = true;  // the server writes; this node only reads
  service_ = std::make_unique<PatientStatusService>(config);
  binding_ = parameters.binding;
  binding_.validate(service_->model(), config.view_id);
  settings_ = markerSettings(parameters, service_->model().anatomy());
  const std::string& status_topic = parameters.status_topic;
  const std::string& render_service = parameters.render_service;
  render_client_ = nh.serviceClient<vicc_msgs::RenderGlyph>(render_service);
  markers_pub_ = private_nh.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  status_sub_ = nh.subscribe(status_topic, 1, &StatusGlyphMarkers::onStatus, this);
  ROS_INFO("status_glyph_markers: %s.%s as design '%s' at (%.3f, %.3f, %.3f) in '%s'",
           binding_.category.c_str(), binding_.property.c_str(), binding_.design.c_str(),
           settings_.anchor.x(), settings_.anchor.y(), settings_.anchor.z(),
           settings_.frame_id.c_str());
}

GlyphReading StatusGlyphMarkers::read(const vicc_msgs::EncodedStatus& status) {
  if (!status.has_examination) return {};
  if (status.view_id != service_->config().view_id) {
    throw std::runtime_error("status of view '" + status.view_id + "', this node reads view '" +
                             service_->config().view_id + "'");
  }
  const auto& hidden = status.hidden_categories;
  const bool is_hidden = std::find(hidden.begin(), hidden.end(), binding_.category) != hidden.end();
  return status_glyph::readGlyph(
      service_->model(), binding_,
      service_->examinationAt(status.patient_id, status.examination_time), is_hidden);
}

visualization_msgs::MarkerArray StatusGlyphMarkers::markersFor(const GlyphReading& reading,
                                                               const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  visualization_msgs::Marker clear;
  clear.ns = kNamespace;
  clear.action = visualization_msgs::Marker::DELETEALL;
  array.markers.push_back(clear);
  if (reading.kind == ReadingKind::kNoExamination || reading.kind == ReadingKind::kHidden) {
    return array;
  }
  std::string caption = reading.caption;
  float glyph_height = 0.f;
  if (reading.kind == ReadingKind::kValue) {
    vicc_msgs::RenderGlyph render;
    render.request.design = binding_.design;
    render.request.names = {binding_.value_variable, binding_.level_variable};
    render.request.values = {static_cast<double>(reading.value),
                             static_cast<double>(reading.level)};
    render.request.size = settings_.resolution_px;
    try {
      if (!vicc_common::callRepeatableService(render_client_, render))
        throw std::runtime_error("glyph server not reachable");
      if (!render.response.success) throw std::runtime_error(render.response.message);
      array.markers.push_back(glyphMarker(render.response, settings_, stamp));
      glyph_height = settings_.width_m * render.response.image.height /
                     std::max(1u, render.response.image.width);
    } catch (const std::exception& e) {
      ROS_WARN("status_glyph_markers: no glyph: %s", e.what());
      caption += " [glyph unavailable]";
    }
  }
  visualization_msgs::Marker text =
      baseMarker(settings_, stamp, 1, visualization_msgs::Marker::TEXT_VIEW_FACING);
  text.pose.position = toPoint(settings_.anchor + Eigen::Vector3f(0.f, 0.f, glyph_height + 0.03f));
  text.scale.z = kCaptionHeightM;
  text.color.r = text.color.g = text.color.b = 0.55f;
  text.text = caption;
  array.markers.push_back(text);
  return array;
}

void StatusGlyphMarkers::onStatus(const vicc_msgs::EncodedStatus& status) {
  GlyphReading reading;
  try {
    reading = read(status);
  } catch (const std::exception& e) {
    // Never a stale glyph: the old one is removed and the caption says why.
    ROS_WARN("status_glyph_markers: %s", e.what());
    reading.kind = ReadingKind::kNoData;
    reading.caption = binding_.category + " glyph: " + std::string(e.what());
  }
  markers_pub_.publish(markersFor(reading, ros::Time::now()));
}

}  // namespace vicc_anatomy_viz::ros_adapter
