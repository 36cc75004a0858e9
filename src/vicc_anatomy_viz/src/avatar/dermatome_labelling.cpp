#include "vicc_anatomy_viz/avatar/dermatome_labelling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

#include "dermatome_map.hpp"
#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/avatar/skin_segmentation.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

constexpr float kUnreached = std::numeric_limits<float>::max();
// Anisotropic surface metric: on the trunk, neck and head the bands run round the body, so a
// vertical step costs more; on a limb they run along it, so a step along the bone costs less.
constexpr float kTrunkVerticalCost = 2.5f;
constexpr float kLimbAxialCost = 0.6f;

bool isTrunk(BodyPart part) {
  return part == BodyPart::kTrunk || part == BodyPart::kNeck || part == BodyPart::kHead;
}

const char* segmentOf(BodyPart part) {
  switch (part) {
    case BodyPart::kUpperArm:
      return "upper_arm";
    case BodyPart::kForearm:
      return "forearm";
    case BodyPart::kHand:
      return "hand";
    case BodyPart::kThigh:
      return "thigh";
    case BodyPart::kShank:
      return "shank";
    case BodyPart::kFoot:
      return "foot";
    default:
      return nullptr;
  }
}

/// What a label may cover: its body parts on its side, within its reach from its seeds.
struct LabelZone {
  std::vector<BodyPart> parts;
  Side side = Side::kLeft;
  float max_reach = 0;
};

/// The skin's triangles as the nodes labels grow over: centroid, body part and side, and edges
/// to the triangles across their sides with the anisotropic cost.
struct TriangleGraph {
  std::vector<Eigen::Vector3f> centre;
  std::vector<BodyPart> part;  ///< the part of two of its corners (else of the first)
  std::vector<Side> side;
  std::vector<bool> midline;
  std::vector<std::vector<std::pair<int, float>>> edges;
};

BodyPart majorityPart(const SkinSegmentation& segmentation, const Eigen::Vector3i& triangle) {
  const BodyPart a = segmentation.part[triangle[0]], b = segmentation.part[triangle[1]],
                 c = segmentation.part[triangle[2]];
  return (b == c) ? b : a;
}

float stepCost(const TriangleGraph& graph,
               const std::map<std::pair<BodyPart, Side>, Eigen::Vector3f>& axes, int a, int b) {
  const Eigen::Vector3f step = graph.centre[b] - graph.centre[a];
  const BodyPart part = graph.part[a];
  if (graph.part[b] != part || !(isTrunk(part) || segmentOf(part))) return step.norm();
  const Eigen::Vector3f axis =
      isTrunk(part) ? Eigen::Vector3f::UnitZ() : axes.at({part, graph.side[a]});
  const float along = step.dot(axis);
  const float scale = isTrunk(part) ? kTrunkVerticalCost : kLimbAxialCost;
  return std::sqrt(std::max(0.0f, step.squaredNorm() - along * along) +
                   scale * scale * along * along);
}

TriangleGraph bandMetricGraph(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                              const SkinSegmentation& segmentation) {
  std::map<std::pair<BodyPart, Side>, Eigen::Vector3f> axes;
  for (BodyPart part : {BodyPart::kUpperArm, BodyPart::kForearm, BodyPart::kHand, BodyPart::kThigh,
                        BodyPart::kShank, BodyPart::kFoot}) {
    for (Side side : {Side::kLeft, Side::kRight}) {
      axes[{part, side}] = landmarks.bone(segmentOf(part), side).axis;
    }
  }
  TriangleGraph graph;
  for (const Eigen::Vector3i& t : skin.triangles) {
    const Eigen::Vector3f centre =
        (skin.vertices[t[0]] + skin.vertices[t[1]] + skin.vertices[t[2]]) / 3;
    graph.centre.push_back(centre);
    graph.part.push_back(majorityPart(segmentation, t));
    graph.side.push_back(centre.y() >= 0 ? Side::kLeft : Side::kRight);
    graph.midline.push_back(segmentation.midline[t[0]] || segmentation.midline[t[1]] ||
                            segmentation.midline[t[2]]);
  }
  const std::vector<std::vector<int>> neighbours = triangleNeighbours(skin);
  graph.edges.resize(skin.triangles.size());
  for (std::size_t a = 0; a < neighbours.size(); ++a) {
    for (int b : neighbours[a]) {
      graph.edges[a].emplace_back(b, stepCost(graph, axes, static_cast<int>(a), b));
    }
  }
  return graph;
}

