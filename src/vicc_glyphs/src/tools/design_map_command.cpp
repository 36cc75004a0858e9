#include "design_map_command.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "command_line.hpp"
#include "model_path.hpp"
#include "vicc_glyphs/design/design_builder.hpp"
#include "vicc_glyphs/design/design_values.hpp"
#include "vicc_glyphs/io/png_codec.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"
#include "vicc_glyphs/render/png_output.hpp"
#include "vicc_glyphs/render/renderer.hpp"

namespace vicc_glyphs::tools {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxMapSide = 8192;  // the --width limit; also the map height's
constexpr int kLabelRoom = 20;     // below the bottom glyphs' labels
// Glyph centres closer than this many glyph widths overlay into an unreadable mix.
constexpr double kOverlapFraction = 0.5;
constexpr int kWhiteBelow = 250;  // a glyph pixel with a channel below this is drawn
constexpr size_t kMaxOverlapWarnings = 10;

const std::vector<OptionSpec>& mapOptions() {
  static const std::vector<OptionSpec> specs{
      {"table", "ROWS.csv", "header label,lon,lat,<design variables...> (required)"},
      {"out", "MAP.png", "PNG to write (required)"},
      {"glyph-size", "PX", "glyph width in pixels, 16..1024 (default 96)"},
      {"width", "PX", "map width in pixels, 3 x glyph-size..8192 (default 900)"},
      perceptionModelOption(),
      {"help", "", "show this help"},
  };
  return specs;
}

void printUsage(std::ostream& out) {
  out << "usage: vicc_glyph design-map DESIGN.yaml --table ROWS.csv --out MAP.png\n"
         "                            [--glyph-size PX] [--width PX] [--model MODEL.yaml]\n\n"
         "Renders one glyph per table row, placed by longitude/latitude, labelled.\n"
         "The table's header is label,lon,lat and then every variable of the design, each\n"
         "once; lon is in [-180, 180], lat in [-90, 90] degrees; CRLF line ends are accepted.\n"
         "North is up. The map is --width wide and at most 8192 pixels high: the rows' extent\n"
         "is scaled to fit both, with one glyph size of margin; rows at one place are centred.\n"
         "Two glyphs closer than half a glyph size are drawn, with a warning naming both.\n\n"
      << formatOptions(mapOptions());
}

struct MapRow {
  int line = 0;
  std::string label;
  double lon = 0.0, lat = 0.0;
  std::vector<int> levels;  // one per design variable, as GlyphDesign::levelsFor returns
};

std::string lineName(const std::string& path, int line) {
  return path + ": line " + std::to_string(line);
}

// A line without its CRLF (Windows) '\r'.
bool readLine(std::istream& in, std::string& line) {
  if (!std::getline(in, line)) return false;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // a trailing empty cell
  return fields;
}

// A finite number in [low, high]; the error names the line and the column.
double cellNumber(const std::string& text, const std::string& where, const std::string& column,
                  double low = -HUGE_VAL, double high = HUGE_VAL) {
  const std::optional<double> parsed = design::parseDecimal(text);
  const std::string cell = where + ", column " + column + ": '" + text + "'";
  if (!parsed) throw std::runtime_error(cell + " is not a number");
  const double value = *parsed;
  if (!std::isfinite(value)) throw std::runtime_error(cell + " is not a finite number");
  if (value < low || value > high) {
    std::ostringstream range;
    range << cell << " is outside [" << low << ", " << high << "]";
    throw std::runtime_error(range.str());
  }
  return value;
}

// The map's font (OpenCV's Hershey) has printable ASCII only: any other byte would be drawn as
// '?', so "Thüringen" came out as "Th??ringen".
void requireDrawableLabel(const std::string& label, const std::string& where) {
  for (const char c : label) {
    if (c < ' ' || c > '~') {
      throw std::runtime_error(where + ", column label: '" + label +
                               "' has a character the map's font cannot draw (printable ASCII "
                               "only; write e.g. 'ue' for 'ü')");
    }
  }
}

std::string variableNames(const design::GlyphDesign& glyph) {
  std::string names;
  for (const design::DesignVariable& v : glyph.variables)
    names += (names.empty() ? "" : ", ") + v.name;
  return names;
}

// label,lon,lat and then each of the design's variables exactly once, in any order.
std::vector<std::string> readHeader(std::istream& file, const std::string& path,
                                    const design::GlyphDesign& glyph) {
  std::string line;
  if (!readLine(file, line)) throw std::runtime_error(path + ": the table is empty");
  if (line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);  // BOM
  const std::vector<std::string> header = splitCsv(line);
  if (header.size() < 3 || header[0] != "label" || header[1] != "lon" || header[2] != "lat") {
    throw std::runtime_error(path + ": the header must start with label,lon,lat");
  }
  const std::string design_has = " (design " + glyph.name + " has " + variableNames(glyph) + ")";
  for (size_t c = 0; c < header.size(); ++c) {
    if (std::find(header.begin(), header.begin() + c, header[c]) != header.begin() + c) {
      throw std::runtime_error(path + ": column '" + header[c] + "' appears twice in the header");
    }
    if (c < 3) continue;
    const bool known = std::any_of(glyph.variables.begin(), glyph.variables.end(),
                                   [&](const auto& v) { return v.name == header[c]; });
    if (!known) {
      throw std::runtime_error(path + ": column '" + header[c] +
                               "' is not a variable of the design" + design_has);
    }
  }
  for (const design::DesignVariable& v : glyph.variables) {
    if (std::find(header.begin() + 3, header.end(), v.name) == header.end()) {
      throw std::runtime_error(path + ": the header has no column for variable '" + v.name + "'" +
                               design_has);
    }
  }
  return header;
}

// Every row checked before any is drawn: the error names the line (and the column).
std::vector<MapRow> readTable(const std::string& path, const design::GlyphDesign& glyph) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot read table " + path);
  const std::vector<std::string> header = readHeader(file, path, glyph);
  std::vector<MapRow> rows;
  std::string line;
  for (int number = 2; readLine(file, line); ++number) {
    if (line.empty()) continue;
    const std::string where = lineName(path, number);
    const std::vector<std::string> cells = splitCsv(line);
    if (cells.size() != header.size()) {
      throw std::runtime_error(where + " has " + std::to_string(cells.size()) +
                               " cells, the header " + std::to_string(header.size()));
    }
    requireDrawableLabel(cells[0], where);
    MapRow row{number,
               cells[0],
               cellNumber(cells[1], where, "lon", -180.0, 180.0),
               cellNumber(cells[2], where, "lat", -90.0, 90.0),
               {}};
    std::map<std::string, double> values;
    for (size_t c = 3; c < cells.size(); ++c)
      values[header[c]] = cellNumber(cells[c], where, header[c]);
    try {
      row.levels = glyph.levelsFor(values);
    } catch (const std::exception& e) {
      throw std::runtime_error(where + " (" + row.label + "): " + e.what());
    }
    rows.push_back(row);
  }
  if (rows.empty()) throw std::runtime_error(path + ": the table has no rows");
  return rows;
}

