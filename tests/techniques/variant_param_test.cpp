#include "techniques/variant_param.h"

#include <gtest/gtest.h>

#include "techniques/registry.h"

namespace tb {
namespace {

enum class Order { kFirst, kSecond, kThird };

const TechniqueInfo& phongInfo() { return TechniqueRegistry::instance().find("phong")->info(); }

TEST(VariantParam, ReadsTypedValues) {
  const VariantInfo variant{"v", "", {{"alpha", 0.75}, {"edge", 1}, {"order", 2}}};
  EXPECT_EQ(param<double>(phongInfo(), variant, "alpha"), 0.75);
  EXPECT_TRUE(param<bool>(phongInfo(), variant, "edge"));
  EXPECT_EQ(param<int>(phongInfo(), variant, "order"), 2);
  EXPECT_EQ(param<Order>(phongInfo(), variant, "order"), Order::kThird);
  EXPECT_EQ(paramOr<double>(phongInfo(), variant, "missing", 0.5), 0.5);
  EXPECT_EQ(paramOr<double>(phongInfo(), variant, "alpha", 0.5), 0.75);
}

TEST(VariantParam, MissingParameterNamesTechniqueVariantAndParameter) {
  const VariantInfo variant = TechniqueRegistry::instance().find("phong")->variants()[0];
  try {
    param<double>(phongInfo(), variant, "beta");
    FAIL() << "expected VariantParameterError";
  } catch (const VariantParameterError& error) {
    EXPECT_EQ(std::string(error.what()),
              "phong/" + variant.name + ": variant parameter 'beta' is missing");
  }
}

TEST(VariantParam, NonIntegralValueForAnIntegerIsAnError) {
  const VariantInfo variant{"odd", "", {{"order", 1.5}}};
  EXPECT_THROW(param<int>(phongInfo(), variant, "order"), VariantParameterError);
  EXPECT_THROW(paramOr<Order>(phongInfo(), variant, "order", Order::kFirst), VariantParameterError);
}

}  // namespace
}  // namespace tb
