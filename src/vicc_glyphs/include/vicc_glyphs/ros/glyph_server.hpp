#pragma once
// The glyph server (ROS): renders glyph designs for data values.
// - Service ~render (vicc_msgs/RenderGlyph): design + values -> rgb8 image (+ PNG bytes).
// - Topics ~<design>/image (image_transport): every glyph rendered for that design is
//   published there while someone subscribes (nothing is encoded otherwise); a new
//   subscriber gets the latest one.
// - At start-up every design's icon is imported and one glyph of each built and rendered (every
//   variable at its lowest level) into the cache, so that a design that cannot be made stops
//   the node with its name instead of failing every request.
// Parameters (read once through vicc_common's table reader: a wrong type or an invalid value
// stops start-up with a message naming it, an unknown key in ~ is warned about):
//   ~designs_dir (string): directory of design YAML files (default: the package's designs/)
//   ~perception_model (string): model file (default: the package's config/perception_model.yaml)
//   ~cache_size (int, 1..10000, default 64): rendered glyphs kept, keyed by design, data
//   levels and size (values in the same bins share an entry)
//   ~check_designs (bool, default true): after start-up, a thread of lower priority builds
//   every level combination of every design at the design's size (as `vicc_glyph
//   check-design` does) and logs, per design, that all build or how many fail and the first of
//   them (a warning), while requests are served

#include <image_transport/image_transport.h>
#include <ros/ros.h>
#include <vicc_msgs/RenderGlyph.h>

#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "vicc_glyphs/dci/diffusion_curve.hpp"
#include "vicc_glyphs/design/background_check.hpp"
#include "vicc_glyphs/design/glyph_design.hpp"
#include "vicc_glyphs/perception/perception_model.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::ros_glyph {

struct GlyphServerParameters {
  std::string designs_dir;
  std::string perception_model;
  int cache_size = 64;
  bool check_designs = true;

  /// The defaults, with the package's designs/ and config/perception_model.yaml.
  static GlyphServerParameters withDefaultPaths();
  /// Throws std::invalid_argument naming the parameter.
  void validate() const;
};

template <typename Config, typename Visitor>
std::enable_if_t<std::is_same_v<std::remove_const_t<Config>, GlyphServerParameters>>
visitParameters(Config& config, Visitor& visit) {
  visit("designs_dir", config.designs_dir);
  visit("perception_model", config.perception_model);
  visit("cache_size", config.cache_size);
  visit("check_designs", config.check_designs);
}

/// Reads the parameters under `private_nh` over withDefaultPaths(); throws
/// std::invalid_argument naming a parameter of the wrong type or an invalid value. Adds the
/// resolved names it read to `read_names`.
GlyphServerParameters readGlyphServerParameters(const ros::NodeHandle& private_nh,
                                                std::set<std::string>& read_names);

class GlyphServer {
 public:
  /// Loads the model and every design; throws std::runtime_error naming the file on errors.
  GlyphServer(ros::NodeHandle nh, ros::NodeHandle private_nh);

  bool render(vicc_msgs::RenderGlyph::Request& request, vicc_msgs::RenderGlyph::Response& response);
  /// Glyphs in the cache (after start-up: one per design, unless ~cache_size is smaller).
  size_t cacheEntries() const { return cache_order_.size(); }

 private:
  struct DesignEntry {
    design::GlyphDesign design;
    image_transport::Publisher publisher;
    sensor_msgs::ImagePtr latest;
    /// The imported icon per requested size (0: the design's), so that a glyph not in the
    /// cache costs PACEMOD and the rendering but no import (at most 8 sizes).
    std::map<int, DiffusionCurveImage> icons;
  };
  using CacheKey = std::pair<std::string, std::vector<int>>;  // design, levels + size

  /// Imports every design's icon and renders one glyph of each into the cache; returns the
  /// milliseconds it took. Throws std::runtime_error naming the design.
  double renderOneGlyphPerDesign();
  cv::Mat renderCached(DesignEntry& entry, const std::vector<int>& levels, int size);
  /// The entry's icon at `size` (imported on first use).
  const DiffusionCurveImage& icon(DesignEntry& entry, int size);
  void onSubscribe(const std::string& design,
                   const image_transport::SingleSubscriberPublisher& pub);
  /// Starts the background check of every level combination (~check_designs).
  void startDesignCheck();
  void logDesignCheck(const design::BackgroundDesignCheck::Outcome& outcome) const;

  ros::NodeHandle private_nh_;
  std::set<std::string> parameter_names_;  ///< the resolved names the table read
  GlyphServerParameters parameters_;
  perception::PerceptionModel model_;
  std::map<std::string, DesignEntry> designs_;
  image_transport::ImageTransport transport_;
  ros::ServiceServer service_;
  /// One renderer, reused: it keeps its buffers (replaced after a large glyph, see
  /// kKeptBufferSize).
  std::unique_ptr<DiffusionCurveRenderer> renderer_ = std::make_unique<DiffusionCurveRenderer>();
  std::map<CacheKey, cv::Mat> cache_;
  std::size_t cache_bytes_ = 0;      ///< pixels of the cached glyphs
  std::list<CacheKey> cache_order_;  // oldest first
  std::mutex mutex_;
  /// Last, so that it stops before the designs and the model it reads go.
  std::unique_ptr<design::BackgroundDesignCheck> design_check_;
};

}  // namespace vicc_glyphs::ros_glyph