struct MapLayout {
  int height = 0;
  std::vector<cv::Point> centres;  // one per row
};

// Equirectangular projection with cos(mean latitude), north up, one scale for both axes: the
// largest that fits the rows' extent into the width and kMaxMapSide with a margin of one glyph
// (plus room for the bottom labels). Rows at one place get scale 0 and sit in the middle.
MapLayout project(const std::vector<MapRow>& rows, int width, int glyph) {
  double lon0 = rows[0].lon, lon1 = lon0, lat0 = rows[0].lat, lat1 = lat0;
  for (const MapRow& r : rows) {
    lon0 = std::min(lon0, r.lon), lon1 = std::max(lon1, r.lon);
    lat0 = std::min(lat0, r.lat), lat1 = std::max(lat1, r.lat);
  }
  const double squeeze = std::cos(0.5 * (lat0 + lat1) * kPi / 180.0);
  const double span_x = (lon1 - lon0) * squeeze, span_y = lat1 - lat0;
  const double room_x = width - 2.0 * glyph;  // >= glyph: checked with the options
  const double room_y = kMaxMapSide - 2.0 * glyph - kLabelRoom;
  double scale = HUGE_VAL;
  if (span_x > 0.0) scale = std::min(scale, room_x / span_x);
  if (span_y > 0.0) scale = std::min(scale, room_y / span_y);
  if (!std::isfinite(scale)) scale = 0.0;  // one place (or spans too small to tell apart)
  MapLayout layout;
  layout.height =
      std::min(kMaxMapSide, 2 * glyph + kLabelRoom + static_cast<int>(std::ceil(span_y * scale)));
  const double lon_middle = 0.5 * (lon0 + lon1);
  for (const MapRow& r : rows) {
    layout.centres.emplace_back(
        static_cast<int>(std::lround(0.5 * width + (r.lon - lon_middle) * squeeze * scale)),
        static_cast<int>(std::lround(glyph + (lat1 - r.lat) * scale)));
  }
  return layout;
}

