// glb vertices through meshoptimizer (mesh/gltf_vertices.hpp): GPU order keeps every triangle and its
// winding, uses vertices in fetch order, drops unused vertices and does not make the vertex cache
// worse; quantized files (KHR_mesh_quantization) read back by tinygltf and dequantized by the
// glTF rules (test support, not the writer's code) stay within the errors mesh/gltf_vertices.hpp
// states, for one mesh, every starter surface and the riders' animated scene.
#include "io/mesh/gltf_vertices.hpp"
#include "io/mesh/gltf_writer.hpp"
#include "io/surface_export.hpp"

#include "geometry/thread_pool.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"
#include "support/gltf_test_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace sweep {
namespace {

using test::mesh_triangles;

/// A model read back from glb bytes; fails the test on an error or a warning.
tinygltf::Model read_glb(const std::string& bytes) {
  tinygltf::Model model;
  std::string error;
  std::string warning;
  tinygltf::TinyGLTF reader;
  const bool ok =
      reader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                  static_cast<unsigned int>(bytes.size()));
  EXPECT_TRUE(ok) << error;
  EXPECT_EQ(warning, "");
  return model;
}

/// The largest |coordinate| of the mesh's positions.
double largest_coordinate(const Mesh& mesh) {
  double largest = 0.0;
  for (const glm::vec3& p : mesh.positions) {
    largest = std::max({largest, std::fabs(double{p.x}), std::fabs(double{p.y}), std::fabs(double{p.z})});
  }
  return largest;
}

/// `mesh` in its GPU order (gpu_order, reorder_into): vertices no triangle uses left out.
Mesh reordered(const Mesh& mesh) {
  const io::GpuOrder order = io::gpu_order(mesh);
  Mesh out;
  out.indices = order.indices;
  const auto reorder = [&order](const auto& values, auto& into) {
    if (values.size() != order.remap.size()) return;
    into.resize(order.vertex_count);
    io::reorder_into(order, values.data(), values.size(), sizeof(values[0]), into.data());
  };
  reorder(mesh.positions, out.positions);
  reorder(mesh.normals, out.normals);
  reorder(mesh.uvs, out.uvs);
  return out;
}

/// Checks the quantized primitive `p` against `mesh` in GPU order (reordered, whose triangles
/// GpuOrder checks): the same indices, and each vertex within the stated errors: a
/// position within step / 2 per coordinate (step: the largest |coordinate| / 32767, the node's
/// scale), a normal within 0.5 / 127 per component, a texture coordinate within 0.5 / 65535, or
/// exact where it stayed float.
void expect_within_stated_errors(const tinygltf::Model& model, const tinygltf::Primitive& p, const Mesh& mesh,
                                 double scale) {
  const Mesh v = reordered(mesh);
  EXPECT_EQ(test::read_indices(model, p), v.indices);
  const std::vector<test::ReadVertex> got = test::read_vertices(model, p, scale);
  ASSERT_EQ(got.size(), v.positions.size());
  const double step = largest_coordinate(mesh) > 0 ? largest_coordinate(mesh) / 32767 : 1.0;
  EXPECT_DOUBLE_EQ(scale, step);
  const bool uv_float = p.attributes.count("TEXCOORD_0") &&
                        model.accessors.at(static_cast<std::size_t>(p.attributes.at("TEXCOORD_0"))).componentType ==
                            TINYGLTF_COMPONENT_TYPE_FLOAT;
  double position = 0.0, normal = 0.0, uv = 0.0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      position = std::max(position, std::fabs(got[i][k] - v.positions[i][static_cast<int>(k)]));
      if (!v.normals.empty()) normal = std::max(normal, std::fabs(got[i][3 + k] - v.normals[i][static_cast<int>(k)]));
    }
    for (std::size_t k = 0; k < 2 && !v.uvs.empty(); ++k) {
      const double expected = k == 0 ? v.uvs[i].x : 1.0 - v.uvs[i].y;  // glTF's v runs down the image
      uv = std::max(uv, std::fabs(got[i][6 + k] - expected));
    }
  }
  // The float positions themselves are within an ulp of the largest coordinate.
  EXPECT_LE(position, step / 2 + 1e-7 * largest_coordinate(mesh));
  EXPECT_LE(normal, 0.5 / 127 + 1e-7);
  EXPECT_LE(uv, uv_float ? 0.0 : 0.5 / 65535 + 1e-7);
}

