#pragma once
// Conversions between the core types and vicc_msgs (EncodedStatus, Finding, PatientSummary).

#include <string>
#include <vector>

#include <vicc_msgs/EncodedStatus.h>
#include <vicc_msgs/Finding.h>
#include <vicc_msgs/PatientSummary.h>

#include "vicc_anatomy_viz/encoding_model.hpp"
#include "vicc_anatomy_viz/patient_record.hpp"
#include "vicc_anatomy_viz/status_encoder.hpp"

namespace vicc_anatomy_viz::ros_adapter {

/// The ROS time of an examination; zero outside ros::Time's range (1970..2106).
ros::Time rosTime(TimestampUs time);
vicc_msgs::EncodedStatus toMessage(const EncodedStatus& status);
vicc_msgs::PatientSummary toMessage(const PatientSummary& summary);

/// A recorded examination from a service request. Values arrive as text and are read with
/// their property's type; a bad side or time throws ValidationError naming the finding.
Examination examinationFromRequest(const EncodingModel& model, const std::string& patient_id,
                                   const std::string& taken_at,
                                   const std::vector<vicc_msgs::Finding>& findings);

}  // namespace vicc_anatomy_viz::ros_adapter
