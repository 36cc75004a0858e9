#include "modify_report.hpp"

namespace vicc_glyphs::tools {
namespace {

nlohmann::json waveJson(const pacemod::CurveWaveReport& r) {
  nlohmann::json reductions = nlohmann::json::array();
  for (const pacemod::PeakReduction& p : r.reductions) {
    reductions.push_back({{"arc_length_mm", p.arc_length_mm},
                          {"allowed_amplitude_mm", p.allowed_mm},
                          {"reason", p.reason}});
  }
  nlohmann::json j{{"curve", r.curve},
                   {"arc_length_mm", r.arc_length_mm},
                   {"requested_waves", r.requested_waves},
                   {"wave_count", r.wave_count},
                   {"knot_points", r.knot_points},
                   {"requested_amplitude_mm", r.requested_amplitude_mm},
                   {"realised_amplitude_mm",
                    {{"min", r.realised_amplitude_min_mm},
                     {"mean", r.realised_amplitude_mean_mm},
                     {"max", r.realised_amplitude_max_mm}}},
                   {"reduced_by_self_intersection_prevention", reductions},
                   {"unresolved_crossings", r.unresolved_crossings}};
  if (!r.skipped.empty()) j["skipped"] = r.skipped;
  return j;
}

nlohmann::json dashJson(const pacemod::CurveDashReport& r) {
  nlohmann::json j{{"curve", r.curve},
                   {"dashes", r.dashes},
                   {"dash_length_mm", r.dash_length_mm},
                   {"barrier_curve", r.barrier_curve}};
  if (!r.skipped.empty()) j["skipped"] = r.skipped;
  return j;
}

nlohmann::json inflateJson(const pacemod::CurveInflateReport& r) {
  nlohmann::json j{{"curve", r.curve},
                   {"offset_mm", r.offset_mm},
                   {"area_before_mm2", r.area_before_mm2},
                   {"area_after_mm2", r.area_after_mm2},
                   {"limited_by_neighbours", r.limited}};
  if (!r.skipped.empty()) j["skipped"] = r.skipped;
  return j;
}

template <typename Reports, typename Convert>
nlohmann::json listJson(const Reports& reports, Convert convert) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& r : reports) list.push_back(convert(r));
  return list;
}

}  // namespace

nlohmann::json modifyReportJson(const ModifyRequest& request, const ModifyOutcome& outcome) {
  nlohmann::json j{{"input", request.input},
                   {"size_px", request.size},
                   {"size_mm", request.size_mm},
                   {"px_per_mm", request.size / request.size_mm},
                   {"selected_curves", outcome.selected},
                   {"curve_count", outcome.curve_count},
                   {"render_ms", outcome.render_ms}};
  if (request.inflate_mm) j["inflate"] = listJson(outcome.inflated, inflateJson);
  if (request.waves) {
    j["waves"] = {{"waveform", pacemod::waveformName(request.waves->waveform)},
                  {"waves_per_10mm", request.waves->waves_per_mm * 10.0},
                  {"amplitude_mm", request.waves->amplitude_mm},
                  {"curves", listJson(outcome.waves, waveJson)}};
  }
  if (request.dashes) {
    const Color& c = request.dashes->color;
    j["dashes"] = {{"count", request.dashes->count},
                   {"color_rgb", {c[0], c[1], c[2]}},
                   {"curves", listJson(outcome.dashes, dashJson)}};
  }
  return j;
}

}  // namespace vicc_glyphs::tools
