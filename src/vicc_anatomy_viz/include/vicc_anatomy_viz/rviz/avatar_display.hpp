#pragma once
// rviz display "vicc_anatomy_viz/Avatar": the patient's encoded neurological status
// (vicc_msgs/EncodedStatus, as patient_status_server publishes it latched) on the 3D body,
// thesis 4.4.1-4.4.2. The avatar stands at the origin of the fixed frame (REP-103, feet at
// z = 0). Thin: the rules live in avatar_view, the OGRE scene in AvatarVisual.

#include <memory>
#include <string>

#include <QObject>

#ifndef Q_MOC_RUN
#include <ros/ros.h>
#include <rviz/display.h>
#include <vicc_msgs/EncodedStatus.h>
#include <Eigen/Core>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/avatar_view/draw_state.hpp"
#include "vicc_anatomy_viz/avatar_view/relief_shading.hpp"
#endif

namespace rviz {
class BoolProperty;
class FloatProperty;
class RosTopicProperty;
class StringProperty;
}  // namespace rviz

namespace vicc_anatomy_viz::rviz_plugin {

class AvatarVisual;
class ScreenOverlay;

class AvatarDisplay : public rviz::Display {
  Q_OBJECT
 public:
  AvatarDisplay();
  ~AvatarDisplay() override;

  void onInitialize() override;
  void update(float wall_dt, float ros_dt) override;
  void reset() override;

  /// For tools embedding the display (vicc_avatar_snapshot, the rostest): the loaded model
  /// (null until loaded), how many statuses were drawn, and the last one's draw state.
  const avatar::AvatarModel* model() const { return model_.get(); }
  const std::string& modelError() const { return model_error_; }
  unsigned drawnStatusCount() const { return drawn_status_count_; }
  const avatar_view::AvatarDrawState& drawState() const { return draw_state_; }
  /// The text overlay of the structure clicked last ("" when none is selected).
  const std::string& selectionText() const { return selection_text_; }
  /// The last status received (empty before the first).
  vicc_msgs::EncodedStatus lastStatus() const {
    return last_msg_ ? *last_msg_ : vicc_msgs::EncodedStatus();
  }
  /// How the pain trigger's texture of the last status is drawn (per pixel or pre-shaded).
  const avatar_view::ReliefStatus& reliefStatus() const { return relief_status_; }
  /// Draws `msg` as if it had arrived on the topic.
  void showStatus(const vicc_msgs::EncodedStatus& msg);

 protected:
  void onEnable() override;
  void onDisable() override;

 private Q_SLOTS:
  void updateTopic();
  void updateModel();
  void updateOptions();

 private:
  void subscribe();
  void unsubscribe();
  void receive(const vicc_msgs::EncodedStatus::ConstPtr& msg);
  void redraw();
  void updateLegend();
  void updateReliefStatus();
  void showSelection(const std::string& text);

  rviz::RosTopicProperty* topic_property_;
  rviz::StringProperty* manifest_property_;
  rviz::StringProperty* catalog_property_;
  rviz::BoolProperty* transparency_property_;
  rviz::FloatProperty* skin_alpha_property_;
  rviz::FloatProperty* see_through_alpha_property_;
  rviz::FloatProperty* alternation_period_property_;
  rviz::BoolProperty* relief_property_;
  rviz::BoolProperty* legend_property_;

  ros::Subscriber subscriber_;
  std::shared_ptr<const avatar::AvatarModel> model_;
  std::string model_error_;
  std::string selection_text_;  ///< why the model did not load, "" when it did
  std::unique_ptr<AvatarVisual> visual_;
  std::unique_ptr<ScreenOverlay> legend_;
  std::unique_ptr<ScreenOverlay> selection_;
  vicc_msgs::EncodedStatus::ConstPtr last_msg_;
  avatar_view::AvatarDrawState draw_state_;
  avatar_view::ReliefStatus relief_status_;
  unsigned drawn_status_count_ = 0;
  double status_age_s_ = 0.0;  ///< alternation clock, restarted with every status
};

}  // namespace vicc_anatomy_viz::rviz_plugin
