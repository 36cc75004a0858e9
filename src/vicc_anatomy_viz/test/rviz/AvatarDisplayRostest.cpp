// rostest: SDH-046 (thesis Fig. 4.6) recorded into the server's database, selected through the
// server's service, drawn by the AvatarDisplay in rviz; the rendered colours at the projected
// positions of known structures are the encoded ones (hue within tolerance), a later date and
// a hidden category change them, and switching the view-dependent transparency off hides the
// paresis under the opaque skin (not under a translucent one).
#include <gtest/gtest.h>

#include <ros/ros.h>
#include <rviz/properties/property.h>
#include <vicc_msgs/SelectPatient.h>
#include <QApplication>
#include <QColor>
#include <QImage>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "sample_patient_database.hpp"
#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_avatar_snapshot_renderer.hpp"
#include "vicc_common/ros_service_call.hpp"

namespace {

using namespace vicc_anatomy_viz;
using avatar_view::BodyView;

constexpr int kWidth = 500, kHeight = 800;
constexpr float kHueToleranceDeg = 15.f;
constexpr double kWaitS = 30.0;
/// The skin and context are neutral grey (saturation < 0.03); the palest encoded colour seen
/// through the skin keeps about 0.25.
constexpr double kMinSaturation = 0.12;

/// What a window of pixels around a point shows: the circular mean hue of its saturated
/// pixels and how many there are.
struct PixelSample {
  int saturated = 0;
  float hue_deg = 0.f;
};

PixelSample sample(const QImage& image, const Eigen::Vector2f& pixel) {
  constexpr int kRadius = 2;
  PixelSample result;
  Eigen::Vector2f direction = Eigen::Vector2f::Zero();
  for (int dy = -kRadius; dy <= kRadius; ++dy) {
    for (int dx = -kRadius; dx <= kRadius; ++dx) {
      const QPoint point(static_cast<int>(pixel.x()) + dx, static_cast<int>(pixel.y()) + dy);
      if (!image.rect().contains(point)) continue;
      const QColor colour = image.pixelColor(point);
      if (colour.hsvSaturationF() < kMinSaturation || colour.hsvHue() < 0) continue;
      ++result.saturated;
      const float angle = static_cast<float>(colour.hsvHue()) * static_cast<float>(M_PI) / 180.f;
      direction += Eigen::Vector2f(std::cos(angle), std::sin(angle));
    }
  }
  result.hue_deg = std::atan2(direction.y(), direction.x()) * 180.f / static_cast<float>(M_PI);
  if (result.hue_deg < 0.f) result.hue_deg += 360.f;
  return result;
}

float hueDistance(float a, float b) {
  const float d = std::fabs(a - b);
  return std::min(d, 360.f - d);
}

float hueOf(const Rgba& colour) {
  return static_cast<float>(QColor::fromRgbF(colour.r, colour.g, colour.b).hsvHueF() * 360.0);
}

class AvatarDisplayRostest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // SDH-046 (Fig. 4.6) and the other sample cases (SDH-101: left L4 pain on stress).
    std::vector<Examination> examinations = rviz_test::figurePatientExaminations();
    for (Examination& examination : rviz_test::sampleExaminations("cases.json"))
      examinations.push_back(std::move(examination));
    rviz_test::recordExaminations(examinations);
    renderer_ = std::make_unique<snapshot::AvatarRenderer>(kWidth, kHeight,
                                                           "/patient_status_server/status");
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    rviz_test::removeDatabase();
  }

  /// Selects (patient, date, filter) at the server and renders the status it publishes.
  QImage show(const std::string& date, const std::vector<std::string>& hidden, BodyView view,
              const std::string& patient = "SDH-046") {
    const unsigned drawn = renderer_->display().drawnStatusCount();
    vicc_msgs::SelectPatient select;
    select.request.patient_id = patient;
    select.request.date = date;
    select.request.hidden_categories = hidden;
    EXPECT_TRUE(ros::service::waitForService("/patient_status_server/select_patient", 20000));
    EXPECT_TRUE(
        vicc_common::callRepeatableService("/patient_status_server/select_patient", select));
    EXPECT_TRUE(renderer_->waitForStatus(drawn, kWaitS)) << "no status drawn for " << date;
    EXPECT_TRUE(renderer_->setView(view));
    return renderer_->grab();
  }

  const avatar::AvatarModel& model() { return *renderer_->display().model(); }

  /// The encoded colour the display drew for (category, structure, side); nullptr if none.
  const avatar_view::DrawItem* drawn(const std::string& category, const std::string& id,
                                     Side side) {
    for (const auto& item : renderer_->display().drawState().items)
      if (item.category == category && item.structure_id == id && item.side == side) return &item;
    return nullptr;
  }

  Eigen::Vector2f project(const Eigen::Vector3f& point) {
    Eigen::Vector2f pixel(-1.f, -1.f);
    EXPECT_TRUE(avatar_view::projectToPixel(point, renderer_->camera(), kWidth, kHeight, pixel));
    return pixel;
  }

  /// A point of a skin region facing the camera: the facing triangle nearest to the centroid
  /// of the region's facing triangles.
  Eigen::Vector3f facingPoint(const std::string& region_id, Side side) {
    const avatar::SkinRegion* region = model().skinRegion(region_id, side);
    EXPECT_NE(region, nullptr) << region_id;
    const Eigen::Vector3f eye = renderer_->orbit().eye();
    std::vector<Eigen::Vector3f> centres;
    for (int t : region ? region->triangles : std::vector<int>{}) {
      const Eigen::Vector3i& tri = model().skin.triangles[static_cast<std::size_t>(t)];
      const Eigen::Vector3f a = model().skin.vertices[tri[0]], b = model().skin.vertices[tri[1]],
                            c = model().skin.vertices[tri[2]];
      const Eigen::Vector3f centre = (a + b + c) / 3.f;
      if ((b - a).cross(c - a).normalized().dot((eye - centre).normalized()) > 0.7f)
        centres.push_back(centre);
    }
    EXPECT_FALSE(centres.empty()) << region_id << " faces away from the camera";
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();
    for (const auto& centre : centres) mean += centre / static_cast<float>(centres.size());
    Eigen::Vector3f best = mean;
    for (const auto& centre : centres)
      if ((centre - mean).norm() < (best - mean).norm() || best == mean) best = centre;
    return best;
  }

  Eigen::Vector3f structureCentre(const std::string& id, Side side) {
    const avatar::AvatarStructure* structure = model().structure(id, side);
    EXPECT_NE(structure, nullptr) << id;
    if (!structure) return Eigen::Vector3f::Zero();
    if (structure->mesh.vertices.empty()) return structure->proxy.centre;
    return avatar_view::boundingSphere(structure->mesh).centre;
  }

  /// The centroid of a structure's vertices on the foot (below `height`) that face the camera.
  Eigen::Vector3f footPoint(const std::string& id, Side side, float height) {
    const avatar::AvatarStructure* structure = model().structure(id, side);
    EXPECT_NE(structure, nullptr) << id;
    const Eigen::Vector3f eye = renderer_->orbit().eye();
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    int count = 0;
    for (std::size_t i = 0; structure && i < structure->mesh.vertices.size(); ++i) {
      const Eigen::Vector3f& v = structure->mesh.vertices[i];
      if (v.z() < height && structure->mesh.normals[i].dot((eye - v).normalized()) > 0.3f) {
        sum += v;
        ++count;
      }
    }
    EXPECT_GT(count, 0) << id << " has no camera-facing part on the foot";
    return count ? Eigen::Vector3f(sum / static_cast<float>(count)) : sum;
  }

  void expectHue(const QImage& image, const Eigen::Vector3f& point, const Rgba& expected,
                 const std::string& what) {
    const PixelSample found = sample(image, project(point));
    EXPECT_GE(found.saturated, 5) << what << ": not coloured at its projected position";
    EXPECT_LT(hueDistance(found.hue_deg, hueOf(expected)), kHueToleranceDeg)
        << what << ": hue " << found.hue_deg << " expected " << hueOf(expected);
  }

  /// Not in `colour`'s hue (uncoloured, or another category's colour where bands overlap).
  void expectNotHue(const QImage& image, const Eigen::Vector3f& point, const Rgba& colour,
                    const std::string& what) {
    const PixelSample found = sample(image, project(point));
    EXPECT_TRUE(found.saturated <= 2 ||
                hueDistance(found.hue_deg, hueOf(colour)) > 2.f * kHueToleranceDeg)
        << what << " shows hue " << found.hue_deg;
  }

  void expectUncoloured(const QImage& image, const Eigen::Vector3f& point,
                        const std::string& what) {
    EXPECT_LE(sample(image, project(point)).saturated, 2) << what << " is coloured";
  }

  static std::unique_ptr<snapshot::AvatarRenderer> renderer_;
};

