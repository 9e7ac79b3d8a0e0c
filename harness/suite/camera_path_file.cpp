// Reading a camera path file (JSON) into a CameraPathSpec: every field's type, range and
// finiteness, each broken rule one InputError naming the file and the field. The format is
// in docs/FORMATS.md, "Camera path files"; the geometric rules (a camera at every keyframe and
// sampled frame) are checked by sampling the path once (camera_path_sampling.cpp).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "harness/suite/camera_path.h"

namespace tb::suite {
namespace {

using Json = nlohmann::json;

// Caps that keep a file's numbers sane: pixels per side, and the views one path may hold.
constexpr uint64_t kMaxPixels = 65536;
constexpr uint64_t kMaxFrames = 100000;

// A key as a message names it: as written, or JSON-quoted and escaped when it holds a
// control character ("a\nb" from a file's "a\u000ab"), so the message stays one line.
std::string shownKey(const std::string& key) {
  for (unsigned char c : key) {
    if (c < 0x20) return Json(key).dump();
  }
  return key;
}

// Reads the fields of one file; every error names the file (`shown`) and the field.
class FieldReader {
 public:
  explicit FieldReader(const std::string& shown) : shown_(shown) {}

  [[noreturn]] void fail(const std::string& field, const std::string& rule) const {
    throw mesh::InputError(shown_, field, rule);
  }

  // Refuses keys other than `known` (a misspelt optional field would be silently ignored).
  void onlyKnownKeys(const Json& object, const std::string& where,
                     std::initializer_list<const char*> known) const {
    for (const auto& item : object.items()) {
      bool found = false;
      std::string names;
      for (const char* key : known) {
        found |= item.key() == key;
        names += (names.empty() ? "" : ", ") + std::string(key);
      }
      if (!found) fail(where + shownKey(item.key()), "unknown field (known: " + names + ")");
    }
  }

  const Json& required(const Json& object, const std::string& where, const char* key) const {
    if (!object.contains(key)) fail(where + key, "missing");
    return object.at(key);
  }

  double number(const Json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number, got " + typeOf(value));
    const double number = value.get<double>();
    // JSON has no NaN or infinity, and parseFile refuses a literal beyond double's range
    // (1e999) naming its field; a parser that reads one as infinity is refused here.
    if (!std::isfinite(number)) fail(field, "not a finite number");
    return number;
  }

  uint32_t wholeNumber(const Json& value, const std::string& field, uint64_t max) const {
    const std::string range = "a whole number in 1.." + std::to_string(max);
    if (value.is_number_unsigned()) {
      const uint64_t n = value.get<uint64_t>();
      if (n >= 1 && n <= max) return uint32_t(n);
      fail(field, std::to_string(n) + " is out of range (expected " + range + ")");
    }
    if (value.is_number_integer()) {  // negative
      fail(field,
           std::to_string(value.get<int64_t>()) + " is out of range (expected " + range + ")");
    }
    fail(field, "expected " + range + ", got " + typeOf(value));
  }

  mesh::Vec3d vec3(const Json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 3) fail(field, "expected [x, y, z]");
    mesh::Vec3d v;
    for (int i = 0; i < 3; ++i)
      v[i] = number(value[size_t(i)], field + "[" + std::to_string(i) + "]");
    return v;
  }

 private:
  static std::string typeOf(const Json& value) {
    if (value.is_number_float()) return "a number with a fraction or exponent";
    return value.type_name();
  }
  const std::string& shown_;
};

// Follows a SAX pass over the text to where it stops, as a field path
// ("keyframes[0].eye[1]"). JSON has no NaN or infinity; a literal beyond double's range
// (1e999) is how a file writes one, and the parser refuses it without naming the field.
class FieldPathTracker final : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& key) override {
    frames_.back().key = key;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const Json::exception& error) override {
    error_id_ = error.id;
    return false;
  }

  // The number overflowed (nlohmann's out_of_range.406).
  bool overflowed() const { return error_id_ == 406; }
  std::string path() const {
    std::string text;
    for (const Frame& frame : frames_) {
      text += frame.array ? "[" + std::to_string(frame.index) + "]"
                          : (text.empty() ? "" : ".") + shownKey(frame.key);
    }
    return text;
  }

 private:
  struct Frame {
    bool array = false;
    size_t index = 0;  // of the element being read, in an array
    std::string key;   // of the member being read, in an object
  };
  bool open(bool array) {
    frames_.push_back({array, 0, ""});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }
  bool value() {  // a value ended: an array moves on to its next element
    if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    return true;
  }
  std::vector<Frame> frames_;
  int error_id_ = 0;
};

