#include "snapshot/sidecar.hpp"

#include "snapshot/capped_read.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace sweep::snapshot {
namespace {

using nlohmann::json;

constexpr std::uintmax_t kMaxSidecarBytes = 64u << 20;

json vec3(const glm::dvec3& v) {
  return json::array({v.x, v.y, v.z});
}

glm::dvec3 vec3_from(const json& j, const char* field) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number()) {
    throw SidecarError(std::string("expected ") + field + " as [x, y, z]");
  }
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

json camera_json(const render::Camera& c) {
  return {{"orientation", {c.orientation.w, c.orientation.x, c.orientation.y, c.orientation.z}},
          {"target", vec3(c.target)},
          {"distance", c.distance},
          {"scene_radius", c.scene_radius},
          {"vertical_fov", c.vertical_fov},
          {"projection", c.projection == render::Projection::Orthographic ? "orthographic" : "perspective"}};
}

render::Camera camera_from(const json& j) {
  render::Camera c;
  const json& q = j.at("orientation");
  if (!q.is_array() || q.size() != 4) throw SidecarError("expected camera.orientation as [w, x, y, z]");
  c.orientation =
      glm::normalize(glm::dquat(q[0].get<double>(), q[1].get<double>(), q[2].get<double>(), q[3].get<double>()));
  c.target = vec3_from(j.at("target"), "camera.target");
  c.distance = j.at("distance").get<double>();
  c.scene_radius = j.at("scene_radius").get<double>();
  c.vertical_fov = j.at("vertical_fov").get<double>();
  c.projection = j.at("projection").get<std::string>() == "orthographic" ? render::Projection::Orthographic
                                                                         : render::Projection::Perspective;
  if (!(c.distance > 0.0) || !(c.scene_radius > 0.0) || !(c.vertical_fov > 0.0)) {
    throw SidecarError("expected a camera with positive distance, scene radius and field of view");
  }
  return c;
}

json object_json(const Fingerprint& f) {
  json samples = json::array();
  for (const glm::dvec3& p : f.samples) samples.push_back(vec3(p));
  char hash[20];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(f.hash));
  return {{"name", f.name},
          {"kind", f.kind},
          {"surface", f.surface},
          {"vertices", f.vertices},
          {"triangles", f.triangles},
          {"box_min", vec3(f.box_min)},
          {"box_max", vec3(f.box_max)},
          {"centroid", vec3(f.centroid)},
          {"hash", hash},
          {"material", f.material},
          {"coverage", f.coverage},
          {"samples", samples}};
}

Fingerprint object_from(const json& j) {
  Fingerprint f;
  f.name = j.at("name").get<std::string>();
  f.kind = j.at("kind").get<std::string>();
  f.surface = j.at("surface").get<bool>();
  f.vertices = j.at("vertices").get<std::size_t>();
  f.triangles = j.at("triangles").get<std::size_t>();
  f.box_min = vec3_from(j.at("box_min"), "box_min");
  f.box_max = vec3_from(j.at("box_max"), "box_max");
  f.centroid = vec3_from(j.at("centroid"), "centroid");
  f.hash = std::stoull(j.at("hash").get<std::string>(), nullptr, 16);
  f.material = j.at("material").get<std::string>();
  f.coverage = j.at("coverage").get<std::size_t>();
  for (const json& p : j.at("samples")) f.samples.push_back(vec3_from(p, "a sample point"));
  return f;
}

/// [id, count, id, count, ...] over the pixels in row order.
json runs_json(const IdMap& ids) {
  json runs = json::array();
  std::size_t i = 0;
  while (i < ids.ids.size()) {
    std::size_t j = i;
    while (j < ids.ids.size() && ids.ids[j] == ids.ids[i]) ++j;
    runs.push_back(ids.ids[i]);
    runs.push_back(j - i);
    i = j;
  }
  return runs;
}

IdMap ids_from(const json& j, std::size_t objects) {
  IdMap ids;
  ids.width = j.at("width").get<int>();
  ids.height = j.at("height").get<int>();
  if (ids.width < 1 || ids.height < 1 || ids.width > 16384 || ids.height > 16384) {
    throw SidecarError("expected ids.width and ids.height in 1..16384");
  }
  const std::size_t total = std::size_t(ids.width) * std::size_t(ids.height);
  const json& runs = j.at("runs");
  if (!runs.is_array() || runs.size() % 2 != 0) throw SidecarError("expected ids.runs as [id, count, ...]");
  ids.ids.reserve(total);
  for (std::size_t r = 0; r < runs.size(); r += 2) {
    const auto id = runs[r].get<std::size_t>();
    const auto count = runs[r + 1].get<std::size_t>();
    if (id > objects || count > total - ids.ids.size())
      throw SidecarError("expected ids.runs within the objects and pixels");
    ids.ids.insert(ids.ids.end(), count, static_cast<std::uint16_t>(id));
  }
  if (ids.ids.size() != total) throw SidecarError("expected ids.runs to cover every pixel");
  return ids;
}

