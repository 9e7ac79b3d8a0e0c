// `tessbench tessellate` argument handling and JSON shape (oracle: the documented
// command contract in harness/cli/tessellate_command.h).
#include "harness/cli/tessellate_command.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace tb::cli {
namespace {

TessellateArgs argsFor(std::string domain, std::string spacing, std::string outer,
                       std::string inner = "") {
  TessellateArgs args;
  args.domain = std::move(domain);
  args.spacing = std::move(spacing);
  args.outer = std::move(outer);
  args.inner = std::move(inner);
  return args;
}

// The error names the option and the rule, on one line.
void expectUsageError(const TessellateArgs& args, const std::string& fragment) {
  try {
    parseTessellateArgs(args);
    FAIL() << "expected a UsageError mentioning '" << fragment << "'";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(TessellateCommand, RejectsBadArgumentsWithOneLine) {
  expectUsageError(argsFor("tri", "integer", "1,2"),
                   "--outer for domain tri needs 3 values, got 2");
  expectUsageError(argsFor("quad", "integer", "1,2,3"), "needs 4 values, got 3");
  expectUsageError(argsFor("isoline", "integer", "1,2,3"), "needs 2 values, got 3");
  expectUsageError(argsFor("quad", "integer", "1,2,x,4"), "--outer: 'x' is not a number");
  expectUsageError(argsFor("quad", "integer", "1,2,,4"), "'' is not a number");
  expectUsageError(argsFor("quad", "integer", "1,2,3,4", "2"), "--inner for domain quad needs 2");
  expectUsageError(argsFor("isoline", "integer", "1,2", "2"), "--inner for domain isoline");
  expectUsageError(argsFor("tri", "integer", "1,2,3", "4e"), "--inner: '4e' is not a number");
  expectUsageError(argsFor("hexagon", "integer", "1,2,3"), "--domain: unknown domain 'hexagon'");
  expectUsageError(argsFor("tri", "fractional", "1,2,3"), "--spacing: unknown spacing");
  TessellateArgs bad_backend = argsFor("tri", "integer", "1,2,3");
  bad_backend.backend = "cuda";
  expectUsageError(bad_backend, "--backend");
}

TEST(TessellateCommand, ParsesLevelsIncludingNaNAndNegative) {
  const TessellateRequest r =
      parseTessellateArgs(argsFor("quad", "fractional_odd", " -1, 2.5 ,nan,64", "3,inf"));
  EXPECT_EQ(r.domain, tess::Domain::kQuad);
  EXPECT_EQ(r.spacing, tess::Spacing::kFractionalOdd);
  EXPECT_EQ(r.levels.outer[0], -1.0f);
  EXPECT_EQ(r.levels.outer[1], 2.5f);
  EXPECT_TRUE(std::isnan(r.levels.outer[2]));
  EXPECT_TRUE(std::isinf(r.levels.inner[1]));

  // Through CLI11: a negative first level needs the --outer=... form.
  CLI::App app;
  TessellateArgs args;
  addTessellateCommand(app, args);
  app.parse("tessellate --domain tri --spacing pow2 --outer=-1,2,3 --inner=2 --json --point-mode",
            /*program_name_included=*/false);
  EXPECT_EQ(args.outer, "-1,2,3");
  EXPECT_EQ(args.spacing, "pow2");
  EXPECT_TRUE(args.json);
  EXPECT_TRUE(args.point_mode);
  EXPECT_EQ(args.backend, "cpu");
  tess::Domain domain = tess::Domain::kQuad;
  EXPECT_TRUE(runCpuTessellate(args, &domain).culled);
  EXPECT_EQ(domain, tess::Domain::kTriangle);
}

TEST(TessellateCommand, JsonHasPointsPrimitivesAndCulled) {
  tess::Domain domain = tess::Domain::kQuad;
  const tess::Tessellation tri =
      runCpuTessellate(argsFor("tri", "fractional_even", "2.5,3,4", "3.3"), &domain);
  const nlohmann::json j = nlohmann::json::parse(tessellationToJson(domain, tri));
  ASSERT_EQ(j.at("points").size(), tri.points.size());
  ASSERT_EQ(j.at("primitives").size(), tri.triangles.size());
  EXPECT_FALSE(j.at("culled").get<bool>());
  for (size_t i = 0; i < tri.points.size(); ++i) {
    ASSERT_EQ(j["points"][i].size(), 3u);
    for (size_t c = 0; c < 3; ++c) {
      // Round trip through the text is exact.
      EXPECT_EQ(static_cast<float>(j["points"][i][c].get<double>()), tri.points[i][c]);
    }
  }
  EXPECT_EQ(j["primitives"][0].get<std::vector<uint32_t>>(),
            (std::vector<uint32_t>(tri.triangles[0].begin(), tri.triangles[0].end())));

  const tess::Tessellation line = runCpuTessellate(argsFor("isoline", "integer", "2,3"), &domain);
  const nlohmann::json l = nlohmann::json::parse(tessellationToJson(domain, line));
  EXPECT_EQ(l["points"][0].size(), 2u);
  EXPECT_EQ(l["primitives"].size(), 6u);
  EXPECT_EQ(l["primitives"][0].size(), 2u);

  const tess::Tessellation culled =
      runCpuTessellate(argsFor("quad", "integer", "1,0,1,1"), &domain);
  const nlohmann::json c = nlohmann::json::parse(tessellationToJson(domain, culled));
  EXPECT_TRUE(c["culled"].get<bool>());
  EXPECT_TRUE(c["points"].empty());
  EXPECT_TRUE(c["primitives"].is_array());
}

TEST(TessNames, ParseAndPrintRoundTrip) {
  for (tess::Domain d : {tess::Domain::kTriangle, tess::Domain::kQuad, tess::Domain::kIsoline}) {
    tess::Domain parsed{};
    ASSERT_TRUE(tess::parseDomain(tess::toString(d), &parsed));
    EXPECT_EQ(parsed, d);
  }
  for (tess::Spacing s : {tess::Spacing::kInteger, tess::Spacing::kPow2,
                          tess::Spacing::kFractionalOdd, tess::Spacing::kFractionalEven}) {
    tess::Spacing parsed{};
    ASSERT_TRUE(tess::parseSpacing(tess::toString(s), &parsed));
    EXPECT_EQ(parsed, s);
  }
  tess::Domain d{};
  EXPECT_FALSE(tess::parseDomain("triangle", &d));
  EXPECT_EQ(tess::toString(tess::Spacing::kFractionalOdd), "fractional_odd");
}

}  // namespace
}  // namespace tb::cli
