#pragma once
// Geometry on closed triangle meshes: normals, volume, inside tests, ray casts and the vertex
// graph that geodesic distances run on.

#include <Eigen/Core>

#include <optional>
#include <utility>
#include <vector>

#include "vicc_anatomy_viz/avatar/avatar_model.hpp"

namespace vicc_anatomy_viz::avatar {

/// Area-weighted vertex normals (unit length; triangles counter-clockwise from outside).
std::vector<Eigen::Vector3f> vertexNormals(const TriangleMesh& mesh);

/// Appends `part` (vertices, normals, triangles) to `mesh`: a structure made of several closed
/// parts, e.g. a muscle belly and its tendon.
void appendMeshPart(TriangleMesh& mesh, const TriangleMesh& part);

/// Signed enclosed volume in m^3: positive when the triangles face outwards.
double signedVolume(const TriangleMesh& mesh);

/// Reverses every triangle (and the normals) when the mesh encloses negative volume.
void orientOutwards(TriangleMesh& mesh);

/// Generalised winding number of `point` (1 inside a closed outward mesh, 0 outside).
double windingNumber(const TriangleMesh& mesh, const Eigen::Vector3f& point);

/// Distance from `point` to the nearest point of the mesh surface.
float distanceToSurface(const TriangleMesh& mesh, const Eigen::Vector3f& point);

/// First intersection of the ray origin + t * direction (t > 0) with the mesh; the hit point.
std::optional<Eigen::Vector3f> castRay(const TriangleMesh& mesh, const Eigen::Vector3f& origin,
                                       const Eigen::Vector3f& direction);

/// The vertex graph: for every vertex its neighbours along mesh edges with the edge lengths.
using VertexGraph = std::vector<std::vector<std::pair<int, float>>>;
VertexGraph vertexGraph(const TriangleMesh& mesh);

/// The index of the vertex nearest to `point`.
int nearestVertex(const TriangleMesh& mesh, const Eigen::Vector3f& point);

/// For every triangle its (up to three) neighbours across its edges.
std::vector<std::vector<int>> triangleNeighbours(const TriangleMesh& mesh);

}  // namespace vicc_anatomy_viz::avatar
