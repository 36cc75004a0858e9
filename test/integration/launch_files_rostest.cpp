// rostest: every launch file of the workspace parses with the arguments a user gives, and
// names the nodes it would start (`roslaunch --nodes`, roslaunch-check style); rig.launch on a
// machine without the camera driver starts nothing and says what to install.
//
// Arguments: WORKSPACE (the checkout), or RIG_LAUNCH for MissingDriverStartsNothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <ros/package.h>
#include <ros/ros.h>

#include "graph_queries.hpp"
#include "roslaunch_child.hpp"

extern char** environ;

namespace {

std::vector<std::string> g_program_args;  // positional, after gtest and ros::init removed theirs

/// Runs roslaunch with `arguments` to its end (at most `limit`); what it printed.
std::string runRoslaunch(const std::vector<std::string>& arguments, int& wait_status,
                         ros::WallDuration limit = ros::WallDuration(60.0)) {
  const std::string output = (std::filesystem::temp_directory_path() /
                              ("vicc_launch_files_" + std::to_string(getpid()) + ".log"))
                                 .string();
  std::vector<std::string> command = {"roslaunch"};
  command.insert(command.end(), arguments.begin(), arguments.end());
  const vicc_test::ChildRun run = vicc_test::runToEnd(command, limit, output);
  EXPECT_TRUE(run.started) << "roslaunch could not be started";
  EXPECT_TRUE(!run.started || run.ended) << "roslaunch did not end";
  wait_status = run.wait_status;
  std::filesystem::remove(output);
  return run.printed;
}

struct LaunchCase {
  std::string file;                    // relative to the workspace, or "$pkg/..." for a package
  std::vector<std::string> arguments;  // as a user passes them
  std::vector<std::string> nodes;      // some of the nodes it must start
};

std::string resolve(const std::string& file, const std::string& workspace) {
  if (file.front() != '$') return workspace + "/" + file;
  const std::size_t slash = file.find('/');
  return ros::package::getPath(file.substr(1, slash - 1)) + file.substr(slash);
}

TEST(LaunchFiles, EveryOneParsesAndNamesItsNodes) {
  ASSERT_EQ(g_program_args.size(), 1u) << "usage: launch_files_rostest WORKSPACE";
  const std::string& workspace = g_program_args[0];
  const std::string bag = "bag:=" + workspace + "/bags/short_test.bag";
  const std::vector<LaunchCase> cases = {
      {"launch/replay.launch", {bag}, {"/player", "/fusion", "/rviz"}},
      {"launch/replay.launch", {bag, "fusion:=false", "rviz:=false"}, {"/player", "/tracker"}},
      {"launch/rig.launch",
       {"drivers:=false", "extrinsic:=0 0 0 0 0 0 1"},
       {"/fusion", "/imu_to_camera", "/rviz"}},
      {"launch/sim.launch", {}, {"/depth_publisher", "/imu_publisher", "/fusion", "/rviz"}},
      {"launch/rig_sim.launch", {"fusion:=false"}, {"/depth_publisher", "/tracker"}},
      {"launch/clinic.launch", {}, {"/patient_status_server", "/glyph_server", "/rviz"}},
      {"launch/demo.launch",
       {},
       {"/player", "/fusion", "/patient_status_server", "/glyph_server", "/map_beside_avatar",
        "/rviz"}},
      {"$vicc_tracking/launch/tracker.launch", {"nodelet:=true"}, {"/vicc_manager", "/tracker"}},
      {"$vicc_tracking/launch/rig_sim.launch", {}, {"/depth_publisher", "/imu_publisher"}},
      {"$vicc_fusion/launch/fusion.launch", {}, {"/fusion"}},
      {"$vicc_anatomy_viz/launch/avatar.launch", {}, {"/patient_status_server", "/rviz"}},
      {"$vicc_anatomy_viz/launch/patient_status_server.launch", {}, {"/patient_status_server"}},
      {"$vicc_glyphs/launch/glyph_server.launch", {}, {"/glyph_server"}},
  };
  for (const LaunchCase& launch : cases) {
    std::vector<std::string> arguments = {"--nodes", resolve(launch.file, workspace)};
    arguments.insert(arguments.end(), launch.arguments.begin(), launch.arguments.end());
    int wait_status = 0;
    const std::string printed = runRoslaunch(arguments, wait_status);
    EXPECT_TRUE(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0)
        << launch.file << " does not parse:\n"
        << printed;
    for (const std::string& node : launch.nodes)
      EXPECT_NE(printed.find(node + "\n"), std::string::npos)
          << launch.file << " would not start " << node << ":\n"
          << printed;
  }
}

TEST(RigLaunch, MissingDriverStartsNothing) {
  ASSERT_EQ(g_program_args.size(), 1u) << "usage: launch_files_rostest RIG_LAUNCH";
  if (!ros::package::getPath("pico_flexx_driver").empty())
    GTEST_SKIP() << "pico_flexx_driver is installed here";
  int wait_status = 0;
  const std::string printed =
      runRoslaunch({g_program_args[0], "rviz:=false"}, wait_status, ros::WallDuration(30.0));
  EXPECT_TRUE(WIFEXITED(wait_status) && WEXITSTATUS(wait_status) != 0)
      << "rig.launch without its camera driver did not fail:\n"
      << printed;
  EXPECT_NE(printed.find("github.com/code-iai/pico_flexx_driver"), std::string::npos)
      << "no word on what to install:\n"
      << printed;
  EXPECT_NE(printed.find("drivers:=false"), std::string::npos) << printed;
  EXPECT_FALSE(vicc_test::nodeIsRegistered("/fusion")) << "the fusion node was started";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "launch_files_rostest");
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]).rfind("--", 0) != 0) g_program_args.emplace_back(argv[i]);
  return RUN_ALL_TESTS();
}
