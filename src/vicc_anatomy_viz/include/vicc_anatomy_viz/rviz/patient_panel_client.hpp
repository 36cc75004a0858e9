#pragma once
// The patient panel's connection to the patient status server. The object lives in a worker
// thread: every service call blocks there, never in rviz's GUI thread, and each result goes back
// as a (queued) signal. The latched status topic is spun on a queue of its own.

#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <vector>

#ifndef Q_MOC_RUN
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <ros/spinner.h>
#include <vicc_msgs/EncodedStatus.h>
#endif

#include "vicc_anatomy_viz/panel_logic/patient_panel_state.hpp"

namespace vicc_anatomy_viz::rviz_plugin {

struct SelectionResult {
  bool success = false;
  std::string message;
  std::optional<panel::ShownStatus> status;  ///< what the server now publishes
  std::vector<std::string> dropped_hidden;   ///< filter ids the view does not have
};

using PatientList = std::vector<panel::PatientItem>;

/// vicc_msgs/EncodedStatus -> what the panel shows of it.
panel::ShownStatus toShownStatus(const vicc_msgs::EncodedStatus& msg);

class PatientServerClient : public QObject {
  Q_OBJECT
 public:
  PatientServerClient();
  ~PatientServerClient() override;

  /// Registers the signal argument types for queued connections (once, before connecting).
  static void registerMetaTypes();

 public Q_SLOTS:
  /// Uses the server in namespace `server` (services and its latched `status` topic).
  void connectTo(const QString& server);
  void listPatients();
  void listDates(const QString& patient);
  /// SelectPatient; before the view's categories are known (`legend_known` false) a read-only
  /// GetEncodedStatus first learns them, so that the filter names only categories of the view.
  void select(const vicc_anatomy_viz::panel::SelectionRequest& request, bool legend_known);

 Q_SIGNALS:
  /// After every call: whether the server answered, and if not, why.
  void reachabilityChanged(bool reachable, const QString& message);
  void patientsListed(const vicc_anatomy_viz::rviz_plugin::PatientList& patients);
  void datesListed(const QString& patient, const QStringList& dates, const QString& problem);
  void selected(const vicc_anatomy_viz::rviz_plugin::SelectionResult& result);
  void statusPublished(const vicc_anatomy_viz::panel::ShownStatus& status);

 private:
  std::string service(const char* name) const { return server_ + "/" + name; }
  /// Calls the service; false (and reachabilityChanged(false)) when it does not answer.
  template <typename Service>
  bool call(const char* name, Service& srv);
  void dropUnknownCategories(panel::SelectionRequest& request, SelectionResult& result);

  std::string server_;
  ros::NodeHandle nh_;
  ros::CallbackQueue status_queue_;
  ros::AsyncSpinner status_spinner_;
  ros::Subscriber status_sub_;
};

}  // namespace vicc_anatomy_viz::rviz_plugin

Q_DECLARE_METATYPE(vicc_anatomy_viz::panel::SelectionRequest)
Q_DECLARE_METATYPE(vicc_anatomy_viz::panel::ShownStatus)
Q_DECLARE_METATYPE(vicc_anatomy_viz::rviz_plugin::SelectionResult)
Q_DECLARE_METATYPE(vicc_anatomy_viz::rviz_plugin::PatientList)
