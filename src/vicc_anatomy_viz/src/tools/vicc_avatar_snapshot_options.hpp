#pragma once
// The vicc_avatar_snapshot command line (a contract other tools call):
//   vicc_avatar_snapshot --db FILE --patient ID [--date D] [--view front|back|left|right]
//                        [--hide CAT,...] [--size WxH] --out FILE.png

#include <string>
#include <vector>

#include "vicc_anatomy_viz/avatar_view/view_preset.hpp"

namespace vicc_anatomy_viz::snapshot {

struct SnapshotOptions {
  std::string db;
  std::string patient;
  std::string date;  ///< "" = latest examination
  avatar_view::BodyView view = avatar_view::BodyView::kFront;
  std::vector<std::string> hidden_categories;
  int width = 800;
  int height = 1000;
  std::string out;
};

extern const char* const kSnapshotUsage;

/// `text` as WxH (each side within the snapshot's limits) into width and height; a
/// cli::UsageError naming --size otherwise.
void parseWindowSize(const std::string& text, int& width, int& height);

/// Throws std::invalid_argument naming the option on a missing, unknown or malformed one.
SnapshotOptions parseSnapshotOptions(const std::vector<std::string>& args);

}  // namespace vicc_anatomy_viz::snapshot
