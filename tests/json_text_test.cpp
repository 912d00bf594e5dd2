// Text that is not UTF-8 (a Linux file name is bytes) is written escaped,
// never thrown on: common/utf8_text.hpp and common/json_text.hpp.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/json_text.hpp"
#include "common/text_format.hpp"
#include "common/utf8_text.hpp"

namespace meshparticles::testing {
namespace {

TEST(Utf8Text, ValidTextIsKept) {
  for (const std::string text : {"", "plain.off", "caf\xc3\xa9", "\xe2\x82\xac", "\xf0\x9f\x98\x80", "\xf4\x8f\xbf\xbf"}) {
    EXPECT_EQ(escaped_utf8(text), text);
  }
}

TEST(Utf8Text, EachStrayByteIsEscaped) {
  EXPECT_EQ(escaped_utf8("\xff.off"), "\\xff.off");
  EXPECT_EQ(escaped_utf8("a\xc3"), "a\\xc3");                        // cut short
  EXPECT_EQ(escaped_utf8("\xc0\xaf"), "\\xc0\\xaf");                 // overlong "/"
  EXPECT_EQ(escaped_utf8("\xed\xa0\x80"), "\\xed\\xa0\\x80");        // a surrogate
  EXPECT_EQ(escaped_utf8("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
  EXPECT_EQ(escaped_utf8("\x80" "caf\xc3\xa9"), "\\x80caf\xc3\xa9");  // the valid rest kept
  EXPECT_NE(escaped_utf8("\xff"), "\xff");
  EXPECT_EQ(one_line("\xfe\n"), "\\xfe\\n");
}

TEST(JsonText, StringsAndKeysThatAreNotUtf8AreWrittenEscaped) {
  const nlohmann::json report = {{"mesh", {{"path", "/data/\xff.off"}, {"vertices", 4}}},
                                 {"names", {"ok", "\xfe"}},
                                 {"\xfd", 1.5}};
  EXPECT_THROW((void)report.dump(), nlohmann::json::type_error);  // what json_text guards against
  const nlohmann::json read = nlohmann::json::parse(json_text(report, 2));
  EXPECT_EQ(read["mesh"]["path"], "/data/\\xff.off");
  EXPECT_EQ(read["mesh"]["vertices"], 4);
  EXPECT_EQ(read["names"][1], "\\xfe");
  EXPECT_EQ(read["\\xfd"], 1.5);
  EXPECT_EQ(read, as_written(report));
  const nlohmann::json plain = {{"a", {1, 2}}, {"b", "x"}};
  EXPECT_EQ(json_text(plain), plain.dump());
}

}  // namespace
}  // namespace meshparticles::testing
