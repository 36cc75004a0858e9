// The default avatar: REP-103 orientation and size, structures under the skin, left/right
// symmetry, hierarchy and FMA ids, proxies on the skin.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

#include "avatar_test_support.hpp"
#include "vicc_anatomy_viz/avatar/cross_section.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"

namespace vicc_anatomy_viz::avatar {
namespace {

using test::defaultAvatar;

TEST(AvatarModelTest, SkinIsTheMakeHumanBodyStandingInRep103) {
  const AvatarModel& model = defaultAvatar().model;
  EXPECT_EQ(model.skin.vertices.size(), 13380u);  // duplicate (seam) vertices merged
  EXPECT_EQ(model.skin.triangles.size(), 26756u);
  float lowest = 1e9f, highest = -1e9f;
  for (const Eigen::Vector3f& v : model.skin.vertices) {
    lowest = std::min(lowest, v.z());
    highest = std::max(highest, v.z());
  }
  EXPECT_NEAR(lowest, 0.0f, 1e-6f);
  EXPECT_NEAR(highest, 1.66f, 0.01f);
  EXPECT_GT(signedVolume(model.skin), 0.04);  // outward triangles, ~55 litres
  EXPECT_LT(signedVolume(model.skin), 0.08);
}

TEST(AvatarModelTest, SkinNormalsPointOutwards) {
  const TriangleMesh& skin = defaultAvatar().model.skin;
  ASSERT_EQ(skin.normals.size(), skin.vertices.size());
  int outward = 0, checked = 0;
  for (std::size_t i = 0; i < skin.vertices.size(); i += 150) {
    EXPECT_NEAR(skin.normals[i].norm(), 1.0f, 1e-4f);
    const Eigen::Vector3f outside = skin.vertices[i] + 0.002f * skin.normals[i];
    const Eigen::Vector3f inside = skin.vertices[i] - 0.002f * skin.normals[i];
    outward += windingNumber(skin, outside) < 0.5 && windingNumber(skin, inside) > 0.5;
    ++checked;
  }
  // At creases (the closed lips, between the toes) 2 mm along the normal reaches the facing
  // skin: measured 3 of 90 samples there.
  EXPECT_GE(outward, 0.95 * checked) << outward << " of " << checked;
}

TEST(AvatarModelTest, BodyFacesPlusXWithItsLeftAtPlusY) {
  const BodyLandmarks& landmarks = defaultAvatar().landmarks;
  for (const std::string side : {"left", "right"}) {
    // Toes in front of the ankle, the heel just behind it.
    EXPECT_GT(landmarks.point("toe_tip_" + side).x() - landmarks.point("ankle_" + side).x(), 0.12f);
    EXPECT_LT(landmarks.point("ankle_" + side).x() - landmarks.point("heel_" + side).x(), 0.08f);
    // The navel and the nipples are on the front of the trunk.
    EXPECT_GT(landmarks.point("key_T4_" + side).x(), landmarks.point("key_S3_" + side).x() + 0.15f);
  }
  EXPECT_GT(landmarks.point("umbilicus").x(), landmarks.point("pelvis").x() + 0.05f);
  EXPECT_GT(landmarks.point("hip_left").y(), 0.05f);
  EXPECT_LT(landmarks.point("hip_right").y(), -0.05f);
}

TEST(AvatarModelTest, JointCentresAreInsideTheSkinInAnatomicalOrder) {
  const AvatarBuild& build = defaultAvatar();
  const BodyLandmarks& landmarks = build.landmarks;
  for (const std::string side : {"left", "right"}) {
    for (const std::string joint : {"shoulder", "elbow", "wrist", "hip", "knee", "ankle", "mtp"}) {
      EXPECT_NEAR(windingNumber(build.model.skin, landmarks.point(joint + "_" + side)), 1.0, 0.01)
          << joint << " " << side;
    }
    EXPECT_GT(landmarks.point("hip_" + side).z(), landmarks.point("knee_" + side).z() + 0.3f);
    EXPECT_GT(landmarks.point("knee_" + side).z(), landmarks.point("ankle_" + side).z() + 0.3f);
    EXPECT_GT(landmarks.point("shoulder_" + side).z(), landmarks.point("elbow_" + side).z() + 0.1f);
    const float forearm =
        (landmarks.point("wrist_" + side) - landmarks.point("elbow_" + side)).norm();
    EXPECT_NEAR(forearm / landmarks.height, 0.146f, 0.03f);  // Drillis & Contini proportion
  }
}

TEST(AvatarModelTest, EveryGeneratedStructureLiesUnderTheSkin) {
  const AvatarModel& model = defaultAvatar().model;
  for (const AvatarStructure& structure : model.structures) {
    ASSERT_FALSE(structure.mesh.vertices.empty()) << structure.display_name;
    EXPECT_GT(signedVolume(structure.mesh), 0) << structure.display_name;
    // Every 12th vertex: all ring positions over the stations (14 per ring) in ~1 s.
    for (std::size_t i = 0; i < structure.mesh.vertices.size(); i += 12) {
      const Eigen::Vector3f& vertex = structure.mesh.vertices[i];
      ASSERT_GT(windingNumber(model.skin, vertex), 0.5)
          << structure.display_name << " vertex " << i;
      ASSERT_GT(distanceToSurface(model.skin, vertex), 0.001f) << structure.display_name;
    }
  }
}

TEST(AvatarModelTest, MusclesAreSpindlesAlongTheirBoneNotBoxes) {
  const AvatarModel& model = defaultAvatar().model;
  const AvatarStructure* quadriceps = model.structure("quadriceps_femoris", Side::kLeft);
  ASSERT_NE(quadriceps, nullptr);
  const BoneFrame thigh = defaultAvatar().landmarks.bone("thigh", Side::kLeft);
  // Thin at both ends, thickest in the middle.
  float low = 1e9f, high = -1e9f;
  for (const Eigen::Vector3f& v : quadriceps->mesh.vertices) {
    const float along = (v - thigh.proximal).dot(thigh.axis);
    low = std::min(low, along);
    high = std::max(high, along);
  }
  EXPECT_GT(high - low, 0.6f * thigh.length());
  EXPECT_GT(signedVolume(quadriceps->mesh) * 1e6, 300.0);  // cm^3
}

/// A muscle's belly in the plane across its bone at one fraction: its share of the limb's
/// cross-section (the skin's loop round the bone axis), and the largest gap between the skin
/// and the belly's outer surface over an arc of azimuths (as a fraction of the axis-to-skin
/// distance there; 1 where the belly does not reach that azimuth).
struct BellySection {
  double share = 0;
  float deepest_gap = 0;
};

BellySection bellySection(const AvatarStructure& muscle, const BoneFrame& bone, float fraction,
                          float first_azimuth, float last_azimuth) {
  const SectionPlane plane = SectionPlane::through(bone.at(fraction), bone.axis, bone.anterior);
  const std::vector<SectionLoop> belly = sliceMesh(muscle.mesh, plane);
  const std::vector<SectionLoop> skin = sliceMesh(defaultAvatar().model.skin, plane);
  const SectionLoop* limb = loopContaining(skin, Eigen::Vector2f::Zero());
  BellySection result;
  if (!limb) return result;
  for (const SectionLoop& loop : belly) result.share += loop.area / limb->area;
  for (float azimuth = first_azimuth; azimuth <= last_azimuth; azimuth += 5.f) {
    const Eigen::Vector3f d3 = bone.direction(azimuth);
    const Eigen::Vector2f direction =
        Eigen::Vector2f(d3.dot(plane.u), d3.dot(plane.v)).normalized();
    const float reach = limb->rayDistance(Eigen::Vector2f::Zero(), direction).value_or(0.f);
    float gap = reach;  // inward from the skin to the first belly contour
    for (const SectionLoop& loop : belly)
      gap = std::min(gap, loop.rayDistance(reach * direction, -direction).value_or(reach));
    result.deepest_gap = std::max(result.deepest_gap, reach > 0 ? gap / reach : 1.f);
  }
  return result;
}

TEST(AvatarModelTest, KeyMuscleBelliesFillTheirPartOfTheLimbUnderTheSkin) {
  // Bellies sized from the limb's cross-section, like the compartments of an MRI slice: their
  // share of the section at mid-belly, and all across their arc of the circumference just
  // under the skin (the subcutaneous layer: 12 % of the axis-to-skin distance, plus where the
  // belly narrows towards its ends). The earlier elliptic spindles curved away from the skin
  // at their flanks, so the skin hid them there and they looked thin.
  struct Belly {
    std::string id, bone;
    float at, first_azimuth, last_azimuth;
    double least_share, most_share;
  };
  const std::vector<Belly> bellies = {
      {"quadriceps_femoris", "thigh", 0.5f, -50, 70, 0.25, 0.6},
      {"biceps_femoris", "thigh", 0.5f, 125, 155, 0.04, 0.2},
      {"tibialis_anterior", "shank", 0.35f, 10, 40, 0.04, 0.2},
      {"gastrocnemius", "shank", 0.3f, 130, 230, 0.15, 0.45},
      {"biceps_brachii", "upper_arm", 0.5f, -25, 25, 0.08, 0.3},
      {"triceps_brachii", "upper_arm", 0.5f, 140, 220, 0.15, 0.45},
      {"flexor_carpi_ulnaris", "forearm", 0.3f, -85, -65, 0.03, 0.15}};
  for (const Belly& belly : bellies) {
    for (Side side : {Side::kLeft, Side::kRight}) {
      const AvatarStructure* muscle = defaultAvatar().model.structure(belly.id, side);
      ASSERT_NE(muscle, nullptr) << belly.id;
      const BellySection section =
          bellySection(*muscle, defaultAvatar().landmarks.bone(belly.bone, side), belly.at,
                       belly.first_azimuth, belly.last_azimuth);
      std::printf("%s (%s): %.1f %% of the %s's section, deepest under the skin %.0f %%\n",
                  belly.id.c_str(), toString(side).c_str(), 100 * section.share, belly.bone.c_str(),
                  100 * section.deepest_gap);
      EXPECT_GE(section.share, belly.least_share) << belly.id << " " << toString(side);
      EXPECT_LE(section.share, belly.most_share) << belly.id << " " << toString(side);
      EXPECT_LT(section.deepest_gap, 0.2f) << belly.id << " " << toString(side);
    }
  }
}

TEST(AvatarModelTest, TheBrainIsTwoHemispheresFillingTheCranium) {
  const AvatarBuild& build = defaultAvatar();
  const AvatarStructure* brain = build.model.structure("brain", Side::kNone);
  ASSERT_NE(brain, nullptr);
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& v : brain->mesh.vertices) box.extend(v);
  const Eigen::Vector3f size = box.sizes();
  const double volume_cm3 = signedVolume(brain->mesh) * 1e6;
  std::printf("brain: %.1f x %.1f x %.1f cm, %.0f cm^3\n", 100 * size.x(), 100 * size.y(),
              100 * size.z(), volume_cm3);
  // A cerebrum: longer than wide, wider than high (adult: about 16 x 13 x 10 cm).
  EXPECT_GT(size.x(), size.y());
  EXPECT_GT(size.y(), size.z());
  // Filling the cranium: at its mid-height most of the head's length and width, inside the
  // scalp and skull (the earlier spindle: 10 x 9 cm, 133 cm^3, a third of the width up top).
  const float middle = box.center().z();
  const SectionPlane level =
      SectionPlane::through(Eigen::Vector3f(0.f, 0.f, middle), Eigen::Vector3f::UnitZ());
  const std::vector<SectionLoop> head_loops = sliceMesh(build.model.skin, level);
  const SectionLoop* head = loopContaining(head_loops, Eigen::Vector2f::Zero());
  ASSERT_NE(head, nullptr);
  Eigen::AlignedBox2f slab;
  for (const Eigen::Vector3f& v : brain->mesh.vertices)
    if (std::fabs(v.z() - middle) < 0.006f) slab.extend(Eigen::Vector2f(v.x(), v.y()));
  const Eigen::Vector2f head_size = head->max_corner - head->min_corner;
  std::printf("at mid-height: brain %.1f x %.1f cm in a head of %.1f x %.1f cm\n",
              100 * slab.sizes().x(), 100 * slab.sizes().y(), 100 * head_size.x(),
              100 * head_size.y());
  EXPECT_GT(slab.sizes().x(), 0.75f * head_size.x());
  EXPECT_GT(slab.sizes().y(), 0.75f * head_size.y());
  EXPECT_LT(slab.sizes().x(), head_size.x() - 0.016f);
  EXPECT_LT(slab.sizes().y(), head_size.y() - 0.016f);
  EXPECT_GT(volume_cm3, 400.0);
  // Inside the cranium: its base about the level of the occiput (the base rises towards the
  // orbits), the top under scalp and skull.
  const float vertex = build.landmarks.height;
  EXPECT_GE(box.min().z(), build.landmarks.point("head_centre").z() - 0.01f);
  EXPECT_GT(box.max().z(), vertex - 0.03f);
  EXPECT_LT(box.max().z(), vertex - 0.008f);
  // Two hemispheres: nothing in the longitudinal fissure.
  for (const Eigen::Vector3f& v : brain->mesh.vertices) ASSERT_GT(std::fabs(v.y()), 0.0015f);
  // A dome, not the tent of a spindle: three quarters up it is still most of its width.
  const auto width_at = [&](float z) {
    float widest = 0;
    for (const Eigen::Vector3f& v : brain->mesh.vertices)
      if (std::fabs(v.z() - z) < 0.006f) widest = std::max(widest, 2 * std::fabs(v.y()));
    return widest;
  };
  EXPECT_GT(width_at(box.min().z() + 0.75f * size.z()), 0.7f * size.y());
}

TEST(AvatarModelTest, LeftAndRightStructuresAreMirrorImages) {
  const AvatarModel& model = defaultAvatar().model;
  int pairs = 0;
  for (const AvatarStructure& left : model.structures) {
    if (left.side != Side::kLeft) continue;
    const AvatarStructure* right = model.structure(left.structure_id, Side::kRight);
    ASSERT_NE(right, nullptr) << left.structure_id;
    // The patient's left is +y (a finding on the wrong side is the worst error).
    Eigen::Vector3f left_centre = Eigen::Vector3f::Zero(), right_centre = Eigen::Vector3f::Zero();
    for (const Eigen::Vector3f& v : left.mesh.vertices) left_centre += v;
    for (const Eigen::Vector3f& v : right->mesh.vertices) right_centre += v;
    EXPECT_GT(left_centre.y(), 0) << left.structure_id;
    EXPECT_LT(right_centre.y(), 0) << left.structure_id;
    ASSERT_EQ(right->mesh.vertices.size(), left.mesh.vertices.size());
    // The mirror image of every left vertex is (nearly) a right vertex; the ring order is
    // reversed by the mirroring, so vertices are matched by position.
    for (const Eigen::Vector3f& vertex : left.mesh.vertices) {
      const Eigen::Vector3f mirrored(vertex.x(), -vertex.y(), vertex.z());
      float nearest = 1e9f;
      for (const Eigen::Vector3f& candidate : right->mesh.vertices) {
        nearest = std::min(nearest, (candidate - mirrored).norm());
      }
      ASSERT_LT(nearest, 0.002f) << left.structure_id;
    }
    ++pairs;
  }
  EXPECT_GE(pairs, 20);
}

TEST(AvatarModelTest, StructuresCarryHierarchyFmaIdsAndDisplayNames) {
  const AvatarModel& model = defaultAvatar().model;
  const AvatarStructure* tibialis = model.structure("tibialis_anterior", Side::kRight);
  ASSERT_NE(tibialis, nullptr);
  EXPECT_EQ(tibialis->fma_id, "FMA:22532");
  EXPECT_EQ(tibialis->structure_class, "muscle");
  EXPECT_EQ(tibialis->display_name, "M. tibialis anterior (right)");
  EXPECT_EQ(tibialis->hierarchy, (std::vector<std::string>{"body", "lower limb", "muscular system",
                                                           "M. tibialis anterior"}));
  for (const AvatarStructure& structure : model.structures) {
    const Structure* catalogued = test::catalog().structure(structure.structure_id);
    ASSERT_NE(catalogued, nullptr);
    EXPECT_EQ(structure.fma_id, catalogued->fma_id);
    if (structure.structure_class == "muscle") {
      EXPECT_FALSE(structure.fma_id.empty());
    }
    EXPECT_EQ(structure.hierarchy.size(), 4u);
  }
  EXPECT_EQ(model.structure("urethra", Side::kLeft), nullptr);
  EXPECT_NE(model.structure("urethra", Side::kNone), nullptr);
}

TEST(AvatarModelTest, EveryCataloguedMuscleTendonAndOrganIsInTheModel) {
  const AvatarModel& model = defaultAvatar().model;
  for (const Structure& structure : test::catalog().structures()) {
    if (structure.class_id == "dermatome") continue;
    const bool midline =
        test::catalog().structureClass(structure.class_id)->laterality == Laterality::kMidline;
    for (Side side :
         midline ? std::vector<Side>{Side::kNone} : std::vector<Side>{Side::kLeft, Side::kRight}) {
      EXPECT_NE(model.structure(structure.id, side), nullptr)
          << structure.id << " " << toString(side);
    }
  }
}

TEST(AvatarModelTest, IssueElevenStructuresAreAllThereOnBothSides) {
  // ISNCSCI key muscles C5-T1 and L2-S1, the other named muscles, the reflex tendons.
  for (const std::string id : {"biceps_brachii",
                               "brachialis",
                               "extensor_carpi_radialis_longus",
                               "triceps_brachii",
                               "flexor_digitorum_profundus",
                               "abductor_digiti_minimi",
                               "iliopsoas",
                               "quadriceps_femoris",
                               "tibialis_anterior",
                               "extensor_hallucis_longus",
                               "gastrocnemius",
                               "soleus",
                               "biceps_femoris",
                               "semitendinosus",
                               "gluteus_maximus",
                               "deltoid",
                               "flexor_carpi_radialis",
                               "flexor_carpi_ulnaris",
                               "biceps_brachii_tendon",
                               "brachioradialis_tendon",
                               "triceps_brachii_tendon",
                               "patellar_ligament",
                               "calcaneal_tendon"}) {
    for (Side side : {Side::kLeft, Side::kRight}) {
      EXPECT_NE(defaultAvatar().model.structure(id, side), nullptr) << id << " " << toString(side);
    }
  }
  EXPECT_NE(defaultAvatar().model.structure("external_anal_sphincter", Side::kNone), nullptr);
}

TEST(AvatarModelTest, SmallStructuresHaveProxiesOnTheSkinAboveThem) {
  const AvatarBuild& build = defaultAvatar();
  for (const AvatarStructure& structure : build.model.structures) {
    const bool small = test::catalog().structureClass(structure.structure_class)->proxy;
    EXPECT_EQ(structure.has_proxy, small) << structure.display_name;
    if (!structure.has_proxy) continue;
    EXPECT_LT(distanceToSurface(build.model.skin, structure.proxy.centre), 0.001f);
    EXPECT_NEAR(structure.proxy.normal.norm(), 1.0f, 1e-4f);
    EXPECT_GT(structure.proxy.radius, 0.005f);
    // Outward: a step along the normal leaves the body.
    EXPECT_LT(
        windingNumber(build.model.skin, structure.proxy.centre + 0.01f * structure.proxy.normal),
        0.5);
  }
  // The proxy is on the skin over its structure (within a few centimetres of it).
  for (const AvatarStructure& structure : build.model.structures) {
    if (!structure.has_proxy) continue;
    float nearest = 1e9f;
    for (const Eigen::Vector3f& v : structure.mesh.vertices) {
      nearest = std::min(nearest, (v - structure.proxy.centre).norm());
    }
    EXPECT_LT(nearest, 0.07f) << structure.display_name;
  }
  // The patellar reflex proxy sits on the patella: front of the knee.
  const AvatarStructure* patellar = build.model.structure("patellar_ligament", Side::kLeft);
  const Eigen::Vector3f& knee = build.landmarks.point("knee_left");
  EXPECT_GT(patellar->proxy.centre.x(), knee.x() + 0.03f);
  EXPECT_NEAR(patellar->proxy.centre.z(), knee.z(), 0.05f);
}

/// The share of `structure`'s front-facing vertices (normal towards +x) from which a ray
/// towards the front (the camera of the front view) meets none of `in_front`.
double shareSeenFromTheFront(const AvatarStructure& structure,
                             const std::vector<const AvatarStructure*>& in_front) {
  int facing = 0, seen = 0;
  for (std::size_t i = 0; i < structure.mesh.vertices.size(); ++i) {
    if (structure.mesh.normals[i].x() < 0.5f) continue;
    ++facing;
    const Eigen::Vector3f start = structure.mesh.vertices[i] + 0.001f * Eigen::Vector3f::UnitX();
    bool hidden = false;
    for (const AvatarStructure* other : in_front)
      hidden = hidden || castRay(other->mesh, start, Eigen::Vector3f::UnitX()).has_value();
    seen += !hidden;
  }
  return facing ? static_cast<double>(seen) / facing : 0.0;
}

TEST(AvatarModelTest, TheExtensorHallucisIsSeenFromTheFrontAndReachesTheBigToe) {
  const AvatarBuild& build = defaultAvatar();
  for (Side side : {Side::kLeft, Side::kRight}) {
    const AvatarStructure* ehl = build.model.structure("extensor_hallucis_longus", side);
    const AvatarStructure* ta = build.model.structure("tibialis_anterior", side);
    const AvatarStructure* edl = build.model.structure("extensor_digitorum_longus", side);
    ASSERT_TRUE(ehl && ta && edl);
    // Its own finding must be readable from the front: not hidden behind TA and EDL (the
    // earlier shank-only spindle behind the TA: 68 % seen).
    const double seen = shareSeenFromTheFront(*ehl, {ta, edl});
    std::printf("EHL (%s): %.0f %% of its front-facing surface seen\n", toString(side).c_str(),
                100 * seen);
    EXPECT_GT(seen, 0.8) << toString(side);
    // The tendon runs over the dorsum of the foot towards the big toe (medial of the foot's
    // centre line), in front of and below the ankle.
    const Eigen::Vector3f& ankle = build.landmarks.point("ankle_" + toString(side));
    const Eigen::Vector3f& mtp = build.landmarks.point("mtp_" + toString(side));
    float most_forward = -1e9f;
    Eigen::Vector3f tip = Eigen::Vector3f::Zero();
    for (const Eigen::Vector3f& v : ehl->mesh.vertices)
      if (v.x() > most_forward) most_forward = (tip = v).x();
    EXPECT_GT(tip.x(), mtp.x()) << toString(side);
    EXPECT_LT(tip.z(), ankle.z()) << toString(side);
    EXPECT_LT(std::fabs(tip.y()), std::fabs(mtp.y())) << toString(side) << ": not medial";
  }
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar
