// A [[mesh]]'s placement in the world: scale, rotate, translate, in double precision.
#pragma once

#include <cmath>
#include <numbers>

#include "lancer/scene/scene_description.hpp"

namespace lancer {

// Scale, then rotate about x, y, z (degrees), then translate: the order the scene file documents.
struct InstanceTransform {
  Vec3d scale;
  double rotation[3][3];
  Vec3d translate;

  explicit InstanceTransform(const MeshInstance& instance)
      : scale(instance.scale), translate(instance.translate) {
    const double k = std::numbers::pi / 180.0;
    const double cx = std::cos(instance.rotateDegrees.x * k), sx = std::sin(instance.rotateDegrees.x * k);
    const double cy = std::cos(instance.rotateDegrees.y * k), sy = std::sin(instance.rotateDegrees.y * k);
    const double cz = std::cos(instance.rotateDegrees.z * k), sz = std::sin(instance.rotateDegrees.z * k);
    // R = Rz * Ry * Rx
    const double r[3][3] = {{cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx},
                            {sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx},
                            {-sy, cy * sx, cy * cx}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rotation[i][j] = r[i][j];
  }

  Vec3d apply(const Vec3d& p) const {
    const Vec3d s = p * scale;
    return Vec3d{rotation[0][0] * s.x + rotation[0][1] * s.y + rotation[0][2] * s.z,
                 rotation[1][0] * s.x + rotation[1][1] * s.y + rotation[1][2] * s.z,
                 rotation[2][0] * s.x + rotation[2][1] * s.y + rotation[2][2] * s.z} +
           translate;
  }

  // The mesh's own coordinates of the scene point p (the inverse of apply).
  Vec3d toLocal(const Vec3d& p) const {
    const Vec3d d = p - translate;
    const Vec3d r{rotation[0][0] * d.x + rotation[1][0] * d.y + rotation[2][0] * d.z,
                  rotation[0][1] * d.x + rotation[1][1] * d.y + rotation[2][1] * d.z,
                  rotation[0][2] * d.x + rotation[1][2] * d.y + rotation[2][2] * d.z};
    return Vec3d{r.x / scale.x, r.y / scale.y, r.z / scale.z};
  }
  // A plane's normal in the mesh's own coordinates (not normalised): S R^T n.
  Vec3d normalToLocal(const Vec3d& n) const {
    const Vec3d r{rotation[0][0] * n.x + rotation[1][0] * n.y + rotation[2][0] * n.z,
                  rotation[0][1] * n.x + rotation[1][1] * n.y + rotation[2][1] * n.z,
                  rotation[0][2] * n.x + rotation[1][2] * n.y + rotation[2][2] * n.z};
    return r * scale;
  }
};

}  // namespace lancer
