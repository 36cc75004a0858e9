// rostest (under Xvfb): the PatientPanel, loaded through pluginlib as rviz loads it, adopts the
// server's selection, and its timeline, category filter and saved configuration reach the
// patient status server: asserted on the EncodedStatus the server then publishes.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QRegularExpression>
#include <QSlider>

#include <memory>

#include <rviz/config.h>
#include <rviz/panel.h>
#include <vicc_msgs/SelectPatient.h>
#include <pluginlib/class_loader.hpp>

#include "panel_test_support.hpp"

using namespace vicc_panel_test;

namespace {

using PanelLoader = pluginlib::ClassLoader<rviz::Panel>;

class PatientPanelTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { loader_ = std::make_unique<PanelLoader>("rviz", "rviz::Panel"); }
  static void TearDownTestSuite() { loader_.reset(); }

  void SetUp() override {
    // Every test starts from the server showing the latest examination, unfiltered.
    vicc_msgs::SelectPatient::Request request;
    request.patient_id = "SDH-046";
    ASSERT_TRUE(call<vicc_msgs::SelectPatient>("select_patient", request).success);
    ASSERT_TRUE(waitFor([&] { return shows(kPostOperative, {}); }));
  }

  /// A panel as rviz creates one: by class name, initialised, then configured.
  std::unique_ptr<rviz::Panel> makePanel(const rviz::Config& config) {
    std::unique_ptr<rviz::Panel> panel(
        loader_->createUnmanagedInstance("vicc_anatomy_viz/PatientPanel"));
    panel->initialize(nullptr);  // the panel needs no VisualizationManager
    panel->load(config);
    panel->show();
    return panel;
  }

  bool shows(const std::string& time, const std::vector<std::string>& hidden) const {
    const auto& last = status_.last();
    return last && last->patient_id == "SDH-046" && last->examination_time == time &&
           last->hidden_categories == hidden;
  }

  static bool waitForPanel(const std::function<bool()>& condition) {
    return waitFor(condition, 10.0, [] { QApplication::processEvents(); });
  }

  template <typename Widget>
  static Widget* child(rviz::Panel& panel, const char* name) {
    auto* widget = panel.findChild<Widget*>(name);
    EXPECT_NE(widget, nullptr) << name;
    return widget;
  }

  // A widget the panel creates once the server has answered (e.g. a category check box);
  // nullptr (and a failure) if it does not appear.
  template <typename Widget>
  static Widget* awaitChild(rviz::Panel& panel, const char* name) {
    waitForPanel([&] { return panel.findChild<Widget*>(name) != nullptr; });
    return child<Widget>(panel, name);
  }

  static std::string text(rviz::Panel& panel, const char* label) {
    return child<QLabel>(panel, label)->text().toStdString();
  }

  static inline std::unique_ptr<PanelLoader> loader_;
  LatchedStatus status_;
};

TEST_F(PatientPanelTest, AdoptsTheServersSelection) {
  auto panel = makePanel({});
  auto* patients = child<QComboBox>(*panel, "patient_selector");
  auto* slider = child<QSlider>(*panel, "timeline_slider");
  ASSERT_TRUE(waitForPanel([&] {
    return patients->currentData().toString() == "SDH-046" && slider->maximum() == 1 &&
           panel->findChildren<QCheckBox*>(QRegularExpression("^category_")).size() == 6;
  })) << text(*panel, "message_label");
  EXPECT_EQ(slider->value(), 1);
  EXPECT_TRUE(child<QCheckBox>(*panel, "latest")->isChecked());
  EXPECT_EQ(text(*panel, "shown_label"), "Shown: SDH-046: examination " + kPostOperative);
  EXPECT_EQ(text(*panel, "timeline_label"), "latest: " + kPostOperative + " (2 of 2)");
}

TEST_F(PatientPanelTest, TimelineAndCategoryFilterReachTheServer) {
  auto panel = makePanel({});
  auto* slider = child<QSlider>(*panel, "timeline_slider");
  ASSERT_TRUE(waitForPanel([&] { return slider->maximum() == 1 && slider->isEnabled(); }));
  slider->setValue(0);  // the pre-operative examination
  ASSERT_TRUE(waitForPanel([&] { return shows(kPreOperative, {}); }))
      << text(*panel, "message_label");
  EXPECT_EQ(status_.last()->requested_date, kPreOperative);
  EXPECT_FALSE(child<QCheckBox>(*panel, "latest")->isChecked());

  auto* paresis = awaitChild<QCheckBox>(*panel, "category_paresis");
  ASSERT_NE(paresis, nullptr);
  ASSERT_TRUE(paresis->isChecked());
  paresis->setChecked(false);
  ASSERT_TRUE(waitForPanel([&] { return shows(kPreOperative, {"paresis"}); }))
      << text(*panel, "message_label");
  for (const auto& structure : status_.last()->structures) {
    EXPECT_NE(structure.category, "paresis") << structure.structure_id;
  }
  child<QCheckBox>(*panel, "latest")->setChecked(true);
  ASSERT_TRUE(waitForPanel([&] { return shows(kPostOperative, {"paresis"}); }));
  EXPECT_EQ(slider->value(), 1);
}