std::unique_ptr<snapshot::AvatarRenderer> AvatarDisplayRostest::renderer_;

TEST_F(AvatarDisplayRostest, PreOperativeFindingsAreDrawnInTheirColoursOnTheirSide) {
  const QImage image = show("2023-03-06", {}, BodyView::kFront);
  ASSERT_NE(renderer_->display().model(), nullptr) << renderer_->display().modelError();
  const auto* pain = drawn("radicular_pain", "dermatome_L5", Side::kLeft);
  const auto* paresis = drawn("paresis", "tibialis_anterior", Side::kRight);
  const auto* reflex = drawn("t_reflex", "patellar_ligament", Side::kRight);
  ASSERT_TRUE(pain && paresis && reflex);
  EXPECT_TRUE(renderer_->display().drawState().warnings.empty());
  // Alternation off in stills: the first category of the L5 alternation (pain) is shown.
  expectHue(image, facingPoint("dermatome_L5", Side::kLeft), pain->color, "left L5 pain");
  expectHue(image, structureCentre("tibialis_anterior", Side::kRight), paresis->color,
            "right tibialis anterior paresis (through the skin)");
  expectHue(image, structureCentre("patellar_ligament", Side::kRight), reflex->color,
            "right patellar reflex proxy");
  // The right EHL's moderate paresis through the skin of the dorsum of the foot (its tendon).
  const auto* ehl = drawn("paresis", "extensor_hallucis_longus", Side::kRight);
  ASSERT_NE(ehl, nullptr);
  expectHue(image, footPoint("extensor_hallucis_longus", Side::kRight, 0.06f), ehl->color,
            "right EHL tendon on the dorsum of the foot");
  // No pain on the other side (the right L5 band covers the dorsum of the foot, where the
  // right EHL's tendon shows its paresis through the skin).
  expectNotHue(image, facingPoint("dermatome_L5", Side::kRight), pain->color, "right L5");
  // (The left L5 band covers the lateral shin: the left tibialis may show the pain's red.)
  expectNotHue(image, structureCentre("tibialis_anterior", Side::kLeft), paresis->color,
               "left tibialis");
  // From the front the patient's right is on the image's left.
  EXPECT_LT(project(structureCentre("tibialis_anterior", Side::kRight)).x(), kWidth / 2.f);
}

