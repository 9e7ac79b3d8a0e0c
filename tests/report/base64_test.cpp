#include "harness/report/base64.h"

#include <gtest/gtest.h>

namespace tb {
namespace {

// Oracle: the test vectors of RFC 4648, section 10, and one byte of each high value.
TEST(Base64, EncodesTheRfc4648Vectors) {
  EXPECT_EQ(report::base64Encode(""), "");
  EXPECT_EQ(report::base64Encode("f"), "Zg==");
  EXPECT_EQ(report::base64Encode("fo"), "Zm8=");
  EXPECT_EQ(report::base64Encode("foo"), "Zm9v");
  EXPECT_EQ(report::base64Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(report::base64Encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(report::base64Encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(report::base64Encode(std::string("\xff\xfe\x00", 3)), "//4A");
  EXPECT_EQ(report::base64Encode("\x89PNG"), "iVBORw==");
}

}  // namespace
}  // namespace tb