TEST_F(PatientPanelTest, RestoresItsSavedSelection) {
  rviz::Config saved;
  {
    auto panel = makePanel({});
    auto* slider = child<QSlider>(*panel, "timeline_slider");
    ASSERT_TRUE(waitForPanel([&] { return slider->maximum() == 1; }));
    slider->setValue(0);
    ASSERT_TRUE(waitForPanel([&] { return shows(kPreOperative, {}); }));
    auto* sensory = awaitChild<QCheckBox>(*panel, "category_sensory_disorder");
    ASSERT_NE(sensory, nullptr);  // the boxes come with the server's view, asynchronously
    sensory->setChecked(false);
    ASSERT_TRUE(waitForPanel([&] { return shows(kPreOperative, {"sensory_disorder"}); }));
    panel->save(saved);
  }
  QString value;
  ASSERT_TRUE(saved.mapGetString("Patient", &value));
  EXPECT_EQ(value.toStdString(), "SDH-046");
  ASSERT_TRUE(saved.mapGetString("Date", &value));
  EXPECT_EQ(value.toStdString(), kPreOperative);
  ASSERT_TRUE(saved.mapGetString("Hidden Categories", &value));
  EXPECT_EQ(value.toStdString(), "sensory_disorder");
  ASSERT_TRUE(saved.mapGetString("Server", &value));
  EXPECT_EQ(value.toStdString(), "/patient_status_server");

  SetUp();  // someone else selects the latest examination meanwhile
  auto restored = makePanel(saved);
  ASSERT_TRUE(waitForPanel([&] { return shows(kPreOperative, {"sensory_disorder"}); }))
      << text(*restored, "message_label");
  auto* restored_sensory = awaitChild<QCheckBox>(*restored, "category_sensory_disorder");
  ASSERT_NE(restored_sensory, nullptr);
  EXPECT_FALSE(restored_sensory->isChecked());
}

TEST_F(PatientPanelTest, ACategoryOutsideTheViewIsReportedAndNotRequested) {
  rviz::Config config;
  config.mapSetValue("Patient", "SDH-046");
  config.mapSetValue("Hidden Categories", "paresis,bowel_noise");
  auto panel = makePanel(config);
  ASSERT_TRUE(waitForPanel([&] { return shows(kPostOperative, {"paresis"}); }))
      << text(*panel, "message_label");
  ASSERT_TRUE(waitForPanel([&] {
    return text(*panel, "message_label").find("'bowel_noise'") != std::string::npos;
  })) << text(*panel, "message_label");
}

TEST_F(PatientPanelTest, SaysSoWhenTheServerIsNotThere) {
  rviz::Config config;
  config.mapSetValue("Server", "/no_such_server");
  config.mapSetValue("Patient", "SDH-046");
  auto panel = makePanel(config);
  ASSERT_TRUE(waitForPanel([&] {
    return text(*panel, "message_label").find("does not answer (/no_such_server/list_patients)") !=
           std::string::npos;
  })) << text(*panel, "message_label");
  EXPECT_TRUE(shows(kPostOperative, {}));  // nothing was selected
}

TEST_F(PatientPanelTest, BadConfigurationValuesAreReportedByKey) {
  rviz::Config config;
  config.mapSetValue("Date", "06.03.2023");
  auto panel = makePanel(config);
  EXPECT_NE(text(*panel, "message_label").find("'Date': '06.03.2023'"), std::string::npos)
      << text(*panel, "message_label");
  // The bad date is not used: the panel adopts what the server shows.
  ASSERT_TRUE(waitForPanel([&] {
    return text(*panel, "shown_label") == "Shown: SDH-046: examination " + kPostOperative;
  }));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "patient_panel_rostest");
  ros::NodeHandle nh;
  QApplication app(argc, argv);
  const int result = RUN_ALL_TESTS();
  removeSampleDatabase();
  return result;
}
