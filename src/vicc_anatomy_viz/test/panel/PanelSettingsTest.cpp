// The panel's configuration as key/value text: round trip, validation naming the key.
#include <gtest/gtest.h>

#include "vicc_anatomy_viz/panel_logic/panel_settings.hpp"

using namespace vicc_anatomy_viz::panel;

TEST(PanelSettingsTest, RoundTripsThroughKeyValues) {
  PanelSettings settings;
  settings.server = "/clinic/patient_status_server";
  settings.patient_id = "SDH-046";
  settings.date = "2023-03-06T09:15:00Z";
  settings.hidden_categories = {"sensory_disorder", "radicular_pain"};
  const KeyValues values = toKeyValues(settings);
  EXPECT_EQ(values.at("Hidden Categories"), "sensory_disorder,radicular_pain");
  const SettingsReading reading = settingsFromKeyValues(values);
  EXPECT_TRUE(reading.problems.empty());
  EXPECT_EQ(reading.settings.server, settings.server);
  EXPECT_EQ(reading.settings.patient_id, settings.patient_id);
  EXPECT_EQ(reading.settings.date, settings.date);
  EXPECT_EQ(reading.settings.hidden_categories, settings.hidden_categories);
}

TEST(PanelSettingsTest, MissingKeysGiveTheDefaultsAndForeignKeysAreIgnored) {
  const SettingsReading reading = settingsFromKeyValues({{"Class", "x"}, {"Name", "Patient"}});
  EXPECT_TRUE(reading.problems.empty());
  EXPECT_EQ(reading.settings.server, "/patient_status_server");
  EXPECT_EQ(reading.settings.patient_id, "");
  EXPECT_EQ(reading.settings.date, "");
  EXPECT_TRUE(reading.settings.hidden_categories.empty());
}

TEST(PanelSettingsTest, BadValuesAreReportedByKeyAndReplacedByDefaults) {
  const SettingsReading reading = settingsFromKeyValues({{"Server", "patient status"},
                                                         {"Patient", "Doe, John"},
                                                         {"Date", "06.03.2023"},
                                                         {"Hidden Categories", "paresis, a b,,"}});
  ASSERT_EQ(reading.problems.size(), 4u);
  EXPECT_NE(reading.problems[0].find("'Server': 'patient status'"), std::string::npos);
  EXPECT_NE(reading.problems[1].find("'Patient'"), std::string::npos);
  EXPECT_NE(reading.problems[2].find("'Date': '06.03.2023'"), std::string::npos);
  EXPECT_NE(reading.problems[3].find("'Hidden Categories': 'a b'"), std::string::npos);
  EXPECT_EQ(reading.settings.server, "/patient_status_server");
  EXPECT_EQ(reading.settings.patient_id, "");
  EXPECT_EQ(reading.settings.date, "");
  EXPECT_EQ(reading.settings.hidden_categories, std::vector<std::string>{"paresis"});
}

TEST(PanelSettingsTest, SplitsAndJoinsCategoryLists) {
  EXPECT_EQ(splitCategories(" a , b,,c "), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_TRUE(splitCategories("").empty());
  EXPECT_EQ(joinCategories({"a", "b"}), "a,b");
  EXPECT_EQ(joinCategories({}), "");
}
