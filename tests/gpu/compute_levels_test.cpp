// Issue 41, acceptance 3: under a factor policy, the compute path's per-patch levels
// (core/gpu/compute_levels.h, shaders/gpu/policy_levels.comp) equal the levels each
// technique's own TCS writes back (PatchProgramCapture::tcs_levels) bit for bit, and the
// compute tessellator fed by them on the device counts per patch the triangles and points
// the CPU tessellator (core/tess) makes of those levels.
//
// Cases: every surface technique's default variant on one bundled asset, every frame of the
// default camera path (orbit) sampled to kFrames views, every factor policy (one
// order-dependent one) and one factor policy with a culling policy; the spacing and inner
// reduction cycle over the policies, so each technique sees all four spacings. Every job
// runs in one counts-only PolicyTessellator batch (one submission; levels and counts), and
// the first frame's again through the whole chain with its write pass (points and
// triangles bit for bit): two pipeline builds in all. Broken controls that must be caught:
// an lp2_edge job whose target is 1% higher, and each job's compute levels against the TCS
// levels of the next frame.
#include "core/gpu/compute_levels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/lod/cull_policy.h"
#include "harness/lod/factor_policy.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb::compute_levels_test {
namespace {

// Frames of orbit the cases run on. Three under a sanitizer too: two samples of the closed
// orbit are its first and last views, the same camera, and the next-frame control then
// compares a frame with itself (caught 0 of 35 pairs under ASan).
constexpr uint32_t kFrames = 3;
constexpr size_t kTargetWord = 22;  // TbFactorParamsBlock::target, a float word

struct TechniqueCase {
  const char* technique;
  const char* asset;
};
constexpr TechniqueCase kTechniqueCases[] = {
    {"acc", "opensubdiv/catmark_xord_interior.obj"},
    {"gregory_acc", "opensubdiv/catmark_nonquads.obj"},
    {"osd_adaptive", "opensubdiv/catmark_xord_interior.obj"},
    {"pn_triangles", "tessbench/tri_torus.obj"},
    {"phong", "tessbench/cylinder_seam.obj"}};

// A factor policy, with a culling policy or none (nullptr).
struct PolicyCase {
  const char* factor;
  const char* cull;
};
constexpr PolicyCase kPolicyCases[] = {{"uniform", nullptr},
                                       {"distance", nullptr},
                                       {"sphere_diameter", nullptr},
                                       {"lp2_edge", nullptr},
                                       {"lp2_edge_silhouette", nullptr},
                                       {"lp2_edge_roundness", nullptr},
                                       {"distance_order_dependent", nullptr},
                                       {"sphere_diameter", "tangent_plane_frustum"}};
constexpr size_t kControlPolicy = 3;  // lp2_edge: its target is perturbed in the control

constexpr tess::Spacing kSpacings[] = {tess::Spacing::kInteger, tess::Spacing::kPow2,
                                       tess::Spacing::kFractionalOdd,
                                       tess::Spacing::kFractionalEven};

// Which technique, frame of the path, policy case and program of the technique.
struct CaseKey {
  size_t technique = 0, frame = 0, policy = 0, program = 0;
};

// One program under one case on the TCS path, and the compute job that repeats it.
struct DeviceCase {
  CaseKey key;
  bool control = false;  // the perturbed job: its levels must differ from tcs_levels
  std::vector<tess::LevelsBits> tcs_levels;
  std::vector<tess::Levels> twin;  // the CPU twin's levels: the job's level bounds
  gpu::TcsFactorPolicy factor;
  gpu::TcsCullPolicy cull;
  gpu::PolicyLevelsJob job;

  std::string label() const {
    const PolicyCase& policy = kPolicyCases[key.policy];
    return std::string(kTechniqueCases[key.technique].technique) + " frame " +
           std::to_string(key.frame) + " " + policy.factor +
           (policy.cull ? std::string(" + ") + policy.cull : "") + " program " +
           std::to_string(key.program) + (control ? " (control)" : "");
  }
};
using DeviceCases = std::vector<std::unique_ptr<DeviceCase>>;

// What one technique's cases need of its surface.
struct Surface {
  techniques::BuiltSurface built;
  lod::FactorCorners corners;
  lod::CullBounds bounds;
  std::vector<gpu::GpuPatchProgram> programs;
  view::CameraPath path;
  double diagonal = 1;
};

Surface surfaceOf(const TechniqueCase& c) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(c.technique);
  if (technique == nullptr) throw std::runtime_error(std::string("no technique ") + c.technique);
  Surface s;
  s.built =
      techniques::buildSurface(*technique, mesh::loadObjFile(::tb::testing::assetPath(c.asset)),
                               technique->variants().front());
  s.corners = lod::factorCorners(*s.built);
  const mesh::Aabb box = mesh::boundsOf(s.built->controlMesh());
  s.diagonal = length(box.max - box.min);
  s.bounds = lod::cullBounds(*s.built, s.corners, s.diagonal, 1);
  s.programs = s.built->gpuPrograms();
  s.path = suite::sampleCameraPath(suite::resolveCameraPath("orbit"), box, kFrames);
  return s;
}

