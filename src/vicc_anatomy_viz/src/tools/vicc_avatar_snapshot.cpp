// vicc_avatar_snapshot: a patient's encoded status rendered by the real rviz and AvatarDisplay
// into a PNG (see vicc_avatar_snapshot_options.hpp for the command line). Exit codes: 0 PNG
// written, 2 bad command line, 3 patient/date/database problem, 4 no display server,
// 5 rendering failed, 6 PNG written but incomplete (an encoded finding could not be drawn).
#include <ros/ros.h>
#include <unistd.h>
#include <vicc_msgs/EncodedStatus.h>
#include <QApplication>

#include <cstdlib>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "vicc_anatomy_viz/errors.hpp"
#include "vicc_anatomy_viz/patient_status_service.hpp"
#include "vicc_anatomy_viz/ros/status_message.hpp"
#include "vicc_anatomy_viz/rviz/avatar_display.hpp"
#include "vicc_anatomy_viz/time_format.hpp"
#include "vicc_avatar_snapshot_environment.hpp"
#include "vicc_avatar_snapshot_options.hpp"
#include "vicc_avatar_snapshot_renderer.hpp"

namespace {

using namespace vicc_anatomy_viz;

struct Failure : std::runtime_error {
  Failure(int code, const std::string& message) : std::runtime_error(message), exit_code(code) {}
  int exit_code;
};

/// The status to draw, or Failure(3) for an unknown patient, a date before the first
/// examination or an unreadable database.
vicc_msgs::EncodedStatus loadStatus(const snapshot::SnapshotOptions& options) {
  PatientStatusConfig config;
  config.encoding_config = defaultEncodingConfigPath();
  config.anatomy_config = defaultAnatomyConfigPath();
  config.store.path = options.db;
  config.store.read_only = true;
  try {
    PatientStatusService service(config);
    const std::vector<TimestampUs> dates = service.examinationDates(options.patient);
    if (dates.empty())
      throw Failure(3, "unknown patient '" + options.patient + "' in " + options.db);
    if (!service.examinationAt(options.patient, options.date))
      throw Failure(3, "no examination of " + options.patient + " at or before " + options.date +
                           " (first examination: " + formatTimestamp(dates.front()) + ")");
    return ros_adapter::toMessage(
        service.encodedStatus(options.patient, options.date, options.hidden_categories));
  } catch (const StoreError& error) {
    throw Failure(3, "cannot read the database " + options.db + ": " + error.what());
  } catch (const ValidationError& error) {
    throw Failure(3, error.what());
  }
}

/// DISPLAY when it answers; otherwise an Xvfb of our own (kept in `xvfb`).
std::string displayServer(const snapshot::SnapshotOptions& options, snapshot::ChildProcess& xvfb) {
  const char* display = std::getenv("DISPLAY");
  if (display && *display) {
    if (!snapshot::displayAnswers(display))
      throw Failure(4, std::string("no display server: DISPLAY=") + display +
                           " does not answer (unset DISPLAY to render under Xvfb)");
    return display;
  }
  try {
    return snapshot::startXvfb(options.width, options.height, xvfb);
  } catch (const std::runtime_error& error) {
    throw Failure(4, error.what());
  }
}

void render(const snapshot::SnapshotOptions& options, const vicc_msgs::EncodedStatus& status) {
  const std::string topic = "/vicc_avatar_snapshot_" + std::to_string(getpid()) + "/status";
  ros::NodeHandle node;
  ros::Publisher publisher = node.advertise<vicc_msgs::EncodedStatus>(topic, 1, /*latch=*/true);
  publisher.publish(status);
  snapshot::AvatarRenderer renderer(options.width, options.height, topic);
  if (!renderer.waitForStatus(0, 30.0))
    throw Failure(5, "the avatar display did not receive the status");
  if (!renderer.setView(options.view))
    throw Failure(5, "the avatar model did not load: " + renderer.display().modelError());
  const QImage image = renderer.grab();
  if (!image.save(QString::fromStdString(options.out), "PNG"))
    throw Failure(5, "cannot write " + options.out);
  const std::vector<std::string>& warnings = renderer.display().drawState().warnings;
  for (const std::string& warning : warnings)
    std::cerr << "vicc_avatar_snapshot: warning: " << warning << "\n";
  // A picture that leaves out a finding must not pass as the patient's status.
  if (!warnings.empty())
    throw Failure(6, options.out + " is incomplete: " + std::to_string(warnings.size()) +
                         " problem(s) drawing the encoded status (see the warnings above)");
}

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  for (const std::string& arg : args)
    if (arg == "-h" || arg == "--help") {
      std::cout << snapshot::kSnapshotUsage << "\n";
      return 0;
    }
  snapshot::SnapshotOptions options;
  try {
    options = snapshot::parseSnapshotOptions(args);
  } catch (const std::invalid_argument& error) {
    throw Failure(2, std::string(error.what()) + "\n" + snapshot::kSnapshotUsage);
  }
  const vicc_msgs::EncodedStatus status = loadStatus(options);
  snapshot::ChildProcess xvfb, master;
  const std::string display = displayServer(options, xvfb);
  setenv("DISPLAY", display.c_str(), 1);
  setenv("QT_QPA_PLATFORM", "xcb", 1);
  std::string master_uri;
  try {
    master_uri = snapshot::startPrivateMaster(master);
  } catch (const std::runtime_error& error) {
    throw Failure(5, error.what());
  }
  ros::init(ros::M_string{{"__master", master_uri}}, "vicc_avatar_snapshot",
            ros::init_options::AnonymousName | ros::init_options::NoSigintHandler |
                ros::init_options::NoRosout);
  int qt_argc = 1;
  QApplication application(qt_argc, argv);
  try {
    render(options, status);
  } catch (const std::runtime_error& error) {
    ros::shutdown();
    if (dynamic_cast<const Failure*>(&error)) throw;
    throw Failure(5, error.what());
  }
  ros::shutdown();
  std::cout << options.out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const Failure& failure) {
    std::cerr << "vicc_avatar_snapshot: " << failure.what() << "\n";
    return failure.exit_code;
  } catch (const std::exception& error) {
    std::cerr << "vicc_avatar_snapshot: " << error.what() << "\n";
    return 5;
  }
}
