#include "vicc_anatomy_viz/avatar/dermatome_labelling.hpp"

#include <limits>
#include <queue>

#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

struct Label {
  int level = -1;
  Side side = Side::kNone;
};

/// Multi-source Dijkstra over the vertex graph: each vertex takes the label of its nearest seed.
std::vector<int> growFromSeeds(const TriangleMesh& skin, const std::vector<std::vector<int>>& seeds,
                               std::vector<float>& distance) {
  const VertexGraph graph = vertexGraph(skin);
  distance.assign(skin.vertices.size(), std::numeric_limits<float>::max());
  std::vector<int> owner(skin.vertices.size(), -1);
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t label = 0; label < seeds.size(); ++label) {
    for (int vertex : seeds[label]) {
      distance[vertex] = 0;
      owner[vertex] = static_cast<int>(label);
      queue.emplace(0.0f, vertex);
    }
  }
  while (!queue.empty()) {
    const auto [d, vertex] = queue.top();
    queue.pop();
    if (d > distance[vertex]) continue;
    for (const auto& [neighbour, length] : graph[vertex]) {
      if (d + length < distance[neighbour]) {
        distance[neighbour] = d + length;
        owner[neighbour] = owner[vertex];
        queue.emplace(distance[neighbour], neighbour);
      }
    }
  }
  return owner;
}

}  // namespace

const std::vector<std::string>& dermatomeLevels() {
  static const std::vector<std::string> levels = {
      "C2", "C3",  "C4",  "C5",  "C6", "C7", "C8", "T1", "T2", "T3", "T4", "T5", "T6", "T7", "T8",
      "T9", "T10", "T11", "T12", "L1", "L2", "L3", "L4", "L5", "S1", "S2", "S3", "S4", "S5"};
  return levels;
}

std::vector<SkinRegion> labelDermatomes(const TriangleMesh& skin, const BodyLandmarks& landmarks,
                                        const AnatomyCatalog& catalog) {
  std::vector<SkinRegion> regions;
  std::vector<std::vector<int>> seeds;
  for (Side side : {Side::kLeft, Side::kRight}) {
    for (const std::string& level : dermatomeLevels()) {
      const std::string id = "dermatome_" + level;
      const Structure* structure = catalog.structure(id);
      if (!structure) throw ConfigError("avatar dermatomes: the catalogue has no '" + id + "'");
      SkinRegion region;
      region.structure_id = id;
      region.side = side;
      region.display_name = catalog.displayName(*structure, side);
      regions.push_back(region);
      seeds.push_back(
          {nearestVertex(skin, landmarks.point("key_" + level + "_" + toString(side)))});
    }
  }
  std::vector<float> distance;
  const std::vector<int> owner = growFromSeeds(skin, seeds, distance);
  for (std::size_t t = 0; t < skin.triangles.size(); ++t) {
    // The triangle goes to the label of its vertex nearest to a seed, so a seed's triangles
    // stay with it.
    const Eigen::Vector3i& triangle = skin.triangles[t];
    int best = triangle[0];
    for (int k = 1; k < 3; ++k) {
      if (distance[triangle[k]] < distance[best]) best = triangle[k];
    }
    if (owner[best] >= 0) regions[owner[best]].triangles.push_back(static_cast<int>(t));
  }
  return regions;
}

}  // namespace vicc_anatomy_viz::avatar
