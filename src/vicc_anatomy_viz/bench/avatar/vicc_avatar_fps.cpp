// Frames per second of rviz drawing the avatar while the camera orbits it (bench, not a test):
//   vicc_avatar_fps --db FILE --patient ID [--date D] [--full [--relief]] [--pre-shaded]
//                   [--no-aa] [--size WxH] [--frames N]
// Starts its own Xvfb (when DISPLAY is unset) and private ROS master like vicc_avatar_snapshot,
// lets rviz's own update loop render N frames with transparency on, N with it off and N with
// the display disabled (the floor), one orbit per 120 frames, and prints one line per mode
// (frames = renders of the 3D view, counted by a render target listener; rviz's Frame Rate cap
// is lifted). --full adds an encoded entry for every structure and skin region of the
// avatar (the heaviest status the display can get), in the noise texture or, with --relief, in
// the pain trigger's normal perturbation (every entry lit per pixel by the relief shader);
// --pre-shaded switches the display's "Per-pixel relief" off (the pre-shaded texture, for an
// A/B of the shader's cost); --no-aa is rviz's --disable-anti-aliasing
// (rviz asks OGRE for 4x multisampling by default). Besides wall-clock FPS it prints frames per
// CPU-second of the process (all its threads, llvmpipe's included): the rate one core would
// give without other processes competing for it.
#include <OGRE/OgreRenderSystem.h>
#include <OGRE/OgreRenderTarget.h>
#include <OGRE/OgreRenderTargetListener.h>
#include <OGRE/OgreRoot.h>
#include <ros/ros.h>
#include <rviz/display_group.h>
#include <rviz/ogre_helpers/render_system.h>
#include <rviz/properties/property.h>
#include <rviz/visualization_manager.h>
#include <time.h>
#include <unistd.h>
#include <QApplication>
#include <QElapsedTimer>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/ros/status_message.hpp"
#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_avatar_snapshot_environment.hpp"
#include "vicc_avatar_snapshot_options.hpp"
#include "vicc_avatar_snapshot_renderer.hpp"
#include "vicc_common/command_line.hpp"

