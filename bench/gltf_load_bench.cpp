// Cost of reading a glTF asset (core/mesh/gltf_loader.h, issue 60: a 100k-triangle .glb in at
// most 1 s): loadGltfFile on a .glb of an n x n grid of quads split into 2 n^2 triangles
// (positions, normals and uvs as float32, uint32 indices; (n + 1)^2 vertices), written once
// to the temporary folder. Argument: the triangle count (about 10k and 100k). Wall clock.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/mesh/gltf_loader.h"

namespace {

// Appends `count` values at a 4-byte boundary and a buffer view and accessor for them.
template <class T>
int appendAccessor(nlohmann::json& gltf, std::vector<uint8_t>& bin, const std::vector<T>& values,
                   const char* type, int component, size_t count) {
  while (bin.size() % 4 != 0) bin.push_back(0);
  const size_t offset = bin.size(), bytes = values.size() * sizeof(T);
  bin.resize(offset + bytes);
  std::memcpy(bin.data() + offset, values.data(), bytes);
  gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
  gltf["accessors"].push_back({{"bufferView", gltf["bufferViews"].size() - 1},
                               {"componentType", component},
                               {"count", count},
                               {"type", type}});
  return int(gltf["accessors"].size() - 1);
}

// The .glb of the grid with `triangles` (rounded to 2 n^2) triangles; returns its path.
std::string writeGridGlb(size_t triangles) {
  size_t n = 1;
  while (2 * (n + 1) * (n + 1) <= triangles) ++n;
  std::vector<float> positions, normals, uvs;
  for (size_t j = 0; j <= n; ++j) {
    for (size_t i = 0; i <= n; ++i) {
      const float u = float(i) / float(n), v = float(j) / float(n);
      positions.insert(positions.end(), {u, v, 0.1f * u * v});
      normals.insert(normals.end(), {0, 0, 1});
      uvs.insert(uvs.end(), {u, v});
    }
  }
  std::vector<uint32_t> indices;
  for (size_t j = 0; j < n; ++j) {
    for (size_t i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 2,
                     d = a + uint32_t(n) + 1;
      indices.insert(indices.end(), {a, b, c, a, c, d});
    }
  }
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}},
                         {"scene", 0},
                         {"scenes", {{{"nodes", {0}}}}},
                         {"nodes", {{{"mesh", 0}}}}};
  std::vector<uint8_t> bin;
  const size_t vertices = (n + 1) * (n + 1);
  nlohmann::json attributes = {
      {"POSITION", appendAccessor(gltf, bin, positions, "VEC3", 5126, vertices)},
      {"NORMAL", appendAccessor(gltf, bin, normals, "VEC3", 5126, vertices)},
      {"TEXCOORD_0", appendAccessor(gltf, bin, uvs, "VEC2", 5126, vertices)}};
  const int index = appendAccessor(gltf, bin, indices, "SCALAR", 5125, indices.size());
  gltf["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"indices", index}}}}}};
  while (bin.size() % 4 != 0) bin.push_back(0);
  gltf["buffers"] = {{{"byteLength", bin.size()}}};
  std::string text = gltf.dump();
  while (text.size() % 4 != 0) text += ' ';
  const auto word = [](std::ofstream& out, uint32_t value) {
    out.write(reinterpret_cast<const char*>(&value), 4);
  };
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("tessbench_grid_" + std::to_string(triangles) + ".glb"))
                               .string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write("glTF", 4);
  word(out, 2);
  word(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  word(out, uint32_t(text.size()));
  out.write("JSON", 4);
  out.write(text.data(), std::streamsize(text.size()));
  word(out, uint32_t(bin.size()));
  out.write("BIN\0", 4);
  out.write(reinterpret_cast<const char*>(bin.data()), std::streamsize(bin.size()));
  return path;
}

void BM_LoadGlb(benchmark::State& state) {
  const std::string path = writeGridGlb(size_t(state.range(0)));
  size_t faces = 0;
  for (auto _ : state) {
    const tb::mesh::Mesh mesh = tb::mesh::loadGltfFile(path);
    faces = mesh.faceCount();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["triangles"] = double(faces);
  std::filesystem::remove(path);
}
BENCHMARK(BM_LoadGlb)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

TB_BENCHMARK_MAIN()
