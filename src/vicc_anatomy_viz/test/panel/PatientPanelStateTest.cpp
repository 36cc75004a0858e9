// The panel without Qt: category filter, patient list, and how requests and published statuses
// keep the controls truthful about what the avatar shows.
#include <gtest/gtest.h>

#include "vicc_anatomy_viz/panel_logic/patient_panel_state.hpp"

using namespace vicc_anatomy_viz::panel;

namespace {

std::vector<CategoryItem> sdhLegend() {
  return {{"radicular_pain", "Radicular pain", 1, 1.f, 0.f, 0.f},
          {"paresis", "Paresis", 2, 0.5f, 0.f, 1.f},
          {"sensory_disorder", "Sensory disorder", 1, 0.f, 1.f, 1.f}};
}

ShownStatus status(const std::string& patient, const std::string& requested,
                   const std::string& time, std::vector<std::string> hidden = {}) {
  ShownStatus shown;
  shown.patient_id = patient;
  shown.requested_date = requested;
  shown.has_examination = !time.empty();
  shown.examination_time = time;
  shown.examination_status = "final";
  shown.hidden_categories = std::move(hidden);
  shown.legend = sdhLegend();
  return shown;
}

const std::string kPre = "2023-03-06T09:15:00Z";
const std::string kPost = "2023-03-10T08:40:00Z";

}  // namespace

TEST(CategoryFilterStateTest, RequestsOnlyHiddenCategoriesOfTheLegendInLegendOrder) {
  CategoryFilterState filter;
  filter.setHidden({"sensory_disorder", "bowel_noise", "paresis"});
  EXPECT_EQ(filter.requestedHidden(),
            (std::vector<std::string>{"bowel_noise", "paresis", "sensory_disorder"}));
  filter.setLegend(sdhLegend());
  EXPECT_EQ(filter.requestedHidden(), (std::vector<std::string>{"paresis", "sensory_disorder"}));
  EXPECT_EQ(filter.unknownHidden(), std::vector<std::string>{"bowel_noise"});
  filter.setVisible("paresis", true);
  filter.setVisible("radicular_pain", false);
  EXPECT_TRUE(filter.isVisible("paresis"));
  EXPECT_FALSE(filter.isVisible("radicular_pain"));
  EXPECT_EQ(filter.requestedHidden(),
            (std::vector<std::string>{"radicular_pain", "sensory_disorder"}));
  EXPECT_EQ(keepKnownCategories({"x", "paresis"}, {"paresis", "t_reflex"}),
            std::vector<std::string>{"paresis"});
}

TEST(PatientListStateTest, KeepsASelectionThatIsNoLongerListed) {
  PatientListState list;
  EXPECT_FALSE(list.listed());
  list.setPatients(
      {{"A-1", 1, "2023-01-01T00:00:00Z", "2023-01-01T00:00:00Z"}, {"SDH-046", 2, kPre, kPost}});
  list.select("SDH-046");
  EXPECT_EQ(list.selectedIndex(), 1u);
  EXPECT_EQ(describePatient(list.patients()[1]),
            "SDH-046 (2 examinations, 2023-03-06 to 2023-03-10)");
  EXPECT_EQ(describePatient(list.patients()[0]), "A-1 (1 examination, 2023-01-01)");
  list.setPatients({{"A-1", 1, "2023-01-01T00:00:00Z", "2023-01-01T00:00:00Z"}});
  EXPECT_EQ(list.selected(), "SDH-046");
  EXPECT_FALSE(list.selectedIsListed());
}

TEST(PatientPanelStateTest, UserActionsBuildTheSelectionRequest) {
  PatientPanelState state;
  auto request = state.choosePatient("SDH-046");
  EXPECT_EQ(request.patient_id, "SDH-046");
  EXPECT_EQ(request.date, "");
  EXPECT_TRUE(state.datesOutdated());
  ASSERT_TRUE(state.datesListed("SDH-046", {kPre, kPost}));
  EXPECT_FALSE(state.datesOutdated());
  EXPECT_FALSE(state.datesListed("OTHER", {kPre}));  // a stale answer
  const auto dated = state.chooseDateIndex(0);
  ASSERT_TRUE(dated.has_value());
  EXPECT_EQ(dated->date, kPre);
  EXPECT_FALSE(state.chooseDateIndex(5).has_value());
  state.categories.setLegend(sdhLegend());
  request = state.chooseCategoryVisible("paresis", false);
  EXPECT_EQ(request.hidden_categories, std::vector<std::string>{"paresis"});
  EXPECT_EQ(request.date, kPre);
  EXPECT_EQ(state.chooseLatest().date, "");
}

