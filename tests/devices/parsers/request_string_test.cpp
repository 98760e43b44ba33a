#include "devices/parsers/request_string.h"

#include <gtest/gtest.h>

namespace tt::devices {
namespace {

TEST(RequestString, UnescapesAndRefusesBadEscapes) {
    EXPECT_EQ(unescapeRequest("1\\r"), std::string("1\r"));
    EXPECT_EQ(unescapeRequest("\\x02R\\x03"), std::string("\x02R\x03"));
    EXPECT_EQ(unescapeRequest("\\\\t\\t"), std::string("\\t\t"));
    EXPECT_FALSE(unescapeRequest("\\x2").has_value());
    EXPECT_FALSE(unescapeRequest("\\xG0").has_value());
    EXPECT_FALSE(unescapeRequest("a\\").has_value());
    EXPECT_FALSE(unescapeRequest("\\q").has_value());
}

}  // namespace
}  // namespace tt::devices
