#include "techniques/mass_spring/soft_body.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <utility>

#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"

namespace tb::mass_spring {
namespace {

using Json = nlohmann::json;

class SectionReader {
 public:
  explicit SectionReader(std::string file) : file_(std::move(file)) {}
  [[noreturn]] void fail(const std::string& field, const std::string& rule) const {
    throw mesh::InputError(file_, "mass_spring." + field, rule);
  }
  double number(const Json& object, const std::string& key, const std::string& field, double lo,
                double hi, std::optional<double> fallback = std::nullopt) const {
    if (!object.contains(key)) {
      if (fallback) return *fallback;
      fail(field, "missing; a number in [" + fmt(lo) + ", " + fmt(hi) + "]");
    }
    const Json& value = object.at(key);
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < lo ||
        value.get<double>() > hi) {
      fail(field, "must be a number in [" + fmt(lo) + ", " + fmt(hi) + "]");
    }
    return value.get<double>();
  }
  mesh::Vec3d vec3(const Json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 3) fail(field, "must be an array of 3 numbers");
    mesh::Vec3d v;
    for (int i = 0; i < 3; ++i) {
      if (!value[i].is_number() || !std::isfinite(value[i].get<double>())) {
        fail(field, "must be an array of 3 finite numbers");
      }
      v[i] = value[i].get<double>();
    }
    return v;
  }
  const Json& object(const Json& parent, const std::string& key, const std::string& field) const {
    if (!parent.contains(key) || !parent.at(key).is_object()) fail(field, "must be an object");
    return parent.at(key);
  }
  static std::string fmt(double x) {
    std::string s = std::to_string(x);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  }

 private:
  std::string file_;
};

// The closest point of segment [p, q] to x: its parameter in [0, 1].
double closestParameter(const mesh::Vec3d& p, const mesh::Vec3d& q, const mesh::Vec3d& x) {
  const mesh::Vec3d d = q - p;
  const double dd = dot(d, d);
  if (!(dd > 0)) return 0;
  return std::clamp(dot(x - p, d) / dd, 0.0, 1.0);
}

// The scenario's "mass_spring" section as a JSON object.
Json sectionOf(const techniques::Scenario& scenario, const SectionReader& read) {
  const auto section_it = scenario.sections.find("mass_spring");
  if (section_it == scenario.sections.end())
    read.fail("", "the scenario has no \"mass_spring\" section");
  Json section;
  try {
    section = Json::parse(section_it->second);
  } catch (const Json::exception& error) {
    read.fail("", std::string("is not valid JSON: ") + error.what());
  }
  if (!section.is_object()) read.fail("", "must be an object");
  return section;
}

void readSoftness(const Json& section, const SectionReader& read, SoftBodyInput& input) {
  const Json& softness = read.object(section, "softness", "softness");
  input.softness_default = read.number(softness, "default", "softness.default", 0, 1, 0.5);
  if (softness.contains("spheres")) {
    if (!softness["spheres"].is_array()) read.fail("softness.spheres", "must be an array");
    for (size_t i = 0; i < softness["spheres"].size(); ++i) {
      const std::string field = "softness.spheres[" + std::to_string(i) + "]";
      const Json& sphere = softness["spheres"][i];
      if (!sphere.is_object()) read.fail(field, "must be an object");
      SoftnessSphere s;
      if (!sphere.contains("center_m")) read.fail(field + ".center_m", "missing");
      s.center_m = read.vec3(sphere["center_m"], field + ".center_m");
      s.radius_m = read.number(sphere, "radius_m", field + ".radius_m", 1e-9, 1e9);
      s.value = read.number(sphere, "value", field + ".value", 0, 1);
      input.softness_spheres.push_back(s);
    }
  }
}