// Overlapping glyphs are still drawn (rows at one place are valid data) but the mix cannot be
// read, so the user is told which rows to look at.
void warnAboutOverlaps(const std::vector<MapRow>& rows, const std::vector<cv::Point>& centres,
                       int glyph, std::ostream& err) {
  const double too_close = kOverlapFraction * glyph;
  size_t pairs = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    for (size_t j = i + 1; j < rows.size(); ++j) {
      const cv::Point d = centres[i] - centres[j];
      if (std::hypot(d.x, d.y) >= too_close) continue;
      if (++pairs <= kMaxOverlapWarnings) {
        err << "vicc_glyph design-map: warning: the glyphs of '" << rows[i].label << "' (line "
            << rows[i].line << ") and '" << rows[j].label << "' (line " << rows[j].line
            << ") overlap and cannot be read; use a larger --width or a smaller --glyph-size, "
               "or move them apart in the table\n";
      }
    }
  }
  if (pairs > kMaxOverlapWarnings) {
    err << "vicc_glyph design-map: warning: " << pairs - kMaxOverlapWarnings
        << " more pairs of glyphs overlap\n";
  }
}

// Where a glyph went on the map: its drawn (not white) pixels as a mask over the map rectangle
// that holds them, and the map row just below its lowest drawn pixel.
struct StampedGlyph {
  cv::Rect drawn;  // map coordinates; empty when nothing of it is drawn within the map
  cv::Mat mask;    // drawn.size(), non-zero where drawn
  int bottom = 0;
};

// Darken-blend (per-channel minimum): the glyphs' white backgrounds do not cover neighbours.
StampedGlyph stamp(cv::Mat& map, const cv::Mat& glyph, cv::Point centre) {
  const cv::Rect target(centre.x - glyph.cols / 2, centre.y - glyph.rows / 2, glyph.cols,
                        glyph.rows);
  const cv::Rect clipped = target & cv::Rect(0, 0, map.cols, map.rows);
  const cv::Mat part = glyph(clipped - target.tl());
  cv::Mat region = map(clipped);
  cv::min(region, part, region);
  // Drawn: a channel below kWhiteBelow. The label goes below the lowest such row of the whole
  // glyph; the mask keeps the part within the map.
  cv::Mat white, drawn;
  cv::inRange(glyph, cv::Scalar::all(kWhiteBelow), cv::Scalar::all(255), white);
  cv::bitwise_not(white, drawn);
  const cv::Rect box = cv::boundingRect(drawn);  // glyph coordinates; empty: nothing drawn
  StampedGlyph stamped;
  stamped.bottom = target.y + box.br().y;
  stamped.drawn = (box + target.tl()) & clipped;
  stamped.mask = drawn(stamped.drawn - target.tl()).clone();
  return stamped;
}

// A label centred just below its glyph's drawn part, and the pixels its halo paints (a mask
// over the map rectangle `box`).
struct LabelPlace {
  cv::Point origin;
  cv::Rect box;
  cv::Mat halo;
};

constexpr int kLabelFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kLabelScale = 0.45;
constexpr int kHaloThickness = 3;

LabelPlace placeLabel(const cv::Mat& map, cv::Point centre, int below, const std::string& text) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kLabelFont, kLabelScale, 1, &baseline);
  const cv::Point origin(centre.x - size.width / 2,
                         std::min(map.rows - baseline, below + 3 + size.height));
  const int margin = 2 * kHaloThickness;  // beyond the thick stroke's reach
  const cv::Rect box = cv::Rect(origin.x - margin, origin.y - size.height - margin,
                                size.width + 2 * margin, size.height + baseline + 2 * margin) &
                       cv::Rect(0, 0, map.cols, map.rows);
  cv::Mat halo = cv::Mat::zeros(box.size(), CV_8U);
  cv::putText(halo, text, origin - box.tl(), kLabelFont, kLabelScale, cv::Scalar(255),
              kHaloThickness, cv::LINE_AA);
  return {origin, box, halo};
}

// Drawn after all glyphs and on a white halo: a neighbouring glyph stamped later covered a
// label's letters (Saarland's spikes over "RP" in the German states map) and left them on its
// colours.
void drawLabel(cv::Mat& map, const LabelPlace& place, const std::string& text) {
  cv::putText(map, text, place.origin, kLabelFont, kLabelScale, cv::Scalar(255, 255, 255),
              kHaloThickness, cv::LINE_AA);
  cv::putText(map, text, place.origin, kLabelFont, kLabelScale, cv::Scalar(40, 40, 40), 1,
              cv::LINE_AA);
}