TEST(PatientPanelStateTest, AdoptsAStatusPublishedForAnotherClient) {
  PatientPanelState state;
  state.statusPublished(status("SDH-046", kPre, kPre, {"paresis"}));
  EXPECT_EQ(state.patients.selected(), "SDH-046");
  EXPECT_EQ(state.timeline.requestedDate(), kPre);
  EXPECT_FALSE(state.categories.isVisible("paresis"));
  EXPECT_TRUE(state.categories.legendKnown());
  EXPECT_TRUE(state.datesOutdated());
  state.datesListed("SDH-046", {kPre, kPost});
  EXPECT_EQ(state.timeline.sliderIndex(), 0u);
  // A newly recorded examination shown that the timeline does not have yet.
  state.statusPublished(status("SDH-046", "", "2023-05-01T10:00:00Z"));
  EXPECT_TRUE(state.datesOutdated());
}

TEST(PatientPanelStateTest, PublishedStatusesDoNotOverwriteChoicesWhileRequestsAreInFlight) {
  PatientPanelState state;
  state.statusPublished(status("SDH-046", "", kPost));
  state.categories.setLegend(sdhLegend());
  state.chooseCategoryVisible("paresis", false);
  state.requestSent();
  state.chooseCategoryVisible("radicular_pain", false);
  state.requestSent();
  // The first request's status arrives: the second choice must survive it.
  state.statusPublished(status("SDH-046", "", kPost, {"paresis"}));
  state.requestAnswered(true, status("SDH-046", "", kPost, {"paresis"}));
  EXPECT_FALSE(state.categories.isVisible("radicular_pain"));
  EXPECT_EQ(state.request().hidden_categories,
            (std::vector<std::string>{"radicular_pain", "paresis"}));
  state.requestAnswered(true, status("SDH-046", "", kPost, {"radicular_pain", "paresis"}));
  EXPECT_EQ(state.requestsInFlight(), 0u);
  EXPECT_EQ(state.shown()->hidden_categories,
            (std::vector<std::string>{"radicular_pain", "paresis"}));
}

TEST(PatientPanelStateTest, AFailedRequestReturnsTheControlsToWhatIsShown) {
  PatientPanelState state;
  state.statusPublished(status("SDH-046", kPre, kPre));
  state.datesListed("SDH-046", {kPre, kPost});
  state.choosePatient("UNKNOWN-1");
  state.requestSent();
  state.requestAnswered(false, std::nullopt);
  EXPECT_EQ(state.patients.selected(), "SDH-046");
  EXPECT_EQ(state.timeline.requestedDate(), kPre);
}

TEST(PatientPanelStateTest, ARestoredSelectionWinsOverTheLatchedStatusAndIsSavedAgain) {
  PatientPanelState state;
  PanelSettings saved;
  saved.server = "/other";
  saved.patient_id = "SDH-046";
  saved.date = kPre;
  saved.hidden_categories = {"sensory_disorder"};
  state.restore(saved);
  EXPECT_TRUE(state.hasPendingRestore());
  state.statusPublished(status("A-1", "", kPost));  // the server's start-up selection
  EXPECT_EQ(state.patients.selected(), "SDH-046");
  const SelectionRequest request = state.takePendingRestore();
  EXPECT_FALSE(state.hasPendingRestore());
  EXPECT_EQ(request.patient_id, "SDH-046");
  EXPECT_EQ(request.date, kPre);
  EXPECT_EQ(request.hidden_categories, std::vector<std::string>{"sensory_disorder"});
  const PanelSettings again = state.settings();
  EXPECT_EQ(again.server, "/other");
  EXPECT_EQ(again.patient_id, "SDH-046");
  EXPECT_EQ(again.date, kPre);
  EXPECT_EQ(again.hidden_categories, saved.hidden_categories);
}

TEST(PatientPanelStateTest, DescribesWhatTheAvatarShows) {
  auto shown = status("SDH-046", "", kPre, {"paresis"});
  EXPECT_EQ(describeShown(shown), "SDH-046: examination " + kPre + "; hidden: paresis");
  shown.examination_status = "preliminary";
  shown.partial = true;
  shown.partial_reason = "unknown structure";
  EXPECT_NE(describeShown(shown).find("PRELIMINARY"), std::string::npos);
  EXPECT_NE(describeShown(shown).find("PARTIAL"), std::string::npos);
  EXPECT_EQ(describeShown(status("SDH-046", "2023-01-01", "")),
            "SDH-046: no examination at or before 2023-01-01");
}
