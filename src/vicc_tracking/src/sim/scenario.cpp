#include "vicc_tracking/sim/scenario.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "vicc_paths/package_share.hpp"

namespace vicc_tracking::sim {
namespace {

double degrees(double value) { return value * M_PI / 180.0; }

/// Reads values with errors that name the file and key.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw std::runtime_error(file_ + ": " + key + ": " + what);
  }

  template <typename T>
  T get(const YAML::Node& node, const std::string& key, const std::string& path) const {
    const YAML::Node value = node[key];
    if (!value) fail(path + key, "missing");
    try {
      return value.as<T>();
    } catch (const YAML::Exception&) {
      fail(path + key, "has the wrong type");
    }
  }

  template <typename T>
  T getOr(const YAML::Node& node, const std::string& key, const std::string& path,
          const T& fallback) const {
    if (!node[key]) return fallback;
    return get<T>(node, key, path);
  }

  Eigen::Vector3d vector3(const YAML::Node& node, const std::string& key,
                          const std::string& path) const {
    const auto values = get<std::vector<double>>(node, key, path);
    if (values.size() != 3) fail(path + key, "needs 3 numbers");
    for (const double v : values) {
      if (!std::isfinite(v)) fail(path + key, "is not finite");
    }
    return Eigen::Vector3d(values[0], values[1], values[2]);
  }

 private:
  std::string file_;
};

CameraModel readCamera(const Reader& reader, const YAML::Node& node) {
  CameraModel camera = picoFlexxCamera();
  if (!node) return camera;
  camera.width = reader.getOr<int>(node, "width", "camera/", camera.width);
  camera.height = reader.getOr<int>(node, "height", "camera/", camera.height);
  camera.fx = reader.getOr<double>(node, "fx", "camera/", camera.fx);
  camera.fy = reader.getOr<double>(node, "fy", "camera/", camera.fy);
  camera.cx = reader.getOr<double>(node, "cx", "camera/", camera.cx);
  camera.cy = reader.getOr<double>(node, "cy", "camera/", camera.cy);
  if (node["distortion_model"]) {
    try {
      camera.model =
          distortionModelFromString(reader.get<std::string>(node, "distortion_model", "camera/"));
    } catch (const std::invalid_argument& error) {
      reader.fail("camera/distortion_model", error.what());
    }
  }
  camera.distortion =
      reader.getOr<std::vector<double>>(node, "distortion", "camera/", camera.distortion);
  return camera;
}

Primitive readPrimitive(const Reader& reader, const YAML::Node& node, size_t index) {
  const std::string path = "scene[" + std::to_string(index) + "]/";
  Primitive primitive;
  const std::string type = reader.get<std::string>(node, "type", path);
  primitive.center = reader.vector3(node, "center", path);
  primitive.yaw = degrees(reader.getOr<double>(node, "yaw_deg", path, 0.0));
  if (type == "box") {
    primitive.type = PrimitiveType::kBox;
    primitive.half_size = 0.5 * reader.vector3(node, "size", path);
  } else if (type == "ellipsoid") {
    primitive.type = PrimitiveType::kEllipsoid;
    primitive.half_size = reader.vector3(node, "radii", path);
  } else if (type == "sphere") {
    primitive.type = PrimitiveType::kEllipsoid;
    primitive.half_size = Eigen::Vector3d::Constant(reader.get<double>(node, "radius", path));
  } else if (type == "cylinder") {
    primitive.type = PrimitiveType::kCylinder;
    const double radius = reader.get<double>(node, "radius", path);
    primitive.half_size =
        Eigen::Vector3d(radius, radius, 0.5 * reader.get<double>(node, "height", path));
  } else {
    reader.fail(path + "type", "'" + type + "' is not one of box, ellipsoid, sphere, cylinder");
  }
  if (!(primitive.half_size.minCoeff() > 0.0) || !primitive.half_size.allFinite()) {
    reader.fail(path + "size", "must be positive");
  }
  primitive.albedo = reader.getOr<double>(node, "albedo", path, 1.0);
  if (!(primitive.albedo >= 0.0) || !std::isfinite(primitive.albedo)) {
    reader.fail(path + "albedo", "must be a finite number >= 0");
  }
  return primitive;
}