// The halo keeps a label readable but whitens what lies under it: where that is part of another
// row's glyph, the glyph loses pixels that may carry its data (a wave's tip, a dash), so the
// user is told which rows to look at.
void warnAboutCoveredGlyphs(const std::vector<MapRow>& rows,
                            const std::vector<StampedGlyph>& glyphs,
                            const std::vector<LabelPlace>& labels, std::ostream& err) {
  size_t pairs = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    for (size_t j = 0; j < rows.size(); ++j) {
      const cv::Rect common = labels[i].box & glyphs[j].drawn;
      if (j == i || common.empty()) continue;
      cv::Mat whitened;
      cv::bitwise_and(labels[i].halo(common - labels[i].box.tl()),
                      glyphs[j].mask(common - glyphs[j].drawn.tl()), whitened);
      if (cv::countNonZero(whitened) == 0) continue;
      if (++pairs <= kMaxOverlapWarnings) {
        err << "vicc_glyph design-map: warning: the label of '" << rows[i].label << "' (line "
            << rows[i].line << ") covers part of the glyph of '" << rows[j].label << "' (line "
            << rows[j].line << "); use a larger --width or a smaller --glyph-size, or move them "
            << "apart in the table\n";
      }
    }
  }
  if (pairs > kMaxOverlapWarnings) {
    err << "vicc_glyph design-map: warning: " << pairs - kMaxOverlapWarnings
        << " more labels cover part of a glyph\n";
  }
}

}  // namespace

int runDesignMapCommand(const std::vector<std::string>& args, std::ostream& out,
                        std::ostream& err) {
  std::string design_path, table, output, model_path;  // model_path: empty for the default
  int glyph_size = 96, width = 900;
  const auto read = [&](const ParsedArguments& parsed) {
    if (parsed.positional.size() != 1) throw UsageError("expected one DESIGN.yaml");
    design_path = parsed.positional.front();
    table = parsed.value("table");
    output = parsed.value("out");
    if (table.empty() || output.empty()) throw UsageError("--table and --out are required");
    if (parsed.has("glyph-size"))
      glyph_size = parseInteger("glyph-size", parsed.value("glyph-size"), 16, 1024);
    if (parsed.has("width")) width = parseInteger("width", parsed.value("width"), 64, 8192);
    // A glyph size of margin on either side, and at least one for the map between them: with
    // less the scale shrinks to nothing or turns negative and flips the map.
    if (width < 3 * glyph_size) {
      throw UsageError("--width " + std::to_string(width) + " is too narrow for --glyph-size " +
                       std::to_string(glyph_size) +
                       ": --width must be at least 3 x --glyph-size (" +
                       std::to_string(3 * glyph_size) + ")");
    }
    if (parsed.has("model")) model_path = parsed.value("model");
    requireDistinctFiles(
        {{"DESIGN", design_path}, {"--table", table}, {"--model", model_path}, {"--out", output}});
  };
  const std::optional<int> done =
      readCommandLine("design-map", args, mapOptions(), printUsage, out, err, read);
  if (done) return *done;
  try {
    const perception::PerceptionModel model =
        perception::loadPerceptionModel(perceptionModelPathOrDefault(model_path));
    const design::GlyphDesign glyph = design::loadDesign(design_path, model);
    const std::vector<MapRow> rows = readTable(table, glyph);
    const MapLayout layout = project(rows, width, glyph_size);
    warnAboutOverlaps(rows, layout.centres, glyph_size, err);
    cv::Mat map(layout.height, width, CV_8UC3, cv::Scalar(255, 255, 255));
    DiffusionCurveRenderer renderer;
    RenderOptions options;
    options.background = glyph.background;
    const DiffusionCurveImage icon = design::loadIcon(glyph, glyph_size);  // once for the map
    std::vector<StampedGlyph> stamped;
    for (size_t i = 0; i < rows.size(); ++i) {
      RenderResult result;
      renderer.render(design::buildGlyph(glyph, rows[i].levels, model, icon), options, result);
      requireSomethingDrawn(result.report, "row " + rows[i].label);
      cv::Mat bgr;
      cv::cvtColor(toRgb8(result.image), bgr, cv::COLOR_RGB2BGR);
      stamped.push_back(stamp(map, bgr, layout.centres[i]));
    }
    std::vector<LabelPlace> labels;
    for (size_t i = 0; i < rows.size(); ++i) {
      labels.push_back(placeLabel(map, layout.centres[i], stamped[i].bottom, rows[i].label));
    }
    warnAboutCoveredGlyphs(rows, stamped, labels, err);
    for (size_t i = 0; i < rows.size(); ++i) drawLabel(map, labels[i], rows[i].label);
    writePng8(map, ChannelOrder::kBgr, output);
    out << "wrote " << output << " (" << rows.size()
        << (rows.size() == 1 ? " glyph)\n" : " glyphs)\n");
  } catch (const std::exception& e) {
    err << "vicc_glyph design-map: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace vicc_glyphs::tools
