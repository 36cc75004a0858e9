#include "vicc_anatomy_viz/rviz/patient_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <ros/console.h>
#include <rviz/config.h>
#include <pluginlib/class_list_macros.hpp>

namespace vicc_anatomy_viz::rviz_plugin {

namespace {

constexpr int kRetryIntervalMs = 2000;

}  // namespace

PatientPanel::PatientPanel(QWidget* parent) : rviz::Panel(parent) {
  PatientServerClient::registerMetaTypes();
  buildWidgets();
  retry_timer_.setInterval(kRetryIntervalMs);
  connect(&retry_timer_, &QTimer::timeout, this, &PatientPanel::onRetry);
}

PatientPanel::~PatientPanel() {
  retry_timer_.stop();
  client_thread_.quit();
  client_thread_.wait();  // a call in progress finishes first
}

void PatientPanel::buildWidgets() {
  auto* layout = new QVBoxLayout(this);
  auto* patient_row = new QHBoxLayout;
  patient_combo_ = new QComboBox;
  patient_combo_->setObjectName("patient_selector");
  patient_combo_->setPlaceholderText("choose a patient");
  patient_combo_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  refresh_button_ = new QPushButton("Refresh");
  refresh_button_->setObjectName("refresh");
  patient_row->addWidget(new QLabel("Patient"));
  patient_row->addWidget(patient_combo_, 1);
  patient_row->addWidget(refresh_button_);
  layout->addLayout(patient_row);

  auto* timeline_row = new QHBoxLayout;
  timeline_slider_ = new QSlider(Qt::Horizontal);
  timeline_slider_->setObjectName("timeline_slider");
  timeline_slider_->setTickPosition(QSlider::TicksBelow);
  timeline_slider_->setTickInterval(1);
  timeline_slider_->setPageStep(1);
  timeline_slider_->setTracking(false);  // a date is requested when the slider is released
  latest_box_ = new QCheckBox("Latest");
  latest_box_->setObjectName("latest");
  latest_box_->setToolTip("Follow the newest examination, also when one is recorded");
  timeline_row->addWidget(new QLabel("Examination"));
  timeline_row->addWidget(timeline_slider_, 1);
  timeline_row->addWidget(latest_box_);
  layout->addLayout(timeline_row);
  timeline_label_ = new QLabel;
  timeline_label_->setObjectName("timeline_label");
  layout->addWidget(timeline_label_);

  auto* categories = new QGroupBox("Categories");
  categories_layout_ = new QVBoxLayout(categories);
  layout->addWidget(categories);
  shown_label_ = new QLabel;
  shown_label_->setObjectName("shown_label");
  shown_label_->setWordWrap(true);
  layout->addWidget(shown_label_);
  message_label_ = new QLabel;
  message_label_->setObjectName("message_label");
  message_label_->setWordWrap(true);
  layout->addWidget(message_label_);
  layout->addStretch(1);

  connect(patient_combo_, QOverload<int>::of(&QComboBox::activated), this,
          &PatientPanel::onPatientActivated);
  connect(refresh_button_, &QPushButton::clicked, this, &PatientPanel::onRefresh);
  connect(timeline_slider_, &QSlider::sliderMoved, this, &PatientPanel::onTimelineMoved);
  connect(timeline_slider_, &QSlider::valueChanged, this, &PatientPanel::onTimelineChosen);
  connect(latest_box_, &QCheckBox::toggled, this, &PatientPanel::onLatestToggled);
  refreshWidgets();
}

void PatientPanel::onInitialize() {
  initialized_ = true;
  connectClient();
}

void PatientPanel::connectClient() {
  client_ = new PatientServerClient;
  client_->moveToThread(&client_thread_);
  connect(&client_thread_, &QThread::finished, client_, &QObject::deleteLater);
  connect(client_, &PatientServerClient::reachabilityChanged, this, &PatientPanel::onReachability);
  connect(client_, &PatientServerClient::patientsListed, this, &PatientPanel::onPatientsListed);
  connect(client_, &PatientServerClient::datesListed, this, &PatientPanel::onDatesListed);
  connect(client_, &PatientServerClient::selected, this, &PatientPanel::onSelected);
  connect(client_, &PatientServerClient::statusPublished, this, &PatientPanel::onStatusPublished);
  client_thread_.start();
  const QString server = QString::fromStdString(state_.server());
  QMetaObject::invokeMethod(client_, [client = client_, server] {
    client->connectTo(server);
    client->listPatients();
  });
  retry_timer_.start();
}

void PatientPanel::load(const rviz::Config& config) {
  rviz::Panel::load(config);
  panel::KeyValues values;
  for (const char* key :
       {panel::kServerKey, panel::kPatientKey, panel::kDateKey, panel::kHiddenCategoriesKey}) {
    QString value;
    if (config.mapGetString(key, &value)) values[key] = value.toStdString();
  }
  const panel::SettingsReading reading = panel::settingsFromKeyValues(values);
  config_problems_.clear();
  for (const auto& problem : reading.problems) {
    ROS_WARN("PatientPanel: %s", problem.c_str());
    config_problems_ += QString::fromStdString(problem) + "\n";
  }
  const bool server_changed = reading.settings.server != state_.server();
  state_.restore(reading.settings);
  if (client_ && server_changed) {
    QMetaObject::invokeMethod(client_,
                              [client = client_, server = QString::fromStdString(state_.server())] {
                                client->connectTo(server);
                                client->listPatients();
                              });
  } else if (reachable_ && state_.hasPendingRestore()) {
    send(state_.takePendingRestore());
  }
  showMessage(config_problems_.trimmed(), !config_problems_.isEmpty());
  refreshWidgets();
}

void PatientPanel::save(rviz::Config config) const {
  rviz::Panel::save(config);
  for (const auto& [key, value] : panel::toKeyValues(state_.settings())) {
    config.mapSetValue(QString::fromStdString(key), QString::fromStdString(value));
  }
}

void PatientPanel::send(const panel::SelectionRequest& request) {
  if (request.patient_id.empty() || !client_) return;
  state_.requestSent();
  QMetaObject::invokeMethod(client_,
                            [client = client_, request, known = state_.categories.legendKnown()] {
                              client->select(request, known);
                            });
  refreshWidgets();
  Q_EMIT configChanged();
}

void PatientPanel::requestDatesIfOutdated() {
  const std::string& patient = state_.patients.selected();
  const std::string key = patient + "@" + (state_.shown() ? state_.shown()->examination_time : "");
  if (!client_ || !state_.datesOutdated() || key == dates_requested_for_) return;
  dates_requested_for_ = key;
  QMetaObject::invokeMethod(
      client_, [client = client_, id = QString::fromStdString(patient)] { client->listDates(id); });
}

void PatientPanel::onPatientActivated(int index) {
  const QString id = patient_combo_->itemData(index).toString();
  if (id.isEmpty()) return;
  send(state_.choosePatient(id.toStdString()));
  requestDatesIfOutdated();
}

void PatientPanel::onTimelineMoved(int index) {
  // While dragging: preview the date under the handle; it is requested on release.
  if (index >= 0 && static_cast<std::size_t>(index) < state_.timeline.size()) {
    timeline_label_->setText(QString::fromStdString(state_.timeline.dateAt(index)) +
                             " (release to show)");
  }
}

void PatientPanel::onTimelineChosen(int index) {
  if (index < 0) return;
  if (const auto request = state_.chooseDateIndex(static_cast<std::size_t>(index))) send(*request);
}

void PatientPanel::onLatestToggled(bool latest) {
  if (latest) {
    send(state_.chooseLatest());
  } else {
    onTimelineChosen(timeline_slider_->value());
  }
}

void PatientPanel::onCategoryToggled(const QString& id, bool visible) {
  send(state_.chooseCategoryVisible(id.toStdString(), visible));
}

void PatientPanel::onRefresh() {
  dates_requested_for_.clear();
  if (!client_) return;
  QMetaObject::invokeMethod(client_, [client = client_] { client->listPatients(); });
  const QString patient = QString::fromStdString(state_.patients.selected());
  if (!patient.isEmpty()) {
    QMetaObject::invokeMethod(client_, [client = client_, patient] { client->listDates(patient); });
  }
}

void PatientPanel::onRetry() {
  if (reachable_ || !client_) return;
  QMetaObject::invokeMethod(client_, [client = client_] { client->listPatients(); });
}

void PatientPanel::onReachability(bool reachable, const QString& message) {
  const bool came_back = reachable && !reachable_;
  reachable_ = reachable;
  if (!message.isEmpty()) {
    showMessage(message, true);
  } else if (came_back) {
    showMessage(config_problems_.isEmpty()
                    ? QString("connected to " + QString::fromStdString(state_.server()))
                    : config_problems_.trimmed(),
                !config_problems_.isEmpty());
  }
  if (!reachable) dates_requested_for_.clear();  // ask again once it answers
}

void PatientPanel::onPatientsListed(const PatientList& patients) {
  state_.patients.setPatients(patients);
  if (state_.hasPendingRestore()) send(state_.takePendingRestore());
  requestDatesIfOutdated();
  refreshWidgets();
}

void PatientPanel::onDatesListed(const QString& patient, const QStringList& dates,
                                 const QString& problem) {
  std::vector<std::string> texts;
  for (const auto& date : dates) texts.push_back(date.toStdString());
  std::vector<std::string> problems;
  if (!state_.datesListed(patient.toStdString(), texts, &problems)) return;  // stale
  if (!problem.isEmpty()) showMessage("examination dates: " + problem, true);
  for (const auto& text : problems) showMessage(QString::fromStdString(text), true);
  refreshWidgets();
}

void PatientPanel::onSelected(const SelectionResult& result) {
  state_.requestAnswered(result.success, result.status);
  QString message = QString::fromStdString(result.message);
  if (!result.success) message = "selection failed: " + message + " (still showing the previous)";
  for (const auto& id : result.dropped_hidden) {
    message += "\nfilter: '" + QString::fromStdString(id) + "' is not a category of this view";
  }
  showMessage(message, !result.success || !result.dropped_hidden.empty());
  requestDatesIfOutdated();
  refreshWidgets();
}

void PatientPanel::onStatusPublished(const panel::ShownStatus& status) {
  state_.statusPublished(status);
  requestDatesIfOutdated();
  refreshWidgets();
}

void PatientPanel::showMessage(const QString& text, bool problem) {
  message_label_->setText(text);
  message_label_->setStyleSheet(problem ? "color: #b00020;" : "");
}

}  // namespace vicc_anatomy_viz::rviz_plugin

PLUGINLIB_EXPORT_CLASS(vicc_anatomy_viz::rviz_plugin::PatientPanel, rviz::Panel)