// Runs one program under the case's policies on its TCS and makes the matching job.
std::unique_ptr<DeviceCase> runOnTcs(gpu::Context& context, const Surface& s, CaseKey key,
                                     const lod::FactorParams& params,
                                     const std::vector<tess::Levels>& twin) {
  auto c = std::make_unique<DeviceCase>();
  c->key = key;
  const gpu::GpuPatchProgram& program = s.programs[key.program];
  const PolicyCase& policy = kPolicyCases[key.policy];
  std::vector<tess::Levels>& expected = c->twin;
  expected.resize(program.patch_count);
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    expected[i] = twin[program.patch_ids.empty() ? i : program.patch_ids[i]];
  }
  c->factor = lod::tcsFactorPolicy(params, s.corners, program);
  if (policy.cull != nullptr) {
    const lod::CullParams cull =
        lod::cullParams(*lod::parseCullPolicy(policy.cull), s.path.views[key.frame], s.bounds);
    c->cull = lod::tcsCullPolicy(cull, s.bounds, program);
  }
  const tess::Spacing spacing = tess::Spacing(params.spacing);
  const gpu::PatchProgramCapture capture =
      gpu::runPatchProgram(context, program, expected,
                           {.spacing = spacing,
                            .patches_per_draw = 256,
                            .capture = false,
                            .statistics = false,
                            .factor_policy = &c->factor,
                            .cull_policy = policy.cull ? &c->cull : nullptr});
  c->tcs_levels = capture.tcs_levels;
  c->job.domain = program.domain;
  c->job.spacing = spacing;
  c->job.patch_count = program.patch_count;
  c->job.factor_policy = &c->factor;
  c->job.cull_policy = policy.cull ? &c->cull : nullptr;
  c->job.level_bounds = c->twin;
  return c;
}

// The perturbed twin of `of`: the same TCS levels, a job whose target is 1% higher.
std::unique_ptr<DeviceCase> controlOf(const DeviceCase& of) {
  auto c = std::make_unique<DeviceCase>();
  c->key = of.key;
  c->control = true;
  c->tcs_levels = of.tcs_levels;
  c->factor = of.factor;
  const float target = std::bit_cast<float>(c->factor.param_words.at(kTargetWord));
  c->factor.param_words[kTargetWord] = std::bit_cast<uint32_t>(target * 1.01f);
  c->job = of.job;
  c->job.factor_policy = &c->factor;
  c->job.level_bounds = {};  // 64: the perturbed levels exceed the twin's
  return c;
}

// Every case of one technique on the TCS path; the control on its first frame.
void addTechniqueCases(gpu::Context& context, size_t t, DeviceCases* cases) {
  const Surface s = surfaceOf(kTechniqueCases[t]);
  ASSERT_FALSE(s.programs.empty()) << kTechniqueCases[t].technique;
  for (size_t f = 0; f < s.path.views.size(); ++f) {
    for (size_t k = 0; k < std::size(kPolicyCases); ++k) {
      lod::FactorPolicy policy = *lod::parseFactorPolicy(kPolicyCases[k].factor);
      policy.reduction = lod::InnerReduction((k + t) % 3);
      const tess::Spacing spacing = kSpacings[(k + t) % 4];
      const lod::FactorParams params =
          lod::factorParams(policy, s.path.views[f], spacing, s.diagonal);
      const std::vector<tess::Levels> twin = lod::policyLevels(params, s.corners);
      for (size_t p = 0; p < s.programs.size(); ++p) {
        cases->push_back(runOnTcs(context, s, CaseKey{t, f, k, p}, params, twin));
        if (f == 0 && k == kControlPolicy) cases->push_back(controlOf(*cases->back()));
      }
    }
  }
}

// Patches of a job whose compute levels (records from `first` on) differ from `tcs`.
size_t differingPatches(const std::vector<tess::LevelsBits>& computed, uint32_t first,
                        const std::vector<tess::LevelsBits>& tcs) {
  size_t differing = 0;
  for (size_t i = 0; i < tcs.size(); ++i) differing += computed[first + i] != tcs[i];
  return differing;
}