bool allowed(const LabelZone& zone, const TriangleGraph& graph, int node, float distance) {
  if (graph.part[node] == BodyPart::kFace) return false;
  if (zone.max_reach > 0 && distance > zone.max_reach) return false;
  // Triangles on the midsagittal plane belong to both sides.
  if (graph.side[node] != zone.side && !graph.midline[node]) return false;
  return std::find(zone.parts.begin(), zone.parts.end(), graph.part[node]) != zone.parts.end();
}

/// Multi-source Dijkstra over the triangles: each takes the label of its nearest seed
/// (anisotropic geodesic distance), a label growing only inside its zone when `zones` is given,
/// into any unlabelled triangle but the face otherwise (the second pass that closes gaps).
void grow(const TriangleGraph& graph, const std::vector<LabelZone>* zones, std::vector<int>& owner,
          std::vector<float>& distance) {
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t node = 0; node < owner.size(); ++node) {
    if (owner[node] >= 0) queue.emplace(distance[node], static_cast<int>(node));
  }
  while (!queue.empty()) {
    const auto [d, node] = queue.top();
    queue.pop();
    if (d > distance[node]) continue;
    for (const auto& [neighbour, cost] : graph.edges[node]) {
      const float reach = d + cost;
      if (reach >= distance[neighbour]) continue;
      if (zones && !allowed((*zones)[owner[node]], graph, neighbour, reach)) continue;
      if (!zones && graph.part[neighbour] == BodyPart::kFace) continue;
      distance[neighbour] = reach;
      owner[neighbour] = owner[node];
      queue.emplace(reach, neighbour);
    }
  }
}

/// The edge-connected pieces of every label: piece id per triangle (-1 unlabelled) and the
/// triangles of each piece.
std::vector<std::vector<int>> labelPieces(const std::vector<std::vector<int>>& neighbours,
                                          const std::vector<int>& label, std::vector<int>& piece) {
  piece.assign(label.size(), -1);
  std::vector<std::vector<int>> pieces;
  for (std::size_t start = 0; start < label.size(); ++start) {
    if (piece[start] >= 0 || label[start] < 0) continue;
    const int id = static_cast<int>(pieces.size());
    pieces.emplace_back();
    std::vector<int> open = {static_cast<int>(start)};
    piece[start] = id;
    while (!open.empty()) {
      const int t = open.back();
      open.pop_back();
      pieces[id].push_back(t);
      for (int n : neighbours[t]) {
        if (piece[n] < 0 && label[n] == label[t]) {
          piece[n] = id;
          open.push_back(n);
        }
      }
    }
  }
  return pieces;
}

