// Camera path files: the bundled paths sampled around a box, and every class of bad input.
// Oracles: the paths' closed forms (a circle of radius 2 diagonals about the box centre, a
// geometric series of distances), the projection of the target to the viewport centre,
// and the near plane's depth 0 in Vulkan clip space.
#include "harness/suite/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// Not a cube, not at the origin: both the centre and the diagonal matter.
const mesh::Aabb kBox{{-1, -2, -3}, {3, 2, 1}};
const mesh::Vec3d kCentre{1, 0, -1};
const double kDiagonal = std::sqrt(48.0);

mesh::Vec3d eyeOf(const view::View& view) { return {view.eye[0], view.eye[1], view.eye[2]}; }

// The camera's forward axis (unit): clip w = dot(forward, p - eye) under lookAt and a
// perspective projection, so the matrix's w row is forward.
mesh::Vec3d forwardOf(const view::View& view) {
  const view::Mat4& m = view.view_projection;
  return {m.m[0][3], m.m[1][3], m.m[2][3]};
}

bool inside(const mesh::Aabb& box, const mesh::Vec3d& p) {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < box.min[i] || p[i] > box.max[i]) return false;
  }
  return true;
}

TEST(CameraPath, BundledPathsAreOrbitDollyAndFlybyNamedRelativeToTheAssetsFolder) {
  EXPECT_EQ(suite::bundledCameraPaths(), (std::vector<std::string>{"dolly", "flyby", "orbit"}));
  const suite::CameraPathSpec orbit = suite::resolveCameraPath("orbit");
  EXPECT_EQ(orbit.name, "orbit");
  EXPECT_EQ(orbit.shown_path, "assets/cameras/orbit.json");
  EXPECT_EQ(orbit.frames, 24u);
  EXPECT_EQ(orbit.keyframes.size(), 5u);
  EXPECT_EQ(suite::resolveCameraPath("dolly").frames, 120u);
  EXPECT_EQ(suite::resolveCameraPath("flyby").frames, 48u);
  EXPECT_THROW(suite::resolveCameraPath("not_a_camera_path"), mesh::InputError);
  // A path given as a file is named as given.
  const std::string file = testing::assetPath("cameras/dolly.json");
  EXPECT_EQ(suite::resolveCameraPath(file).shown_path, file);
}

TEST(CameraPath, OrbitFramesAreAllTwoDiagonalsFromTheCentre) {
  const view::CameraPath path = suite::sampleCameraPath(suite::resolveCameraPath("orbit"), kBox);
  EXPECT_EQ(path.name, "orbit");
  ASSERT_EQ(path.views.size(), 24u);
  for (const view::View& view : path.views) {
    EXPECT_NEAR(mesh::length(eyeOf(view) - kCentre) / kDiagonal, 2, 2e-9);
    // A horizontal circle 0.25 diagonals above the centre.
    EXPECT_NEAR(view.eye[1], kCentre.y + 0.25 * kDiagonal, 1e-12 * kDiagonal);
  }
  // The path closes: 360 degrees is 0 degrees.
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(path.views.front().eye[size_t(i)], path.views.back().eye[size_t(i)],
                1e-12 * kDiagonal);
  }
}

TEST(CameraPath, OrbitFramesAt45And90DegreesAreOnTheCircle) {
  // 9 frames: every 45 degrees, so frame 2 is keyframe 1 and frame 1 is halfway (slerp).
  const view::CameraPath path = suite::sampleCameraPath(suite::resolveCameraPath("orbit"), kBox, 9);
  ASSERT_EQ(path.views.size(), 9u);
  const double radius = std::sqrt(3.9375);  // horizontal radius: sqrt(2^2 - 0.25^2) diagonals
  const mesh::Vec3d at_90 = kCentre + kDiagonal * mesh::Vec3d{radius, 0.25, 0};
  const mesh::Vec3d at_45 =
      kCentre + kDiagonal * mesh::Vec3d{radius * std::sqrt(0.5), 0.25, radius * std::sqrt(0.5)};
  EXPECT_LT(mesh::length(eyeOf(path.views[2]) - at_90), 1e-12 * kDiagonal);
  EXPECT_LT(mesh::length(eyeOf(path.views[1]) - at_45), 1e-12 * kDiagonal);
}