Json parseFile(const std::string& file, const std::string& shown) {
  if (!std::filesystem::is_regular_file(file)) throw mesh::InputError(shown, "", "no such file");
  std::ifstream stream(file);
  if (!stream) throw mesh::InputError(shown, "", "cannot be read");
  const std::string text{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  try {
    return Json::parse(text);
  } catch (const Json::exception& error) {
    FieldPathTracker tracker;
    Json::sax_parse(text, &tracker);
    if (tracker.overflowed()) throw mesh::InputError(shown, tracker.path(), "not a finite number");
    // "[json.exception.parse_error.101] parse error at line 2, column 5: ...": one line,
    // without the library's prefix.
    std::string what = error.what();
    if (const size_t end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
    for (char& c : what) c = (c == '\n' || c == '\r') ? ' ' : c;
    throw mesh::InputError(shown, "", "malformed JSON: " + what);
  }
}

void readResolution(const FieldReader& reader, const Json& json, CameraPathSpec* spec) {
  if (!json.contains("resolution")) return;
  const Json& resolution = json.at("resolution");
  if (!resolution.is_array() || resolution.size() != 2) {
    reader.fail("resolution", "expected [width, height] in pixels");
  }
  spec->width_px = reader.wholeNumber(resolution[0], "resolution[0]", kMaxPixels);
  spec->height_px = reader.wholeNumber(resolution[1], "resolution[1]", kMaxPixels);
}

void readPlanes(const FieldReader& reader, const Json& json, CameraPathSpec* spec) {
  spec->near_plane = reader.number(reader.required(json, "", "near"), "near");
  if (!(spec->near_plane > 0)) reader.fail("near", "must be > 0");
  spec->far_plane = reader.number(reader.required(json, "", "far"), "far");
  if (!(spec->far_plane > spec->near_plane)) reader.fail("far", "must be > near");
}

void readKeyframes(const FieldReader& reader, const Json& json, CameraPathSpec* spec) {
  const Json& keyframes = reader.required(json, "", "keyframes");
  if (!keyframes.is_array() || keyframes.empty()) {
    reader.fail("keyframes", "expected an array of at least one keyframe");
  }
  for (size_t k = 0; k < keyframes.size(); ++k) {
    const std::string where = "keyframes[" + std::to_string(k) + "].";
    const Json& key = keyframes[k];
    if (!key.is_object()) reader.fail(where.substr(0, where.size() - 1), "expected an object");
    reader.onlyKnownKeys(key, where, {"eye", "target", "up"});
    CameraKeyframe keyframe;
    keyframe.eye = reader.vec3(reader.required(key, where, "eye"), where + "eye");
    keyframe.target = reader.vec3(reader.required(key, where, "target"), where + "target");
    keyframe.up = reader.vec3(reader.required(key, where, "up"), where + "up");
    spec->keyframes.push_back(keyframe);
  }
}

}  // namespace

CameraPathSpec loadCameraPath(const std::string& file, const std::string& shown_path) {
  const Json json = parseFile(file, shown_path);
  const FieldReader reader(shown_path);
  if (!json.is_object()) reader.fail("", "expected a JSON object");
  reader.onlyKnownKeys(json, "",
                       {"name", "resolution", "fov_y_deg", "frames", "space", "near", "far",
                        "target_pixels_per_edge", "keyframes"});
  CameraPathSpec spec;
  spec.shown_path = shown_path;
  spec.name = std::filesystem::path(file).stem().string();
  if (json.contains("name")) {
    const Json& name = json.at("name");
    if (!name.is_string() || name.get<std::string>().empty()) {
      reader.fail("name", "expected a non-empty string");
    }
    spec.name = name.get<std::string>();
  }
  readResolution(reader, json, &spec);
  spec.fov_y_deg = reader.number(reader.required(json, "", "fov_y_deg"), "fov_y_deg");
  if (!(spec.fov_y_deg > 0 && spec.fov_y_deg < 180)) {
    reader.fail("fov_y_deg", "must be in (0, 180) degrees");
  }
  spec.frames = reader.wholeNumber(reader.required(json, "", "frames"), "frames", kMaxFrames);
  const Json& space = reader.required(json, "", "space");
  if (space != "bounds" && space != "world") {
    reader.fail("space", "expected \"bounds\" or \"world\", got " + space.dump());
  }
  spec.bounds_space = space == "bounds";
  readPlanes(reader, json, &spec);
  if (json.contains("target_pixels_per_edge")) {
    spec.target_pixels_per_edge =
        reader.number(json.at("target_pixels_per_edge"), "target_pixels_per_edge");
    if (!(spec.target_pixels_per_edge > 0)) reader.fail("target_pixels_per_edge", "must be > 0");
  }
  readKeyframes(reader, json, &spec);
  // The geometric rules: a camera at every keyframe and every frame (around a unit box;
  // the box moves and scales a path, never turns it, so any box gives the same verdict).
  sampleCameraPath(spec, mesh::Aabb{{-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}});
  return spec;
}

}  // namespace tb::suite
