#include "vicc_glyphs/ros/glyph_server.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/io/png_codec.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/ros/image_message.hpp"
#include "vicc_paths/package_share.hpp"

namespace vicc_glyphs::ros_glyph {
namespace {

constexpr std::size_t kMaxIconSizes = 8;  // imported icons kept per design
// The cache's pixels: ~cache_size glyphs of 4096 px would be 3 GB.
constexpr std::size_t kMaxCacheBytes = std::size_t{256} << 20;
// After a glyph wider than this the renderer's buffers (80 bytes per pixel and more) are
// freed: one 4096 px request would otherwise keep 2.8 GB resident for good.
constexpr int kKeptBufferSize = 1024;

/// share/vicc_glyphs/<relative> of the devel or install space that holds this library.
std::string packageFile(const std::string& relative) {
  static const int anchor = 0;
  return vicc_paths::packageDataPath("vicc_glyphs", relative, &anchor).string();
}

}  // namespace

GlyphServerParameters GlyphServerParameters::withDefaultPaths() {
  GlyphServerParameters parameters;
  parameters.designs_dir = packageFile("designs");
  parameters.perception_model = packageFile("config/perception_model.yaml");
  return parameters;
}

void GlyphServerParameters::validate() const {
  if (designs_dir.empty()) throw std::invalid_argument("designs_dir is empty");
  if (perception_model.empty()) throw std::invalid_argument("perception_model is empty");
  if (cache_size < 1 || cache_size > 10000) {
    throw std::invalid_argument("cache_size must be an integer from 1 to 10000, got " +
                                std::to_string(cache_size));
  }
}

GlyphServerParameters readGlyphServerParameters(const ros::NodeHandle& private_nh,
                                                std::set<std::string>& read_names) {
  GlyphServerParameters parameters = GlyphServerParameters::withDefaultPaths();
  vicc_common::readRosParameters(private_nh, parameters, read_names);
  return parameters;
}

GlyphServer::GlyphServer(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : private_nh_(private_nh),
      parameters_(readGlyphServerParameters(private_nh, parameter_names_)),
      model_(perception::loadPerceptionModel(parameters_.perception_model)),
      transport_(private_nh) {
  if (!std::filesystem::is_directory(parameters_.designs_dir)) {
    throw std::runtime_error("parameter ~designs_dir: " + parameters_.designs_dir +
                             " is not a directory");
  }
  for (const auto& file : std::filesystem::directory_iterator(parameters_.designs_dir)) {
    if (file.path().extension() != ".yaml") continue;
    const std::string stem = file.path().stem().string();
    design::GlyphDesign loaded = design::loadDesign(file.path().string(), model_);
    // Requests name the file; a different name inside would make the answers and the cache
    // (keyed by name) mix up two designs.
    if (loaded.name != stem) {
      throw std::runtime_error("design " + file.path().string() + " is named '" + loaded.name +
                               "': a design's name must be its file name (" + stem + ")");
    }
    designs_[stem].design = std::move(loaded);
  }
  if (designs_.empty()) {
    throw std::runtime_error("parameter ~designs_dir: no design (.yaml) in " +
                             parameters_.designs_dir);
  }
  const double start_up_ms = renderOneGlyphPerDesign();
  // Checked before the image topics exist; their transports (e.g. compressed) keep their
  // parameters under ~<design>/image.
  std::vector<std::string> transport_namespaces;
  for (const auto& design : designs_) {
    transport_namespaces.push_back(private_nh_.resolveName(design.first + "/image"));
  }
  vicc_common::warnUnknownRosParameters(private_nh_, parameter_names_, transport_namespaces);
  for (auto& [name, entry] : designs_) {
    entry.publisher = transport_.advertise(
        name + "/image", 1,
        [this, design = name](const image_transport::SingleSubscriberPublisher& pub) {
          onSubscribe(design, pub);
        });
  }
  service_ = private_nh_.advertiseService("render", &GlyphServer::render, this);
  (void)nh;
  ROS_INFO(
      "glyph_server: %zu designs from %s (icons imported and one glyph each rendered in "
      "%.0f ms)",
      designs_.size(), parameters_.designs_dir.c_str(), start_up_ms);
  if (parameters_.check_designs) startDesignCheck();
}

void GlyphServer::startDesignCheck() {
  design::BackgroundDesignCheck::Designs designs;
  for (const auto& [name, entry] : designs_) designs.emplace_back(name, &entry.design);
  design_check_ = std::make_unique<design::BackgroundDesignCheck>(
      std::move(designs), model_,
      [this](const design::BackgroundDesignCheck::Outcome& outcome) { logDesignCheck(outcome); });
}

// On the check's thread: reads only the designs and the parameters, which no request changes.
void GlyphServer::logDesignCheck(const design::BackgroundDesignCheck::Outcome& outcome) const {
  const char* name = outcome.name.c_str();
  if (!outcome.error.empty()) {
    ROS_WARN("glyph_server: design '%s' could not be checked: %s", name, outcome.error.c_str());
    return;
  }
  const design::DesignCheck& check = outcome.check;
  if (check.problems.empty()) {
    ROS_INFO("glyph_server: design '%s': all %d level combinations build at %d px (%.1f s)", name,
             check.combinations, check.size_px, outcome.seconds);
    return;
  }
  const design::LevelProblem& first = check.problems.front();
  ROS_WARN(
      "glyph_server: design '%s': %zu of %d level combinations fail at %d px, the first: %s: %s. "
      "`vicc_glyph check-design %s/%s.yaml --size %d` lists them all",
      name, check.problems.size(), check.combinations, check.size_px,
      design::describeLevels(designs_.at(outcome.name).design, first.levels).c_str(),
      first.problem.c_str(), parameters_.designs_dir.c_str(), name, check.size_px);
}

// Each icon imported now at the design's size, and one glyph per design built and rendered
// (every variable at its lowest level) into the cache: a missing or broken icon, or a design
// whose glyph cannot be made (e.g. an encoding on a curve the icon does not have), stops the
// node with the design's name instead of failing every request, and no request pays the
// import at the design's size.
double GlyphServer::renderOneGlyphPerDesign() {
  const auto start = std::chrono::steady_clock::now();
  for (auto& [name, entry] : designs_) {
    try {
      renderCached(entry, std::vector<int>(entry.design.variables.size(), 0), 0);
    } catch (const std::exception& e) {
      throw std::runtime_error("design '" + name + "': " + e.what());
    }
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

void GlyphServer::onSubscribe(const std::string& design,
                              const image_transport::SingleSubscriberPublisher& pub) {
  std::lock_guard<std::mutex> lock(mutex_);
  const DesignEntry& entry = designs_.at(design);
  if (entry.latest) pub.publish(entry.latest);
}

const DiffusionCurveImage& GlyphServer::icon(DesignEntry& entry, int size) {
  auto found = entry.icons.find(size);
  if (found != entry.icons.end()) return found->second;
  // Clients asking for ever new sizes must not grow the memory without bound.
  if (entry.icons.size() >= kMaxIconSizes) entry.icons.clear();
  return entry.icons.emplace(size, design::loadIcon(entry.design, size)).first->second;
}

cv::Mat GlyphServer::renderCached(DesignEntry& entry, const std::vector<int>& levels, int size) {
  std::vector<int> key_levels = levels;
  key_levels.push_back(size);
  const CacheKey key{entry.design.name, key_levels};
  const auto found = cache_.find(key);
  if (found != cache_.end()) return found->second;
  const DiffusionCurveImage image =
      design::buildGlyph(entry.design, levels, model_, icon(entry, size));
  RenderOptions options;
  options.background = entry.design.background;
  RenderResult result;
  renderer_->render(image, options, result);
  if (image.width > kKeptBufferSize) renderer_ = std::make_unique<DiffusionCurveRenderer>();
  requireSomethingDrawn(result.report, "size " + std::to_string(size) + " px");
  if (!result.report.multigrid.converged) {
    ROS_WARN("glyph_server: design '%s': the diffusion did not reach its error tolerance %g",
             entry.design.name.c_str(), options.multigrid.tolerance);
  }
  cv::Mat rgb8 = toRgb8(result.image);
  cache_[key] = rgb8;
  cache_order_.push_back(key);
  cache_bytes_ += rgb8.total() * rgb8.elemSize();
  // The newest stays even if it alone exceeds the bytes (it is the answer to this request).
  while (static_cast<int>(cache_order_.size()) > parameters_.cache_size ||
         (cache_bytes_ > kMaxCacheBytes && cache_order_.size() > 1)) {
    const cv::Mat& oldest = cache_.at(cache_order_.front());
    cache_bytes_ -= oldest.total() * oldest.elemSize();
    cache_.erase(cache_order_.front());
    cache_order_.pop_front();
  }
  return rgb8;
}

bool GlyphServer::render(vicc_msgs::RenderGlyph::Request& request,
                         vicc_msgs::RenderGlyph::Response& response) {
  std::lock_guard<std::mutex> lock(mutex_);
  response.success = false;
  const auto found = designs_.find(request.design);
  if (found == designs_.end()) {
    response.message = "unknown design '" + request.design + "'";
    return true;
  }
  if (request.names.size() != request.values.size()) {
    response.message = "names and values differ in number";
    return true;
  }
  if (request.size != 0 &&
      (request.size < design::kMinGlyphPixels || request.size > design::kMaxGlyphPixels)) {
    response.message = "size must be 0 (the design's default) or " +
                       std::to_string(design::kMinGlyphPixels) + " to " +
                       std::to_string(design::kMaxGlyphPixels) + " pixels, got " +
                       std::to_string(request.size);
    return true;
  }
  try {
    std::map<std::string, double> values;
    for (size_t i = 0; i < request.names.size(); ++i) {
      if (!values.emplace(request.names[i], request.values[i]).second) {
        throw design::DesignValueError(request.names[i] + " is given twice");
      }
    }
    DesignEntry& entry = found->second;
    const std::vector<int> levels = entry.design.levelsFor(values);
    const cv::Mat rgb8 = renderCached(entry, levels, request.size);
    response.image = toImageMsg(rgb8, "glyph");
    response.image.header.stamp = ros::Time::now();
    if (request.want_png) response.png = encodePng8(rgb8, ChannelOrder::kRgb);
    entry.latest = boost::make_shared<sensor_msgs::Image>(response.image);
    if (entry.publisher.getNumSubscribers() > 0) entry.publisher.publish(entry.latest);
    response.success = true;
    response.message = "ok";
  } catch (const std::exception& e) {
    response.message = request.design + ": " + e.what();
  }
  return true;
}

}  // namespace vicc_glyphs::ros_glyph