/// The value among `values` that JSON string `j` names; "unknown NAME 'x'" for another.
template <typename Enum, std::size_t N>
Enum named_in(const std::array<Enum, N>& values, const json& j, const char* what) {
  const std::string text = j.get<std::string>();
  if (const std::optional<Enum> value = named(values, text)) return *value;
  throw SidecarError(std::string("unexpected content: unknown ") + what + " '" + text + "'");
}

}  // namespace

Sidecar make_sidecar(const CaseSpec& spec, const std::string& renderer, const render::Camera& camera,
                     std::vector<Fingerprint> objects, IdMap ids) {
  Sidecar s;
  s.sweep_version = SWEEP_VERSION;
  s.renderer = renderer;
  s.mode = spec.mode;
  s.setup = spec;
  s.camera = camera;
  s.objects = std::move(objects);
  s.ids = std::move(ids);
  return s;
}

std::string sidecar_json(const Sidecar& s) {
  const CaseSetup& setup = s.setup;
  json view = {{"name", name_of(setup.view.name)}};
  if (setup.view.yaw) view["yaw"] = *setup.view.yaw;
  if (setup.view.pitch) view["pitch"] = *setup.view.pitch;
  if (setup.view.distance) view["distance"] = *setup.view.distance;
  json objects = json::array();
  for (const Fingerprint& f : s.objects) objects.push_back(object_json(f));
  const json out = {{"sweep", s.sweep_version},
                    {"renderer", s.renderer},
                    {"options",
                     {{"mode", name_of(s.mode)},
                      {"color", name_of(setup.color)},
                      {"size", {setup.size.x, setup.size.y}},
                      {"tolerance", setup.tolerance},
                      {"frames", name_of(setup.frames)},
                      {"seam", name_of(setup.seam)},
                      {"time", setup.time},
                      {"view", view}}},
                    {"camera", camera_json(s.camera)},
                    {"objects", objects},
                    {"ids", {{"width", s.ids.width}, {"height", s.ids.height}, {"runs", runs_json(s.ids)}}}};
  return out.dump(1) + "\n";
}

Sidecar parse_sidecar(const std::string& text) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw SidecarError("not JSON");
  try {
    Sidecar s;
    s.sweep_version = j.at("sweep").get<std::string>();
    s.renderer = j.at("renderer").get<std::string>();
    const json& o = j.at("options");
    s.mode = named_in(kEveryMode, o.at("mode"), "mode");
    CaseSetup& setup = s.setup;
    setup.color = named_in(render::kColorModes, o.at("color"), "color");
    setup.size = {o.at("size").at(0).get<int>(), o.at("size").at(1).get<int>()};
    setup.tolerance = o.at("tolerance").get<double>();
    setup.frames = named_in(kEveryFrames, o.at("frames"), "frames");
    setup.seam = named_in(kEverySeam, o.at("seam"), "seam");
    setup.time = o.at("time").get<double>();
    const json& v = o.at("view");
    setup.view.name = named_in(kEveryView, v.at("name"), "view");
    if (v.contains("yaw")) setup.view.yaw = v["yaw"].get<double>();
    if (v.contains("pitch")) setup.view.pitch = v["pitch"].get<double>();
    if (v.contains("distance")) setup.view.distance = v["distance"].get<double>();
    s.camera = camera_from(j.at("camera"));
    for (const json& f : j.at("objects")) s.objects.push_back(object_from(f));
    s.ids = ids_from(j.at("ids"), s.objects.size());
    return s;
  } catch (const SidecarError&) {
    throw;
  } catch (const std::exception& e) {  // a missing field or a wrong type
    throw SidecarError(std::string("unexpected content: ") + e.what());
  }
}

Sidecar read_sidecar(const std::filesystem::path& file) {
  std::string text;
  try {
    text = read_capped(file, kMaxSidecarBytes, "a sidecar");
  } catch (const std::runtime_error& e) {
    throw SidecarError(e.what());
  }
  try {
    return parse_sidecar(text);
  } catch (const SidecarError& e) {
    throw SidecarError(file.string() + ": " + e.what());
  }
}

bool same_setup(const Sidecar& a, const Sidecar& b) {
  // The camera as read back: its orientation is normalized on reading, so a sidecar written from
  // a camera that was read compares within rounding, not bit for bit.
  const auto close = [](double x, double y) {
    return std::abs(x - y) <= 1e-9 * std::max({1.0, std::abs(x), std::abs(y)});
  };
  const render::Camera& p = a.camera;
  const render::Camera& q = b.camera;
  bool same_camera = p.projection == q.projection && close(p.distance, q.distance) &&
                     close(p.scene_radius, q.scene_radius) && close(p.vertical_fov, q.vertical_fov);
  for (int i = 0; i < 4; ++i) same_camera = same_camera && close(p.orientation[i], q.orientation[i]);
  for (int i = 0; i < 3; ++i) same_camera = same_camera && close(p.target[i], q.target[i]);
  for (int i = 0; i < 2; ++i) same_camera = same_camera && close(p.lens_shift[i], q.lens_shift[i]);
  return same_camera && a.mode == b.mode && a.setup == b.setup;
}

}  // namespace sweep::snapshot