Mesh grid_with_unit_uvs() {
  Mesh mesh;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      const float x = static_cast<float>(i) / 3.0f, y = static_cast<float>(j) / 2.0f;
      mesh.positions.push_back({x * 7.0f - 2.0f, y * 3.0f + 100.0f, 0.1f * x * y});
      mesh.normals.push_back(glm::normalize(glm::vec3(0.1f * y, 0.1f * x, -1.0f)));
      mesh.uvs.push_back({x, y});
    }
  }
  for (std::uint32_t j = 0; j < 2; ++j) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t a = 4 * j + i;
      mesh.indices.insert(mesh.indices.end(), {a, a + 1, a + 5, a, a + 5, a + 4});
    }
  }
  return mesh;
}

TEST(GpuOrder, KeepsEveryTriangleAndItsWindingInFetchOrderAndDropsUnusedVertices) {
  Mesh mesh = grid_with_unit_uvs();
  mesh.positions.push_back({9, 9, 9});  // used by no triangle
  mesh.normals.push_back({0, 0, 1});
  mesh.uvs.push_back({0, 0});
  const Mesh back = reordered(mesh);
  EXPECT_EQ(back.positions.size(), 12u);
  EXPECT_EQ(back.normals.size(), 12u);
  EXPECT_EQ(back.uvs.size(), 12u);
  EXPECT_TRUE(test::in_fetch_order(back.indices));
  mesh.positions.pop_back();
  mesh.normals.pop_back();
  mesh.uvs.pop_back();
  EXPECT_EQ(mesh_triangles(back), mesh_triangles(mesh));
}

TEST(GpuOrder, TheVertexCacheMissesOfAStarterSurfaceDoNotGrow) {
  const Document doc = test::load_starter("weird.swp");
  const Scene scene = evaluate_document(doc);
  const Mesh& mesh = scene.objects[static_cast<std::size_t>(doc.find("weird"))].mesh;
  ASSERT_GT(mesh.triangle_count(), 1000u);
  const Mesh v = reordered(mesh);
  const auto misses = [](const std::vector<std::uint32_t>& indices, std::size_t vertices) {
    return meshopt_analyzeVertexCache(indices.data(), indices.size(), vertices, 16, 0, 0).acmr;
  };
  const float before = misses(mesh.indices, mesh.vertex_count());
  const float after = misses(v.indices, v.positions.size());
  EXPECT_LE(after, before) << "ACMR " << before << " -> " << after;
  EXPECT_LE(after, 0.69f) << "the full optimizer's ACMR on this surface, which the FIFO one must keep";
  ::testing::Test::RecordProperty("acmr", std::to_string(before) + " -> " + std::to_string(after));
  EXPECT_EQ(mesh_triangles(v), mesh_triangles(Mesh{mesh.positions, mesh.normals, mesh.indices, {}, {}, {}}));
}

/// weird.swp's surface with every STEPS times `factor`.
Mesh weird_mesh(int factor) {
  Document doc = test::load_starter("weird.swp");
  for (Object& object : doc.objects) {
    if (int* steps = sweep::steps_field(object)) *steps *= factor;
  }
  Scene scene = evaluate_document(doc);
  return std::move(scene.objects[static_cast<std::size_t>(doc.find("weird"))].mesh);
}

/// A sheet of `rows` x `columns` vertices, its quads row after row (ACMR ~1: each row's vertices
/// have left a 16-entry cache before the next row needs them).
Mesh row_order_grid(std::uint32_t rows, std::uint32_t columns) {
  Mesh mesh;
  for (std::uint32_t i = 0; i < rows; ++i) {
    for (std::uint32_t j = 0; j < columns; ++j) {
      mesh.positions.emplace_back(0.01f * float(j), 0.0f, 0.01f * float(i));
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
    }
  }
  for (std::uint32_t i = 0; i + 1 < rows; ++i) {
    for (std::uint32_t j = 0; j + 1 < columns; ++j) {
      const std::uint32_t a = i * columns + j;
      mesh.indices.insert(mesh.indices.end(), {a, a + columns, a + 1, a + 1, a + columns, a + columns + 1});
    }
  }
  return mesh;
}

float acmr(const Mesh& mesh) {
  return meshopt_analyzeVertexCache(mesh.indices.data(), mesh.indices.size(), mesh.positions.size(), 16, 0, 0).acmr;
}

