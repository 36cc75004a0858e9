// rostest: SDH-046 with its (illustrative) ICP recorded into the server's database and selected
// at three dates; rviz draws the avatar and the MarkerArray of status_glyph_markers. Above the
// head, in the projected box of the glyph, the pixels carry the brain colour the glyph server
// renders for that date's ICP and level (26 mmHg / 2, 12 mmHg / 0), not the other date's; a
// later examination without an ICP has no glyph at all (its caption says "no data").
#include <gtest/gtest.h>

#include <ros/ros.h>
#include <rviz/display.h>
#include <rviz/properties/property.h>
#include <rviz/visualization_manager.h>
#include <vicc_msgs/RenderGlyph.h>
#include <vicc_msgs/SelectPatient.h>
#include <visualization_msgs/MarkerArray.h>
#include <QApplication>
#include <QColor>
#include <QImage>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

#include "../rviz/sample_patient_database.hpp"
#include "vicc_anatomy_viz/avatar/avatar_model.hpp"
#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_avatar_snapshot_renderer.hpp"
#include "vicc_common/ros_service_call.hpp"

namespace {

using namespace vicc_anatomy_viz;

constexpr int kWidth = 600, kHeight = 600;
constexpr double kWaitS = 30.0;
constexpr const char* kMarkerTopic = "/status_glyph_markers/markers";
// The design's category colours (vicc_glyphs designs/intracranial_pressure.yaml).
/// Per channel: a rendered pixel shows a colour of the glyph image (rviz draws the quads unlit
/// enough to keep them within a few levels).
constexpr int kColourTolerance = 12;
constexpr int kMinGlyphPixels = 200;

/// The Fig. 4.6 patient (pre-op 26 mmHg, post-op 12 mmHg) and a later examination that
/// measured no ICP, written into the server's database.
void recordPatient() {
  auto examinations = rviz_test::figurePatientExaminations();
  Examination without_icp = examinations.back();
  without_icp.taken_at_us += 10LL * 24 * 3600 * 1000000;
  without_icp.findings.erase(
      std::remove_if(without_icp.findings.begin(), without_icp.findings.end(),
                     [](const Finding& f) { return f.category == "intracranial_pressure"; }),
      without_icp.findings.end());
  examinations.push_back(without_icp);
  rviz_test::recordExaminations(examinations);
}

bool near(const QColor& a, const QColor& b) {
  return std::abs(a.red() - b.red()) <= kColourTolerance &&
         std::abs(a.green() - b.green()) <= kColourTolerance &&
         std::abs(a.blue() - b.blue()) <= kColourTolerance;
}

/// Pixels inside a pixel box near a colour.
int pixelsNear(const QImage& image, const QRect& box, const QColor& colour) {
  int count = 0;
  for (int y = box.top(); y <= box.bottom(); ++y)
    for (int x = box.left(); x <= box.right(); ++x)
      if (image.rect().contains(x, y) && near(image.pixelColor(x, y), colour)) ++count;
  return count;
}

/// The colour the glyph server gives the brain of the ICP design for (pressure, level): the
/// most frequent colour of its image that is neither the white background nor the head's skin
/// (the most frequent of all). Asked of the server, so that the test checks what the node
/// shows against what the server rendered.
QColor brainColour(double pressure, double level) {
  vicc_msgs::RenderGlyph render;
  render.request.design = "intracranial_pressure";
  render.request.names = {"pressure", "category"};
  render.request.values = {pressure, level};
  render.request.size = 96;
  EXPECT_TRUE(ros::service::waitForService("/glyph_server/render", 20000));
  EXPECT_TRUE(vicc_common::callRepeatableService("/glyph_server/render", render));
  EXPECT_TRUE(render.response.success) << render.response.message;
  std::map<QRgb, int> counts;
  const auto& data = render.response.image.data;
  for (std::size_t i = 0; i + 2 < data.size(); i += 3)
    ++counts[qRgb(data[i], data[i + 1], data[i + 2])];
  counts.erase(qRgb(255, 255, 255));
  std::vector<std::pair<int, QRgb>> ranked;
  for (const auto& [rgb, count] : counts) ranked.push_back({count, rgb});
  std::sort(ranked.rbegin(), ranked.rend());
  EXPECT_GE(ranked.size(), 2u);
  return ranked.size() >= 2 ? QColor(ranked[1].second) : QColor();
}

class StatusGlyphRostest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    recordPatient();
    renderer_ = std::make_unique<snapshot::AvatarRenderer>(kWidth, kHeight,
                                                           "/patient_status_server/status");
    rviz::Display* markers =
        renderer_->manager().createDisplay("rviz/MarkerArray", "Status glyph", true);
    ASSERT_NE(markers, nullptr);
    rviz::Property* topic = markers->subProp("Marker Topic");
    ASSERT_NE(topic, nullptr);
    topic->setValue(kMarkerTopic);
    subscriber_ = std::make_unique<ros::Subscriber>(
        ros::NodeHandle().subscribe(kMarkerTopic, 5, &StatusGlyphRostest::onMarkers));
  }
  static void TearDownTestSuite() {
    subscriber_.reset();
    renderer_.reset();
    rviz_test::removeDatabase();
  }
  static void onMarkers(const visualization_msgs::MarkerArray& array) { last_ = array; }

  /// Selects SDH-046 at `date`, waits for the avatar's status and for the node's markers of
  /// the examination taken at `taken_at`, and renders the head from the front.
  QImage show(const std::string& date, const std::string& taken_at) {
    const unsigned drawn = renderer_->display().drawnStatusCount();
    vicc_msgs::SelectPatient select;
    select.request.patient_id = "SDH-046";
    select.request.date = date;
    EXPECT_TRUE(ros::service::waitForService("/patient_status_server/select_patient", 20000));
    EXPECT_TRUE(
        vicc_common::callRepeatableService("/patient_status_server/select_patient", select));
    EXPECT_TRUE(renderer_->waitForStatus(drawn, kWaitS)) << "no status drawn for " << date;
    auto arrived = [&] { return caption() && caption()->text.find(taken_at) != std::string::npos; };
    const ros::WallTime until = ros::WallTime::now() + ros::WallDuration(kWaitS);
    while (!arrived() && ros::WallTime::now() < until) renderer_->spin(0.05);
    EXPECT_TRUE(arrived()) << "no markers for the examination of " << taken_at;
    EXPECT_TRUE(renderer_->setView(avatar_view::BodyView::kFront));
    avatar_view::OrbitCamera orbit = renderer_->orbit();
    orbit.focus = headTop() + Eigen::Vector3f(0.f, 0.f, 0.05f);
    orbit.distance = 1.2f;
    renderer_->setOrbit(orbit);
    renderer_->spin(0.5);  // rviz's MarkerArray display takes the message in its update
    const QImage image = renderer_->grab();
    // For a look at the frames: VICC_STATUS_GLYPH_FRAMES=DIR saves them as DIR/<date>.png.
    if (const char* dir = std::getenv("VICC_STATUS_GLYPH_FRAMES")) {
      image.save(QString::fromStdString(std::string(dir) + "/" + date + ".png"));
    }
    return image;
  }

  Eigen::Vector3f headTop() {
    const auto& vertices = renderer_->display().model()->skin.vertices;
    return *std::max_element(vertices.begin(), vertices.end(),
                             [](const auto& a, const auto& b) { return a.z() < b.z(); });
  }

  const visualization_msgs::Marker* glyph() const {
    for (const auto& marker : last_.markers)
      if (marker.type == visualization_msgs::Marker::TRIANGLE_LIST) return &marker;
    return nullptr;
  }
  const visualization_msgs::Marker* caption() const {
    for (const auto& marker : last_.markers)
      if (marker.type == visualization_msgs::Marker::TEXT_VIEW_FACING) return &marker;
    return nullptr;
  }

  Eigen::Vector2f project(const Eigen::Vector3f& point) {
    Eigen::Vector2f pixel(-1.f, -1.f);
    EXPECT_TRUE(avatar_view::projectToPixel(point, renderer_->camera(), kWidth, kHeight, pixel));
    return pixel;
  }

  /// The glyph marker's points projected: their pixel bounding box.
  QRect glyphBox(const visualization_msgs::Marker& marker) {
    Eigen::AlignedBox2f box;
    for (const auto& p : marker.points)
      box.extend(project(Eigen::Vector3f(static_cast<float>(p.x), static_cast<float>(p.y),
                                         static_cast<float>(p.z))));
    return QRect(QPoint(static_cast<int>(box.min().x()), static_cast<int>(box.min().y())),
                 QPoint(static_cast<int>(box.max().x()), static_cast<int>(box.max().y())));
  }

  /// The glyph is drawn above the head, its brain in `brain`; returns its box.
  QRect expectGlyph(const QImage& image, const QColor& brain, const std::string& what) {
    const visualization_msgs::Marker* marker = glyph();
    EXPECT_NE(marker, nullptr) << what << ": no glyph marker";
    if (!marker) return {};
    const QRect box = glyphBox(*marker);
    std::printf("%s: glyph of %zu triangles, box %dx%d px, brain %s\n", what.c_str(),
                marker->points.size() / 3, box.width(), box.height(),
                brain.name().toStdString().c_str());
    EXPECT_GT(box.width(), 40) << what;
    EXPECT_LT(box.bottom(), project(headTop()).y()) << what << ": glyph not above the head";
    EXPECT_GE(pixelsNear(image, box, brain), kMinGlyphPixels)
        << what << ": the brain colour " << brain.name().toStdString() << " is not drawn";
    return box;
  }

  static std::unique_ptr<snapshot::AvatarRenderer> renderer_;
  static std::unique_ptr<ros::Subscriber> subscriber_;
  static visualization_msgs::MarkerArray last_;
};

