// The workspace installed into a temporary prefix, used from there the way a user would:
// CLIs, a node and a nodelet started from the install space while the source, build and devel
// trees are hidden (tmpfs over them in a private mount namespace), so that anything that still
// reaches into the checkout fails here. What this build did not build is not checked.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace fs = std::filesystem;

namespace {

using vicc_test::CommandResult;

CommandResult run(const std::string& command) { return vicc_test::runCommand(command); }

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

const std::vector<std::string> kCheckoutTrees = {VICC_SOURCE_DIR, VICC_BUILD_DIR, VICC_DEVEL_DIR};

/// Strings in an ELF file that name a place inside the checkout. Source file names are allowed:
/// rosconsole's macros record __FILE__ for log locations, which is no lookup.
std::set<std::string> checkoutPathsIn(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::set<std::string> found;
  if (bytes.compare(0, 4,
                    "\x7f"
                    "ELF") != 0)
    return found;
  for (const std::string& tree : kCheckoutTrees) {
    for (size_t at = bytes.find(tree); at != std::string::npos; at = bytes.find(tree, at + 1)) {
      const size_t end = bytes.find('\0', at);
      const std::string text = bytes.substr(at, end == std::string::npos ? 256 : end - at);
      const std::string extension = fs::path(text).extension().string();
      if (extension == ".cpp" || extension == ".hpp" || extension == ".h" || extension == ".cc")
        continue;
      found.insert(text);
    }
  }
  return found;
}

class InstallSpaceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    char root_template[] = "/tmp/vicc_install_test_XXXXXX";
    const char* root = mkdtemp(root_template);
    ASSERT_NE(root, nullptr);
    root_ = root;
    // catkin writes the configured prefix into its install rules (setup.bash & co.), so the
    // install is staged with DESTDIR instead of a different CMAKE_INSTALL_PREFIX; setup.bash
    // finds its own place, so the staged tree works where it is.
    const fs::path stage = root_ / "stage";
    prefix_ = stage / fs::path(VICC_INSTALL_PREFIX).relative_path();
    install_ =
        run("DESTDIR='" + stage.string() + "' cmake -P '" VICC_BUILD_DIR "/cmake_install.cmake'");
    can_hide_ = run("unshare --mount --propagation private true").exit_code == 0;
  }

  static void TearDownTestSuite() {
    std::error_code error;
    fs::remove_all(root_, error);
  }

  void SetUp() override {
    ASSERT_EQ(install_.exit_code, 0) << install_.output;
    if (!can_hide_) {
      // Without CAP_SYS_ADMIN the trees stay visible; the steps still run from the install
      // space and the ELF check below still finds compiled-in checkout paths.
      RecordProperty("checkout_hidden", "no (unshare --mount not permitted)");
    }
  }

  /// Runs `steps` in bash with only the install space's setup sourced and, when permitted,
  /// the checkout's source, build and devel trees hidden.
  static CommandResult runInstalled(const std::string& steps) {
    static int count = 0;
    const fs::path script = root_ / ("step" + std::to_string(++count) + ".sh");
    std::ofstream out(script);
    out << "set -eo pipefail\n";
    if (can_hide_) {
      for (const std::string& tree : kCheckoutTrees)
        out << "mount -t tmpfs tmpfs '" << tree << "'\n";
    }
    out << "unset ROS_PACKAGE_PATH CMAKE_PREFIX_PATH LD_LIBRARY_PATH PYTHONPATH PKG_CONFIG_PATH\n"
        << "export ROS_HOME='" << (root_ / "ros_home").string() << "'\n"
        << "export HOME='" << root_.string() << "'\n"
        << "cd '" << root_.string() << "'\n"
        << "source '" << (prefix_ / "setup.bash").string() << "'\n"
        << steps << "\n";
    out.close();
    const std::string shell = can_hide_ ? "unshare --mount --propagation private bash " : "bash ";
    return run(shell + "'" + script.string() + "'");
  }

  static inline fs::path root_;
  static inline fs::path prefix_;
  static inline CommandResult install_;
  static inline bool can_hide_ = false;
};

TEST_F(InstallSpaceTest, InstalledBinariesNameNoPlaceInTheCheckout) {
  std::set<std::string> found;
  size_t elf_files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(prefix_)) {
    if (!entry.is_regular_file() || entry.is_symlink()) continue;
    const auto paths = checkoutPathsIn(entry.path());
    for (const auto& path : paths) found.insert(entry.path().filename().string() + ": " + path);
    std::ifstream in(entry.path(), std::ios::binary);
    std::array<char, 4> magic{};
    in.read(magic.data(), magic.size());
    if (in && std::string(magic.data(), 4) ==
                  "\x7f"
                  "ELF")
      ++elf_files;
  }
  EXPECT_GT(elf_files, 5u) << "the install space holds hardly any binaries";
  for (const auto& entry : found) ADD_FAILURE() << "compiled-in checkout path: " << entry;
}