namespace {

using namespace vicc_anatomy_viz;

struct BenchOptions {
  std::string db, patient, date;
  bool full = false;
  bool relief = false;
  bool pre_shaded = false;
  bool no_antialiasing = false;
  int width = 1280, height = 800, frames = 360;
};

namespace cli = vicc_common::cli;

const std::vector<cli::OptionSpec> kOptionSpecs = {
    {"db", "FILE", "record database (vicc_patient's)"},
    {"patient", "ID", "patient whose status is drawn"},
    {"date", "D", "examination at or before this date (default: the latest)"},
    {"full", "", "a full status instead: every structure and skin region encoded"},
    {"relief", "", "with --full: every entry in the pain trigger's relief"},
    {"pre-shaded", "", "the relief as the pre-shaded texture (per-pixel relief off)"},
    {"no-aa", "", "rviz without multisampling (--disable-anti-aliasing)"},
    {"size", "WxH", "render window size (default 1280x800)"},
    {"frames", "N", "frames per mode (default 360)"},
};

std::string usage() {
  return cli::helpText(
      "vicc_avatar_fps --db FILE --patient ID [--date D] [--full [--relief]] [--pre-shaded] "
      "[--no-aa] [--size WxH] [--frames N]",
      "Frames per second of rviz drawing the avatar while orbiting it, transparency on and "
      "off, and the floor with the display off.\nExit code 0 on success, 1 on an error, 2 on a "
      "usage error.",
      kOptionSpecs);
}

/// Throws cli::UsageError naming what is wrong.
BenchOptions parseOptions(const std::vector<std::string>& args) {
  const cli::ParsedArguments parsed = cli::parseArguments(args, kOptionSpecs);
  if (!parsed.positional.empty()) throw cli::UsageError("unexpected " + parsed.positional[0]);
  BenchOptions options;
  options.db = parsed.required("db", "a run");
  options.patient = parsed.required("patient", "a run");
  options.date = parsed.value("date");
  options.full = parsed.flag("full");
  options.relief = parsed.flag("relief");
  options.pre_shaded = parsed.flag("pre-shaded");
  options.no_antialiasing = parsed.flag("no-aa");
  if (parsed.has("size"))
    snapshot::parseWindowSize(parsed.value("size"), options.width, options.height);
  options.frames = parsed.integer("frames", options.frames, 1, 1000000);
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
/// colour of the patient's first entry, textured (textured entries cost the most): noise, or
/// the pain trigger's normal perturbation (`relief`).
vicc_msgs::EncodedStatus fullStatus(vicc_msgs::EncodedStatus status,
                                    const avatar::AvatarModel& model, bool relief) {
  if (status.structures.empty()) return status;
  vicc_msgs::EncodedStructure pattern = status.structures.front();
  pattern.alternation_group = -1;
  pattern.texture_id = relief ? "normal_perturbation" : "noise";
  pattern.texture_level = relief ? 1 : 2;
  pattern.texture_levels = relief ? 1 : 3;
  pattern.texture_frequency = relief ? 6.f : 8.f;
  pattern.texture_amplitude = relief ? 0.6f : 0.65f;
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

/// Counts the updates of every render target (rviz's own update timer may render the window
/// besides the bench's explicit frames) and keeps the window's last frame statistics.
class RenderCounter : public Ogre::RenderTargetListener {
 public:
  RenderCounter() {
    auto targets = Ogre::Root::getSingleton().getRenderSystem()->getRenderTargetIterator();
    while (targets.hasMoreElements()) {
      Ogre::RenderTarget* target = targets.getNext();
      target->addListener(this);
      targets_.push_back(target);
    }
  }
  ~RenderCounter() override {
    for (Ogre::RenderTarget* target : targets_) target->removeListener(this);
  }
  void postRenderTargetUpdate(const Ogre::RenderTargetEvent& event) override {
    // Only the 3D view (rviz also keeps a 1x1 window for its GL context).
    if (event.source->getWidth() < 2) return;
    ++updates_;
    const Ogre::RenderTarget::FrameStats& stats = event.source->getStatistics();
    triangles_ = stats.triangleCount;
    batches_ = stats.batchCount;
  }
  unsigned long updates() const { return updates_; }
  std::size_t triangles() const { return triangles_; }
  std::size_t batches() const { return batches_; }

 private:
  std::vector<Ogre::RenderTarget*> targets_;
  unsigned long updates_ = 0;
  std::size_t triangles_ = 0, batches_ = 0;
};

struct Rate {
  double wall_fps = 0.0, cpu_fps = 0.0;
};

/// `frames` frames rendered by rviz's own update loop (VisualizationManager::onUpdate on its
/// timer: displays' update, view controller, one window render), the camera advanced before
/// each; FPS counts the window renders, as a user of rviz gets them.
Rate framesPerSecond(snapshot::AvatarRenderer& renderer, const RenderCounter& counter, int frames) {
  const unsigned long updates_start = counter.updates();
  avatar_view::OrbitCamera orbit = renderer.orbit();
  const float start_yaw = orbit.yaw;
  QElapsedTimer timer;
  const double cpu_start = cpuSeconds();
  timer.start();
  for (unsigned long rendered = 0; rendered < static_cast<unsigned long>(frames);
       rendered = counter.updates() - updates_start) {
    orbit.yaw = start_yaw + 2.f * static_cast<float>(M_PI) * static_cast<float>(rendered) / 120.f;
    renderer.setOrbit(orbit);
    renderer.manager().queueRender();  // what a moved camera asks for
    QApplication::processEvents();
  }
  const double rendered = static_cast<double>(counter.updates() - updates_start);
  return {rendered / (timer.nsecsElapsed() * 1e-9), rendered / (cpuSeconds() - cpu_start)};
}

int run(const BenchOptions& options, char** argv) {
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
  if (options.pre_shaded) renderer.display().subProp("Per-pixel relief")->setValue(false);
  if (options.full)
    renderer.display().showStatus(fullStatus(status, *renderer.display().model(), options.relief));
  const avatar_view::ReliefStatus& relief = renderer.display().reliefStatus();
  // rviz renders at most its "Frame Rate" (default 30) per second; uncapped here to measure
  // what the frame costs.
  renderer.manager()
      .getRootDisplayGroup()
      ->subProp("Global Options")
      ->subProp("Frame Rate")
      ->setValue(1000);
  std::cout << "status: " << renderer.display().drawState().items.size()
            << " encoded entries drawn, " << options.width << "x" << options.height << ", "
            << options.frames << " frames per mode; relief: "
            << (!relief.needed     ? "none"
                : relief.per_pixel ? "per pixel (GLSL)"
                                   : "pre-shaded (" + relief.fallback_reason + ")")
            << "\n";
  const RenderCounter counter;
  for (bool transparency : {true, false}) {
    renderer.setTransparency(transparency);
    framesPerSecond(renderer, counter, 10);  // warm-up: textures, shaders, first swaps
    const Rate rate = framesPerSecond(renderer, counter, options.frames);
    std::cout << "transparency " << (transparency ? "on " : "off") << ": " << rate.wall_fps
              << " FPS wall clock, " << rate.cpu_fps << " frames per CPU-second; "
              << "last frame " << counter.triangles() << " triangles in " << counter.batches()
              << " batches\n";
  }
  // The floor: rviz with the display disabled (clear, multisample resolve, swap, overlays).
  renderer.display().setEnabled(false);
  framesPerSecond(renderer, counter, 10);
  const Rate floor = framesPerSecond(renderer, counter, options.frames);
  std::cout << "display off (floor): " << floor.wall_fps << " FPS wall clock, " << floor.cpu_fps
            << " frames per CPU-second\n";
  ros::shutdown();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return cli::runTool("vicc_avatar_fps", argc, argv, usage(),
                      [argv](const std::vector<std::string>& arguments) {
                        return run(parseOptions(arguments), argv);
                      });
}
