// rostest: the patient_status_server records examinations (rejecting invalid ones whole),
// lists patients and dates, serves encoded statuses at dates with the category filter, and
// publishes the selected patient's status latched (selection by service and by topic).
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <optional>
#include <type_traits>

#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>
#include <vicc_msgs/EncodedStatus.h>
#include <vicc_msgs/GetEncodedStatus.h>
#include <vicc_msgs/ListExaminationDates.h>
#include <vicc_msgs/ListPatients.h>
#include <vicc_msgs/PatientSelection.h>
#include <vicc_msgs/RecordExamination.h>
#include <vicc_msgs/SelectPatient.h>
#include <nlohmann/json.hpp>

#include "vicc_anatomy_viz/record_json.hpp"
#include "vicc_anatomy_viz/time_format.hpp"
#include "vicc_common/ros_service_call.hpp"

namespace {

const std::string kNs = "/patient_status_server/";

std::vector<vicc_anatomy_viz::Examination> figurePatient() {
  const std::string path = std::string(VICC_TEST_PACKAGE_DIR) + "/data/samples/fig4_6_patient.json";
  return vicc_anatomy_viz::examinationsFromJson(
      vicc_anatomy_viz::parseJsonText(vicc_anatomy_viz::readTextFile(path), path));
}

vicc_msgs::RecordExamination::Request recordRequest(const vicc_anatomy_viz::Examination& exam) {
  vicc_msgs::RecordExamination::Request request;
  request.patient_id = exam.patient_id;
  request.taken_at = vicc_anatomy_viz::formatTimestamp(exam.taken_at_us);
  for (const auto& finding : exam.findings) {
    vicc_msgs::Finding msg;
    msg.category = finding.category;
    msg.structure_id = finding.structure;
    msg.side = vicc_anatomy_viz::toString(finding.side);
    for (const auto& [prop_type, value] : finding.values) {
      vicc_msgs::PropertyValue v;
      v.prop_type = prop_type;
      v.value = value.toString();
      msg.values.push_back(v);
    }
    request.findings.push_back(msg);
  }
  return request;
}

template <typename Service>
typename Service::Response call(const std::string& name, typename Service::Request request) {
  Service service;
  service.request = request;
  EXPECT_TRUE(ros::service::waitForService(kNs + name, ros::Duration(20.0))) << name;
  // A record must reach the server once (a repeat after a lost response would be rejected as
  // already recorded); queries and selections may be repeated (ros_service_call.hpp).
  constexpr bool kRecords = std::is_same_v<Service, vicc_msgs::RecordExamination>;
  EXPECT_TRUE(kRecords ? ros::service::call(kNs + name, service)
                       : vicc_common::callRepeatableService(kNs + name, service))
      << name;
  return service.response;
}

bool waitFor(const std::function<bool()>& condition, double seconds = 10.0) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    if (condition()) return true;
    ros::WallDuration(0.02).sleep();
  }
  return condition();
}

/// The tests share one server and database and run in order.
class PatientStatusServerTest : public ::testing::Test {
 protected:
  static void TearDownTestSuite() {
    std::string db;
    if (ros::param::get("~db", db)) {
      for (const char* suffix : {"", "-wal", "-shm"}) std::remove((db + suffix).c_str());
    }
  }
};

TEST_F(PatientStatusServerTest, StartsWithAnEmptyDatabase) {
  const auto response = call<vicc_msgs::ListPatients>("list_patients", {});
  EXPECT_TRUE(response.success) << response.message;
  EXPECT_TRUE(response.patients.empty());
}

TEST_F(PatientStatusServerTest, RecordsValidExaminationsAndRejectsInvalidOnesWhole) {
  const auto figure = figurePatient();
  for (const auto& exam : figure) {
    const auto response =
        call<vicc_msgs::RecordExamination>("record_examination", recordRequest(exam));
    EXPECT_TRUE(response.success) << response.message;
  }
  // Everything the server logs (what rosout writes into rosout.log), to prove that a rejected
  // value never reaches the log. Read from /rosout: rostest runs no rosout aggregator here.
  std::vector<std::string> logged;
  std::vector<std::string> senders;
  ros::NodeHandle nh;
  const ros::Subscriber rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 100, [&](const rosgraph_msgs::Log::ConstPtr& log) {
        senders.push_back(log->name);
        if (log->name == "/patient_status_server") logged.push_back(log->msg);
      });
  // This node publishes /rosout too: wait for the server's connection as well.
  ASSERT_TRUE(waitFor([&] { return rosout.getNumPublishers() >= 2; }));
  auto bad = recordRequest(figure[0]);
  bad.taken_at = "2023-03-20T10:00:00Z";
  bad.findings[0].values[0].value = "4711";  // pain intensity far outside 0..10
  auto response = call<vicc_msgs::RecordExamination>("record_examination", bad);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("property 'intensity': the value is outside the domain 0..10"),
            std::string::npos)
      << response.message;
  EXPECT_EQ(response.message.find("4711"), std::string::npos) << response.message;
  ASSERT_TRUE(waitFor([&] {
    for (const auto& line : logged) {
      if (line.find("record_examination failed") != std::string::npos) return true;
    }
    return false;
  })) << "the rejection was not logged; "
      << senders.size() << " messages from "
      << (senders.empty() ? std::string("nobody") : senders.front());
  for (const auto& line : logged) EXPECT_EQ(line.find("4711"), std::string::npos) << line;
  bad = recordRequest(figure[0]);
  bad.taken_at = "2023-03-21T10:00:00Z";
  bad.findings[1].structure_id = "dermatome_L9";
  bad.findings[2].side = "middle";
  response = call<vicc_msgs::RecordExamination>("record_examination", bad);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("side 'middle' is not left, right or none"), std::string::npos)
      << response.message;
  response = call<vicc_msgs::RecordExamination>("record_examination", recordRequest(figure[0]));
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("already recorded"), std::string::npos);

  const auto patients = call<vicc_msgs::ListPatients>("list_patients", {});
  ASSERT_EQ(patients.patients.size(), 1u);
  EXPECT_EQ(patients.patients[0].patient_id, "SDH-046");
  EXPECT_EQ(patients.patients[0].examination_count, 2u);
}

