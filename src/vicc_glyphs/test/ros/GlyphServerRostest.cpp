// Against a running glyph_server: valid request -> image of the right size (and PNG bytes);
// unknown design, NaN, out-of-range and malformed requests -> success false with a message
// naming the problem, and the server still answers afterwards; the image topic delivers.
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <unistd.h>
#include <vicc_msgs/RenderGlyph.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "vicc_common/ros_parameters.hpp"
#include "vicc_common/ros_service_call.hpp"
#include "vicc_glyphs/ros/glyph_server.hpp"

namespace {

vicc_msgs::RenderGlyph request(const std::string& design, std::vector<std::string> names,
                               std::vector<double> values, int size = 64, bool png = false) {
  vicc_msgs::RenderGlyph call;
  call.request.design = design;
  call.request.names = std::move(names);
  call.request.values = std::move(values);
  call.request.size = size;
  call.request.want_png = png;
  return call;
}

bool callRender(vicc_msgs::RenderGlyph& call) {
  return vicc_common::callRepeatableService("/glyph_server/render", call);
}

}  // namespace

TEST(GlyphServer, ValidRequestGivesAnImageOfTheRequestedSize) {
  ASSERT_TRUE(ros::service::waitForService("/glyph_server/render", ros::Duration(60)));
  auto call = request("rain_forecast_sine", {"probability", "amount"}, {65, 3}, 96, true);
  ASSERT_TRUE(callRender(call));
  ASSERT_TRUE(call.response.success) << call.response.message;
  EXPECT_EQ(call.response.image.width, 96u);
  EXPECT_EQ(call.response.image.encoding, "rgb8");
  EXPECT_EQ(call.response.image.step, 3u * 96u);
  EXPECT_EQ(call.response.image.data.size(), call.response.image.step * call.response.image.height);
  ASSERT_GT(call.response.png.size(), 8u);
  EXPECT_EQ(call.response.png[1], 'P');  // PNG signature
  // The same levels again (other values in the same bins): the cached image, identical.
  auto again = request("rain_forecast_sine", {"probability", "amount"}, {69, 4}, 96);
  ASSERT_TRUE(callRender(again));
  EXPECT_EQ(again.response.image.data, call.response.image.data);
  EXPECT_TRUE(again.response.png.empty());
}

TEST(GlyphServer, BadRequestsAreErrorsAndTheServerStaysAlive) {
  ASSERT_TRUE(ros::service::waitForService("/glyph_server/render", ros::Duration(60)));
  const struct {
    vicc_msgs::RenderGlyph call;
    std::string expected;
  } cases[] = {
      {request("no_such_design", {}, {}), "unknown design 'no_such_design'"},
      {request("rain_forecast_sine", {"probability", "amount"}, {std::nan(""), 3}),
       "probability is NaN"},
      {request("rain_forecast_sine", {"probability", "amount"}, {140, 3}),
       "probability = 140 is outside its domain"},
      {request("rain_forecast_sine", {"probability"}, {50}), "missing value for 'amount'"},
      {request("rain_forecast_sine", {"probability", "amount"}, {50}), "differ in number"},
      {request("rain_forecast_sine", {"probability", "amount", "wind"}, {50, 1, 2}),
       "no variable 'wind'"},
      {request("rain_forecast_sine", {"probability", "amount"}, {50, 1}, -5), "size must be"},
      // Below 16 px waves and levels cannot be told apart (it used to draw 2 px "glyphs").
      {request("intracranial_pressure", {"pressure", "category"}, {30, 2}, 8),
       "size must be 0 (the design's default) or 16 to 4096 pixels, got 8"},
  };
  for (auto c : cases) {
    ASSERT_TRUE(callRender(c.call)) << c.expected;
    EXPECT_FALSE(c.call.response.success) << c.expected;
    EXPECT_NE(c.call.response.message.find(c.expected), std::string::npos)
        << c.call.response.message;
    EXPECT_TRUE(c.call.response.image.data.empty());
  }
  auto alive = request("intracranial_pressure", {"pressure", "category"}, {30, 2}, 48);
  ASSERT_TRUE(callRender(alive));
  EXPECT_TRUE(alive.response.success) << alive.response.message;
  EXPECT_EQ(alive.response.image.width, 48u);
}