#ifdef VICC_HAS_TRACKING
TEST_F(InstallSpaceTest, ScenariosAndConfigAreFoundInTheInstallSpace) {
  // The usage lists the named scenarios, read from share/vicc_tracking/config/scenarios.
  const CommandResult help = runInstalled("rosrun vicc_tracking vicc_make_bag --help");
  EXPECT_TRUE(contains(help.output, "short_test")) << help.output;
  EXPECT_FALSE(contains(help.output, "not found")) << help.output;
  const CommandResult launch_files = runInstalled(
      "for f in tracker.yaml tracker_thesis.yaml; do test -f \"$(rospack find vicc_tracking)/"
      "config/$f\"; done && echo CONFIG_PRESENT");
  EXPECT_TRUE(contains(launch_files.output, "CONFIG_PRESENT")) << launch_files.output;
}

TEST_F(InstallSpaceTest, TrackerNodeAndNodeletStartFromTheInstallSpace) {
  const int port = 20000 + static_cast<int>(getpid() % 20000);
  // Each is started, watched until it logs its start-up line (at most 30 s: pluginlib's crawl
  // of all packages is slow on a loaded machine), then stopped with SIGINT.
  const CommandResult result = runInstalled(
      "export ROS_MASTER_URI=http://localhost:" + std::to_string(port) +
      "\n"
      "rosmaster --core -p " +
      std::to_string(port) +
      " >master.log 2>&1 &\n"
      "master=$!\n"
      "trap 'kill $master' EXIT\n"
      "for i in $(seq 50); do rostopic list >/dev/null 2>&1 && break; sleep 0.2; done\n"
      "run_until_started() {\n"
      "  log=$1; shift\n"
      "  stdbuf -oL \"$@\" >\"$log\" 2>&1 &\n"
      "  pid=$!\n"
      "  for i in $(seq 150); do\n"
      "    grep -q 'init strategy' \"$log\" && break; kill -0 $pid 2>/dev/null || break; sleep "
      "0.2\n"
      "  done\n"
      "  kill -INT $pid 2>/dev/null || true; wait $pid || true; cat \"$log\"\n"
      "}\n"
      "echo '== node'\n"
      "run_until_started node.log rosrun vicc_tracking tracker\n"
      "echo '== nodelet'\n"
      "run_until_started nodelet.log rosrun nodelet nodelet standalone "
      "vicc_tracking/TrackerNodelet\n"
      "echo '== done'\n");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  const size_t node = result.output.find("== node");
  const size_t nodelet = result.output.find("== nodelet");
  const size_t done = result.output.find("== done");
  ASSERT_TRUE(node != std::string::npos && nodelet != std::string::npos &&
              done != std::string::npos)
      << result.output;
  EXPECT_TRUE(contains(result.output.substr(node, nodelet - node), "init strategy"))
      << result.output;
  EXPECT_TRUE(contains(result.output.substr(nodelet, done - nodelet), "init strategy"))
      << result.output;
  EXPECT_FALSE(contains(result.output, "Failed to load nodelet")) << result.output;
}
#endif

#ifdef VICC_HAS_ANATOMY
TEST_F(InstallSpaceTest, PatientCliUsesTheInstalledConfiguration) {
  const CommandResult result = runInstalled(
      "vicc=$(rospack find vicc_anatomy_viz)\n"
      "rosrun vicc_anatomy_viz vicc_patient --help | head -1\n"
      "rosrun vicc_anatomy_viz vicc_patient import --db p.db "
      "\"$vicc/data/samples/fig4_6_patient.json\"\n"
      "rosrun vicc_anatomy_viz vicc_patient encode --db p.db --patient SDH-046\n");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "usage: vicc_patient")) << result.output;
  EXPECT_TRUE(contains(result.output, "SDH-046")) << result.output;
}
#endif

#ifdef VICC_HAS_GLYPHS
TEST_F(InstallSpaceTest, GlyphToolRendersAnInstalledSample) {
  const CommandResult result = runInstalled(
      "rosrun vicc_glyphs vicc_glyph render \"$(rospack find vicc_glyphs)/data/samples/"
      "two_curves.xml\" --out glyph.png --size 64\n"
      "head -c 8 glyph.png | od -An -c | tr -d ' \\n'; echo\n");
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "211PNG")) << result.output;  // \x89PNG as od -c prints it
}
#endif

}  // namespace