/// Pieces of a region apart from the one with its key point go, whole, to the neighbouring
/// region they share most edges with, so that every dermatome is one connected region.
void keepConnected(const TriangleMesh& skin, const std::vector<int>& key_triangle,
                   std::vector<int>& label) {
  const std::vector<std::vector<int>> neighbours = triangleNeighbours(skin);
  for (int round = 0; round < 32; ++round) {
    std::vector<int> piece;
    const std::vector<std::vector<int>> pieces = labelPieces(neighbours, label, piece);
    // Winners from the labels at the start of the round, so that the result does not depend
    // on the order of the triangles.
    std::vector<std::pair<const std::vector<int>*, int>> moves;
    for (const std::vector<int>& triangles : pieces) {
      const int own = label[triangles.front()];
      if (piece[key_triangle[own]] == piece[triangles.front()]) continue;
      // Votes only from settled pieces (those with their key point), so that two loose
      // pieces never swap labels back and forth.
      std::map<int, int> votes;
      bool labelled_neighbour = false;
      for (int t : triangles) {
        for (int n : neighbours[t]) {
          if (label[n] < 0 || label[n] == own) continue;
          labelled_neighbour = true;
          if (piece[key_triangle[label[n]]] == piece[n]) ++votes[label[n]];
        }
      }
      if (votes.empty() && labelled_neighbour) continue;  // settled in a later round
      // A piece enclosed by the face (unlabelled) belongs to the face.
      int winner = -1;
      if (!votes.empty()) {
        winner = std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) {
                   return x.second < y.second;
                 })->first;
      }
      moves.emplace_back(&triangles, winner);
    }
    for (const auto& [triangles, winner] : moves) {
      for (int t : *triangles) label[t] = winner;
    }
    bool changed = !moves.empty();
    if (!changed && round < 31) {
      // Loose pieces that only touch other loose pieces: the one with the most neighbours in
      // one region goes first.
      for (const std::vector<int>& triangles : pieces) {
        const int own = label[triangles.front()];
        if (own < 0 || piece[key_triangle[own]] == piece[triangles.front()]) continue;
        std::map<int, int> votes;
        for (int t : triangles) {
          for (int n : neighbours[t]) {
            if (label[n] >= 0 && label[n] != own) ++votes[label[n]];
          }
        }
        if (votes.empty()) continue;
        const int winner =
            std::max_element(votes.begin(), votes.end(), [](const auto& x, const auto& y) {
              return x.second < y.second;
            })->first;
        for (int t : triangles) label[t] = winner;
        changed = true;
        break;
      }
    }
    if (!changed) return;
  }
}

}  // namespace

const std::vector<std::string>& dermatomeLevels() {
  static const std::vector<std::string> levels = [] {
    std::vector<std::string> names;
    for (const dermatome_map::LevelMap& level : dermatome_map::levels())
      names.push_back(level.level);
    return names;
  }();
  return levels;
}

std::vector<SkinRegion> labelDermatomes(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                                        const AnatomyCatalog& catalog) {
  const SkinSegmentation segmentation = segmentSkin(skin, landmarks);
  const TriangleGraph graph = bandMetricGraph(skin, landmarks, segmentation);
  const TriangleGrid grid(skin);
  std::vector<SkinRegion> regions;
  std::vector<LabelZone> zones;
  std::vector<int> owner(skin.triangles.size(), -1), key_triangle;
  std::vector<float> distance(skin.triangles.size(), kUnreached);
  for (Side side : {Side::kLeft, Side::kRight}) {
    for (const dermatome_map::LevelMap& level : dermatome_map::levels()) {
      const std::string id = "dermatome_" + level.level;
      const Structure* structure = catalog.structure(id);
      if (!structure) throw ConfigError("avatar dermatomes: the catalogue has no '" + id + "'");
      const int label = static_cast<int>(regions.size());
      regions.push_back({id, side, catalog.displayName(*structure, side), {}});
      zones.push_back({level.parts, side, level.max_reach});
      const std::vector<Eigen::Vector3f> seeds =
          dermatome_map::seedPoints(skin, grid, landmarks, segmentation, level, side);
      for (std::size_t k = 0; k < seeds.size(); ++k) {
        const int triangle = grid.nearestTriangle(seeds[k]);
        if (k == 0) key_triangle.push_back(triangle);
        // A band seed off the level's zone (a ray that missed its limb) is dropped; seeds of
        // different levels on one triangle: the nearest to its centre wins.
        if (k > 0 && !allowed(zones.back(), graph, triangle, 0)) continue;
        const float d = (graph.centre[triangle] - seeds[k]).norm();
        if (d < distance[triangle]) {
          owner[triangle] = label;
          distance[triangle] = d;
        }
      }
    }
  }
  // Key points always keep their own level.
  for (std::size_t region = 0; region < key_triangle.size(); ++region) {
    owner[key_triangle[region]] = static_cast<int>(region);
    distance[key_triangle[region]] = 0;
  }
  grow(graph, &zones, owner, distance);
  grow(graph, nullptr, owner, distance);
  keepConnected(skin, key_triangle, owner);
  for (std::size_t t = 0; t < owner.size(); ++t) {
    if (owner[t] >= 0) regions[owner[t]].triangles.push_back(static_cast<int>(t));
  }
  return regions;
}

}  // namespace vicc_anatomy_viz::avatar