TEST(CameraPath, DollyDistancesAreGeometric) {
  const view::CameraPath path = suite::sampleCameraPath(suite::resolveCameraPath("dolly"), kBox);
  ASSERT_EQ(path.views.size(), 120u);
  std::vector<double> distances;
  for (const view::View& view : path.views)
    distances.push_back(mesh::length(eyeOf(view) - kCentre));
  EXPECT_NEAR(distances.front() / kDiagonal, 20, 1e-12);
  EXPECT_NEAR(distances.back() / kDiagonal, 0.3, 1e-12);
  const double ratio = std::pow(0.3 / 20, 1.0 / 119);  // about 0.965: 3.5 % closer a frame
  for (size_t i = 1; i < distances.size(); ++i) {
    EXPECT_NEAR(distances[i] / distances[i - 1], ratio, 1e-12) << i;
  }
  // One direction all along.
  const mesh::Vec3d first = mesh::normalize(eyeOf(path.views.front()) - kCentre);
  EXPECT_LT(mesh::length(mesh::normalize(eyeOf(path.views.back()) - kCentre) - first), 1e-12);
}

TEST(CameraPath, FlybyNearPlaneEntersTheBoundingBox) {
  const mesh::Aabb cube{{-1, -1, -1}, {1, 1, 1}};
  const view::CameraPath path = suite::sampleCameraPath(suite::resolveCameraPath("flyby"), cube);
  ASSERT_EQ(path.views.size(), 48u);
  size_t frames_inside = 0;
  for (const view::View& view : path.views) {
    const mesh::Vec3d near_point = eyeOf(view) + view.near_plane * forwardOf(view);
    // The point is on the near plane: clip depth 0 (Vulkan depth in [0, 1]).
    const auto clip = view.view_projection.transform({near_point.x, near_point.y, near_point.z, 1});
    EXPECT_NEAR(clip[2] / clip[3], 0, 1e-9);
    frames_inside += inside(cube, near_point);
  }
  EXPECT_GT(frames_inside, 0u);
  EXPECT_FALSE(inside(cube, eyeOf(path.views.front())));  // it starts and ends outside
  EXPECT_FALSE(inside(cube, eyeOf(path.views.back())));
}

TEST(CameraPath, TheTargetProjectsToTheViewportCentreOnEveryFrame) {
  const suite::CameraPathSpec orbit = suite::resolveCameraPath("orbit");
  const view::CameraPath path = suite::sampleCameraPath(orbit, kBox);
  const mesh::Vec3d target = kCentre + kDiagonal * mesh::Vec3d{0, 0.25, 0};
  for (const view::View& view : path.views) {
    const view::ProjectedPoint p = view::projectToPixels(view, target.x, target.y, target.z);
    EXPECT_GT(p.clip_w, 0);
    EXPECT_NEAR(p.x_px, 960, 1e-6);
    EXPECT_NEAR(p.y_px, 540, 1e-6);
    EXPECT_EQ(view.viewport_width_px, 1920u);
    EXPECT_EQ(view.viewport_height_px, 1080u);
    EXPECT_EQ(view.target_pixels_per_edge, 8);
    EXPECT_NEAR(view.projection_y_scale, 1 / std::tan(22.5 * std::numbers::pi / 180), 1e-15);
    EXPECT_NEAR(view.near_plane, 0.01 * kDiagonal, 1e-15);
  }
}

// A world-space path of one keyframe, written out: every frame the same view, in world
// units whatever the box.
TEST(CameraPath, WorldSpaceAndASingleKeyframe) {
  const auto dir = testing::scratchDirectory("camera_world");
  const std::string file = testing::writeTextFile(
      dir / "still.json",
      R"({"resolution": [640, 480], "fov_y_deg": 60, "frames": 3, "space": "world",
          "near": 0.5, "far": 50, "target_pixels_per_edge": 4,
          "keyframes": [{"eye": [0, 0, 10], "target": [1, 2, 3], "up": [0, 1, 0]}]})");
  const suite::CameraPathSpec spec = suite::loadCameraPath(file, "still.json");
  EXPECT_EQ(spec.name, "still");  // the file's stem
  EXPECT_FALSE(spec.bounds_space);
  const view::CameraPath path = suite::sampleCameraPath(spec, kBox);
  ASSERT_EQ(path.views.size(), 3u);
  for (const view::View& view : path.views) {
    EXPECT_EQ(view.view_projection, path.views[0].view_projection);
    EXPECT_EQ(eyeOf(view), (mesh::Vec3d{0, 0, 10}));
    EXPECT_EQ(view.near_plane, 0.5);
    EXPECT_EQ(view.target_pixels_per_edge, 4);
    const view::ProjectedPoint p = view::projectToPixels(view, 1, 2, 3);
    EXPECT_NEAR(p.x_px, 320, 1e-9);
    EXPECT_NEAR(p.y_px, 240, 1e-9);
  }
  EXPECT_EQ(suite::sampleCameraPath(spec, kBox, 7).views.size(), 7u);  // frames_override
}

