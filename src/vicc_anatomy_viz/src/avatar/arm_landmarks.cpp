// The arms' centre lines by marching cross-sections along the limb (each section
// perpendicular to the current direction, the next centre its centroid), and the joints on
// them: the elbow where the line bends most, the wrist at the narrowest forearm section.
#include <Eigen/Geometry>

#include <cmath>

#include "landmark_steps.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar::landmark_steps {

namespace {

// Segment lengths as fractions of the stature (Drillis & Contini 1966).
constexpr float kUpperArmLength = 0.186f;
constexpr float kForearmLength = 0.146f;
// The glenohumeral centre about 3.5 % of the stature above the armpit.
constexpr float kShoulderAboveArmpit = 0.035f;
constexpr float kMinimumElbowBendDegrees = 15.0f;

/// The lateral loop of a horizontal section: entirely on the side, apart from the trunk.
const SectionLoop* armLoop(const std::vector<SectionLoop>& loops, Side side) {
  const SectionLoop* trunk = midlineLoop(loops);
  const float sign = sideSign(side);
  const SectionLoop* best = nullptr;
  for (const SectionLoop& loop : loops) {
    const float inner = sign > 0 ? loop.min_corner.y() : -loop.max_corner.y();
    const float trunk_outer =
        trunk ? (sign > 0 ? trunk->max_corner.y() : -trunk->min_corner.y()) : 0.0f;
    if (inner <= trunk_outer) continue;
    if (!best || loop.area > best->area) best = &loop;
  }
  return best;
}

Eigen::Vector3f horizontalCentre(const TriangleMesh& skin, float z, Side side) {
  const std::vector<SectionLoop> loops = horizontalLoops(skin, z);
  const SectionLoop* loop = armLoop(loops, side);
  if (!loop) {
    throw ConfigError("avatar landmarks: no " + toString(side) +
                      " arm section at z=" + std::to_string(z));
  }
  return {loop->centroid.x(), loop->centroid.y(), z};
}

/// Marches from `start` along `direction` until the sections end (past the fingertips).
LimbTrack marchAlongLimb(const TriangleMesh& skin, Eigen::Vector3f start, Eigen::Vector3f direction,
                         float step, float max_length) {
  LimbTrack track;
  track.centres.push_back(start);
  track.areas.push_back(0);
  track.arc_length.push_back(0);
  while (track.arc_length.back() < max_length) {
    const Eigen::Vector3f ahead = track.centres.back() + step * direction;
    const SectionPlane plane = SectionPlane::through(ahead, direction, Eigen::Vector3f::UnitZ());
    const std::vector<SectionLoop> loops = sliceMesh(skin, plane);
    const SectionLoop* loop = loopContaining(loops, Eigen::Vector2f::Zero());
    if (!loop) break;
    const Eigen::Vector3f centre = plane.lift(loop->centroid);
    const Eigen::Vector3f moved = centre - track.centres.back();
    if (moved.norm() < 0.25f * step) break;
    // Half the old direction keeps the line smooth over the knuckles and the elbow crease.
    direction = (direction + moved.normalized()).normalized();
    track.arc_length.push_back(track.arc_length.back() + moved.norm());
    track.centres.push_back(centre);
    track.areas.push_back(static_cast<float>(loop->area));
  }
  if (track.areas.size() > 1) track.areas[0] = track.areas[1];
  return track;
}

/// The index of the track station with the largest bend between `from` and `to` arc length,
/// measured over +-`window`; -1 when no station bends by the minimum angle.
int sharpestBend(const LimbTrack& track, float from, float to, float window) {
  int best = -1;
  float best_angle = kMinimumElbowBendDegrees * static_cast<float>(M_PI) / 180.0f;
  const int count = static_cast<int>(track.centres.size());
  for (int i = 0; i < count; ++i) {
    if (track.arc_length[i] < from || track.arc_length[i] > to) continue;
    int before = i, after = i;
    while (before > 0 && track.arc_length[i] - track.arc_length[before] < window) --before;
    while (after < count - 1 && track.arc_length[after] - track.arc_length[i] < window) ++after;
    if (before == i || after == i) continue;
    const Eigen::Vector3f in = (track.centres[i] - track.centres[before]).normalized();
    const Eigen::Vector3f out = (track.centres[after] - track.centres[i]).normalized();
    const float angle = std::acos(std::clamp(in.dot(out), -1.0f, 1.0f));
    if (angle > best_angle) {
      best_angle = angle;
      best = i;
    }
  }
  return best;
}

int stationAtLength(const LimbTrack& track, float length) {
  int index = 0;
  while (index + 1 < static_cast<int>(track.centres.size()) && track.arc_length[index] < length) {
    ++index;
  }
  return index;
}

/// Sections across the hand at `fraction` of wrist -> fingertip: the loops near the axis.
std::vector<Eigen::Vector3f> handLoopCentres(const TriangleMesh& skin, const Eigen::Vector3f& wrist,
                                             const Eigen::Vector3f& fingertip, float fraction,
                                             float reach, std::vector<float>* areas) {
  const Eigen::Vector3f axis = (fingertip - wrist).normalized();
  const SectionPlane plane =
      SectionPlane::through(wrist + fraction * (fingertip - wrist), axis, Eigen::Vector3f::UnitZ());
  std::vector<Eigen::Vector3f> centres;
  for (const SectionLoop& loop : sliceMesh(skin, plane)) {
    if (loop.centroid.norm() > reach || loop.area < 2e-5) continue;  // not this hand's digits
    centres.push_back(plane.lift(loop.centroid));
    if (areas) areas->push_back(static_cast<float>(loop.area));
  }
  return centres;
}

/// The thumb: the first digit that parts from the palm going from the wrist to the fingertip;
/// the little finger: of the four digits across the proximal phalanges, the one furthest from
/// the thumb.
void findDigits(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  const Eigen::Vector3f& wrist = landmarks.point(sided("wrist", side));
  const Eigen::Vector3f& fingertip = landmarks.point(sided("fingertip", side));
  const float reach = 0.05f * landmarks.height;
  for (float fraction = 0.2f; fraction < 0.6f; fraction += 0.025f) {
    std::vector<float> areas;
    const std::vector<Eigen::Vector3f> centres =
        handLoopCentres(skin, wrist, fingertip, fraction, reach, &areas);
    if (centres.size() != 2) continue;
    // The smaller of palm and thumb is the thumb.
    landmarks.points[sided("thumb", side)] = areas[0] < areas[1] ? centres[0] : centres[1];
    break;
  }
  if (!landmarks.points.count(sided("thumb", side))) {
    throw ConfigError("avatar landmarks: no " + toString(side) + " thumb apart from the palm");
  }
  const Eigen::Vector3f& thumb = landmarks.point(sided("thumb", side));
  for (float fraction = 0.55f; fraction < 0.85f; fraction += 0.025f) {
    const std::vector<Eigen::Vector3f> digits =
        handLoopCentres(skin, wrist, fingertip, fraction, reach, nullptr);
    if (digits.size() < 4) continue;
    Eigen::Vector3f little = digits.front();
    for (const Eigen::Vector3f& digit : digits) {
      if ((digit - thumb).norm() > (little - thumb).norm()) little = digit;
    }
    landmarks.points[sided("little_finger", side)] = little;
    return;
  }
  throw ConfigError("avatar landmarks: no " + toString(side) + " fingers apart");
}

void findArm(const TriangleMesh& skin, Side side, BodyLandmarks& landmarks) {
  const float height = landmarks.height;
  const Eigen::Vector3f upper = horizontalCentre(skin, landmarks.armpit_z - 0.015f * height, side);
  const Eigen::Vector3f lower = horizontalCentre(skin, landmarks.armpit_z - 0.045f * height, side);
  const Eigen::Vector3f direction = (lower - upper).normalized();
  LimbTrack track = marchAlongLimb(skin, upper, direction, 0.006f * height, 0.6f * height);
  const float shoulder_rise = landmarks.armpit_z + kShoulderAboveArmpit * height - upper.z();
  const float back_along = direction.z() < -0.2f
                               ? std::min(shoulder_rise / -direction.z(), 0.1f * height)
                               : 0.05f * height;
  const Eigen::Vector3f shoulder = upper - back_along * direction;
  // Arc lengths on the track start below the shoulder by back_along.
  const float expected_elbow = kUpperArmLength * height - back_along;
  int elbow = sharpestBend(track, 0.6f * expected_elbow, 1.4f * expected_elbow, 0.04f * height);
  if (elbow < 0) elbow = stationAtLength(track, expected_elbow);
  int wrist = -1;
  const float elbow_length = track.arc_length[elbow];
  for (std::size_t i = elbow; i < track.centres.size(); ++i) {
    const float along = track.arc_length[i] - elbow_length;
    if (along < 0.7f * kForearmLength * height || along > 1.3f * kForearmLength * height) continue;
    if (wrist < 0 || track.areas[i] < track.areas[wrist]) wrist = static_cast<int>(i);
  }
  if (wrist < 0 || wrist + 3 >= static_cast<int>(track.centres.size())) {
    throw ConfigError("avatar landmarks: the " + toString(side) + " forearm ends too early");
  }
  landmarks.points[sided("shoulder", side)] = shoulder;
  landmarks.points[sided("elbow", side)] = track.centres[elbow];
  landmarks.points[sided("wrist", side)] = track.centres[wrist];
  landmarks.points[sided("fingertip", side)] = track.centres.back();
  landmarks.arm_tracks[sideIndex(side)] = std::move(track);
  findDigits(skin, side, landmarks);
}

}  // namespace

void findArmJoints(const TriangleMesh& skin, BodyLandmarks& landmarks) {
  findArm(skin, Side::kLeft, landmarks);
  findArm(skin, Side::kRight, landmarks);
}

}  // namespace vicc_anatomy_viz::avatar::landmark_steps
