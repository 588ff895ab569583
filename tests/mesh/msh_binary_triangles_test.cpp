// Binary MSH 4.1 blocks of 3-node triangles are read in parallel chunks straight into the mesh's
// faces: the same mesh as the element-by-element reading of the same file in ASCII, and a missing node
// reported at the first element (in file order) that names one, whichever chunk finds it first.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "lancer/mesh/msh_reader.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

// More triangles than one chunk of the parallel pass (32768) holds: three chunks and a bit.
constexpr std::uint64_t kTriangles = 100'000;
constexpr std::uint64_t kNodes = kTriangles + 2;

// A strip: triangle t (tag 1000 + t) on nodes t + 1, t + 2, t + 3, except the triangles in `missing`,
// whose last node is 999999999. Two blocks (entities 1 and 2) to check that each keeps its entity.
std::string strip(bool binary, const std::vector<std::uint64_t>& missing = {}) {
  std::string bytes = binary ? "$MeshFormat\n4.1 1 8\n" : "$MeshFormat\n4.1 0 8\n";
  const auto put = [&](const auto& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof(value));
  };
  if (binary) {
    put(std::int32_t{1});
    bytes += "\n";
  }
  bytes += "$EndMeshFormat\n$Nodes\n";
  const auto lastNode = [&](std::uint64_t t) {
    for (const std::uint64_t m : missing)
      if (m == t) return std::uint64_t{999999999};
    return t + 3;
  };
  if (binary) {
    for (const std::uint64_t v : {std::uint64_t{1}, kNodes, std::uint64_t{1}, kNodes}) put(v);
    for (const std::int32_t v : {2, 1, 0}) put(v);
    put(kNodes);
    for (std::uint64_t n = 1; n <= kNodes; ++n) put(n);
    for (std::uint64_t n = 1; n <= kNodes; ++n)
      for (const double c : {static_cast<double>(n / 2), static_cast<double>(n % 2), 0.0}) put(c);
    bytes += "\n$EndNodes\n$Elements\n";
    for (const std::uint64_t v : {std::uint64_t{2}, kTriangles, std::uint64_t{1000}, 1000 + kTriangles - 1})
      put(v);
    const std::uint64_t half = kTriangles / 2;
    for (int block = 0; block < 2; ++block) {
      for (const std::int32_t v : {2, block + 1, 2}) put(v);
      put(half);
      for (std::uint64_t t = block * half; t < (block + 1) * half; ++t)
        for (const std::uint64_t v : {1000 + t, t + 1, t + 2, lastNode(t)}) put(v);
    }
    bytes += "\n$EndElements\n";
  } else {
    bytes += "1 " + std::to_string(kNodes) + " 1 " + std::to_string(kNodes) + "\n";
    bytes += "2 1 0 " + std::to_string(kNodes) + "\n";
    for (std::uint64_t n = 1; n <= kNodes; ++n) bytes += std::to_string(n) + "\n";
    for (std::uint64_t n = 1; n <= kNodes; ++n)
      bytes += std::to_string(n / 2) + " " + std::to_string(n % 2) + " 0\n";
    bytes += "$EndNodes\n$Elements\n";
    bytes += "2 " + std::to_string(kTriangles) + " 1000 " + std::to_string(1000 + kTriangles - 1) + "\n";
    const std::uint64_t half = kTriangles / 2;
    for (int block = 0; block < 2; ++block) {
      bytes += "2 " + std::to_string(block + 1) + " 2 " + std::to_string(half) + "\n";
      for (std::uint64_t t = block * half; t < (block + 1) * half; ++t)
        bytes += std::to_string(1000 + t) + " " + std::to_string(t + 1) + " " + std::to_string(t + 2) + " " +
                 std::to_string(lastNode(t)) + "\n";
    }
    bytes += "$EndElements\n";
  }
  return bytes;
}

TEST(MshBinaryTriangles, BlocksGiveTheMeshTheTextFileGives) {
  const Mesh text = readMshFromMemory(strip(false), "strip.msh", 1);
  for (const int threads : {1, 2, 3}) {
    const Mesh binary = readMshFromMemory(strip(true), "strip.msh", threads);
    ASSERT_EQ(binary.faceCount(), kTriangles);
    ASSERT_EQ(binary.faces.size(), text.faces.size());
    for (std::size_t f = 0; f < binary.faces.size(); ++f)
      for (int c = 0; c < 4; ++c)
        ASSERT_EQ(binary.faces[f].vertex[c], text.faces[f].vertex[c]) << "face " << f << ", corner " << c;
    EXPECT_EQ(binary.facePhysicalTag, text.facePhysicalTag);
    EXPECT_EQ(binary.faceEntityTag, text.faceEntityTag);
    EXPECT_EQ(binary.faceEdgeMask, text.faceEdgeMask);
    EXPECT_EQ(binary.positions, text.positions);
    EXPECT_EQ(binary.faceEntityTag.front(), 1);
    EXPECT_EQ(binary.faceEntityTag.back(), 2);
  }
}

TEST(MshBinaryTrianglesBadInput, TheFirstElementNamingAMissingNodeIsReported) {
  // Triangles 45000 (the first block's second chunk), 20000 (its first chunk) and 90000 (the second
  // block): 20000 is reported, at its record, whichever chunk finished first.
  const std::string bytes = strip(true, {45'000, 20'000, 90'000});
  const std::string message = test::messageOf([&] { readMshFromMemory(bytes, "strip.msh", 2); });
  EXPECT_NE(message.find("element 21000 (3-node triangle) uses node 999999999, which $Nodes does not define"),
            std::string::npos)
      << message;
  const std::size_t record = bytes.find("$Elements\n") + 10 + 32 + 20 + 20000 * 32;
  EXPECT_NE(message.find("strip.msh:@" + std::to_string(record) + ":"), std::string::npos) << message;
}

}  // namespace
}  // namespace lancer
