// Writes one scene twice, for bench/povray_compare.sh: a lancer scene (.toml) and a POV-Ray 3.7
// scene (.pov, a mesh2 with lancer's own smoothed vertex normals, in the mesh's origin-relative frame), with
// the same camera, point light, material, resolution and anti-aliasing, so the two renderers' wall times can
// be compared.
//   pov_scene_writer MESH.msh OUT_BASE WIDTH HEIGHT    -> OUT_BASE.toml, OUT_BASE.pov
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "lancer/mesh/msh_reader.hpp"
#include "lancer/mesh/vertex_normals.hpp"

namespace {

using lancer::Vec3;

struct View {
  Vec3 eye, center, light;
  float fovDegrees = 40;  // vertical, as lancer's camera takes it
};

// The camera of bench/accel_bench_support.hpp's primary rays: on the diagonal (1, -1.6, 0.9) of the
// box, framing its bounding sphere; the light above and in front of the part.
View frame(const lancer::Aabb& box) {
  View v;
  v.center = box.center();
  const float diagonal = lancer::length(box.extent());
  const Vec3 forward = lancer::normalize(Vec3{-1.0f, 1.6f, -0.9f});
  const float distance = 0.5f * diagonal / std::sin(0.5f * v.fovDegrees * 3.14159265f / 180.0f);
  v.eye = v.center - forward * distance;
  v.light = v.center + Vec3{-0.6f, -1.0f, 1.4f} * diagonal;
  return v;
}

std::string vec(const Vec3& p) { return fmt::format("<{:.9g}, {:.9g}, {:.9g}>", p.x, p.y, p.z); }

// `origin`: the mesh's (its positions are relative to it); lancer's scene takes world coordinates.
void writeToml(const std::string& path, const std::string& mesh, const std::string& png, const View& local,
               const lancer::Vec3d& origin, int width, int height) {
  View v = local;
  for (Vec3* p : {&v.eye, &v.center, &v.light}) *p = lancer::toFloat(origin + lancer::toDouble(*p));
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw std::runtime_error("cannot write " + path);
  auto arr = [](const Vec3& p) { return fmt::format("[{:.9g}, {:.9g}, {:.9g}]", p.x, p.y, p.z); };
  fmt::print(out, "[render]\nwidth = {}\nheight = {}\nsamples = 4\nshading = \"phong\"\nmax_depth = 1\n",
             width, height);
  fmt::print(out, "background = [0, 0, 0]\noutput = \"{}\"\n\n", png);
  fmt::print(
      out,
      "[camera]\nprojection = \"perspective\"\nposition = {}\nlook_at = {}\nup = [0, 0, 1]\nfov = {}\n\n",
      arr(v.eye), arr(v.center), v.fovDegrees);
  fmt::print(out,
             "[ambient]\nintensity = [0.1, 0.1, 0.1]\n\n[[light]]\nposition = {}\nintensity = [1, 1, 1]\n\n",
             arr(v.light));
  fmt::print(
      out, "[material.part]\nka = [1, 1, 1]\nkd = [0.7, 0.7, 0.7]\nks = [0.3, 0.3, 0.3]\nshininess = 32\n\n");
  fmt::print(out, "[[mesh]]\nfile = \"{}\"\nmaterial = \"part\"\nsmooth_angle = 60\n", mesh);
  std::fclose(out);
}

void writePov(const std::string& path, const lancer::Mesh& mesh, const View& v, int width, int height) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw std::runtime_error("cannot write " + path);
  const float aspect = float(width) / float(height);
  // POV-Ray's angle is horizontal; `right -x` makes its left-handed frame right-handed like gmsh's.
  const float horizontal =
      2.0f * std::atan(std::tan(0.5f * v.fovDegrees * 3.14159265f / 180.0f) * aspect) * 180.0f / 3.14159265f;
  fmt::print(
      out, "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 max_trace_level 1 ambient_light rgb 1 }}\n");
  fmt::print(out, "background {{ rgb 0 }}\n");
  fmt::print(out,
             "camera {{ perspective location {} sky <0, 0, 1> up <0, 0, 1> right <{:.9g}, 0, 0> look_at {} "
             "angle {:.9g} }}\n",
             vec(v.eye), -aspect, vec(v.center), horizontal);
  fmt::print(out, "light_source {{ {} color rgb 1 }}\n", vec(v.light));
  const lancer::CornerNormals normals =
      lancer::computeCornerNormals(mesh.positions, mesh.faces, mesh.facePhysicalTag, 60.0f);
  std::size_t triangles = 0;
  for (const lancer::MeshFace& f : mesh.faces) triangles += f.isQuad() ? 2 : 1;
  fmt::print(out, "mesh2 {{\n vertex_vectors {{ {}", mesh.positions.size());
  for (const Vec3& p : mesh.positions) fmt::print(out, ",\n{}", vec(p));
  fmt::print(out, "\n }}\n normal_vectors {{ {}", normals.normals.size());
  for (const Vec3& n : normals.normals) fmt::print(out, ",\n{}", vec(n));
  // Quads as two triangles, corners (0,1,2) and (0,2,3), as lancer splits them.
  auto faces = [&](const char* name, auto index) {
    fmt::print(out, "\n }}\n {} {{ {}", name, triangles);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const int halves = mesh.faces[f].isQuad() ? 2 : 1;
      for (int h = 0; h < halves; ++h)
        fmt::print(out, ",\n<{}, {}, {}>", index(f, 0), index(f, 1 + h), index(f, 2 + h));
    }
  };
  faces("face_indices", [&](std::size_t f, int c) { return mesh.faces[f].vertex[c]; });
  faces("normal_indices", [&](std::size_t f, int c) { return normals.faceCorner[f][c]; });
  fmt::print(out,
             "\n }}\n texture {{ pigment {{ rgb 1 }} finish {{ ambient 0.1 diffuse 0.7 phong 0.3 phong_size "
             "32 }} }}\n}}\n");
  std::fclose(out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s MESH.msh OUT_BASE WIDTH HEIGHT\n", argv[0]);
    return 2;
  }
  try {
    const std::string meshPath = argv[1], base = argv[2];
    const int width = std::atoi(argv[3]), height = std::atoi(argv[4]);
    const lancer::Mesh mesh = lancer::readMsh(meshPath);
    const View view = frame(lancer::faceBounds(mesh));
    writeToml(base + ".toml", meshPath, base + "-lancer.png", view, mesh.origin, width, height);
    writePov(base + ".pov", mesh, view, width, height);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pov_scene_writer: %s\n", e.what());
    return 1;
  }
  return 0;
}