Stomp readStomp(const Json& motion, const std::string& field, const SectionReader& read,
                size_t joint_count) {
  Stomp stomp;
  if (motion.contains("direction")) {
    stomp.direction = read.vec3(motion["direction"], field + ".direction");
  }
  stomp.frequency_hz = read.number(motion, "frequency_hz", field + ".frequency_hz", 0, 1e6);
  const Json& amplitudes =
      motion.contains("joint_amplitudes_m") ? motion["joint_amplitudes_m"] : Json();
  if (!amplitudes.is_array() || amplitudes.size() != joint_count) {
    read.fail(field + ".joint_amplitudes_m",
              "must be an array of one number (metres) per joint of bone_chain_m");
  }
  for (const Json& a : amplitudes) {
    if (!a.is_number() || !std::isfinite(a.get<double>())) {
      read.fail(field + ".joint_amplitudes_m", "must hold finite numbers");
    }
    stomp.joint_amplitudes_m.push_back(a.get<double>());
  }
  return stomp;
}

Blast readBlast(const Json& motion, const std::string& field, const SectionReader& read) {
  Blast blast;
  blast.time_s = read.number(motion, "time_s", field + ".time_s", 0, 1e9);
  if (!motion.contains("center_m")) read.fail(field + ".center_m", "missing");
  blast.center_m = read.vec3(motion["center_m"], field + ".center_m");
  blast.radius_m = read.number(motion, "radius_m", field + ".radius_m", 1e-9, 1e9);
  blast.speed_m_per_s = read.number(motion, "speed_m_per_s", field + ".speed_m_per_s", 0, 1e6);
  return blast;
}

void readAnimation(const Json& section, const SectionReader& read, SoftBodyInput& input) {
  if (!section["animation"].is_array()) read.fail("animation", "must be an array of motions");
  for (size_t i = 0; i < section["animation"].size(); ++i) {
    const std::string field = "animation[" + std::to_string(i) + "]";
    const Json& motion = section["animation"][i];
    if (!motion.is_object() || !motion.contains("kind") || !motion["kind"].is_string()) {
      read.fail(field + ".kind", "must be \"stomp\" or \"blast\"");
    }
    const std::string kind = motion["kind"].get<std::string>();
    if (kind == "stomp") {
      input.stomps.push_back(readStomp(motion, field, read, input.bone_joints_m.size()));
    } else if (kind == "blast") {
      input.blasts.push_back(readBlast(motion, field, read));
    } else {
      read.fail(field + ".kind", "must be \"stomp\" or \"blast\", not \"" + kind + "\"");
    }
  }
}

}  // namespace

SoftBodyInput parseSoftBody(const techniques::Scenario& scenario) {
  const std::string file = scenario.path.empty() ? scenario.name : scenario.path;
  const SectionReader read(file);
  SoftBodyInput input;
  input.source = file;
  Json section = sectionOf(scenario, read);

  if (!section.contains("bone_chain_m") || !section["bone_chain_m"].is_array() ||
      section["bone_chain_m"].size() < 2) {
    read.fail("bone_chain_m", "must be an array of >= 2 joints [x, y, z] in metres");
  }
  for (size_t j = 0; j < section["bone_chain_m"].size(); ++j) {
    input.bone_joints_m.push_back(
        read.vec3(section["bone_chain_m"][j], "bone_chain_m[" + std::to_string(j) + "]"));
  }
  const Json& stiffness = read.object(section, "stiffness", "stiffness");
  input.surface_stiffness = read.number(stiffness, "surface", "stiffness.surface", 0, 1);
  if (!(input.surface_stiffness > 0)) read.fail("stiffness.surface", "must be a number in (0, 1]");
  input.inner_stiffness = read.number(stiffness, "inner", "stiffness.inner", 0, 1);
  input.goal_stiffness = read.number(stiffness, "goal", "stiffness.goal", 0, 1);
  if (section.contains("softness")) readSoftness(section, read, input);
  input.damping = read.number(section, "damping", "damping", 0, 0.999, 0.01);
  if (section.contains("gravity_m_per_s2")) {
    input.gravity_m_per_s2 = read.vec3(section["gravity_m_per_s2"], "gravity_m_per_s2");
  }
  if (section.contains("animation")) readAnimation(section, read, input);
  if (const auto it = scenario.parameters.find("dispatches_per_step");
      it != scenario.parameters.end()) {
    if (!(it->second >= 1 && it->second <= 4096)) {
      throw mesh::InputError(file, "parameters.dispatches_per_step", "must be in [1, 4096]");
    }
    input.dispatches_per_step = size_t(it->second);
  }
  if (scenario.mesh_path.empty()) {
    throw mesh::InputError(file, "mesh", "a mass_spring scenario needs a skin mesh");
  }
  input.skin = mesh::loadObjFile(scenario.mesh_path);
  return input;
}

SoftBodyRig::SoftBodyRig(const SoftBodyInput& input, const mesh::Vec3d& origin)
    : input_(input), origin_(origin) {
  const auto& joints = input.bone_joints_m;
  auto local = [&](const mesh::Vec3d& world) {
    return vecCast<double>(vecCast<float>(world - origin));
  };
  for (const mesh::Vec3d& x : input.skin.positions) {
    rest_.push_back(local(x));
    double best = INFINITY;
    uint32_t best_segment = 0;
    double best_u = 0;
    for (size_t s = 0; s + 1 < joints.size(); ++s) {
      const double u = closestParameter(joints[s], joints[s + 1], x);
      const mesh::Vec3d p = joints[s] + u * (joints[s + 1] - joints[s]);
      const double d = length(x - p);
      if (d < best) best = d, best_segment = uint32_t(s), best_u = u;
    }
    bone_segment_.push_back(best_segment);
    bone_parameter_.push_back(best_u);
    bone_point_.push_back(
        local(joints[best_segment] + best_u * (joints[best_segment + 1] - joints[best_segment])));
    double softness = input.softness_default;
    for (const SoftnessSphere& sphere : input.softness_spheres) {
      const double t = std::max(0.0, 1 - length(x - sphere.center_m) / sphere.radius_m);
      softness += (sphere.value - softness) * t;
    }
    softness_.push_back(softness);
  }
}

mesh::Vec3d SoftBodyRig::stompAmplitude(size_t v, size_t s) const {
  const Stomp& stomp = input_.stomps[s];
  const uint32_t segment = bone_segment_[v];
  const double u = bone_parameter_[v];
  const double amplitude =
      (1 - u) * stomp.joint_amplitudes_m[segment] + u * stomp.joint_amplitudes_m[segment + 1];
  return amplitude * stomp.direction;
}

SpringSystem buildSpringSystem(const SoftBodyInput& input, const SoftBodyRig& rig,
                               bool goal_springs) {
  SpringSystem system;
  const size_t n = rig.vertexCount();
  system.vertex_count = n;
  system.anchor_count = 2 * n;
  const std::vector<mesh::Vec3d>& rest = rig.restPositions();
  std::map<std::pair<uint32_t, uint32_t>, bool> seen;
  double total_length = 0;
  for (size_t f = 0; f < input.skin.faceCount(); ++f) {
    const auto face = input.skin.facePositions(f);
    for (size_t k = 0; k < face.size(); ++k) {
      const uint32_t a = face[k], b = face[(k + 1) % face.size()];
      if (a == b || !seen.emplace(std::minmax(a, b), true).second) continue;
      const double length_m = length(rest[b] - rest[a]);
      if (!(length_m > 0)) {
        throw mesh::InputError(input.skin.source, mesh::describeFace(input.skin, f),
                               "an edge of zero length cannot be a spring");
      }
      system.springs.push_back(
          {a, b, length_m, 0.5 * input.surface_stiffness, SpringKind::kSurface});
      total_length += length_m;
    }
  }
  if (system.springs.empty()) {
    throw mesh::InputError(input.skin.source, "mesh", "has no edges to make surface springs of");
  }
  system.length_scale_m = total_length / double(system.springs.size());
  if (input.inner_stiffness > 0) {
    for (uint32_t v = 0; v < n; ++v) {
      system.springs.push_back({v, kAnchorBit | v, length(rest[v] - rig.restBonePoint(v)),
                                input.inner_stiffness, SpringKind::kInner});
    }
  }
  if (goal_springs) {
    for (uint32_t v = 0; v < n; ++v) {
      const double weight = (1 - rig.softness()[v]) * input.goal_stiffness;
      if (weight > 0) {
        system.springs.push_back({v, kAnchorBit | uint32_t(n + v), 0, weight, SpringKind::kGoal});
      }
    }
  }
  buildSolverTables(system);
  return system;
}

}  // namespace tb::mass_spring
