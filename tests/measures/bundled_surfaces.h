// Test helper: a technique variant built on every bundled asset it accepts.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb::testing {

// The variant of `technique` named `name`; throws when it has none.
inline techniques::VariantInfo variantNamed(const techniques::Technique& technique,
                                            const std::string& name) {
  for (const techniques::VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  throw std::runtime_error(technique.info().id + " has no variant " + name);
}

// Technique `id`'s variant `variant` built on the bundled asset `asset` (a path under
// assets/); throws when the technique or the variant is not there.
inline techniques::BuiltSurface builtSurface(const std::string& id, const std::string& variant,
                                             const std::string& asset) {
  const techniques::Technique& t = technique(id);
  return techniques::buildSurface(t, loadAsset(asset), variantNamed(t, variant));
}

// Calls fn(asset name, patches) for every bundled asset that technique `id`'s variant
// `variant` supports and builds; returns how many.
template <class Fn>
size_t forEachBundledSurface(const std::string& id, const std::string& variant, Fn fn) {
  const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
  if (technique == nullptr) throw std::runtime_error("no technique " + id);
  const techniques::VariantInfo info = variantNamed(*technique, variant);
  size_t supported = 0;
  for (const suite::AssetRef& asset : suite::bundledAssets()) {
    const mesh::Mesh mesh = suite::loadAsset(asset);
    if (!technique->checkSupport(mesh).empty()) continue;
    techniques::BuiltSurface patches;
    try {
      patches = techniques::buildSurface(*technique, mesh, info);
    } catch (const techniques::UnsupportedInput&) {
      continue;
    }
    ++supported;
    fn(asset.name, *patches);
  }
  return supported;
}

}  // namespace tb::testing