TrajectoryConfig readTrajectory(const Reader& reader, const YAML::Node& node) {
  if (!node) reader.fail("trajectory", "missing");
  TrajectoryConfig trajectory;
  trajectory.target = reader.vector3(node, "target", "trajectory/");
  trajectory.still_start = reader.getOr<double>(node, "still_start", "trajectory/", 2.0);
  trajectory.still_end = reader.getOr<double>(node, "still_end", "trajectory/", 1.0);
  const YAML::Node keys = node["keyframes"];
  if (!keys || !keys.IsSequence()) reader.fail("trajectory/keyframes", "missing or not a list");
  for (size_t i = 0; i < keys.size(); ++i) {
    std::vector<double> values;
    try {
      values = keys[i].as<std::vector<double>>();
    } catch (const YAML::Exception&) {
      values.clear();
    }
    if (values.size() != 5) {
      reader.fail("trajectory/keyframes[" + std::to_string(i) + "]",
                  "needs [time, azimuth_deg, elevation_deg, radius, roll_deg]");
    }
    trajectory.keyframes.push_back({values[0], values[1], values[2], values[3], values[4]});
  }
  return trajectory;
}

}  // namespace

void TofNoiseConfig::validate() const {
  if (!(sigma0 >= 0.0) || !(sigma_quadratic >= 0.0))
    throw std::invalid_argument("tof: sigma must be >= 0");
  for (const double p : {flying_pixel_probability, dropout_probability}) {
    if (!(p >= 0.0 && p <= 1.0))
      throw std::invalid_argument("tof: probabilities must be in [0, 1]");
  }
  if (!(edge_jump > 0.0)) throw std::invalid_argument("tof: edge_jump must be > 0");
  if (!(min_range >= 0.0 && max_range > min_range)) {
    throw std::invalid_argument("tof: need 0 <= min_range < max_range");
  }
  if (!(amplitude_scale > 0.0 && amplitude_scale < 1e9) ||
      !(amplitude_sigma >= 0.0 && amplitude_sigma < 1e9)) {
    throw std::invalid_argument("tof: need amplitude_scale > 0 and amplitude_sigma >= 0");
  }
}

void ImuNoiseConfig::validate() const {
  if (!(rate_hz >= 50.0 && rate_hz <= 2000.0))
    throw std::invalid_argument("imu: rate_hz must be in [50, 2000]");
  if (!gyro_bias.allFinite() || !accel_bias.allFinite())
    throw std::invalid_argument("imu: bias not finite");
  if (!(gyro_noise_density >= 0.0) || !(accel_noise_density >= 0.0)) {
    throw std::invalid_argument("imu: noise densities must be >= 0");
  }
}