/// Relief as the eye reads it at whole-body scale: the spread (standard deviation) of the
/// brightness, averaged over 4 x 4 pixel blocks (the bumps are about 7 pixels across; finer
/// aliasing patterns of a minified texture average out), over the blocks in `hue` (the
/// finding's pixels) in a window of `radius` around a pixel.
double reliefContrast(const QImage& image, const Eigen::Vector2f& centre, int radius, float hue) {
  constexpr int kBlock = 4;
  const auto in_hue = [&](const QColor& colour) {
    return colour.hsvSaturationF() >= kMinSaturation && colour.hsvHue() >= 0 &&
           hueDistance(static_cast<float>(colour.hsvHue()), hue) < kHueToleranceDeg;
  };
  std::vector<double> blocks;
  for (int dy = -radius; dy < radius; ++dy) {
    for (int dx = -radius; dx < radius; ++dx) {
      const QPoint corner(static_cast<int>(centre.x()) + dx, static_cast<int>(centre.y()) + dy);
      double sum = 0.0;
      bool inside = true;
      for (int by = 0; by < kBlock && inside; ++by)
        for (int bx = 0; bx < kBlock && inside; ++bx) {
          const QPoint point = corner + QPoint(bx, by);
          inside = image.rect().contains(point) && in_hue(image.pixelColor(point));
          if (inside) sum += image.pixelColor(point).valueF();
        }
      if (inside) blocks.push_back(sum / (kBlock * kBlock));
    }
  }
  if (blocks.size() < 30) return 0.0;
  double mean = 0.0, spread = 0.0;
  for (double value : blocks) mean += value / static_cast<double>(blocks.size());
  for (double value : blocks) spread += (value - mean) * (value - mean);
  return std::sqrt(spread / static_cast<double>(blocks.size()));
}