using Fields = std::vector<std::pair<std::string, std::string>>;

// A valid file with fields replaced (or removed where the value is empty) or added.
std::string pathWithAll(const Fields& changes) {
  Fields fields = {{"name", R"("test")"},
                   {"resolution", "[1920, 1080]"},
                   {"fov_y_deg", "45"},
                   {"frames", "5"},
                   {"space", R"("bounds")"},
                   {"near", "0.01"},
                   {"far", "100"},
                   {"target_pixels_per_edge", "8"},
                   {"keyframes", R"([{"eye": [2, 0.5, 0], "target": [0, 0, 0], "up": [0, 1, 0]},
                        {"eye": [0, 0.5, 2], "target": [0, 0, 0], "up": [0, 1, 0]}])"}};
  for (const auto& [field, value] : changes) {
    bool replaced = false;
    for (auto& [key, json] : fields) {
      if (key != field) continue;
      json = value;
      replaced = true;
    }
    if (!replaced) fields.emplace_back(field, value);
  }
  std::string text = "{";
  for (const auto& [key, json] : fields) {
    if (!json.empty()) text += (text.size() > 1 ? ", \"" : "\"") + key + "\": " + json;
  }
  return text + "}";
}

std::string pathWith(const std::string& field, const std::string& value) {
  return pathWithAll({{field, value}});
}

