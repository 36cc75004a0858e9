#include "vicc_anatomy_viz/avatar/avatar_report.hpp"

#include <Eigen/Geometry>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>

#include "vicc_anatomy_viz/avatar/mesh_geometry.hpp"
#include "vicc_anatomy_viz/errors.hpp"

namespace vicc_anatomy_viz::avatar {

namespace {

void writePly(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::ofstream out(path);
  if (!out) throw ConfigError("cannot write '" + path.string() + "'");
  out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
      << "property float nx\nproperty float ny\nproperty float nz\nelement face "
      << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Eigen::Vector3f normal =
        i < mesh.normals.size() ? mesh.normals[i] : Eigen::Vector3f::UnitZ();
    out << mesh.vertices[i].x() << ' ' << mesh.vertices[i].y() << ' ' << mesh.vertices[i].z() << ' '
        << normal.x() << ' ' << normal.y() << ' ' << normal.z() << '\n';
  }
  for (const Eigen::Vector3i& t : mesh.triangles) {
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  }
  if (!out) throw ConfigError("cannot write '" + path.string() + "'");
}

std::string fileStem(const std::string& id, Side side) {
  return side == Side::kNone ? id : id + "_" + toString(side);
}

}  // namespace

double trianglesArea(const TriangleMesh& mesh, const std::vector<int>& triangles) {
  double area = 0;
  for (int index : triangles) {
    const Eigen::Vector3i& t = mesh.triangles[index];
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                      .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                      .norm();
  }
  return area;
}

TriangleMesh regionMesh(const TriangleMesh& skin, const SkinRegion& region) {
  TriangleMesh mesh;
  std::map<int, int> renumbered;
  for (int index : region.triangles) {
    Eigen::Vector3i triangle;
    for (int k = 0; k < 3; ++k) {
      const int vertex = skin.triangles[index][k];
      const auto [entry, inserted] =
          renumbered.emplace(vertex, static_cast<int>(mesh.vertices.size()));
      if (inserted) {
        mesh.vertices.push_back(skin.vertices[vertex]);
        mesh.normals.push_back(skin.normals[vertex]);
      }
      triangle[k] = entry->second;
    }
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

void writeReport(const AvatarBuild& build, std::ostream& out) {
  const AvatarModel& model = build.model;
  out << std::fixed << std::setprecision(3);
  out << "manifest: " << build.manifest.path << "\nskin: " << build.manifest.skin.path << ", "
      << model.skin.vertices.size() << " vertices, " << model.skin.triangles.size()
      << " triangles, height " << build.landmarks.height << " m, volume "
      << signedVolume(model.skin) * 1000 << " l\n";
  out << "build time: " << build.times.total_seconds << " s (load " << build.times.load_seconds
      << ", landmarks " << build.times.landmark_seconds << ", structures "
      << build.times.structure_seconds << ", dermatomes " << build.times.dermatome_seconds
      << ")\nlevels: crotch " << build.landmarks.crotch_z << " m, armpit "
      << build.landmarks.armpit_z << " m, neck " << build.landmarks.neck_z << " m\nlandmarks ("
      << build.landmarks.points.size() << ", x y z m):\n";
  for (const auto& [name, point] : build.landmarks.points) {
    out << "  " << std::left << std::setw(18) << name << std::right << std::setw(8) << point.x()
        << std::setw(8) << point.y() << std::setw(8) << point.z() << '\n';
  }
  out << "structures (" << model.structures.size() << "): id side fma vertices volume_cm3 proxy\n";
  for (const AvatarStructure& structure : model.structures) {
    out << "  " << std::left << std::setw(32) << structure.structure_id << std::setw(6)
        << toString(structure.side) << std::setw(11)
        << (structure.fma_id.empty() ? "-" : structure.fma_id) << std::right << std::setw(6)
        << structure.mesh.vertices.size() << std::setw(9) << signedVolume(structure.mesh) * 1e6
        << (structure.has_proxy ? "  proxy" : "") << '\n';
  }
  out << "skin regions (" << model.skin_regions.size() << "): id side triangles area_cm2\n";
  for (const SkinRegion& region : model.skin_regions) {
    out << "  " << std::left << std::setw(16) << region.structure_id << std::setw(6)
        << toString(region.side) << std::right << std::setw(6) << region.triangles.size()
        << std::setw(10) << trianglesArea(model.skin, region.triangles) * 1e4 << '\n';
  }
}

std::size_t exportPly(const AvatarModel& model, const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw ConfigError("cannot create '" + directory + "': " + error.message());
  const std::filesystem::path base(directory);
  std::size_t files = 0;
  writePly(model.skin, base / "skin.ply");
  ++files;
  for (const AvatarStructure& structure : model.structures) {
    if (structure.mesh.triangles.empty()) continue;
    writePly(structure.mesh, base / (fileStem(structure.structure_id, structure.side) + ".ply"));
    ++files;
  }
  for (const SkinRegion& region : model.skin_regions) {
    writePly(regionMesh(model.skin, region),
             base / (fileStem(region.structure_id, region.side) + ".ply"));
    ++files;
  }
  return files;
}

}  // namespace vicc_anatomy_viz::avatar