TEST_F(AvatarDisplayRostest, ThePainTriggerIsAReliefLitPerPixelOrSaysWhyNot) {
  // SDH-101 (thesis Fig. 4.5B): left L4 radicular pain on stress, the normal perturbation.
  const QImage shaded = show("2023-05-02", {}, BodyView::kFront, "SDH-101");
  const auto* pain = drawn("radicular_pain", "dermatome_L4", Side::kLeft);
  ASSERT_NE(pain, nullptr);
  ASSERT_EQ(pain->texture.kind, avatar_view::TextureKind::kNormalPerturbation);
  const auto& relief = renderer_->display().reliefStatus();
  EXPECT_TRUE(relief.needed);
  EXPECT_TRUE(relief.per_pixel) << relief.fallback_reason;
  const Eigen::Vector3f band = facingPoint("dermatome_L4", Side::kLeft);
  expectHue(shaded, band, pain->color, "left L4 pain under its relief");
  const double per_pixel = reliefContrast(shaded, project(band), 10, hueOf(pain->color));

  rviz::Property* switch_off = renderer_->display().subProp("Per-pixel relief");
  ASSERT_NE(switch_off, nullptr);
  switch_off->setValue(false);
  const QImage pre_shaded = renderer_->grab();
  EXPECT_FALSE(renderer_->display().reliefStatus().per_pixel);
  EXPECT_NE(renderer_->display().reliefStatus().fallback_reason.find("switched off"),
            std::string::npos);
  switch_off->setValue(true);
  // The fallback keeps the band in its colour (never an empty or black structure).
  expectHue(pre_shaded, band, pain->color, "left L4 pain, pre-shaded");
  const double baked = reliefContrast(pre_shaded, project(band), 10, hueOf(pain->color));
  std::printf("L4 pain relief contrast: per pixel %.4f, pre-shaded %.4f\n", per_pixel, baked);
  // For a look at the frames: VICC_AVATAR_RELIEF_FRAMES=DIR saves them there.
  if (const char* dir = std::getenv("VICC_AVATAR_RELIEF_FRAMES")) {
    shaded.save(QString::fromStdString(std::string(dir) + "/relief_per_pixel.png"));
    pre_shaded.save(QString::fromStdString(std::string(dir) + "/relief_pre_shaded.png"));
  }
  // The relief reads at whole-body scale: bumps a few pixels across, where the pre-shaded
  // texture, minified, is only aliasing finer than that.
  EXPECT_GT(per_pixel, 0.05);
  EXPECT_GT(per_pixel, 2.0 * baked);
  // A status without the trigger needs no relief.
  show("2023-03-06", {}, BodyView::kFront);
  EXPECT_FALSE(renderer_->display().reliefStatus().needed);
}

TEST_F(AvatarDisplayRostest, TheLaterDateShowsThePostOperativeStatus) {
  const QImage image = show("2023-03-10", {}, BodyView::kFront);
  const auto* sensory = drawn("sensory_disorder", "dermatome_L5", Side::kLeft);
  ASSERT_NE(sensory, nullptr);
  EXPECT_EQ(drawn("radicular_pain", "dermatome_L5", Side::kLeft), nullptr);
  expectHue(image, facingPoint("dermatome_L5", Side::kLeft), sensory->color,
            "left L5 sensory disorder");
  // Symmetric reflexes post-op: no proxy any more.
  expectUncoloured(image, structureCentre("patellar_ligament", Side::kRight),
                   "right patellar proxy");
}

TEST_F(AvatarDisplayRostest, AHiddenCategoryIsNotDrawn) {
  const QImage image = show("2023-03-06", {"paresis"}, BodyView::kFront);
  EXPECT_EQ(drawn("paresis", "tibialis_anterior", Side::kRight), nullptr);
  expectUncoloured(image, structureCentre("tibialis_anterior", Side::kRight), "hidden paresis");
  const auto* reflex = drawn("t_reflex", "patellar_ligament", Side::kRight);
  ASSERT_NE(reflex, nullptr);
  expectHue(image, structureCentre("patellar_ligament", Side::kRight), reflex->color,
            "right patellar reflex proxy");
}

TEST_F(AvatarDisplayRostest, WithoutTransparencyTheSkinHidesTheParesis) {
  renderer_->setTransparency(false);
  const QImage opaque = show("2023-03-06", {}, BodyView::kFront);
  renderer_->setTransparency(true);
  expectUncoloured(opaque, structureCentre("tibialis_anterior", Side::kRight),
                   "tibialis anterior under an opaque skin");
  const auto* pain = drawn("radicular_pain", "dermatome_L5", Side::kLeft);
  ASSERT_NE(pain, nullptr);
  expectHue(opaque, facingPoint("dermatome_L5", Side::kLeft), pain->color, "left L5 pain");
}