// The loader's message for `text`, or "" when it loads.
std::string loadError(const std::string& text) {
  const auto dir = testing::scratchDirectory("camera_bad");
  const std::string file = testing::writeTextFile(dir / "bad.json", text);
  try {
    suite::loadCameraPath(file, "assets/cameras/bad.json");
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

TEST(CameraPath, TheValidTemplateLoads) { EXPECT_EQ(loadError(pathWith("name", R"("ok")")), ""); }

TEST(CameraPath, EveryBadInputIsOneLineNamingTheFileAndTheField) {
  struct Case {
    std::string text;
    std::string expected;  // after "assets/cameras/bad.json: "
  };
  const std::vector<Case> cases = {
      {R"({"frames": 24,)", "malformed JSON"},
      {"", "malformed JSON"},
      {"[1, 2]", "expected a JSON object"},
      {pathWith("near", ""), "near: missing"},
      {pathWith("keyframes", ""), "keyframes: missing"},
      {pathWith("fov", "45"), "fov: unknown field"},
      // Found by tests/fuzz: a key holding a newline (written \n in the file) is escaped.
      {pathWith(R"(fo\nv)", "45"), R"("fo\nv": unknown field)"},
      {pathWith(R"(fo\nv)", "[1e999]"), R"("fo\nv"[0]: not a finite number)"},
      {pathWith("frames", R"("24")"), "frames: expected a whole number in 1..100000, got string"},
      {pathWith("frames", "0"), "frames: 0 is out of range"},
      {pathWith("frames", "-3"), "frames: -3 is out of range"},
      {pathWith("frames", "2.5"), "frames: expected a whole number"},
      {pathWith("frames", "1e999"), "frames: not a finite number"},
      {pathWith("resolution", "[0, 1080]"), "resolution[0]: 0 is out of range"},
      {pathWith("resolution", "[1920]"), "resolution: expected [width, height]"},
      {pathWith("fov_y_deg", "180"), "fov_y_deg: must be in (0, 180)"},
      {pathWith("fov_y_deg", "0"), "fov_y_deg: must be in (0, 180)"},
      {pathWith("fov_y_deg", "true"), "fov_y_deg: expected a number, got boolean"},
      {pathWith("near", "0"), "near: must be > 0"},
      {pathWith("near", "1e999"), "near: not a finite number"},
      {pathWith("far", "0.01"), "far: must be > near"},
      {pathWith("space", R"("screen")"), R"(space: expected "bounds" or "world", got "screen")"},
      {pathWith("target_pixels_per_edge", "-8"), "target_pixels_per_edge: must be > 0"},
      {pathWith("name", "7"), "name: expected a non-empty string"},
      {pathWith("keyframes", "[]"), "keyframes: expected an array of at least one keyframe"},
      {pathWith("keyframes", R"([{"eye": [1, 0, 0], "target": [0, 0, 0]}])"),
       "keyframes[0].up: missing"},
      {pathWith("keyframes", R"([{"eye": [1, 0], "target": [0, 0, 0], "up": [0, 1, 0]}])"),
       "keyframes[0].eye: expected [x, y, z]"},
      {pathWith("keyframes", R"([{"eye": [1, -1e999, 0], "target": [0, 0, 0], "up": [0, 1, 0]}])"),
       "keyframes[0].eye[1]: not a finite number"},
      {pathWith("keyframes", R"([{"eye": [1, 0, 0], "target": [0, 0, 0], "up": [0, 1, 0]},
                                 {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 0, 0]}])"),
       "keyframes[1].up: zero-length vector"},
      {pathWith("keyframes", R"([{"eye": [0, 3, 0], "target": [0, 1, 0], "up": [0, 2, 0]}])"),
       "keyframes[0].up: parallel to the view direction (eye - target)"},
      {pathWith("keyframes", R"([{"eye": [1, 2, 3], "target": [1, 2, 3], "up": [0, 1, 0]}])"),
       "keyframes[0].eye: equals the target"},
      {pathWith("keyframes", R"([{"eye": [2, 0, 0], "target": [0, 0, 0], "up": [0, 1, 0]},
                                 {"eye": [-1, 0, 0], "target": [0, 0, 0], "up": [0, 1, 0]}])"),
       "keyframes[1].eye: seen from the target, opposite to keyframes[0]"},
  };
  for (const Case& c : cases) {
    const std::string message = loadError(c.text);
    EXPECT_EQ(message.rfind("assets/cameras/bad.json: ", 0), 0u) << c.text << "\n-> " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n-> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Up is checked at every sampled frame, not only at the keyframes: a turn through straight
// up (along `up`) has no camera halfway. Sampled at 4 frames the path misses the halfway
// point and loads; at 5, frame 2 is halfway.
TEST(CameraPath, UpIsCheckedAtEverySampledFrame) {
  const std::string over_the_top = R"([{"eye": [1, 1, 0], "target": [0, 0, 0], "up": [0, 1, 0]},
                                       {"eye": [-1, 1, 0], "target": [0, 0, 0], "up": [0, 1, 0]}])";
  EXPECT_NE(loadError(pathWithAll({{"keyframes", over_the_top}, {"frames", "5"}}))
                .find("frame 2 of 5 (after keyframes[0]).up: parallel to the view direction"),
            std::string::npos);
  EXPECT_EQ(loadError(pathWithAll({{"keyframes", over_the_top}, {"frames", "4"}})), "");
  const auto dir = testing::scratchDirectory("camera_frames");
  const std::string file = testing::writeTextFile(
      dir / "four.json", pathWithAll({{"keyframes", over_the_top}, {"frames", "4"}}));
  const suite::CameraPathSpec four = suite::loadCameraPath(file, "four.json");
  EXPECT_EQ(suite::sampleCameraPath(four, kBox).views.size(), 4u);
  EXPECT_THROW(suite::sampleCameraPath(four, kBox, 5), mesh::InputError);
}

TEST(CameraPath, AMissingFileNamesTheFile) {
  try {
    suite::loadCameraPath("/does/not/exist.json", "assets/cameras/exist.json");
    FAIL() << "no error";
  } catch (const mesh::InputError& error) {
    EXPECT_STREQ(error.what(), "assets/cameras/exist.json: no such file");
  }
  try {
    suite::resolveCameraPath("does/not/exist.json");
    FAIL() << "no error";
  } catch (const mesh::InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("does/not/exist.json: no such file", 0), 0u)
        << error.what();
  }
}

}  // namespace
}  // namespace tb
