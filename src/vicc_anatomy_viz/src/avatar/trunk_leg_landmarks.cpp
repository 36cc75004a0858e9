// Levels of the trunk and the joints of the legs from horizontal cross-sections.
#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar::landmark_steps {

namespace {

// Anthropometric heights as fractions of the stature (Drillis & Contini 1966, as tabulated
// in Winter, Biomechanics and Motor Control of Human Movement, Fig. 4.1).
constexpr float kKneeHeight = 0.285f;
constexpr float kAnkleHeight = 0.039f;
// Hip joint centres lie about 4.5 % of the stature above the perineum (pubic symphysis level).
constexpr float kHipAboveCrotch = 0.045f;
// The metatarsophalangeal joints at 72 % of the foot length from the heel, 2 cm above the sole.
constexpr float kMtpFootFraction = 0.72f;
constexpr float kMtpHeight = 0.012f;

bool onSide(const SectionLoop& loop, Side side) {
  return side == Side::kLeft ? loop.min_corner.y() > 0 : loop.max_corner.y() < 0;
}

/// The loop on `side` whose centroid is nearest to `previous` (the largest when none given).
const SectionLoop* sideLoop(const std::vector<SectionLoop>& loops, Side side,
                            const Eigen::Vector2f* previous) {
  const SectionLoop* best = nullptr;
  float best_score = 0;
  for (const SectionLoop& loop : loops) {
    if (!onSide(loop, side)) continue;
    const float score =
        previous ? -(loop.centroid - *previous).norm() : static_cast<float>(loop.area);
    if (!best || score > best_score) {
      best = &loop;
      best_score = score;
    }
  }
  return best;
}

Eigen::Vector3f at(const Eigen::Vector2f& xy, float z) { return {xy.x(), xy.y(), z}; }

/// Centre of the track (ordered by increasing z) at height z, interpolated.
Eigen::Vector3f trackAt(const LimbTrack& track, float z) {
  for (std::size_t i = 1; i < track.centres.size(); ++i) {
    if (track.centres[i].z() >= z) {
      const Eigen::Vector3f& a = track.centres[i - 1];
      const Eigen::Vector3f& b = track.centres[i];
      const float t = std::clamp((z - a.z()) / std::max(b.z() - a.z(), 1e-6f), 0.0f, 1.0f);
      return a + t * (b - a);
    }
  }
  return track.centres.back();
}

LimbTrack trackLeg(const TriangleMesh& skin, const BodyLandmarks& landmarks, Side side) {
  LimbTrack track;
  const float step = 0.01f * landmarks.height;
  Eigen::Vector2f previous;
  for (float z = 0.07f * landmarks.height; z < landmarks.crotch_z - step; z += step) {
    const std::vector<SectionLoop> loops = horizontalLoops(skin, z);
    const SectionLoop* loop = sideLoop(loops, side, track.centres.empty() ? nullptr : &previous);
    if (!loop)
      throw ConfigError("avatar landmarks: no " + toString(side) +
                        " leg section at z=" + std::to_string(z));
    previous = loop->centroid;
    track.arc_length.push_back(track.centres.empty()
                                   ? 0.0f
                                   : track.arc_length.back() +
                                         (at(previous, z) - track.centres.back()).norm());
    track.centres.push_back(at(previous, z));
    track.areas.push_back(static_cast<float>(loop->area));
  }
  if (track.centres.size() < 5) throw ConfigError("avatar landmarks: the legs are too short");
  return track;
}

void findFoot(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  const float height = landmarks.height;
  const std::vector<SectionLoop> loops = horizontalLoops(skin, 0.006f * height);
  const SectionLoop* foot = sideLoop(loops, side, nullptr);
  if (!foot) throw ConfigError("avatar landmarks: no " + toString(side) + " foot on the floor");
  Eigen::Vector2f toe = foot->points.front(), heel = foot->points.front();
  for (const Eigen::Vector2f& p : foot->points) {
    if (p.x() > toe.x()) toe = p;
    if (p.x() < heel.x()) heel = p;
  }
  const float mtp_x = heel.x() + kMtpFootFraction * (toe.x() - heel.x());
  landmarks.points[sided("toe_tip", side)] = at(toe, 0.006f * height);
  landmarks.points[sided("heel", side)] = at(heel, 0.006f * height);
  landmarks.points[sided("mtp", side)] =
      Eigen::Vector3f(mtp_x, foot->centroid.y(), kMtpHeight * height);
}

}  // namespace

void findTrunkLevels(const TriangleMesh& skin, BodyLandmarks& landmarks) {
  const float height = landmarks.height;
  const float step = 0.0025f * height;
  landmarks.crotch_z = 0;
  for (float z = 0.30f * height; z < 0.65f * height; z += step) {
    if (midlineLoop(horizontalLoops(skin, z))) {
      landmarks.crotch_z = z;
      break;
    }
  }
  if (landmarks.crotch_z <= 0.30f * height) {
    throw ConfigError(
        "avatar landmarks: the legs touch or never join (no crotch between 30 % "
        "and 65 % of the height)");
  }
  landmarks.armpit_z = 0;
  for (float z = 0.82f * height; z > landmarks.crotch_z + 0.05f * height; z -= step) {
    const std::vector<SectionLoop> loops = horizontalLoops(skin, z);
    if (sideLoop(loops, Side::kLeft, nullptr) && sideLoop(loops, Side::kRight, nullptr)) {
      landmarks.armpit_z = z;
      break;
    }
  }
  if (landmarks.armpit_z == 0) {
    throw ConfigError("avatar landmarks: the arms are nowhere apart from the trunk");
  }
  double narrowest = 0;
  for (float z = landmarks.armpit_z + 0.05f * height; z < 0.93f * height; z += step) {
    const std::vector<SectionLoop> loops = horizontalLoops(skin, z);
    const SectionLoop* neck = midlineLoop(loops);
    if (neck && (narrowest == 0 || neck->area < narrowest)) {
      narrowest = neck->area;
      landmarks.neck_z = z;
      landmarks.points["neck"] = at(neck->centroid, z);
    }
  }
  if (narrowest == 0) throw ConfigError("avatar landmarks: no neck section found");
}

void findLegJoints(const TriangleMesh& skin, BodyLandmarks& landmarks) {
  const float height = landmarks.height;
  for (Side side : {Side::kLeft, Side::kRight}) {
    LimbTrack track = trackLeg(skin, landmarks, side);
    const Eigen::Vector3f& top = track.centres.back();
    landmarks.points[sided("hip", side)] =
        Eigen::Vector3f(top.x(), top.y(), landmarks.crotch_z + kHipAboveCrotch * height);
    Eigen::Vector3f knee = trackAt(track, kKneeHeight * height);
    landmarks.points[sided("knee", side)] = knee;
    const Eigen::Vector3f& lowest = track.centres.front();
    landmarks.points[sided("ankle", side)] =
        Eigen::Vector3f(lowest.x(), lowest.y(), kAnkleHeight * height);
    findFoot(skin, side, landmarks);
    landmarks.leg_tracks[sideIndex(side)] = std::move(track);
  }
  const Eigen::Vector3f pelvis = (landmarks.point("hip_left") + landmarks.point("hip_right")) / 2;
  landmarks.points["pelvis"] = pelvis;
}

}  // namespace vicc_anatomy_viz::avatar::landmark_steps