TEST(GlyphServer, ImageTopicDeliversRenderedGlyphsToSubscribers) {
  ASSERT_TRUE(ros::service::waitForService("/glyph_server/render", ros::Duration(60)));
  ros::NodeHandle nh;
  sensor_msgs::Image received;
  bool got = false;
  ros::Subscriber sub = nh.subscribe<sensor_msgs::Image>(
      "/glyph_server/rain_forecast_dashes/image", 1, [&](const sensor_msgs::ImageConstPtr& msg) {
        received = *msg;
        got = true;
      });
  for (int i = 0; i < 100 && sub.getNumPublishers() == 0; ++i) ros::Duration(0.05).sleep();
  ASSERT_GT(sub.getNumPublishers(), 0u);
  auto call = request("rain_forecast_dashes", {"probability", "amount"}, {50, 20}, 80);
  ASSERT_TRUE(callRender(call));
  ASSERT_TRUE(call.response.success) << call.response.message;
  for (int i = 0; i < 100 && !got; ++i) ros::Duration(0.05).sleep();
  ASSERT_TRUE(got);
  EXPECT_EQ(received.width, 80u);
  EXPECT_EQ(received.data, call.response.image.data);
}

// Parameters are read through the shared table with errors that name them (in-process, on a
// private namespace): wrong types, invalid values, bad paths, and typos.
TEST(GlyphServerParameters, BadParametersAreNamed) {
  const auto message = [](const std::string& name, const auto& value) {
    ros::NodeHandle nh("~/bad_" + name);
    nh.setParam(name, value);
    try {
      vicc_glyphs::ros_glyph::GlyphServer server(ros::NodeHandle(), nh);
    } catch (const std::exception& e) {
      nh.deleteParam(name);
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("cache_size", 0).find("cache_size must be an integer from 1 to 10000, got 0"),
            std::string::npos);
  EXPECT_NE(message("cache_size", std::string("many"))
                .find("/bad_cache_size/cache_size has the wrong type: expected an integer, got "
                      "'many'"),
            std::string::npos);
  EXPECT_NE(message("designs_dir", std::string("/nonexistent")).find("~designs_dir"),
            std::string::npos);
  EXPECT_NE(message("check_designs", std::string("yes"))
                .find("/bad_check_designs/check_designs has the wrong type: expected true or "
                      "false, got 'yes'"),
            std::string::npos);
  EXPECT_NE(
      message("designs_dir", 3)
          .find("/bad_designs_dir/designs_dir has the wrong type: expected a string, got '3'"),
      std::string::npos);
  EXPECT_NE(message("perception_model", std::string("/nonexistent.yaml")).find("/nonexistent.yaml"),
            std::string::npos);
}

namespace {

// The message a server started on a directory holding only `name`.yaml (with `yaml` in it)
// stops with ("" if it starts).
std::string startUpError(const std::string& name, const std::string& yaml) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("glyph_server_" + name + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / (name + ".yaml")) << yaml;
  ros::NodeHandle nh("~/" + name);
  nh.setParam("designs_dir", dir.string());
  std::string message;
  try {
    vicc_glyphs::ros_glyph::GlyphServer server(ros::NodeHandle(), nh);
  } catch (const std::exception& e) {
    message = e.what();
  }
  nh.deleteParam("designs_dir");
  std::filesystem::remove_all(dir);
  return message;
}

// A one-variable colour design on `icon`, its colour on `curves` (replacing head_brain.svg's
// brain colour).
std::string colourDesign(const std::string& name, const std::string& icon,
                         const std::string& curves) {
  return "name: " + name + "\nicon: " + icon +
         "\nsize_mm: 50\n"
         "size_px: 64\n"
         "variables:\n"
         "  - name: value\n"
         "    domain: [0, 1]\n"
         "    edges: [0.5]\n"
         "    encodings:\n"
         "      - channel: fill_color\n"
         "        curves: \"" +
         curves +
         "\"\n"
         "        replace: \"e7a3ad\"\n"
         "        colors: [\"ff0000\", \"00ff00\"]\n";
}

}  // namespace