TEST(GpuOrder, ASweepsGridIsMadeInCacheOrderAndKeptAsItIs) {
  const Mesh mesh = weird_mesh(4);  // 262 144 triangles
  ASSERT_GT(mesh.triangle_count(), 200'000u);
  EXPECT_LE(acmr(mesh), 0.6f) << "bands of kBandQuads columns";
  const io::GpuOrder order = io::gpu_order(mesh);
  std::vector<std::uint32_t> kept = mesh.indices;
  for (std::uint32_t& i : kept) i = order.remap[i];
  EXPECT_EQ(order.indices, kept);
}

TEST(GpuOrder, ALargeGridInRowOrderIsOrderedByPiecesAlikeAtAnyThreadCount) {
  const Mesh mesh = row_order_grid(300, 1000);  // 598 002 triangles: 19 pieces of 32 768
  ASSERT_GT(acmr(mesh), 0.9f);
  set_worker_count(1);
  const io::GpuOrder one = io::gpu_order(mesh);
  set_worker_count(3);
  const io::GpuOrder three = io::gpu_order(mesh);
  set_worker_count(default_worker_count());
  EXPECT_EQ(one.indices, three.indices);
  EXPECT_EQ(one.remap, three.remap);
  const Mesh v = reordered(mesh);
  EXPECT_LE(acmr(v), 0.69f);
  ::testing::Test::RecordProperty("acmr", std::to_string(acmr(v)));
  EXPECT_EQ(mesh_triangles(v), mesh_triangles(Mesh{mesh.positions, mesh.normals, mesh.indices, {}, {}, {}}));
}

TEST(GpuOrder, APieceSpanningTheWholeMeshIsOrderedInOneGoAndKeepsEveryTriangle) {
  Mesh mesh = row_order_grid(300, 400);
  // A last piece of one triangle from the first vertex to the last: far wider than 4 vertices per
  // index, so the mesh is ordered in one go.
  const auto last = static_cast<std::uint32_t>(mesh.vertex_count() - 1);
  mesh.indices.insert(mesh.indices.end(), {0u, last / 2, last});
  const Mesh v = reordered(mesh);
  EXPECT_TRUE(test::in_fetch_order(v.indices));
  EXPECT_LE(acmr(v), 0.69f);
  EXPECT_EQ(mesh_triangles(v), mesh_triangles(Mesh{mesh.positions, mesh.normals, mesh.indices, {}, {}, {}}));
}

TEST(Quantize, PositionsOnAUniformGridOfTheLargestCoordinate) {
  const std::vector<glm::vec3> positions{{-4.0f, 0.0f, 1.0f}, {0.5f, 2.0f, -1e-6f}, {4.0f, -4.0f, 3.999f}};
  const io::QuantizedPositions q = io::quantize_positions(positions);
  EXPECT_DOUBLE_EQ(q.step, 4.0 / 32767);
  ASSERT_EQ(q.values.size(), 3u);
  EXPECT_EQ(q.values[0], (std::array<std::int16_t, 4>{-32767, 0, 8192, 0}));
  EXPECT_EQ(q.values[2][0], 32767);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(std::fabs(q.values[i][static_cast<std::size_t>(k)] * q.step - positions[i][k]), q.step / 2 * 1.0001);
    }
  }
  EXPECT_EQ(io::quantize_positions(std::vector<glm::vec3>{{0, 0, 0}}).step, 1.0);
}

TEST(Quantize, NormalsAsBytesAndTextureCoordinatesOnlyInsideTheUnitSquare) {
  const std::vector<glm::vec3> normals{{1, 0, 0}, {0, -1, 0}, glm::normalize(glm::vec3(1, 2, 3))};
  const auto n = io::quantize_normals(normals);
  EXPECT_EQ(n[0], (std::array<std::int8_t, 4>{127, 0, 0, 0}));
  EXPECT_EQ(n[1], (std::array<std::int8_t, 4>{0, -127, 0, 0}));
  for (int k = 0; k < 3; ++k)
    EXPECT_LE(std::fabs(n[2][static_cast<std::size_t>(k)] / 127.0 - normals[2][k]), 0.5 / 127);
  const auto uvs = io::quantize_uvs(std::vector<glm::vec2>{{0, 1}, {0.5f, 0.25f}});
  ASSERT_TRUE(uvs);
  EXPECT_EQ((*uvs)[0], (std::array<std::uint16_t, 2>{0, 65535}));
  EXPECT_EQ((*uvs)[1][1], 16384);
  EXPECT_FALSE(io::quantize_uvs(std::vector<glm::vec2>{{0, 1}, {1.5f, 0}}));
}