TEST_F(AvatarDisplayRostest, WithoutTransparencyATranslucentSkinStillShowsTheParesis) {
  // Transparency off skips the inner structures only under an opaque skin.
  renderer_->setTransparency(false);
  renderer_->display().subProp("Skin alpha")->setValue(0.4f);
  const QImage image = show("2023-03-06", {}, BodyView::kFront);
  renderer_->display().subProp("Skin alpha")->setValue(1.0f);
  renderer_->setTransparency(true);
  const auto* paresis = drawn("paresis", "tibialis_anterior", Side::kRight);
  ASSERT_NE(paresis, nullptr);
  expectHue(image, structureCentre("tibialis_anterior", Side::kRight), paresis->color,
            "right tibialis anterior paresis through a skin of alpha 0.4");
}

TEST_F(AvatarDisplayRostest, ClickingAStructureShowsItsNameAndRawValues) {
  show("2023-03-06", {}, BodyView::kFront);
  const auto* paresis = drawn("paresis", "tibialis_anterior", Side::kRight);
  ASSERT_NE(paresis, nullptr);
  // Through the see-through skin, on the muscle the user sees.
  const Eigen::Vector2f muscle = project(structureCentre("tibialis_anterior", Side::kRight));
  renderer_->click(static_cast<int>(muscle.x()), static_cast<int>(muscle.y()));
  EXPECT_EQ(renderer_->display().selectionText(), paresis->overlay_text);
  EXPECT_NE(paresis->overlay_text.find("MRC"), std::string::npos) << paresis->overlay_text;
  // A click on the empty background deselects.
  renderer_->click(5, kHeight - 5);
  EXPECT_EQ(renderer_->display().selectionText(), "");
}

TEST_F(AvatarDisplayRostest, BadStatusEntriesAreWarnedAndTheRestIsDrawn) {
  show("2023-03-06", {}, BodyView::kFront);
  vicc_msgs::EncodedStatus status = renderer_->display().lastStatus();
  ASSERT_FALSE(status.structures.empty());
  vicc_msgs::EncodedStructure unknown = status.structures.front();
  unknown.structure_id = "spleen";
  unknown.alternation_group = -1;
  // The right tibialis's paresis copied to the left one with a NaN colour.
  vicc_msgs::EncodedStructure nan_colour = unknown;
  for (const auto& entry : status.structures)
    if (entry.category == "paresis" && entry.structure_id == "tibialis_anterior")
      nan_colour = entry;
  ASSERT_EQ(nan_colour.category, "paresis");
  nan_colour.side = "left";
  nan_colour.color.r = std::nanf("");
  status.structures.push_back(unknown);
  status.structures.push_back(nan_colour);
  renderer_->display().showStatus(status);
  const QImage image = renderer_->grab();
  const auto& warnings = renderer_->display().drawState().warnings;
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("spleen"), std::string::npos);
  EXPECT_NE(warnings[1].find("colour"), std::string::npos);
  const auto* paresis = drawn("paresis", "tibialis_anterior", Side::kRight);
  ASSERT_NE(paresis, nullptr);
  EXPECT_EQ(drawn("paresis", "tibialis_anterior", Side::kLeft), nullptr);
  expectNotHue(image, structureCentre("tibialis_anterior", Side::kLeft), paresis->color,
               "NaN-coloured left tibialis");
  expectHue(image, structureCentre("tibialis_anterior", Side::kRight), paresis->color,
            "right tibialis anterior next to bad entries");
  // An empty status: a warning, nothing coloured.
  renderer_->display().showStatus(vicc_msgs::EncodedStatus());
  const QImage empty = renderer_->grab();
  EXPECT_FALSE(renderer_->display().drawState().warnings.empty());
  expectUncoloured(empty, structureCentre("tibialis_anterior", Side::kRight), "empty status");
}

TEST_F(AvatarDisplayRostest, AMissingMeshFileIsAnErrorNotACrash) {
  rviz::Property* manifest = renderer_->display().subProp("Avatar manifest");
  ASSERT_NE(manifest, nullptr);
  manifest->setValue("/nonexistent/avatar.yaml");
  EXPECT_EQ(renderer_->display().model(), nullptr);
  EXPECT_NE(renderer_->display().modelError().find("/nonexistent/avatar.yaml"), std::string::npos)
      << renderer_->display().modelError();
  renderer_->grab();  // renders without a model
  manifest->setValue("");
  EXPECT_NE(renderer_->display().model(), nullptr);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "avatar_display_rostest");
  ros::NodeHandle node;
  QApplication application(argc, argv);
  return RUN_ALL_TESTS();
}