// A design whose colour to replace is not on the selected curves would show every level
// alike; requests ask for designs by file name, and a different name inside made the cache
// (keyed by name) answer with another design's glyph. Both stop the server at start.
TEST(GlyphServerParameters, ADesignThatCannotShowItsLevelsOrIsMisnamedStopsTheStart) {
  const std::string icon =
      vicc_glyphs::ros_glyph::GlyphServerParameters::withDefaultPaths().designs_dir +
      "/icons/head_brain.svg";
  std::string yaml = colourDesign("wrong_colour", icon, "1");
  yaml.replace(yaml.find("e7a3ad"), 6, "123456");
  const std::string no_colour = startUpError("wrong_colour", yaml);
  EXPECT_NE(no_colour.find("the colour to replace, 123456, is not on the selected curves"),
            std::string::npos)
      << no_colour;
  const std::string misnamed = startUpError("file_name", colourDesign("other_name", icon, "1"));
  EXPECT_NE(misnamed.find("is named 'other_name'"), std::string::npos) << misnamed;
  EXPECT_NE(misnamed.find("must be its file name (file_name)"), std::string::npos) << misnamed;
}

// A design whose icon cannot be imported stops the server at start, naming design and file
// (it used to fail only when a glyph was requested).
TEST(GlyphServerParameters, ADesignWithoutItsIconIsNamedAtStart) {
  const std::string message =
      startUpError("lost_icon", colourDesign("lost_icon", "no_such_icon.svg", "all"));
  EXPECT_NE(message.find("design 'lost_icon'"), std::string::npos) << message;
  EXPECT_NE(message.find("no_such_icon.svg"), std::string::npos) << message;
}

// So does a design whose glyph cannot be made (it loads, but its encoding names a curve the
// icon does not have): start-up builds and renders one glyph of each design.
TEST(GlyphServerParameters, ADesignWhoseGlyphCannotBeMadeIsNamedAtStart) {
  const std::string icon =
      vicc_glyphs::ros_glyph::GlyphServerParameters::withDefaultPaths().designs_dir +
      "/icons/head_brain.svg";
  ASSERT_TRUE(std::filesystem::exists(icon)) << icon;
  const std::string message = startUpError("no_curve_7", colourDesign("no_curve_7", icon, "7"));
  EXPECT_NE(message.find("design 'no_curve_7'"), std::string::npos) << message;
  EXPECT_NE(message.find("curve index 7 out of range"), std::string::npos) << message;
  // The same design on a curve the icon has starts.
  EXPECT_EQ(startUpError("curve_1", colourDesign("curve_1", icon, "1")), "");
}

// Start-up renders one glyph per design into the cache; a smaller cache keeps only the last ones.
TEST(GlyphServerParameters, StartUpRendersOneGlyphPerDesignIntoTheCache) {
  const auto defaults = vicc_glyphs::ros_glyph::GlyphServerParameters::withDefaultPaths();
  std::size_t design_files = 0;
  for (const auto& file : std::filesystem::directory_iterator(defaults.designs_dir)) {
    design_files += file.path().extension() == ".yaml";
  }
  ASSERT_GE(design_files, 4u);
  {
    ros::NodeHandle nh("~/start_up");
    vicc_glyphs::ros_glyph::GlyphServer server(ros::NodeHandle(), nh);
    EXPECT_EQ(server.cacheEntries(), design_files);
  }
  ros::NodeHandle small("~/start_up_small_cache");
  small.setParam("cache_size", 2);
  vicc_glyphs::ros_glyph::GlyphServer server(ros::NodeHandle(), small);
  small.deleteParam("cache_size");
  EXPECT_EQ(server.cacheEntries(), 2u);
}

TEST(GlyphServerParameters, KeysLeftOutTakeThePackagesFilesAndTyposAreNamed) {
  ros::NodeHandle nh("~/typo");
  nh.setParam("cache_sise", 5);
  std::set<std::string> read_names;
  const auto parameters = vicc_glyphs::ros_glyph::readGlyphServerParameters(nh, read_names);
  const auto defaults = vicc_glyphs::ros_glyph::GlyphServerParameters::withDefaultPaths();
  EXPECT_EQ(parameters.cache_size, 64);
  EXPECT_TRUE(parameters.check_designs);
  EXPECT_EQ(parameters.designs_dir, defaults.designs_dir);
  EXPECT_FALSE(parameters.designs_dir.empty());
  EXPECT_EQ(vicc_common::unknownRosParameters(nh, read_names),
            std::vector<std::string>{nh.resolveName("cache_sise")});
  nh.deleteParam("cache_sise");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "glyph_server_rostest");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
