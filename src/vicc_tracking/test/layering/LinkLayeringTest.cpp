// The tracker nodelet is loaded into a camera driver's nodelet manager: it must not drag the
// rig simulator or rosbag into that process. Checked on the built files with ldd, which
// resolves the whole dependency tree, not only the direct NEEDED entries.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

std::string lddOutput(const std::string& file) {
  const std::string command = "ldd '" + file + "' 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return {};
  std::string output;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) output += buffer.data();
  return output;
}

const std::vector<std::string> kForbiddenInTracker = {
    "librosbag", "libvicc_tracking_sim", "libvicc_tracking_rig", "libvicc_tracking_bag"};

void expectNoneOf(const std::string& file, const std::vector<std::string>& forbidden) {
  const std::string output = lddOutput(file);
  ASSERT_NE(output.find("libvicc_tracking_core"), std::string::npos)
      << "ldd did not list the tracking core for " << file << ":\n"
      << output;
  for (const auto& library : forbidden) {
    EXPECT_EQ(output.find(library), std::string::npos) << file << " depends on " << library << ":\n"
                                                       << output;
  }
}

}  // namespace

TEST(LinkLayeringTest, TrackerNodeletLinksNeitherSimulatorNorRosbag) {
  expectNoneOf(VICC_TRACKER_NODELET_LIBRARY, kForbiddenInTracker);
}

TEST(LinkLayeringTest, TrackerNodeLinksNeitherSimulatorNorRosbag) {
  expectNoneOf(VICC_TRACKER_NODE, kForbiddenInTracker);
}

// The check can see these libraries: the bag writer has both.
TEST(LinkLayeringTest, BagWriterDoesLinkSimulatorAndRosbag) {
  const std::string output = lddOutput(VICC_MAKE_BAG_TOOL);
  EXPECT_NE(output.find("librosbag"), std::string::npos) << output;
  EXPECT_NE(output.find("libvicc_tracking_sim"), std::string::npos) << output;
}
