#include "events/json_output.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "json_test_parser.h"

namespace getme::cli {
namespace {

using testing::JsonValue;
using testing::ParseJson;

TEST(JsonOutput, EscapesStringsSoTheyParseBack) {
  const std::string nasty = "quote\" backslash\\ newline\n tab\t bell\x07 path C:\\x ünïcode";
  const std::string json = events::JsonObject().AddString("s", nasty).Build();
  const std::optional<JsonValue> parsed = ParseJson(json);
  ASSERT_TRUE(parsed.has_value()) << json;
  EXPECT_EQ(parsed->Find("s")->string, nasty);
  EXPECT_EQ(json.find('\n'), std::string::npos);  // one line
}

// Messages quote bytes from files (a reader's "value 12 is '\xff'") and JSON must be UTF-8:
// well-formed sequences pass, every byte of an ill-formed one becomes U+FFFD.
TEST(JsonOutput, BytesThatAreNotUtf8BecomeReplacementCharacters) {
  EXPECT_EQ(JsonString("a\xff b"), "\"a\\ufffd b\"");
  EXPECT_EQ(JsonString("\xc3\xbc \xe2\x82\xac \xf0\x9f\x98\x80"),
            "\"\xc3\xbc \xe2\x82\xac \xf0\x9f\x98\x80\"");             // ü € 😀 kept
  EXPECT_EQ(JsonString("\xc0\x80"), "\"\\ufffd\\ufffd\"");             // overlong NUL
  EXPECT_EQ(JsonString("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // a surrogate
  EXPECT_EQ(JsonString("\xf4\x90\x80\x80"),
            "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");            // beyond U+10FFFF
  EXPECT_EQ(JsonString("\xe2\x82"), "\"\\ufffd\\ufffd\"");  // cut short at the end
  EXPECT_EQ(JsonString("\xe2\x82x"), "\"\\ufffd\\ufffdx\"");
  EXPECT_EQ(JsonString("del\x7f cr\r"), "\"del\\u007f cr\\r\"");
}

TEST(JsonOutput, DoublesRoundTripExactly) {
  for (const double value : {0.1, 1.0 / 3.0, 0.7550748808053224, 1e-300, -2.5e10, 0.0,
                             std::nextafter(1.0, 0.0), 5e-324}) {
    const std::optional<JsonValue> parsed =
        ParseJson(events::JsonObject().AddDouble("x", value).Build());
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(parsed->Find("x")->number, value);
  }
}

TEST(JsonOutput, NonFiniteDoublesBecomeNull) {
  const std::string json = events::JsonObject()
                               .AddDouble("nan", std::nan(""))
                               .AddDouble("inf", std::numeric_limits<double>::infinity())
                               .Build();
  EXPECT_EQ(json, R"({"nan":null,"inf":null})");
}

TEST(JsonOutput, KeepsKeyOrderAndTypes) {
  const std::int64_t ids[] = {3, 1, 2};
  const std::string json = events::JsonObject()
                               .AddString("event", "result")
                               .AddInt("big", INT64_C(9007199254740993))
                               .AddBool("done", true)
                               .AddRaw("ids", events::JsonIntArray(ids))
                               .Build();
  EXPECT_EQ(json, R"({"event":"result","big":9007199254740993,"done":true,"ids":[3,1,2]})");
}

}  // namespace
}  // namespace getme::cli
