// vicc_avatar_model's report and PLY export of the default avatar.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "avatar_test_support.hpp"
#include "vicc_anatomy_viz/avatar/avatar_report.hpp"

namespace vicc_anatomy_viz::avatar {
namespace {

TEST(AvatarReportTest, ReportListsCountsLandmarksStructuresAndRegions) {
  std::ostringstream out;
  writeReport(test::defaultAvatar(), out);
  const std::string report = out.str();
  EXPECT_NE(report.find("13380 vertices, 26756 triangles"), std::string::npos) << report;
  EXPECT_NE(report.find("build time: "), std::string::npos);
  EXPECT_NE(report.find("elbow_left"), std::string::npos);
  EXPECT_NE(report.find("structures (" +
                        std::to_string(test::defaultAvatar().model.structures.size()) + ")"),
            std::string::npos);
  EXPECT_NE(report.find("skin regions (58)"), std::string::npos);
  EXPECT_NE(report.find("tibialis_anterior"), std::string::npos);
}

TEST(AvatarReportTest, ExportWritesOnePlyPerStructureAndRegion) {
  const AvatarModel& model = test::defaultAvatar().model;
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("vicc_avatar_export_" + std::to_string(::getpid()));
  const std::size_t files = exportPly(model, directory.string());
  EXPECT_EQ(files, 1 + model.structures.size() + model.skin_regions.size());
  std::ifstream ply(directory / "dermatome_L5_left.ply");
  std::string magic, format;
  std::getline(ply, magic);
  std::getline(ply, format);
  EXPECT_EQ(magic, "ply");
  EXPECT_EQ(format, "format ascii 1.0");
  EXPECT_TRUE(std::filesystem::exists(directory / "urethra.ply"));
  EXPECT_TRUE(std::filesystem::exists(directory / "biceps_brachii_right.ply"));
  std::filesystem::remove_all(directory);
}

TEST(AvatarReportTest, RegionMeshKeepsTheRegionsTrianglesAndArea) {
  const AvatarModel& model = test::defaultAvatar().model;
  const SkinRegion* region = model.skinRegion("dermatome_T10", Side::kRight);
  ASSERT_NE(region, nullptr);
  const TriangleMesh mesh = regionMesh(model.skin, *region);
  EXPECT_EQ(mesh.triangles.size(), region->triangles.size());
  std::vector<int> all(mesh.triangles.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  EXPECT_NEAR(trianglesArea(mesh, all), trianglesArea(model.skin, region->triangles), 1e-9);
}

}  // namespace
}  // namespace vicc_anatomy_viz::avatar