void Scenario::validate() const {
  camera.validate();
  if (!(depth_rate_hz > 0.0 && depth_rate_hz <= 100.0)) {
    throw std::invalid_argument("depth_rate_hz must be in (0, 100]");
  }
  tof.validate();
  imu.validate();
  trajectory.validate();
  if (scene.empty()) throw std::invalid_argument("scene: no primitives");
  for (size_t i = 0; i < scene.size(); ++i) {
    if (!(scene[i].albedo >= 0.0) || !std::isfinite(scene[i].albedo)) {
      throw std::invalid_argument("scene[" + std::to_string(i) + "]/albedo must be >= 0");
    }
  }
  const Eigen::Matrix3d r = imu_to_camera.linear();
  if ((r * r.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-6) {
    throw std::invalid_argument("extrinsic is not a rotation");
  }
}

CameraModel picoFlexxCamera() {
  CameraModel camera;
  camera.width = 224;
  camera.height = 171;
  camera.fx = camera.fy = 210.0;
  camera.cx = 111.5;
  camera.cy = 85.5;
  camera.model = DistortionModel::kPlumbBob;
  camera.distortion = {-0.12, 0.03, 0.0005, -0.0003, 0.0};
  return camera;
}

Eigen::Isometry3d defaultImuToCamera() {
  Eigen::Matrix3d mounting;  // columns: optical x, y, z in IMU coordinates
  mounting << 0, 0, 1,       //
      -1, 0, 0,              //
      0, -1, 0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = mounting * (Eigen::AngleAxisd(degrees(2.0), Eigen::Vector3d::UnitX()) *
                              Eigen::AngleAxisd(degrees(-1.5), Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(degrees(1.0), Eigen::Vector3d::UnitZ()))
                                 .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.02, -0.01, 0.005);
  return pose;
}

std::string scenarioDirectory() {
  // Anchored at this library: <prefix>/lib/libvicc_tracking_sim.so -> <prefix>/share/vicc_tracking.
  return vicc_paths::packageDataPath("vicc_tracking", "config/scenarios",
                                     reinterpret_cast<const void*>(&scenarioDirectory))
      .string();
}

Scenario loadScenario(const std::string& name_or_path) {
  std::string path = name_or_path;
  const bool is_path = path.size() > 5 && (path.substr(path.size() - 5) == ".yaml" ||
                                           path.find('/') != std::string::npos);
  if (!is_path) path = scenarioDirectory() + "/" + name_or_path + ".yaml";
  if (!std::filesystem::exists(path)) {
    std::string names;
    for (const auto& name : availableScenarios()) names += " " + name;
    throw std::runtime_error("scenario '" + name_or_path + "' not found (" + path +
                             "); available:" + names);
  }
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& error) {
    throw std::runtime_error(path + ": not valid YAML: " + error.what());
  }
  const Reader reader(path);
  Scenario scenario;
  scenario.name = reader.get<std::string>(root, "name", "");
  scenario.description = reader.getOr<std::string>(root, "description", "", "");
  scenario.seed = reader.getOr<unsigned>(root, "seed", "", 1u);
  scenario.depth_rate_hz = reader.getOr<double>(root, "depth_rate_hz", "", 15.0);
  scenario.camera = readCamera(reader, root["camera"]);
  scenario.imu_to_camera = defaultImuToCamera();
  if (const YAML::Node extrinsic = root["extrinsic"]) {
    const Eigen::Vector3d rpy = reader.vector3(extrinsic, "rpy_deg", "extrinsic/");
    Eigen::Matrix3d rotation;
    rotation = Eigen::AngleAxisd(degrees(rpy.z()), Eigen::Vector3d::UnitZ()) *
               Eigen::AngleAxisd(degrees(rpy.y()), Eigen::Vector3d::UnitY()) *
               Eigen::AngleAxisd(degrees(rpy.x()), Eigen::Vector3d::UnitX());
    scenario.imu_to_camera.linear() = rotation;
    scenario.imu_to_camera.translation() = reader.vector3(extrinsic, "translation", "extrinsic/");
  }
  if (const YAML::Node tof = root["tof"]) {
    auto& t = scenario.tof;
    t.sigma0 = reader.getOr(tof, "sigma0", "tof/", t.sigma0);
    t.sigma_quadratic = reader.getOr(tof, "sigma_quadratic", "tof/", t.sigma_quadratic);
    t.flying_pixel_probability =
        reader.getOr(tof, "flying_pixel_probability", "tof/", t.flying_pixel_probability);
    t.edge_jump = reader.getOr(tof, "edge_jump", "tof/", t.edge_jump);
    t.dropout_probability = reader.getOr(tof, "dropout_probability", "tof/", t.dropout_probability);
    t.min_range = reader.getOr(tof, "min_range", "tof/", t.min_range);
    t.max_range = reader.getOr(tof, "max_range", "tof/", t.max_range);
    t.amplitude_scale = reader.getOr(tof, "amplitude_scale", "tof/", t.amplitude_scale);
    t.amplitude_sigma = reader.getOr(tof, "amplitude_sigma", "tof/", t.amplitude_sigma);
  }
  if (const YAML::Node imu = root["imu"]) {
    auto& i = scenario.imu;
    i.rate_hz = reader.getOr(imu, "rate_hz", "imu/", i.rate_hz);
    if (imu["gyro_bias"]) i.gyro_bias = reader.vector3(imu, "gyro_bias", "imu/");
    if (imu["accel_bias"]) i.accel_bias = reader.vector3(imu, "accel_bias", "imu/");
    i.gyro_noise_density = reader.getOr(imu, "gyro_noise_density", "imu/", i.gyro_noise_density);
    i.accel_noise_density = reader.getOr(imu, "accel_noise_density", "imu/", i.accel_noise_density);
  }
  const YAML::Node scene = root["scene"];
  if (!scene || !scene.IsSequence()) reader.fail("scene", "missing or not a list");
  for (size_t i = 0; i < scene.size(); ++i)
    scenario.scene.push_back(readPrimitive(reader, scene[i], i));
  scenario.trajectory = readTrajectory(reader, root["trajectory"]);
  try {
    scenario.validate();
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  return scenario;
}

std::vector<std::string> availableScenarios() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(scenarioDirectory(), error)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace vicc_tracking::sim
