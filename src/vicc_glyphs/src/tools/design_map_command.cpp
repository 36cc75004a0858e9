#include "design_map_command.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/io/png_codec.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::tools {
namespace {

constexpr double kPi = 3.14159265358979323846;

const std::vector<OptionSpec>& mapOptions() {
  static const std::vector<OptionSpec> specs{
      {"table", "ROWS.csv", "header label,lon,lat,<design variables...> (required)"},
      {"out", "MAP.png", "PNG to write (required)"},
      {"glyph-size", "PX", "glyph width in pixels (default 96)"},
      {"width", "PX", "map width in pixels (default 900)"},
      {"model", "MODEL.yaml", "perception model (default: config/perception_model.yaml)"},
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph design-map DESIGN.yaml --table ROWS.csv --out MAP.png\n"
         "                            [--glyph-size PX] [--width PX] [--model MODEL.yaml]\n\n"
         "Renders one glyph per table row, placed by longitude/latitude, labelled.\n\n"
      << formatOptions(mapOptions());
}

struct MapRow {
  std::string label;
  double lon = 0.0, lat = 0.0;
  std::map<std::string, double> values;
};

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  return fields;
}

double cellNumber(const std::string& text, int line, const std::string& column) {
  size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw std::runtime_error("line " + std::to_string(line) + ": " + column + " = '" + text +
                             "' is not a number");
  }
  return value;
}

std::vector<MapRow> readTable(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read table " + path);
  std::string line;
  std::getline(file, line);
  const std::vector<std::string> header = splitCsv(line);
  if (header.size() < 4 || header[0] != "label" || header[1] != "lon" || header[2] != "lat") {
    throw std::runtime_error(path + ": header must be label,lon,lat,<variables...>");
  }
  std::vector<MapRow> rows;
  for (int number = 2; std::getline(file, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = splitCsv(line);
    if (cells.size() != header.size()) {
      throw std::runtime_error(path + ": line " + std::to_string(number) + " has " +
                               std::to_string(cells.size()) + " cells, the header " +
                               std::to_string(header.size()));
    }
    MapRow row{
        cells[0], cellNumber(cells[1], number, "lon"), cellNumber(cells[2], number, "lat"), {}};
    for (size_t c = 3; c < cells.size(); ++c)
      row.values[header[c]] = cellNumber(cells[c], number, header[c]);
    rows.push_back(row);
  }
  if (rows.empty()) throw std::runtime_error(path + ": no rows");
  return rows;
}

// Equirectangular projection with cos(mean latitude), fitted into the map with a margin of
// one glyph.
std::vector<cv::Point> project(const std::vector<MapRow>& rows, int width, int glyph, int& height) {
  double lon0 = 1e9, lon1 = -1e9, lat0 = 1e9, lat1 = -1e9;
  for (const MapRow& r : rows) {
    lon0 = std::min(lon0, r.lon), lon1 = std::max(lon1, r.lon);
    lat0 = std::min(lat0, r.lat), lat1 = std::max(lat1, r.lat);
  }
  const double squeeze = std::cos(0.5 * (lat0 + lat1) * kPi / 180.0);
  const double span_x = std::max(1e-6, (lon1 - lon0) * squeeze),
               span_y = std::max(1e-6, lat1 - lat0);
  const double scale = (width - 2.0 * glyph) / span_x;
  height = static_cast<int>(span_y * scale) + 2 * glyph + 20;
  std::vector<cv::Point> centres;
  for (const MapRow& r : rows) {
    centres.emplace_back(static_cast<int>(glyph + (r.lon - lon0) * squeeze * scale),
                         static_cast<int>(glyph + (lat1 - r.lat) * scale));
  }
  return centres;
}

// Darken-blend (per-channel minimum): the glyphs' white backgrounds do not cover neighbours.
void stamp(cv::Mat& map, const cv::Mat& glyph, cv::Point centre, const std::string& label) {
  const cv::Rect target(centre.x - glyph.cols / 2, centre.y - glyph.rows / 2, glyph.cols,
                        glyph.rows);
  const cv::Rect clipped = target & cv::Rect(0, 0, map.cols, map.rows);
  cv::Mat region = map(clipped);
  cv::min(region, glyph(clipped - target.tl()), region);
  cv::putText(map, label, {centre.x - 10, std::min(map.rows - 4, target.br().y + 4)},
              cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
}

}  // namespace

int runDesignMapCommand(const std::vector<std::string>& args, std::ostream& out,
                        std::ostream& err) {
  std::string design_path, table, output, model_path = defaultPerceptionModelPath();
  int glyph_size = 96, width = 900;
  try {
    const ParsedArguments parsed = parseArguments(args, mapOptions());
    if (parsed.has("help")) {
      printUsage(out);
      return 0;
    }
    if (parsed.positional.size() != 1) throw UsageError("expected one DESIGN.yaml");
    design_path = parsed.positional.front();
    table = parsed.value("table");
    output = parsed.value("out");
    if (table.empty() || output.empty()) throw UsageError("--table and --out are required");
    if (parsed.has("glyph-size"))
      glyph_size = parseInteger("glyph-size", parsed.value("glyph-size"), 16, 1024);
    if (parsed.has("width")) width = parseInteger("width", parsed.value("width"), 64, 8192);
    if (parsed.has("model")) model_path = parsed.value("model");
  } catch (const UsageError& e) {
    err << "vicc_glyph design-map: " << e.what() << "\n\n";
    printUsage(err);
    return 2;
  }
  try {
    const perception::PerceptionModel model = perception::loadPerceptionModel(model_path);
    const design::GlyphDesign glyph = design::loadDesign(design_path, model);
    const std::vector<MapRow> rows = readTable(table);
    int height = 0;
    const std::vector<cv::Point> centres = project(rows, width, glyph_size, height);
    cv::Mat map(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    DiffusionCurveRenderer renderer;
    RenderOptions options;
    options.background = glyph.background;
    const DiffusionCurveImage icon = design::loadIcon(glyph, glyph_size);  // once for the map
    for (size_t i = 0; i < rows.size(); ++i) {
      const std::vector<int> levels = glyph.levelsFor(rows[i].values);
      RenderResult result;
      renderer.render(design::buildGlyph(glyph, levels, model, icon), options, result);
      cv::Mat bgr;
      cv::cvtColor(toRgb8(result.image), bgr, cv::COLOR_RGB2BGR);
      stamp(map, bgr, centres[i], rows[i].label);
    }
    writePng8(map, ChannelOrder::kBgr, output);
    out << "wrote " << output << " (" << rows.size() << " glyphs)\n";
  } catch (const std::exception& e) {
    err << "vicc_glyph design-map: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