std::unique_ptr<snapshot::AvatarRenderer> StatusGlyphRostest::renderer_;
std::unique_ptr<ros::Subscriber> StatusGlyphRostest::subscriber_;
visualization_msgs::MarkerArray StatusGlyphRostest::last_;

TEST_F(StatusGlyphRostest, TheGlyphAboveTheHeadFollowsTheDate) {
  // The sample's ICP: 26 mmHg (level 2, pathological) before, 12 mmHg (normal) after.
  const QColor pathological = brainColour(26, 2), normal = brainColour(12, 0);
  ASSERT_FALSE(near(pathological, normal)) << "the design draws 26 and 12 mmHg alike";

  const QImage before = show("2023-03-06", "2023-03-06T09:15:00Z");
  ASSERT_NE(renderer_->display().model(), nullptr) << renderer_->display().modelError();
  const QRect box = expectGlyph(before, pathological, "pre-operative 26 mmHg");
  ASSERT_NE(caption(), nullptr);
  EXPECT_NE(caption()->text.find("26"), std::string::npos) << caption()->text;
  EXPECT_LE(pixelsNear(before, box, normal), 5);

  const QImage after = show("2023-03-10", "2023-03-10T08:40:00Z");
  expectGlyph(after, normal, "post-operative 12 mmHg");
  EXPECT_LE(pixelsNear(after, box, pathological), 5);
  ASSERT_NE(caption(), nullptr);
  EXPECT_NE(caption()->text.find("normal"), std::string::npos) << caption()->text;

  // No ICP measured: no glyph, no glyph colour where it was, and a caption saying so.
  const QImage missing = show("2023-03-21", "2023-03-20T08:40:00Z");
  EXPECT_EQ(glyph(), nullptr);
  ASSERT_NE(caption(), nullptr);
  EXPECT_NE(caption()->text.find("no data"), std::string::npos) << caption()->text;
  EXPECT_EQ(caption()->text.find("normal"), std::string::npos) << caption()->text;
  EXPECT_LE(pixelsNear(missing, box, normal), 5);
  EXPECT_LE(pixelsNear(missing, box, pathological), 5);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "status_glyph_rostest");
  QApplication app(argc, argv);
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
