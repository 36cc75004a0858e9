#pragma once
// PatientPanel (rviz::Panel, thesis 4.4.1 and Fig. 4.7A): chooses the patient, the examination
// date on a timeline slider and the categories the avatar shows, by calling the patient status
// server's SelectPatient; the AvatarDisplay draws what the server then publishes. The Qt part
// is thin: state and decisions are in panel::PatientPanelState, the service calls in a
// PatientServerClient on a worker thread. Saved in the rviz configuration (keys in
// panel_settings.hpp).

#include <QString>
#include <QThread>
#include <QTimer>

#include <map>
#include <string>

#ifndef Q_MOC_RUN
#include <rviz/panel.h>
#endif

#include "vicc_anatomy_viz/panel_logic/patient_panel_state.hpp"
#include "vicc_anatomy_viz/rviz/patient_panel_client.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;
class QVBoxLayout;

namespace vicc_anatomy_viz::rviz_plugin {

class PatientPanel : public rviz::Panel {
  Q_OBJECT
 public:
  explicit PatientPanel(QWidget* parent = nullptr);
  ~PatientPanel() override;

  void onInitialize() override;
  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

 private Q_SLOTS:
  void onPatientActivated(int index);
  void onTimelineMoved(int index);
  void onTimelineChosen(int index);
  void onLatestToggled(bool latest);
  void onCategoryToggled(const QString& id, bool visible);
  void onRefresh();
  void onRetry();

  void onReachability(bool reachable, const QString& message);
  void onPatientsListed(const vicc_anatomy_viz::rviz_plugin::PatientList& patients);
  void onDatesListed(const QString& patient, const QStringList& dates, const QString& problem);
  void onSelected(const vicc_anatomy_viz::rviz_plugin::SelectionResult& result);
  void onStatusPublished(const vicc_anatomy_viz::panel::ShownStatus& status);

 private:
  void buildWidgets();
  void connectClient();
  void send(const panel::SelectionRequest& request);
  void requestDatesIfOutdated();
  void showMessage(const QString& text, bool problem);

  // Widgets follow the state (patient_panel_widgets.cpp); signals blocked while they do.
  void refreshWidgets();
  void refreshPatients();
  void refreshTimeline();
  void refreshCategories();

  panel::PatientPanelState state_;
  QThread client_thread_;
  PatientServerClient* client_ = nullptr;  ///< owned by client_thread_ (deleteLater)
  QTimer retry_timer_;
  bool reachable_ = false;
  bool initialized_ = false;
  std::string dates_requested_for_;  ///< avoids asking twice for the same dates
  QString config_problems_;

  QComboBox* patient_combo_ = nullptr;
  QPushButton* refresh_button_ = nullptr;
  QSlider* timeline_slider_ = nullptr;
  QCheckBox* latest_box_ = nullptr;
  QLabel* timeline_label_ = nullptr;
  QVBoxLayout* categories_layout_ = nullptr;
  std::map<std::string, QCheckBox*> category_boxes_;
  QLabel* shown_label_ = nullptr;
  QLabel* message_label_ = nullptr;
};

}  // namespace vicc_anatomy_viz::rviz_plugin