TEST(QuantizedGlb, DeclaresTheExtensionAndReadsBackWithinTheStatedErrors) {
  const Mesh mesh = grid_with_unit_uvs();
  const tinygltf::Model model = read_glb(
      io::glb_bytes(mesh, "grid", SurfaceMaterial{}, io::MaterialImages{}, {"test", io::GlbEncoding::Quantized}));
  EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"KHR_mesh_quantization"});
  EXPECT_EQ(model.extensionsRequired, std::vector<std::string>{"KHR_mesh_quantization"});
  const tinygltf::Primitive& p = model.meshes.at(0).primitives.at(0);
  const auto accessor = [&](const char* name) {
    return model.accessors.at(static_cast<std::size_t>(p.attributes.at(name)));
  };
  EXPECT_EQ(accessor("POSITION").componentType, TINYGLTF_COMPONENT_TYPE_SHORT);
  EXPECT_FALSE(accessor("POSITION").normalized);
  EXPECT_EQ(accessor("NORMAL").componentType, TINYGLTF_COMPONENT_TYPE_BYTE);
  EXPECT_TRUE(accessor("NORMAL").normalized);
  EXPECT_EQ(accessor("TEXCOORD_0").componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  EXPECT_TRUE(accessor("TEXCOORD_0").normalized);
  const double step = largest_coordinate(mesh) / 32767;
  ASSERT_EQ(model.nodes.at(0).scale, (std::vector<double>{step, step, step}));
  // The bounds are the accessor's own integers: y from 100 / step up.
  EXPECT_EQ(accessor("POSITION").maxValues.at(1), 32767.0);
  expect_within_stated_errors(model, p, mesh, step);
}

TEST(QuantizedGlb, EveryStarterSurfaceStaysWithinTheStatedErrors) {
  int surfaces = 0;
  for (const auto& file : test::starter_files()) {
    const Document doc = io::load_swp_file(file);
    const Scene scene = evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const Mesh& mesh = scene.objects[i].mesh;
      if (!is_surface(doc.objects[i].kind()) || mesh.triangle_count() == 0) continue;
      SCOPED_TRACE(file.filename().string() + " " + display_name(doc, static_cast<int>(i)));
      ++surfaces;
      const tinygltf::Model model = read_glb(
          io::glb_bytes(mesh, "s", SurfaceMaterial{}, io::MaterialImages{}, {"test", io::GlbEncoding::Quantized}));
      const double scale = model.nodes.at(0).scale.empty() ? 1.0 : model.nodes.at(0).scale.at(0);
      expect_within_stated_errors(model, model.meshes.at(0).primitives.at(0), mesh, scale);
    }
  }
  EXPECT_GT(surfaces, 10);
}

TEST(QuantizedGlb, AnimatedRidersKeepTheirAnimationsAndTheirMeshesScale) {
  const Document doc = io::parse_swp(
      "circ track 40 2\ncirc body 12 0.2\nbez3 spine 4 4\n[0 0 0]\n[0 0 0.3]\n[0 0 0.6]\n[0 0 1]\n"
      "gcyl car body spine\ncirc hoop 16 1\nsrev pole 16 hoop\nrider loop track car seconds 4\n",
      "riders.swp");
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Glb));
  const test::ScratchFolder folder("sweep-quantize");
  const std::string prefix = (folder.path() / "r").string();
  io::export_surfaces(doc, scene, "riders.swp", prefix, io::ExportFormat::Glb, io::GlbEncoding::Quantized);
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(tinygltf::TinyGLTF().LoadBinaryFromFile(&model, &error, &warning, prefix + ".glb")) << error;
  EXPECT_EQ(warning, "");
  EXPECT_EQ(model.extensionsRequired, std::vector<std::string>{"KHR_mesh_quantization"});
  ASSERT_EQ(model.animations.size(), 1u);
  for (const tinygltf::AnimationChannel& c : model.animations[0].channels) {
    EXPECT_NE(c.target_path, "scale") << "the quantization scale is never animated";
  }
  int with_mesh = 0;
  for (const tinygltf::Node& node : model.nodes) {
    if (node.mesh < 0) continue;
    ++with_mesh;
    const tinygltf::Primitive& p = model.meshes.at(static_cast<std::size_t>(node.mesh)).primitives.at(0);
    const Mesh& mesh = scene.objects[static_cast<std::size_t>(doc.find(node.name == "loop" ? "car" : node.name))].mesh;
    const double step = largest_coordinate(mesh) / 32767;
    ASSERT_EQ(node.scale, (std::vector<double>{step, step, step})) << node.name;
    expect_within_stated_errors(model, p, mesh, step);
  }
  EXPECT_EQ(with_mesh, 2);
}

}  // namespace
}  // namespace sweep
