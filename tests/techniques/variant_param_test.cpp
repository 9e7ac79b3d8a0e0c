#include "techniques/variant_param.h"

#include <gtest/gtest.h>

#include "techniques/registry.h"

namespace tb {
namespace {

enum class Order { kFirst, kSecond, kThird };

const techniques::TechniqueInfo& phongInfo() {
  return techniques::TechniqueRegistry::instance().find("phong")->info();
}

TEST(VariantParam, ReadsTypedValues) {
  const techniques::VariantInfo variant{"v", "", {{"alpha", 0.75}, {"edge", 1}, {"order", 2}}};
  EXPECT_EQ(techniques::param<double>(phongInfo(), variant, "alpha"), 0.75);
  EXPECT_TRUE(techniques::param<bool>(phongInfo(), variant, "edge"));
  EXPECT_EQ(techniques::param<int>(phongInfo(), variant, "order"), 2);
  EXPECT_EQ(techniques::param<Order>(phongInfo(), variant, "order"), Order::kThird);
  EXPECT_EQ(techniques::paramOr<double>(phongInfo(), variant, "missing", 0.5), 0.5);
  EXPECT_EQ(techniques::paramOr<double>(phongInfo(), variant, "alpha", 0.5), 0.75);
}

TEST(VariantParam, MissingParameterNamesTechniqueVariantAndParameter) {
  const techniques::VariantInfo variant =
      techniques::TechniqueRegistry::instance().find("phong")->variants()[0];
  try {
    techniques::param<double>(phongInfo(), variant, "beta");
    FAIL() << "expected VariantParameterError";
  } catch (const techniques::VariantParameterError& error) {
    EXPECT_EQ(std::string(error.what()),
              "phong/" + variant.name + ": variant parameter 'beta' is missing");
  }
}

TEST(VariantParam, NonIntegralValueForAnIntegerIsAnError) {
  const techniques::VariantInfo variant{"odd", "", {{"order", 1.5}}};
  EXPECT_THROW(techniques::param<int>(phongInfo(), variant, "order"),
               techniques::VariantParameterError);
  EXPECT_THROW(techniques::paramOr<Order>(phongInfo(), variant, "order", Order::kFirst),
               techniques::VariantParameterError);
}

}  // namespace
}  // namespace tb
