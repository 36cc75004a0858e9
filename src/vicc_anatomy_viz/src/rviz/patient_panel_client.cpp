#include "vicc_anatomy_viz/rviz/patient_panel_client.hpp"

#include <algorithm>

#include <vicc_msgs/GetEncodedStatus.h>
#include <vicc_msgs/ListExaminationDates.h>
#include <vicc_msgs/ListPatients.h>
#include <vicc_msgs/SelectPatient.h>

#include "vicc_common/ros_service_call.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

panel::ShownStatus toShownStatus(const vicc_msgs::EncodedStatus& msg) {
  panel::ShownStatus shown;
  shown.patient_id = msg.patient_id;
  shown.requested_date = msg.requested_date;
  shown.has_examination = msg.has_examination;
  shown.examination_time = msg.examination_time;
  shown.examination_status = msg.examination_status;
  shown.partial = msg.examination_partial;
  shown.partial_reason = msg.partial_reason;
  shown.hidden_categories = msg.hidden_categories;
  for (const auto& entry : msg.legend) {
    shown.legend.push_back(
        {entry.id, entry.label, entry.count, entry.color.r, entry.color.g, entry.color.b});
  }
  return shown;
}

PatientServerClient::PatientServerClient() : status_spinner_(1, &status_queue_) {
  nh_.setCallbackQueue(&status_queue_);
  status_spinner_.start();
}

PatientServerClient::~PatientServerClient() {
  status_sub_.shutdown();
  status_spinner_.stop();
}

void PatientServerClient::registerMetaTypes() {
  qRegisterMetaType<panel::SelectionRequest>("vicc_anatomy_viz::panel::SelectionRequest");
  qRegisterMetaType<panel::ShownStatus>("vicc_anatomy_viz::panel::ShownStatus");
  qRegisterMetaType<SelectionResult>("vicc_anatomy_viz::rviz_plugin::SelectionResult");
  qRegisterMetaType<PatientList>("vicc_anatomy_viz::rviz_plugin::PatientList");
}

void PatientServerClient::connectTo(const QString& server) {
  const std::string name = server.toStdString();
  if (name == server_ && status_sub_) return;
  server_ = name == "/" ? "" : name;
  status_sub_ = nh_.subscribe<vicc_msgs::EncodedStatus>(
      service("status"), 1, [this](const vicc_msgs::EncodedStatus::ConstPtr& msg) {
        Q_EMIT statusPublished(toShownStatus(*msg));  // queued into the GUI thread
      });
}

template <typename Service>
bool PatientServerClient::call(const char* name, Service& srv) {
  const std::string full_name = service(name);
  // Every request of the panel may be repeated (queries and selections).
  if (vicc_common::callRepeatableService(full_name, srv)) {
    Q_EMIT reachabilityChanged(true, QString());
    return true;
  }
  Q_EMIT reachabilityChanged(
      false, QString::fromStdString("the patient status server does not answer (" + full_name +
                                    "); is it running? Retrying."));
  return false;
}

void PatientServerClient::listPatients() {
  vicc_msgs::ListPatients srv;
  if (!call("list_patients", srv)) return;
  if (!srv.response.success) {
    Q_EMIT reachabilityChanged(
        true, QString::fromStdString("listing patients failed: " + srv.response.message));
    return;
  }
  PatientList patients;
  for (const auto& summary : srv.response.patients) {
    patients.push_back({summary.patient_id, summary.examination_count, summary.first_examination,
                        summary.last_examination});
  }
  Q_EMIT patientsListed(patients);
}

void PatientServerClient::listDates(const QString& patient) {
  vicc_msgs::ListExaminationDates srv;
  srv.request.patient_id = patient.toStdString();
  if (!call("list_examination_dates", srv)) return;
  QStringList dates;
  for (const auto& date : srv.response.dates) dates << QString::fromStdString(date);
  Q_EMIT datesListed(
      patient, dates,
      srv.response.success ? QString() : QString::fromStdString(srv.response.message));
}

void PatientServerClient::dropUnknownCategories(panel::SelectionRequest& request,
                                                SelectionResult& result) {
  vicc_msgs::GetEncodedStatus probe;
  probe.request.patient_id = request.patient_id;
  probe.request.date = request.date;
  // Without a successful answer the selection goes ahead unchanged and the server reports.
  if (!call("get_encoded_status", probe) || !probe.response.success) return;
  std::vector<std::string> known;
  for (const auto& entry : probe.response.status.legend) known.push_back(entry.id);
  const auto kept = panel::keepKnownCategories(request.hidden_categories, known);
  for (const auto& id : request.hidden_categories) {
    if (std::find(kept.begin(), kept.end(), id) == kept.end()) result.dropped_hidden.push_back(id);
  }
  request.hidden_categories = kept;
}

void PatientServerClient::select(const panel::SelectionRequest& request, bool legend_known) {
  SelectionResult result;
  panel::SelectionRequest effective = request;
  if (!legend_known && !effective.hidden_categories.empty()) {
    dropUnknownCategories(effective, result);
  }
  vicc_msgs::SelectPatient srv;
  srv.request.patient_id = effective.patient_id;
  srv.request.date = effective.date;
  srv.request.hidden_categories = effective.hidden_categories;
  if (!call("select_patient", srv)) {
    result.message = "the patient status server does not answer";
  } else {
    result.success = srv.response.success;
    result.message = srv.response.message;
    if (result.success) result.status = toShownStatus(srv.response.status);
  }
  Q_EMIT selected(result);
}

}  // namespace vicc_anatomy_viz::rviz_plugin