// The CPU tessellator's output per (levels bits, domain, spacing): many patches share levels.
class CpuTessellations {
 public:
  const tess::Tessellation& of(const gpu::PolicyLevelsJob& job, const tess::LevelsBits& bits) {
    auto [it, fresh] = cache_.try_emplace({bits, int(job.domain) * 4 + int(job.spacing)});
    if (fresh) {
      tess::Levels levels;
      for (int j = 0; j < 4; ++j) levels.outer[j] = std::bit_cast<float>(bits[j]);
      for (int j = 0; j < 2; ++j) levels.inner[j] = std::bit_cast<float>(bits[4 + j]);
      it->second = tess::tessellate(job.domain, job.spacing, levels);
    }
    return it->second;
  }

 private:
  std::map<std::pair<tess::LevelsBits, int>, tess::Tessellation> cache_;
};

// Patches of a job whose compute tessellation differs from the CPU tessellator's for the
// TCS's levels: in the triangle or point count and culling, or (`full`: a batch with its
// write pass) in any point bit or triangle index.
size_t differingTessellations(const DeviceCase& c, const gpu::PolicyTessellation& out,
                              uint32_t first, bool full, CpuTessellations* cpu) {
  size_t differing = 0;
  for (size_t i = 0; i < c.tcs_levels.size(); ++i) {
    const tess::Tessellation& expected = cpu->of(c.job, c.tcs_levels[i]);
    const gpu::TessPatchRange& range = out.tessellation.patches[first + i];
    bool same = range.index_count / 3 == expected.triangles.size() &&
                range.point_count == expected.points.size() && range.culled == expected.culled;
    if (full && same) {
      const tess::Tessellation t = gpu::toTessellation(out.tessellation, first + i, c.job.domain);
      same = t.points == expected.points && t.triangles == expected.triangles;
    }
    differing += !same;
  }
  return differing;
}

// Tallies of one batch's comparison.
struct Tally {
  size_t jobs = 0, patches = 0, equal_jobs = 0, controls = 0, caught = 0;
  size_t culled = 0;  // patches with outer levels 0 (the culling case culls some)
};

// Compares every job of `cases` run as one batch: levels bitwise against the TCS's, the
// tessellation against the CPU tessellator's, the controls' levels caught.
Tally compareBatch(gpu::Context& context, const std::vector<const DeviceCase*>& cases,
                   bool counts_only, CpuTessellations* cpu, std::vector<tess::LevelsBits>* levels,
                   std::vector<uint32_t>* first) {
  std::vector<gpu::PolicyLevelsJob> jobs;
  for (const DeviceCase* c : cases) jobs.push_back(c->job);
  gpu::PolicyTessellator tessellator(context, jobs, counts_only);
  tessellator.run();
  const gpu::PolicyTessellation out = tessellator.read();
  Tally tally;
  for (size_t j = 0; j < cases.size(); ++j) {
    const DeviceCase& c = *cases[j];
    first->push_back(tessellator.firstRecord(j));
    const size_t levels_differ = differingPatches(out.levels, first->back(), c.tcs_levels);
    if (c.control) {
      ++tally.controls;
      tally.caught += levels_differ > 0;
      EXPECT_GT(levels_differ, 0u) << c.label() << ": the perturbed target went unseen";
      continue;
    }
    ++tally.jobs;
    tally.patches += c.tcs_levels.size();
    for (const tess::LevelsBits& bits : c.tcs_levels) tally.culled += bits[0] == 0u;
    tally.equal_jobs += levels_differ == 0;
    EXPECT_EQ(levels_differ, 0u) << c.label() << ": compute levels != TCS levels";
    EXPECT_EQ(differingTessellations(c, out, first->back(), !counts_only, cpu), 0u)
        << c.label() << ": compute tessellation != CPU tessellator";
  }
  *levels = out.levels;
  return tally;
}

