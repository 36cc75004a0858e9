// Frames per second of rviz drawing the avatar while the camera orbits it (bench, not a test):
//   vicc_avatar_fps --db FILE --patient ID [--date D] [--full] [--no-aa] [--size WxH]
//                   [--frames N]
// Starts its own Xvfb (when DISPLAY is unset) and private ROS master like vicc_avatar_snapshot,
// renders N frames with transparency on and N with it off, one orbit per 120 frames, and prints
// one line per mode. --full adds an encoded entry for every structure and skin region of the
// avatar (the heaviest status the display can get); --no-aa is rviz's --disable-anti-aliasing
// (rviz asks OGRE for 4x multisampling by default). Besides wall-clock FPS it prints frames per
// CPU-second of the process (all its threads, llvmpipe's included): the rate one core would
// give without other processes competing for it.
#include <ros/ros.h>
#include <rviz/ogre_helpers/render_system.h>
#include <time.h>
#include <unistd.h>
#include <QApplication>
#include <QElapsedTimer>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <regex>

#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/ros/status_message.hpp"
#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_avatar_snapshot_environment.hpp"
#include "vicc_avatar_snapshot_renderer.hpp"

namespace {

using namespace vicc_anatomy_viz;

struct BenchOptions {
  std::string db, patient, date;
  bool full = false;
  bool no_antialiasing = false;
  int width = 1280, height = 800, frames = 360;
};

BenchOptions parse(int argc, char** argv) {
  BenchOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::string value = i + 1 < argc ? argv[i + 1] : "";
    if (arg == "--full") {
      options.full = true;
      continue;
    }
    if (arg == "--no-aa") {
      options.no_antialiasing = true;
      continue;
    }
    ++i;
    if (arg == "--db")
      options.db = value;
    else if (arg == "--patient")
      options.patient = value;
    else if (arg == "--date")
      options.date = value;
    else if (arg == "--frames")
      options.frames = std::stoi(value);
    else if (arg == "--size") {
      std::smatch match;
      if (!std::regex_match(value, match, std::regex("([0-9]+)x([0-9]+)")))
        throw std::invalid_argument("--size WxH");
      options.width = std::stoi(match[1]);
      options.height = std::stoi(match[2]);
    } else
      throw std::invalid_argument("unknown option " + arg);
  }
  if (options.db.empty() || options.patient.empty())
    throw std::invalid_argument(
        "usage: vicc_avatar_fps --db FILE --patient ID [--date D] [--full] "
        "[--size WxH] [--frames N]");
  return options;
}

vicc_msgs::EncodedStatus patientStatus(const BenchOptions& options) {
  PatientStatusConfig config;
  config.encoding_config = defaultEncodingConfigPath();
  config.anatomy_config = defaultAnatomyConfigPath();
  config.store.path = options.db;
  config.store.read_only = true;
  PatientStatusService service(config);
  return ros_adapter::toMessage(service.encodedStatus(options.patient, options.date));
}

/// The patient's status plus one entry per structure and skin region of the avatar, in the
/// colour and texture of the patient's first entry (textured entries cost the most).
vicc_msgs::EncodedStatus fullStatus(vicc_msgs::EncodedStatus status,
                                    const avatar::AvatarModel& model) {
  if (status.structures.empty()) return status;
  vicc_msgs::EncodedStructure pattern = status.structures.front();
  pattern.alternation_group = -1;
  pattern.texture_id = "noise";
  pattern.texture_level = 2;
  pattern.texture_levels = 3;
  pattern.texture_frequency = 8.f;
  pattern.texture_amplitude = 0.65f;
  status.alternations.clear();
  status.structures.clear();
  auto add = [&](const std::string& id, Side side, bool proxy) {
    vicc_msgs::EncodedStructure entry = pattern;
    entry.structure_id = id;
    entry.side = toString(side);
    entry.proxy = proxy;
    status.structures.push_back(entry);
  };
  for (const auto& region : model.skin_regions) add(region.structure_id, region.side, false);
  for (const auto& structure : model.structures)
    add(structure.structure_id, structure.side,
        structure.has_proxy && structure.mesh.triangles.empty());
  return status;
}

double cpuSeconds() {
  timespec time{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &time);
  return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
}

struct Rate {
  double wall_fps = 0.0, cpu_fps = 0.0;
};

Rate framesPerSecond(snapshot::AvatarRenderer& renderer, int frames) {
  avatar_view::OrbitCamera orbit = renderer.orbit();
  const float start_yaw = orbit.yaw;
  QElapsedTimer timer;
  const double cpu_start = cpuSeconds();
  timer.start();
  for (int frame = 0; frame < frames; ++frame) {
    orbit.yaw = start_yaw + 2.f * static_cast<float>(M_PI) * static_cast<float>(frame) / 120.f;
    renderer.setOrbit(orbit);
    renderer.renderFrame(1.f / 30.f);
    QApplication::processEvents();
  }
  return {frames / (timer.nsecsElapsed() * 1e-9), frames / (cpuSeconds() - cpu_start)};
}

int run(int argc, char** argv) {
  const BenchOptions options = parse(argc, argv);
  const vicc_msgs::EncodedStatus status = patientStatus(options);
  snapshot::ChildProcess xvfb, master;
  const char* display = std::getenv("DISPLAY");
  const std::string server = display && *display
                                 ? std::string(display)
                                 : snapshot::startXvfb(options.width, options.height, xvfb);
  setenv("DISPLAY", server.c_str(), 1);
  ros::init(ros::M_string{{"__master", snapshot::startPrivateMaster(master)}}, "vicc_avatar_fps",
            ros::init_options::AnonymousName | ros::init_options::NoRosout);
  if (options.no_antialiasing) rviz::RenderSystem::disableAntiAliasing();
  int qt_argc = 1;
  QApplication application(qt_argc, argv);
  const std::string topic = "/vicc_avatar_fps_" + std::to_string(getpid()) + "/status";
  snapshot::AvatarRenderer renderer(options.width, options.height, topic);
  ros::NodeHandle node;
  ros::Publisher publisher = node.advertise<vicc_msgs::EncodedStatus>(topic, 1, true);
  publisher.publish(status);
  if (!renderer.waitForStatus(0, 30.0) || !renderer.setView(avatar_view::BodyView::kFront))
    throw std::runtime_error("no avatar drawn: " + renderer.display().modelError());
  if (options.full) renderer.display().showStatus(fullStatus(status, *renderer.display().model()));
  std::cout << "status: " << renderer.display().drawState().items.size()
            << " encoded entries drawn, " << options.width << "x" << options.height << ", "
            << options.frames << " frames per mode\n";
  for (bool transparency : {true, false}) {
    renderer.setTransparency(transparency);
    framesPerSecond(renderer, 10);  // warm-up: textures, shaders, first swaps
    const Rate rate = framesPerSecond(renderer, options.frames);
    std::cout << "transparency " << (transparency ? "on " : "off") << ": " << rate.wall_fps
              << " FPS wall clock, " << rate.cpu_fps << " frames per CPU-second\n";
  }
  ros::shutdown();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "vicc_avatar_fps: " << error.what() << "\n";
    return 1;
  }
}
