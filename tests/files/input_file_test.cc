#include "files/input_file.h"

#include <gtest/gtest.h>

#include "tests/input_error_message.h"

namespace walkers {
namespace {

using nlohmann::json;

// the message of the InputError `f` throws, or "" if it throws none
template <typename F>
std::string Error(const F& f) {
  return testing::InputErrorMessage(f);
}

TEST(ParseJsonTest, RefusesAKeyGivenTwiceAtAnyDepth) {
  EXPECT_EQ(ParseJson(R"({"a": 1, "b": {"a": 2}})", "f.json")["b"]["a"], 2);  // one per object is fine
  EXPECT_EQ(Error([] { ParseJson(R"({"a": 1, "a": 2})", "f.json"); }), "f.json: key 'a' appears twice in one object");
  EXPECT_NE(Error([] { ParseJson(R"({"x": [{"b": 1, "b": 1}]})", "f.json"); }).find("key 'b' appears twice"),
            std::string::npos);
}

TEST(ParseJsonTest, NamesTheProblemOfTextThatIsNotJson) {
  const std::string error = Error([] { ParseJson("{\"a\": ", "f.json"); });
  EXPECT_EQ(error.rfind("f.json: not valid JSON (", 0), 0u) << error;
  EXPECT_EQ(error.find("json.exception"), std::string::npos) << error;  // not the library's tag
  EXPECT_NE(Error([] { ParseJson(R"({"big": 1e999})", "f.json"); }).find("'big' is not a finite number"),
            std::string::npos);
}

TEST(JsonFieldsTest, NamesTheFileTheFieldAndTheRange) {
  const json j = ParseJson(R"({"n": -3, "x": 0.1, "s": "a", "b": true, "o": {"k": 1.5}})", "cp.json");
  const JsonFields f(j, "cp.json");
  EXPECT_EQ(Error([&] { f.Integer("n", 1, 40); }), "cp.json: field 'n' = -3 is outside its allowed range [1, 40]");
  EXPECT_EQ(Error([&] { f.Integer("x", 0, 1); }), "cp.json: field 'x' must be an integer, got 0.1");
  EXPECT_EQ(Error([&] { f.Number("x", {0.5, 1.9}); }), "cp.json: field 'x' = 0.1 is outside its allowed range [0.5, 1.9]");
  EXPECT_EQ(Error([&] { f.Number("x", {0.1, 1.0, true}); }),
            "cp.json: field 'x' = 0.1 is outside its allowed range (0.1, 1]");
  EXPECT_EQ(Error([&] { f.Get("format"); }), "cp.json: missing field 'format'");
  EXPECT_EQ(Error([&] { f.Unsigned("n", 10); }), "cp.json: field 'n' = -3 is outside its allowed range [0, 10]");
  EXPECT_EQ(Error([&] { f.Bool("s"); }), "cp.json: field 's' must be true or false, got \"a\"");
  EXPECT_EQ(Error([&] { f.OneOf("s", {"biped", "tripod"}); }), "cp.json: field 's' = \"a\" is not one of biped, tripod");
  EXPECT_EQ(Error([&] { f.Object("o").Integer("k", 0, 9); }), "cp.json: field 'o.k' must be an integer, got 1.5");
  EXPECT_EQ(Error([&] { f.RequireOnly({"n", "x", "s", "b"}); }), "cp.json: unknown field 'o'");
  EXPECT_EQ(f.Integer("n", -5, 5), -3);
  EXPECT_TRUE(f.Bool("b"));
}

TEST(JsonFieldsTest, IntegersBeyondTheirTypeAreOutOfRangeNotWrapped) {
  const json j = ParseJson(R"({"u": 18446744073709551615})", "f.json");
  const JsonFields f(j, "f.json");
  EXPECT_NE(Error([&] { f.Integer("u", 0, 100); }).find("is outside its allowed range [0, 100]"), std::string::npos);
  EXPECT_EQ(f.Unsigned("u", UINT64_MAX), UINT64_MAX);
}

TEST(RequireInRangeTest, PrintsBoundsInTheirShortestForm) {
  try {
    RequireInRange("mutation_probability", 1.5, {0.0, 1.0, true});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "mutation_probability = 1.5 is outside its allowed range (0, 1]");
  }
  EXPECT_NO_THROW(RequireInRange("population", 2, 2, 100000));
}

}  // namespace
}  // namespace walkers
