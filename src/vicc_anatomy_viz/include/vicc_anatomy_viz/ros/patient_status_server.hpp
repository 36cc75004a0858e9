#pragma once
// The patient_status_server node: services to list patients, list a patient's examination
// dates, get the encoded status at a date and record an examination; the selected patient's
// encoded status is published latched on ~status (selection by service or topic, for the
// rviz panel's timeline). Bad requests get success=false and a message; the node keeps running.

#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <vicc_msgs/GetEncodedStatus.h>
#include <vicc_msgs/ListExaminationDates.h>
#include <vicc_msgs/ListPatients.h>
#include <vicc_msgs/PatientSelection.h>
#include <vicc_msgs/RecordExamination.h>
#include <vicc_msgs/SelectPatient.h>

#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/ros/patient_status_server_settings.hpp"

namespace vicc_anatomy_viz::ros_adapter {

/// Parameters (the table of patient_status_server_settings.hpp): ~db, ~encoding_config,
/// ~anatomy_config, ~view, ~busy_timeout_ms, ~max_future_s, and an optional initial selection
/// ~patient / ~date. A wrong type or an invalid value throws std::invalid_argument naming the
/// parameter; unknown parameters in the node's namespace are named in a warning.
PatientStatusServerSettings readServerSettings(const ros::NodeHandle& private_nh);

class PatientStatusServer {
 public:
  /// Throws ConfigError / std::invalid_argument for an unusable configuration.
  PatientStatusServer(ros::NodeHandle& nh, ros::NodeHandle& private_nh);

 private:
  struct Selection {
    std::string patient_id;
    std::string date;
    std::vector<std::string> hidden_categories;
  };

  bool listPatients(vicc_msgs::ListPatients::Request& request,
                    vicc_msgs::ListPatients::Response& response);
  bool listDates(vicc_msgs::ListExaminationDates::Request& request,
                 vicc_msgs::ListExaminationDates::Response& response);
  bool getStatus(vicc_msgs::GetEncodedStatus::Request& request,
                 vicc_msgs::GetEncodedStatus::Response& response);
  bool record(vicc_msgs::RecordExamination::Request& request,
              vicc_msgs::RecordExamination::Response& response);
  bool select(vicc_msgs::SelectPatient::Request& request,
              vicc_msgs::SelectPatient::Response& response);
  void onSelection(const vicc_msgs::PatientSelection& selection);

  /// Encodes `selection`, publishes it latched and makes it current; false + message if the
  /// selection cannot be encoded (the previous one stays).
  bool applySelection(const Selection& selection, std::string& message,
                      vicc_msgs::EncodedStatus* status);

  std::unique_ptr<PatientStatusService> service_;
  Selection selection_;
  bool has_selection_ = false;
  ros::Publisher status_pub_;
  ros::Subscriber select_sub_;
  std::vector<ros::ServiceServer> services_;
};

}  // namespace vicc_anatomy_viz::ros_adapter
