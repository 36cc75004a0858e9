#include "vicc_anatomy_viz/ros/patient_status_server.hpp"

#include <set>
#include <stdexcept>

#include "vicc_anatomy_viz/encoded_status_json.hpp"
#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/ros/status_message.hpp"
#include "vicc_anatomy_viz/time_format.hpp"
#include "vicc_common/ros_parameters.hpp"

namespace vicc_anatomy_viz::ros_adapter {

namespace {

/// Runs one request; any failure becomes success=false with a message naming the problem.
/// (`Flag` is bool or the uint8 of a ROS bool field.)
template <typename Flag, typename Action>
bool guarded(const char* what, Flag& success, std::string& message, Action action) {
  try {
    action();
    success = true;
  } catch (const std::exception& e) {
    success = false;
    message = e.what();
    ROS_WARN("patient_status_server: %s failed: %s", what, e.what());
  }
  return true;  // the service call itself succeeded; the outcome is in `success`
}

}  // namespace

PatientStatusServerSettings PatientStatusServerSettings::withDefaultPaths() {
  PatientStatusServerSettings settings;
  settings.db = defaultDatabasePath();
  settings.encoding_config = defaultEncodingConfigPath();
  settings.anatomy_config = defaultAnatomyConfigPath();
  return settings;
}

PatientStatusConfig PatientStatusServerSettings::serviceConfig() const {
  PatientStatusConfig config;
  config.store.path = db;
  config.encoding_config = encoding_config;
  config.anatomy_config = anatomy_config;
  config.view_id = view;
  config.store.busy_timeout_ms = busy_timeout_ms;
  config.plausibility.max_future_seconds = max_future_s;
  return config;
}

void PatientStatusServerSettings::validate() const {
  if (!date.empty() && patient.empty()) {
    throw std::invalid_argument(
        "date is set but patient is not (the date selects an "
        "examination of that patient)");
  }
  serviceConfig().validate();
}

PatientStatusServerSettings readServerSettings(const ros::NodeHandle& private_nh) {
  PatientStatusServerSettings settings = PatientStatusServerSettings::withDefaultPaths();
  std::set<std::string> read_names;
  vicc_common::readRosParameters(private_nh, settings, read_names);
  vicc_common::warnUnknownRosParameters(private_nh, read_names);
  return settings;
}

PatientStatusServer::PatientStatusServer(ros::NodeHandle& nh, ros::NodeHandle& private_nh) {
  (void)nh;
  const PatientStatusServerSettings settings = readServerSettings(private_nh);
  service_ = std::make_unique<PatientStatusService>(settings.serviceConfig());
  for (const auto& note : service_->model().notes(service_->view())) {
    ROS_INFO("patient_status_server: %s", note.c_str());
  }
  for (const auto& warning : service_->model().report().global_warnings) {
    ROS_WARN("patient_status_server: %s", warning.c_str());
  }
  status_pub_ = private_nh.advertise<vicc_msgs::EncodedStatus>("status", 1, /*latch=*/true);
  select_sub_ = private_nh.subscribe("select", 10, &PatientStatusServer::onSelection, this);
  services_.push_back(
      private_nh.advertiseService("list_patients", &PatientStatusServer::listPatients, this));
  services_.push_back(
      private_nh.advertiseService("list_examination_dates", &PatientStatusServer::listDates, this));
  services_.push_back(
      private_nh.advertiseService("get_encoded_status", &PatientStatusServer::getStatus, this));
  services_.push_back(
      private_nh.advertiseService("record_examination", &PatientStatusServer::record, this));
  services_.push_back(
      private_nh.advertiseService("select_patient", &PatientStatusServer::select, this));

  // The database is opened now to report problems early; requests retry a failed open.
  try {
    RecordStore& store = service_->store();
    ROS_INFO("patient_status_server: database %s, view %s", service_->config().store.path.c_str(),
             service_->config().view_id.c_str());
    for (const auto& warning : store.warnings()) {
      ROS_WARN("patient_status_server: %s", warning.c_str());
    }
  } catch (const std::exception& e) {
    ROS_ERROR("patient_status_server: %s (requests will retry)", e.what());
  }
  Selection initial;
  initial.patient_id = settings.patient;
  initial.date = settings.date;
  if (!initial.patient_id.empty()) {
    std::string message;
    if (!applySelection(initial, message, nullptr)) {
      ROS_WARN("patient_status_server: initial selection failed: %s", message.c_str());
    }
  }
}

bool PatientStatusServer::listPatients(vicc_msgs::ListPatients::Request& /*request*/,
                                       vicc_msgs::ListPatients::Response& response) {
  return guarded("list_patients", response.success, response.message, [&] {
    for (const auto& summary : service_->listPatients()) {
      response.patients.push_back(toMessage(summary));
    }
  });
}

bool PatientStatusServer::listDates(vicc_msgs::ListExaminationDates::Request& request,
                                    vicc_msgs::ListExaminationDates::Response& response) {
  return guarded("list_examination_dates", response.success, response.message, [&] {
    for (const auto time : service_->examinationDates(request.patient_id)) {
      response.dates.push_back(formatTimestamp(time));
      response.stamps.push_back(rosTime(time));
    }
  });
}

bool PatientStatusServer::getStatus(vicc_msgs::GetEncodedStatus::Request& request,
                                    vicc_msgs::GetEncodedStatus::Response& response) {
  return guarded("get_encoded_status", response.success, response.message, [&] {
    const EncodedStatus status =
        service_->encodedStatus(request.patient_id, request.date, request.hidden_categories);
    response.status = toMessage(status);
    response.status.header.stamp = ros::Time::now();
    response.json = toJson(status).dump();
  });
}

bool PatientStatusServer::record(vicc_msgs::RecordExamination::Request& request,
                                 vicc_msgs::RecordExamination::Response& response) {
  return guarded("record_examination", response.success, response.message, [&] {
    Examination examination = examinationFromRequest(service_->model(), request.patient_id,
                                                     request.taken_at, request.findings);
    const std::string described = examination.describe();
    const WriteMode mode = !request.replace             ? WriteMode::kRejectExisting
                           : request.replace_with_empty ? WriteMode::kReplaceEvenWithEmpty
                                                        : WriteMode::kReplace;
    service_->record({examination}, mode);
    response.message = "recorded " + described;
    ROS_INFO("patient_status_server: %s", response.message.c_str());
    // Keep the published status current when the selected patient got a new examination.
    if (has_selection_ && selection_.patient_id == request.patient_id) {
      std::string message;
      if (!applySelection(selection_, message, nullptr)) {
        ROS_WARN("patient_status_server: republishing failed: %s", message.c_str());
      }
    }
  });
}

bool PatientStatusServer::select(vicc_msgs::SelectPatient::Request& request,
                                 vicc_msgs::SelectPatient::Response& response) {
  const Selection selection{request.patient_id, request.date, request.hidden_categories};
  response.success = applySelection(selection, response.message, &response.status);
  return true;
}

void PatientStatusServer::onSelection(const vicc_msgs::PatientSelection& msg) {
  const Selection selection{msg.patient_id, msg.date, msg.hidden_categories};
  std::string message;
  if (!applySelection(selection, message, nullptr)) {
    ROS_WARN("patient_status_server: selection ignored: %s", message.c_str());
  }
}

bool PatientStatusServer::applySelection(const Selection& selection, std::string& message,
                                         vicc_msgs::EncodedStatus* status) {
  bool success = false;
  guarded("select", success, message, [&] {
    vicc_msgs::EncodedStatus msg = toMessage(
        service_->encodedStatus(selection.patient_id, selection.date, selection.hidden_categories));
    msg.header.stamp = ros::Time::now();
    status_pub_.publish(msg);
    selection_ = selection;
    has_selection_ = true;
    message = "selected patient " + selection.patient_id +
              (msg.has_examination ? ", examination " + msg.examination_time
                                   : ", no examination at that date");
    if (status) *status = msg;
  });
  return success;
}

}  // namespace vicc_anatomy_viz::ros_adapter
