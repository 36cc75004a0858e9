#include "vicc_anatomy_viz/rviz/avatar_display.hpp"

#include <OGRE/OgreCamera.h>
#include <OGRE/OgreRenderSystem.h>
#include <OGRE/OgreRenderSystemCapabilities.h>
#include <OGRE/OgreRoot.h>
#include <rviz/display_context.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/ros_topic_property.h>
#include <rviz/properties/status_property.h>
#include <rviz/properties/string_property.h>
#include <rviz/view_controller.h>
#include <rviz/view_manager.h>
#include <pluginlib/class_list_macros.hpp>

#include <sstream>

#include "vicc_anatomy_viz/anatomy_catalog.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/rviz/avatar_visual.hpp"
#include "vicc_anatomy_viz/rviz/encoded_status_conversion.hpp"
#include "vicc_anatomy_viz/rviz/ogre_camera.hpp"
#include "vicc_anatomy_viz/rviz/renderer_heap.hpp"
#include "vicc_anatomy_viz/rviz/screen_overlay.hpp"

namespace vicc_anatomy_viz::rviz_plugin {
namespace {

/// At most this many warnings in the status text; the count says how many more.
constexpr std::size_t kShownWarnings = 12;

std::string joinWarnings(const std::vector<std::string>& warnings) {
  std::ostringstream text;
  for (std::size_t i = 0; i < warnings.size() && i < kShownWarnings; ++i)
    text << (i ? "\n" : "") << warnings[i];
  if (warnings.size() > kShownWarnings)
    text << "\n... " << warnings.size() - kShownWarnings << " more";
  return text.str();
}

/// The legend's label of a category, its id when the legend lacks it.
std::string categoryLabel(const vicc_msgs::EncodedStatus& status, const std::string& category) {
  for (const auto& entry : status.legend)
    if (entry.id == category) return entry.label;
  return category;
}

/// Once per process: on a CPU rasteriser, llvmpipe's per-frame scene memory stays mapped
/// instead of being page-faulted in again every frame (renderer_heap.hpp).
void tuneHeapForSoftwareRendering() {
  static bool done = false;
  if (done) return;
  done = true;
  const Ogre::RenderSystem* system = Ogre::Root::getSingleton().getRenderSystem();
  const Ogre::RenderSystemCapabilities* capabilities = system ? system->getCapabilities() : nullptr;
  if (!capabilities || !isSoftwareRenderer(capabilities->getDeviceName())) return;
  if (keepFreedHeapForRendering())
    ROS_INFO("Avatar: software renderer (%s): heap trim threshold raised to %zu MB",
             capabilities->getDeviceName().c_str(), kRendererTrimThresholdBytes >> 20);
}

}  // namespace

AvatarDisplay::AvatarDisplay() {
  topic_property_ = new rviz::RosTopicProperty(
      "Topic", "/patient_status_server/status",
      QString::fromStdString(ros::message_traits::datatype<vicc_msgs::EncodedStatus>()),
      "vicc_msgs/EncodedStatus topic (patient_status_server's latched ~status).", this,
      SLOT(updateTopic()));
  manifest_property_ = new rviz::StringProperty(
      "Avatar manifest", "", "Avatar manifest YAML; empty: the package's default body.", this,
      SLOT(updateModel()));
  catalog_property_ = new rviz::StringProperty("Anatomy catalogue", "",
                                               "Anatomy catalogue YAML; empty: the package's.",
                                               this, SLOT(updateModel()));
  transparency_property_ = new rviz::BoolProperty(
      "View-dependent transparency", true,
      "Skin and unencoded structures become see-through where they hide an encoded structure.",
      this, SLOT(updateOptions()));
  skin_alpha_property_ = new rviz::FloatProperty("Skin alpha", 1.0f, "Opacity of the whole skin.",
                                                 this, SLOT(updateOptions()));
  skin_alpha_property_->setMin(0.05f);
  skin_alpha_property_->setMax(1.0f);
  see_through_alpha_property_ = new rviz::FloatProperty(
      "See-through alpha", 0.8f, "Opacity of an encoded structure seen through what hides it.",
      this, SLOT(updateOptions()));
  see_through_alpha_property_->setMin(0.05f);
  see_through_alpha_property_->setMax(1.0f);
  alternation_period_property_ = new rviz::FloatProperty(
      "Alternation period", 1.5f,
      "Seconds each category is shown where several share a structure (0: no alternation).", this,
      SLOT(updateOptions()));
  alternation_period_property_->setMin(0.0f);
  relief_property_ = new rviz::BoolProperty(
      "Per-pixel relief", true,
      "Light the pain trigger's normal-perturbation texture per pixel (GLSL); off: the "
      "pre-shaded bump texture.",
      this, SLOT(updateOptions()));
  legend_property_ = new rviz::BoolProperty("Legend", true, "Show the category legend.", this,
                                            SLOT(updateOptions()));
}

AvatarDisplay::~AvatarDisplay() {
  unsubscribe();
  visual_.reset();
  legend_.reset();
  selection_.reset();
}

void AvatarDisplay::onInitialize() {
  tuneHeapForSoftwareRendering();
  static unsigned instances = 0;
  const std::string name = "vicc_avatar_overlay_" + std::to_string(++instances);
  legend_ = std::make_unique<ScreenOverlay>(name + "/legend", ScreenOverlay::Corner::kTopLeft);
  selection_ =
      std::make_unique<ScreenOverlay>(name + "/selection", ScreenOverlay::Corner::kBottomLeft);
  visual_ = std::make_unique<AvatarVisual>(context_, scene_node_);
  updateOptions();
  updateModel();
}

void AvatarDisplay::onEnable() {
  scene_node_->setVisible(true);
  subscribe();
  updateOptions();
}

void AvatarDisplay::onDisable() {
  unsubscribe();
  scene_node_->setVisible(false);
  if (legend_) legend_->setVisible(false);
  if (selection_) selection_->setVisible(false);
}

void AvatarDisplay::reset() {
  rviz::Display::reset();
  redraw();
}

void AvatarDisplay::subscribe() {
  if (!isEnabled() || topic_property_->getTopicStd().empty()) return;
  try {
    subscriber_ =
        update_nh_.subscribe(topic_property_->getTopicStd(), 1, &AvatarDisplay::receive, this);
    setStatus(rviz::StatusProperty::Ok, "Topic", "subscribed");
  } catch (const ros::Exception& error) {
    setStatus(rviz::StatusProperty::Error, "Topic", QString("cannot subscribe: ") + error.what());
  }
}

void AvatarDisplay::unsubscribe() { subscriber_.shutdown(); }

void AvatarDisplay::updateTopic() {
  unsubscribe();
  subscribe();
}

void AvatarDisplay::updateModel() {
  model_error_.clear();
  try {
    const std::string manifest = manifest_property_->getStdString();
    const std::string catalog = catalog_property_->getStdString();
    const AnatomyCatalog anatomy =
        AnatomyCatalog::load(catalog.empty() ? defaultAnatomyConfigPath() : catalog);
    model_ = std::make_shared<const avatar::AvatarModel>(avatar::buildAvatarModel(
        manifest.empty() ? avatar::defaultAvatarManifestPath() : manifest, anatomy));
    setStatus(rviz::StatusProperty::Ok, "Model",
              QString("%1 structures, %2 skin regions")
                  .arg(model_->structures.size())
                  .arg(model_->skin_regions.size()));
  } catch (const std::exception& error) {
    model_.reset();
    model_error_ = error.what();
    setStatus(rviz::StatusProperty::Error, "Model", error.what());
  }
  if (visual_) visual_->setModel(model_);
  redraw();
}

void AvatarDisplay::updateOptions() {
  if (!visual_) return;
  VisualOptions options;
  options.transparency = transparency_property_->getBool();
  options.skin_alpha = skin_alpha_property_->getFloat();
  options.see_through_alpha = see_through_alpha_property_->getFloat();
  options.alternation_period_s = alternation_period_property_->getFloat();
  options.relief = relief_property_->getBool();
  visual_->setOptions(options);
  updateReliefStatus();
  if (legend_) legend_->setVisible(legend_property_->getBool() && isEnabled());
  if (selection_) selection_->setVisible(isEnabled());
  context_->queueRender();
}

void AvatarDisplay::receive(const vicc_msgs::EncodedStatus::ConstPtr& msg) {
  last_msg_ = msg;
  redraw();
}

void AvatarDisplay::showStatus(const vicc_msgs::EncodedStatus& msg) {
  receive(boost::make_shared<const vicc_msgs::EncodedStatus>(msg));
}

void AvatarDisplay::redraw() {
  draw_state_ = avatar_view::AvatarDrawState{};
  if (selection_) selection_->setLines({});
  if (!last_msg_) {
    setStatus(rviz::StatusProperty::Warn, "Status", "no EncodedStatus received yet");
  } else {
    std::vector<std::string> warnings;
    const EncodedStatus status = fromMessage(*last_msg_, warnings);
    draw_state_ =
        model_ ? avatar_view::buildDrawState(status, *model_) : avatar_view::AvatarDrawState{};
    warnings.insert(warnings.end(), draw_state_.warnings.begin(), draw_state_.warnings.end());
    if (!model_) warnings.push_back("no avatar model: nothing drawn (see Model)");
    if (warnings.empty())
      setStatus(rviz::StatusProperty::Ok, "Status",
                QString::fromStdString(draw_state_.headline + ": " +
                                       std::to_string(draw_state_.items.size()) + " structures"));
    else
      setStatus(rviz::StatusProperty::Warn, "Status",
                QString::fromStdString(joinWarnings(warnings)));
    ++drawn_status_count_;
  }
  status_age_s_ = 0.0;
  if (visual_)
    visual_->setState(draw_state_, [this](const std::string& text) { showSelection(text); });
  updateReliefStatus();
  updateLegend();
  context_->queueRender();
}

void AvatarDisplay::updateReliefStatus() {
  if (!visual_) return;
  relief_status_ = visual_->reliefStatus();
  const avatar_view::ReliefStatus& relief = relief_status_;
  if (!relief.needed) {
    deleteStatus("Relief");
  } else if (relief.per_pixel) {
    setStatus(rviz::StatusProperty::Ok, "Relief",
              "pain trigger: per-pixel normal perturbation (GLSL)");
  } else {
    // Never an empty structure: the pre-shaded texture keeps the category's colour.
    setStatus(relief.unavailable ? rviz::StatusProperty::Warn : rviz::StatusProperty::Ok, "Relief",
              QString::fromStdString("pain trigger: pre-shaded bump texture (" +
                                     relief.fallback_reason + ")"));
  }
}

void AvatarDisplay::updateLegend() {
  if (!legend_) return;
  std::vector<OverlayLine> lines;
  if (last_msg_) {
    lines.push_back({draw_state_.headline.empty() ? last_msg_->patient_id : draw_state_.headline,
                     false,
                     {},
                     true});
    for (const avatar_view::LegendLine& entry : draw_state_.legend)
      lines.push_back({entry.label, true, entry.color, false});
    for (const auto& alternation : last_msg_->alternations) {
      std::string categories;
      for (const auto& category : alternation.categories)
        categories += (categories.empty() ? "" : " / ") + categoryLabel(*last_msg_, category);
      lines.push_back({"alternating on " + alternation.display_name + ":", false, {}, false});
      lines.push_back({"  " + categories, false, {}, false});
    }
  }
  legend_->setLines(lines);
}

void AvatarDisplay::showSelection(const std::string& text) {
  selection_text_ = text;
  std::vector<OverlayLine> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) lines.push_back({line, false, {}, lines.empty()});
  selection_->setLines(lines);
  context_->queueRender();
}

void AvatarDisplay::update(float wall_dt, float /*ros_dt*/) {
  status_age_s_ += wall_dt;
  const rviz::ViewController* view = context_->getViewManager()->getCurrent();
  if (!visual_ || !view || !view->getCamera()) return;
  visual_->update(status_age_s_, cameraModel(*view->getCamera()));
}

}  // namespace vicc_anatomy_viz::rviz_plugin

PLUGINLIB_EXPORT_CLASS(vicc_anatomy_viz::rviz_plugin::AvatarDisplay, rviz::Display)
