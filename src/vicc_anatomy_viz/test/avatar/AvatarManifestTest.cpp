// Manifest errors name the file and the entry; the skin loader converts axes properly.
#include <gtest/gtest.h>

#include "avatar_test_support.hpp"
#include "vicc_anatomy_viz/avatar/avatar_manifest.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/avatar/skin_mesh_loader.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {
namespace {

std::string manifestWith(const std::string& skin_file, const std::string& structures) {
  return "skin:\n  file: " + skin_file + "\n  mesh: human-baseMesh\n  up_axis: \"+y\"\n" +
         "  forward_axis: \"+z\"\nstructures:\n" + structures;
}

const std::string kHumanZae = "/usr/share/assimp/models/Collada/human.zae";

std::string errorOf(const std::string& manifest_text) {
  const std::string path = test::writeTemporary("manifest.yaml", manifest_text);
  try {
    buildAvatarModel(path, test::catalog());
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(AvatarManifestTest, MissingSkinMeshIsAConfigErrorNamingTheFile) {
  const std::string message = errorOf(manifestWith("/nonexistent/body.dae", "  []\n"));
  EXPECT_NE(message.find("/nonexistent/body.dae"), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(AvatarManifestTest, UnreadableSkinMeshIsAConfigErrorNamingTheFile) {
  const std::string garbage = test::writeTemporary("garbage.dae", "this is not a mesh");
  const std::string message = errorOf(manifestWith(garbage, "  []\n"));
  EXPECT_NE(message.find(garbage), std::string::npos) << message;
}

TEST(AvatarManifestTest, UnknownStructureIdIsRejected) {
  const std::string message =
      errorOf(manifestWith(kHumanZae,
                           "  - {id: musculus_imaginarius, sides: [left], region: r, system: s,\n"
                           "     generated: {bone: thigh}}\n"));
  EXPECT_NE(message.find("musculus_imaginarius"), std::string::npos) << message;
  EXPECT_NE(message.find("manifest.yaml"), std::string::npos) << message;
}

TEST(AvatarManifestTest, BadSidesAreRejected) {
  for (const std::string side : {"up", "none"}) {
    const std::string message = errorOf(
        manifestWith(kHumanZae, "  - {id: biceps_brachii, sides: [" + side +
                                    "], region: r, system: s, generated: {bone: upper_arm}}\n"));
    EXPECT_NE(message.find("bad side '" + side + "'"), std::string::npos) << message;
  }
  const std::string midline =
      errorOf(manifestWith(kHumanZae,
                           "  - {id: urethra, sides: [left], region: r, system: s,\n"
                           "     proxy: {bone: trunk}}\n"));
  EXPECT_NE(midline.find("bad side 'left'"), std::string::npos) << midline;
}

TEST(AvatarManifestTest, FmaIdThatDiffersFromTheCatalogueIsRejected) {
  const std::string message = errorOf(
      manifestWith(kHumanZae,
                   "  - {id: soleus, sides: [left], fma_id: \"FMA:1\", region: r, system: s,\n"
                   "     generated: {bone: shank}}\n"));
  EXPECT_NE(message.find("FMA:1"), std::string::npos) << message;
}

TEST(AvatarManifestTest, MissingAtlasMeshNamesTheFile) {
  const std::string message =
      errorOf(manifestWith(kHumanZae,
                           "  - {id: soleus, sides: [left], region: r, system: s,\n"
                           "     mesh: {file: FMA22542.obj, unit_in_metres: 0.001}}\n"));
  EXPECT_NE(message.find("FMA22542.obj"), std::string::npos) << message;
}

TEST(AvatarManifestTest, MisspeltKeysAndBadShapesAreRejected) {
  EXPECT_NE(errorOf(manifestWith(kHumanZae,
                                 "  - {id: soleus, sides: [left], region: r, system: s,\n"
                                 "     generated: {bone: shank, thicknes: 0.2}}\n"))
                .find("thicknes"),
            std::string::npos);
  EXPECT_NE(errorOf(manifestWith(kHumanZae,
                                 "  - {id: soleus, sides: [left], region: r, system: s,\n"
                                 "     generated: {bone: shank, from: 0.8, to: 0.2}}\n"))
                .find("'to' must be greater"),
            std::string::npos);
  EXPECT_NE(errorOf(manifestWith(kHumanZae,
                                 "  - {id: soleus, sides: [left], region: r, system: s,\n"
                                 "     generated: {bone: tail}}\n"))
                .find("tail"),
            std::string::npos);
}

TEST(AvatarManifestTest, SectionShapesTakeOnlyTheirOwnKeys) {
  const auto soleus = [](const std::string& generated) {
    return errorOf(manifestWith(kHumanZae,
                                "  - {id: soleus, sides: [left], region: r, system: s,\n"
                                "     generated: " +
                                    generated + "}\n"));
  };
  EXPECT_NE(soleus("{bone: shank, section: wedge}").find("ellipse, sector or cavity"),
            std::string::npos);
  // An ellipse has no span, a sector no thickness: a key of the wrong shape is named.
  EXPECT_NE(soleus("{bone: shank, span: 40}").find("span"), std::string::npos);
  EXPECT_NE(soleus("{bone: shank, section: sector, thickness: 0.3}").find("thickness"),
            std::string::npos);
  EXPECT_NE(soleus("{bone: shank, section: sector, inner: 0.6, outer: 0.5}")
                .find("0 < inner < outer < 1"),
            std::string::npos);
  EXPECT_NE(soleus("{bone: shank, section: sector, span: 400}").find("span"), std::string::npos);
  EXPECT_NE(soleus("{bone: shank, section: cavity, half: up}").find("half"), std::string::npos);
  EXPECT_NE(soleus("{bone: shank, profile: [0.5, 0.6, 0.7]}").find("[proximal, distal]"),
            std::string::npos);
  EXPECT_NE(soleus("{bone: shank, profile: 0}").find("profile"), std::string::npos);
  EXPECT_NE(soleus("{bone: shank, tilt: 75}").find("tilt"), std::string::npos);
  EXPECT_EQ(soleus("{bone: shank, section: sector, span: 60, inner: 0.3, outer: 0.8, "
                   "profile: [0.4, 0.7], tilt: 10}"),
            "");
}

TEST(AvatarManifestTest, NonFiniteNumbersAreRejected) {
  // The YAML reader refuses .nan and .inf; the manifest also what overflows to infinity.
  for (const std::string value : {".nan", ".inf", "-.inf", "1e999"}) {
    const std::string message =
        errorOf(manifestWith(kHumanZae,
                             "  - {id: soleus, sides: [left], region: r, system: s,\n"
                             "     generated: {bone: shank, azimuth: " +
                                 value + "}}\n"));
    EXPECT_NE(message.find("structures[0].generated.azimuth"), std::string::npos) << message;
    EXPECT_TRUE(message.find("not a number") != std::string::npos ||
                message.find("must be a finite number") != std::string::npos)
        << message;
  }
}

TEST(AvatarManifestTest, SkinAxesMustBeTwoDifferentSignedAxes) {
  MeshSource source;
  source.path = kHumanZae;
  source.up_axis = "+y";
  source.forward_axis = "-y";
  EXPECT_THROW(loadSkinMesh(source), ConfigError);
  source.forward_axis = "forward";
  EXPECT_THROW(loadSkinMesh(source), ConfigError);
}

TEST(AvatarManifestTest, AxisConversionKeepsTheBodysLeftOnItsLeft) {
  // A tetrahedron in a y-up, +z-facing file with its far vertex at the file's +x: the body's
  // left for a body facing +z with the head at +y. In REP-103 that vertex must be at +y.
  const std::string obj = test::writeTemporary(
      "marker.obj",
      "v 0 0 0\nv 0 1 0\nv 0 0 0.2\nv 0.5 0.3 0.05\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  MeshSource source;
  source.path = obj;
  const TriangleMesh mesh = loadSkinMesh(source);
  const auto marker = std::max_element(
      mesh.vertices.begin(), mesh.vertices.end(),
      [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return a.y() < b.y(); });
  EXPECT_GT(marker->y(), 0.2f);
  float highest = 0;
  for (const Eigen::Vector3f& v : mesh.vertices) highest = std::max(highest, v.z());
  EXPECT_NEAR(highest, 1.0f, 1e-5f);  // the file's +y is up
}

TEST(AvatarManifestTest, AtlasMeshReplacesTheGeneratedShapeWithoutCodeChanges) {
  // A millimetre, z-up "atlas" tetrahedron facing -y (BodyParts3D's convention) as the soleus.
  test::writeTemporary("FMA22542.obj",
                       "v 0 0 0\nv 0 0 100\nv 0 -20 0\nv 50 -5 30\nf 1 2 3\nf 1 4 2\nf 2 4 3\n"
                       "f 1 3 4\n");
  const std::string path = test::writeTemporary(
      "atlas_manifest.yaml",
      manifestWith(
          kHumanZae,
          "  - {id: soleus, sides: [left], region: lower limb, system: muscular system,\n"
          "     fma_id: \"FMA:22542\", mesh: {file: FMA22542.obj, up_axis: \"+z\",\n"
          "     forward_axis: \"-y\", unit_in_metres: 0.001, translation: [0, 0.1, 0.2]}}\n"));
  const AvatarModel model = buildAvatarModel(path, test::catalog());
  const AvatarStructure* soleus = model.structure("soleus", Side::kLeft);
  ASSERT_NE(soleus, nullptr);
  EXPECT_EQ(soleus->fma_id, "FMA:22542");
  ASSERT_EQ(soleus->mesh.vertices.size(), 4u);
  float top = -1, forward = -1;
  for (const Eigen::Vector3f& v : soleus->mesh.vertices) {
    top = std::max(top, v.z());
    forward = std::max(forward, v.x());
  }
  EXPECT_NEAR(top, 0.3f, 1e-5f);       // 100 mm up, translated 0.2 m
  EXPECT_NEAR(forward, 0.02f, 1e-5f);  // the file's -y (20 mm) is forward
  EXPECT_GT(signedVolume(soleus->mesh), 0);
  EXPECT_EQ(model.structures.size(), 1u);
}

TEST(AvatarManifestTest, GeneratedPartsFormOneStructure) {
  const std::string belly = "{bone: shank, from: 0.4, to: 0.95, azimuth: 45}";
  const std::string tendon = "{bone: foot, from: 0.1, to: 0.9, azimuth: 0, depth: 0.4}";
  const auto build = [](const std::string& generated) {
    return buildAvatarModel(
        test::writeTemporary("parts_manifest.yaml",
                             manifestWith(kHumanZae,
                                          "  - {id: extensor_hallucis_longus, sides: [right],\n"
                                          "     region: r, system: s, generated: " +
                                              generated + "}\n")),
        test::catalog());
  };
  const TriangleMesh shank_part = build(belly).structures.at(0).mesh;
  const TriangleMesh foot_part = build(tendon).structures.at(0).mesh;
  const TriangleMesh both = build("[" + belly + ", " + tendon + "]").structures.at(0).mesh;
  ASSERT_EQ(both.vertices.size(), shank_part.vertices.size() + foot_part.vertices.size());
  ASSERT_EQ(both.triangles.size(), shank_part.triangles.size() + foot_part.triangles.size());
  ASSERT_EQ(both.normals.size(), both.vertices.size());
  // The second part's triangles index its own vertices, after the first part's.
  const Eigen::Vector3i last = both.triangles.back();
  EXPECT_EQ(both.vertices[last[0]], foot_part.vertices[foot_part.triangles.back()[0]]);
  EXPECT_NEAR(signedVolume(both), signedVolume(shank_part) + signedVolume(foot_part), 1e-9);
  const std::string message = errorOf(manifestWith(
      kHumanZae, "  - {id: soleus, sides: [left], region: r, system: s, generated: []}\n"));
  EXPECT_NE(message.find("at least one part"), std::string::npos) << message;
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar
