#include "techniques/wave_particles/wave_scene.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/mesh/input_error.h"
#include "techniques/technique.h"

namespace tb::wave_particles {
namespace {

using Json = nlohmann::json;

class Reader {
 public:
  explicit Reader(const techniques::Scenario& scenario)
      : scenario_(scenario), file_(scenario.path.empty() ? scenario.name : scenario.path) {}

  [[noreturn]] void fail(const std::string& field, const std::string& rule) const {
    throw mesh::InputError(file_, field, rule);
  }
  double parameter(const char* name, double fallback, bool required = false) const {
    auto found = scenario_.parameters.find(name);
    if (found == scenario_.parameters.end()) {
      if (required) fail(std::string("parameters.") + name, "missing");
      return fallback;
    }
    return found->second;
  }
  double positive(const char* name, double fallback, bool required = false) const {
    const double value = parameter(name, fallback, required);
    if (!(value > 0)) fail(std::string("parameters.") + name, "must be > 0");
    return value;
  }
  uint32_t count(const char* name, uint32_t fallback) const {
    const double value = parameter(name, fallback);
    if (!(value >= 1 && value <= 1e7 && std::trunc(value) == value)) {
      fail(std::string("parameters.") + name, "expected a whole number in 1..10000000");
    }
    return uint32_t(value);
  }
  double number(const Json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) fail(field, "not a finite number");
    return number;
  }
  Point2 point(const Json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 2) fail(field, "expected [x, y] in metres");
    return {number(value[0], field + "[0]"), number(value[1], field + "[1]")};
  }
  const Json& member(const Json& object, const std::string& where, const char* key) const {
    if (!object.is_object()) fail(where, "expected an object");
    if (!object.contains(key)) fail(where + "." + key, "missing");
    return object.at(key);
  }
  const std::string& file() const { return file_; }

 private:
  const techniques::Scenario& scenario_;
  std::string file_;
};

}  // namespace

double WaveScene::maxAmplitude() const {
  double peak = 0;
  for (const WaveSource& source : sources) peak = std::max(peak, std::abs(source.amplitude_m));
  return peak;
}

std::vector<WaveWall> WaveScene::allWalls() const {
  std::vector<WaveWall> all = walls;
  const double h = domain_size_m / 2;
  all.push_back({{-h, -h}, {h, -h}});
  all.push_back({{h, -h}, {h, h}});
  all.push_back({{h, h}, {-h, h}});
  all.push_back({{-h, h}, {-h, -h}});
  return all;
}

WaveScene parseWaveScene(const techniques::Scenario& scenario) {
  const Reader reader(scenario);
  auto section = scenario.sections.find("wave_particles");
  if (section == scenario.sections.end()) {
    throw techniques::UnsupportedInput("wave_particles: scenario " + scenario.name +
                                       " has no \"wave_particles\" section");
  }
  const Json json = Json::parse(section->second);  // written by the loader: valid JSON
  WaveScene scene;
  scene.domain_size_m = reader.positive("domain_size_m", 0, true);
  scene.wave_speed_m_per_s = reader.positive("wave_speed_m_per_s", 0, true);
  scene.particle_radius_m = reader.positive("particle_radius_m", 0.25);
  scene.particles_per_source = reader.count("particles_per_source", 32);
  scene.particle_lifetime_s = reader.positive("particle_lifetime_s", scenario.duration_s);
  scene.damping_per_s = reader.parameter("damping_per_s", 0);
  if (!(scene.damping_per_s >= 0)) reader.fail("parameters.damping_per_s", "must be >= 0");
  scene.height_field_spacing_m = reader.positive("height_field_spacing_m", 0.05);
  scene.reference_spacing_m = reader.positive("reference_spacing_m", 0.025);
  if (scene.domain_size_m / scene.reference_spacing_m > 4096 ||
      scene.domain_size_m / scene.height_field_spacing_m > 4096) {
    reader.fail("parameters.reference_spacing_m", "more than 4096 nodes a side");
  }
  const double half = scene.domain_size_m / 2;
  auto inside = [&](const Point2& p) { return std::abs(p[0]) < half && std::abs(p[1]) < half; };
  const std::string where = "wave_particles";
  const Json& sources = reader.member(json, where, "sources");
  if (!sources.is_array() || sources.empty())
    reader.fail(where + ".sources", "expected a non-empty array");
  for (size_t i = 0; i < sources.size(); ++i) {
    const std::string field = where + ".sources[" + std::to_string(i) + "]";
    WaveSource source;
    source.position_m =
        reader.point(reader.member(sources[i], field, "position_m"), field + ".position_m");
    if (!inside(source.position_m)) reader.fail(field + ".position_m", "outside the domain");
    source.amplitude_m =
        reader.number(reader.member(sources[i], field, "amplitude_m"), field + ".amplitude_m");
    if (sources[i].contains("time_s")) {
      source.time_s = reader.number(sources[i].at("time_s"), field + ".time_s");
      if (source.time_s < 0 || source.time_s > scenario.duration_s) {
        reader.fail(field + ".time_s", "outside 0..duration_s");
      }
    }
    if (sources[i].contains("velocity_m_per_s")) {
      throw techniques::UnsupportedInput("wave_particles: " + reader.file() + ": " + field +
                                         ".velocity_m_per_s: moving sources are not supported");
    }
    scene.sources.push_back(source);
  }
  if (json.contains("walls")) {
    const Json& walls = json.at("walls");
    if (!walls.is_array()) reader.fail(where + ".walls", "expected an array");
    for (size_t i = 0; i < walls.size(); ++i) {
      const std::string field = where + ".walls[" + std::to_string(i) + "]";
      WaveWall wall;
      wall.from_m = reader.point(reader.member(walls[i], field, "from_m"), field + ".from_m");
      wall.to_m = reader.point(reader.member(walls[i], field, "to_m"), field + ".to_m");
      if (wall.from_m == wall.to_m) reader.fail(field, "has zero length");
      scene.walls.push_back(wall);
    }
  }
  if (json.contains("probes_m")) {
    const Json& probes = json.at("probes_m");
    if (!probes.is_array()) reader.fail(where + ".probes_m", "expected an array of [x, y]");
    for (size_t i = 0; i < probes.size(); ++i) {
      const std::string field = where + ".probes_m[" + std::to_string(i) + "]";
      const Point2 probe = reader.point(probes[i], field);
      if (!inside(probe)) reader.fail(field, "outside the domain");
      scene.probes_m.push_back(probe);
    }
  }
  const double fallback_max = double(scene.particles_per_source) * double(scene.sources.size());
  scene.max_particles = reader.count("max_particles", uint32_t(std::min(fallback_max, 1e7)));
  return scene;
}

}  // namespace tb::wave_particles