// The next-frame control: each job's compute levels against the TCS levels of the same
// program and policy on the following frame (uniform excepted: no view). {caught, pairs}.
std::pair<size_t, size_t> nextFrameControl(const DeviceCases& cases,
                                           const std::vector<tess::LevelsBits>& levels,
                                           const std::vector<uint32_t>& first) {
  std::map<std::tuple<size_t, size_t, size_t, size_t>, const DeviceCase*> by_key;
  for (const auto& c : cases) {
    if (!c->control)
      by_key[{c->key.technique, c->key.frame, c->key.policy, c->key.program}] = c.get();
  }
  size_t caught = 0, pairs = 0;
  for (size_t j = 0; j < cases.size(); ++j) {
    const CaseKey& k = cases[j]->key;
    auto next = by_key.find({k.technique, k.frame + 1, k.policy, k.program});
    if (cases[j]->control || k.policy == 0 || next == by_key.end()) continue;
    ++pairs;
    caught += differingPatches(levels, first[j], next->second->tcs_levels) > 0;
  }
  return {caught, pairs};
}

// Every case in one counts-only batch (levels, counts, both controls), then the first
// frame's through the whole chain with its write pass (points and triangles bitwise).
TEST(ComputeTessPolicyLevels, EqualEveryTechniqueTcsBitwiseAndCountsEqualTheCpuTessellator) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  DeviceCases cases;
  for (size_t t = 0; t < std::size(kTechniqueCases); ++t) {
    ASSERT_NO_FATAL_FAILURE(addTechniqueCases(context, t, &cases));
  }
  CpuTessellations cpu;
  std::vector<const DeviceCase*> all, first_frame;
  for (const auto& c : cases) {
    all.push_back(c.get());
    if (c->key.frame == 0 && !c->control) first_frame.push_back(c.get());
  }
  std::vector<tess::LevelsBits> levels;
  std::vector<uint32_t> first;
  const Tally counted = compareBatch(context, all, true, &cpu, &levels, &first);
  EXPECT_GT(counted.culled, 0u);
  EXPECT_GT(counted.controls, 0u);
  EXPECT_EQ(counted.caught, counted.controls);
  const auto [next_caught, next_pairs] = nextFrameControl(cases, levels, first);
  EXPECT_GT(next_pairs, 0u);
  EXPECT_EQ(next_caught, next_pairs);
  std::vector<tess::LevelsBits> written_levels;
  std::vector<uint32_t> written_first;
  const Tally written =
      compareBatch(context, first_frame, false, &cpu, &written_levels, &written_first);
  std::printf(
      "compute levels: %zu jobs, %zu patches (%zu culled), %zu jobs bitwise equal to "
      "the TCS with counts equal to the CPU's; perturbed-target control caught %zu/%zu, "
      "next-frame control %zu/%zu; written in full (frame 0): %zu jobs, %zu patches, "
      "%zu equal\n",
      counted.jobs, counted.patches, counted.culled, counted.equal_jobs, counted.caught,
      counted.controls, next_caught, next_pairs, written.jobs, written.patches, written.equal_jobs);
}

// The levels-only call (computePolicyLevels) equals the TCS too: a factor policy with a
// culling policy, and the culling policy alone on the harness's levels.
TEST(ComputeTessPolicyLevels, LevelsAloneEqualTheTcs) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const Surface s = surfaceOf(kTechniqueCases[0]);
  const size_t k = std::size(kPolicyCases) - 1;  // a factor and a culling policy
  const lod::FactorParams params =
      lod::factorParams(*lod::parseFactorPolicy(kPolicyCases[k].factor), s.path.views[0],
                        tess::Spacing::kFractionalOdd, s.diagonal);
  const auto c =
      runOnTcs(context, s, CaseKey{0, 0, k, 0}, params, lod::policyLevels(params, s.corners));
  const std::vector<tess::LevelsBits> levels = gpu::computePolicyLevels(
      context, c->job.domain, c->job.spacing, c->job.patch_count, &c->factor, &c->cull);
  EXPECT_EQ(levels, c->tcs_levels);

  const tess::Levels level_two{{2, 2, 2, 2}, {2, 2}};
  const gpu::GpuPatchProgram& program = s.programs[0];
  const gpu::PatchProgramCapture cull_only = gpu::runPatchProgram(
      context, program, level_two,
      {.patches_per_draw = 256, .capture = false, .statistics = false, .cull_policy = &c->cull});
  const std::vector<tess::LevelsBits> computed =
      gpu::computePolicyLevels(context, program.domain, tess::Spacing::kInteger,
                               program.patch_count, nullptr, &c->cull, level_two);
  EXPECT_EQ(computed, cull_only.tcs_levels);
  const auto culled = std::count_if(computed.begin(), computed.end(),
                                    [](const tess::LevelsBits& b) { return b[0] == 0u; });
  EXPECT_GT(culled, 0);  // the view culls some patches and keeps others
  EXPECT_LT(culled, std::ptrdiff_t(computed.size()));
}

}  // namespace
}  // namespace tb::compute_levels_test