TEST_F(PatientStatusServerTest, ListsExaminationDates) {
  vicc_msgs::ListExaminationDates::Request request;
  request.patient_id = "SDH-046";
  auto response = call<vicc_msgs::ListExaminationDates>("list_examination_dates", request);
  ASSERT_TRUE(response.success) << response.message;
  EXPECT_EQ(response.dates,
            (std::vector<std::string>{"2023-03-06T09:15:00Z", "2023-03-10T08:40:00Z"}));
  ASSERT_EQ(response.stamps.size(), 2u);
  EXPECT_EQ(response.stamps[0].sec, 1678094100u);
  request.patient_id = "SDH-404";
  response = call<vicc_msgs::ListExaminationDates>("list_examination_dates", request);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("unknown patient 'SDH-404'"), std::string::npos);
}

TEST_F(PatientStatusServerTest, ServesTheEncodedStatusAtOrBeforeADate) {
  vicc_msgs::GetEncodedStatus::Request request;
  request.patient_id = "SDH-046";
  request.date = "2023-03-08";
  auto response = call<vicc_msgs::GetEncodedStatus>("get_encoded_status", request);
  ASSERT_TRUE(response.success) << response.message;
  const vicc_msgs::EncodedStatus& status = response.status;
  EXPECT_TRUE(status.has_examination);
  EXPECT_EQ(status.examination_time, "2023-03-06T09:15:00Z");
  EXPECT_EQ(status.structures.size(), 7u);  // Fig. 4.6 and the (illustrative) ICP 26 mmHg
  ASSERT_EQ(status.alternations.size(), 1u);
  EXPECT_EQ(status.alternations[0].structure_id, "dermatome_L5");
  EXPECT_EQ(status.alternations[0].side, "left");
  EXPECT_EQ(status.legend.size(), 6u);
  std::size_t proxies = 0;
  for (const auto& entry : status.structures) proxies += entry.proxy;
  EXPECT_EQ(proxies, 2u);  // both patellar reflexes
  const auto json = nlohmann::json::parse(response.json);
  EXPECT_EQ(json["structures"].size(), 7u);

  request.hidden_categories = {"radicular_pain"};
  response = call<vicc_msgs::GetEncodedStatus>("get_encoded_status", request);
  ASSERT_TRUE(response.success);
  EXPECT_TRUE(response.status.alternations.empty());
  EXPECT_EQ(response.status.structures.size(), 6u);

  request.hidden_categories = {};
  request.date = "2023-03-10";
  response = call<vicc_msgs::GetEncodedStatus>("get_encoded_status", request);
  EXPECT_EQ(response.status.examination_time, "2023-03-10T08:40:00Z");
  EXPECT_EQ(response.status.structures.size(), 2u);

  request.date = "not a date";
  response = call<vicc_msgs::GetEncodedStatus>("get_encoded_status", request);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("is not ISO 8601"), std::string::npos);
}

TEST_F(PatientStatusServerTest, PublishesTheSelectedPatientLatched) {
  ros::NodeHandle nh;
  std::optional<vicc_msgs::EncodedStatus> last;
  ros::Subscriber sub = nh.subscribe<vicc_msgs::EncodedStatus>(
      kNs + "status", 10, [&](const vicc_msgs::EncodedStatusConstPtr& msg) { last = *msg; });

  vicc_msgs::SelectPatient::Request select;
  select.patient_id = "SDH-046";
  const auto selected = call<vicc_msgs::SelectPatient>("select_patient", select);
  ASSERT_TRUE(selected.success) << selected.message;
  EXPECT_EQ(selected.status.examination_time, "2023-03-10T08:40:00Z");
  ASSERT_TRUE(waitFor([&] { return last.has_value(); }));
  EXPECT_EQ(last->examination_time, "2023-03-10T08:40:00Z");

  // Selection by topic, as the timeline slider of the rviz panel does.
  ros::Publisher pub = nh.advertise<vicc_msgs::PatientSelection>(kNs + "select", 1, true);
  vicc_msgs::PatientSelection selection;
  selection.patient_id = "SDH-046";
  selection.date = "2023-03-06";
  pub.publish(selection);
  ASSERT_TRUE(waitFor([&] { return last && last->examination_time == "2023-03-06T09:15:00Z"; }));
  EXPECT_EQ(last->alternations.size(), 1u);

  // A failed selection keeps the current one.
  select.patient_id = "SDH-404";
  EXPECT_FALSE(call<vicc_msgs::SelectPatient>("select_patient", select).success);

  // A new examination of the selected patient is published at once.
  select.patient_id = "SDH-046";
  ASSERT_TRUE(call<vicc_msgs::SelectPatient>("select_patient", select).success);
  auto later = recordRequest(figurePatient()[1]);
  later.taken_at = "2023-04-20T09:00:00Z";
  ASSERT_TRUE(call<vicc_msgs::RecordExamination>("record_examination", later).success);
  ASSERT_TRUE(waitFor([&] { return last && last->examination_time == "2023-04-20T09:00:00Z"; }));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "patient_status_server_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
