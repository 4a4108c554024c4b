// SPDX-License-Identifier: BSD-3-Clause
// Requirement: Parameters is a view into one shared JSON document (Kratos semantics); every getter
// rejects a value of the wrong type with an InputError naming the file, the path and the value;
// JSON syntax errors give line and column; files with a BOM and CRLF line ends are read.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/parameters/parameters.h"
#include "core/utilities/error.h"
#include "tests/cpp/common/error_message.h"

namespace mc {
namespace {

const char* kSettings = R"({
  "problem_data": {"problem_name": "hertz", "echo_level": 1, "start_time": 0.0, "end_time": 1},
  "solver_settings": {
    "max_iteration": "ten",
    "tolerance": 1e-6,
    "flag": true,
    "direction": [0.0, -1.0, 0],
    "mixed": [1, "a"],
    "matrix": [[1, 2, 3], [4, 5, 6]],
    "ragged": [[1, 2], [3]],
    "names": ["A", "B"],
    "nothing": null,
    "float_int": 10.0,
    "half": 2.5
  }
})";

TEST(Parameters, SubViewWritesAreSeenFromTheRoot) {
  Parameters root(kSettings, "ProjectParameters.json");
  Parameters solver = root["solver_settings"];
  solver["tolerance"].SetDouble(1e-9);
  solver.AddString("new_key", "hello");
  EXPECT_DOUBLE_EQ(root["solver_settings"]["tolerance"].GetDouble(), 1e-9);
  EXPECT_EQ(root["solver_settings"]["new_key"].GetString(), "hello");
  Parameters copy = solver;  // copying a view shares the document
  copy["flag"].SetBool(false);
  EXPECT_FALSE(root["solver_settings"]["flag"].GetBool());
  EXPECT_EQ(solver["tolerance"].Path(), "solver_settings.tolerance");
  EXPECT_EQ(root["solver_settings"]["direction"][1].Path(), "solver_settings.direction[1]");
}

TEST(Parameters, CloneIsIndependent) {
  Parameters root(kSettings, "f.json");
  Parameters clone = root["solver_settings"].Clone();
  clone["tolerance"].SetDouble(5.0);
  EXPECT_DOUBLE_EQ(root["solver_settings"]["tolerance"].GetDouble(), 1e-6);
  EXPECT_DOUBLE_EQ(clone["tolerance"].GetDouble(), 5.0);
  EXPECT_EQ(clone.Origin(), "f.json");
  EXPECT_EQ(clone["tolerance"].Path(), "solver_settings.tolerance");
}

TEST(Parameters, AddValueAndAppendCopyDeeply) {
  Parameters root;
  Parameters item(R"({"a": 1})");
  root.AddValue("item", item);
  root.AddEmptyArray("list");
  root["list"].Append(item);
  root["list"].Append(item);
  item["a"].SetInt(7);
  EXPECT_EQ(root["item"]["a"].GetInt(), 1);
  EXPECT_EQ(root["list"].size(), 2u);
  EXPECT_EQ(root["list"][1]["a"].GetInt(), 1);
  root.AddValue("item", item);  // overwrites
  EXPECT_EQ(root["item"]["a"].GetInt(), 7);
  root.SetValue("item", root["item"]["a"]);  // source inside the target
  EXPECT_EQ(root["item"].GetInt(), 7);
  EXPECT_TRUE(root.RemoveValue("item"));
  EXPECT_FALSE(root.RemoveValue("item"));
  EXPECT_FALSE(root.Has("item"));
  root.AddEmptyValue("later");
  EXPECT_TRUE(root["later"].IsNull());
  EXPECT_EQ(root.WriteJsonString(), R"({"later":null,"list":[{"a":1},{"a":1}]})");
  EXPECT_EQ(Parameters(R"({"a":[1]})").PrettyPrintJsonString(), "{\n    \"a\": [\n        1\n    ]\n}");
}

TEST(Parameters, GettersReturnValues) {
  Parameters s = Parameters(kSettings)["solver_settings"];
  EXPECT_DOUBLE_EQ(s["tolerance"].GetDouble(), 1e-6);
  EXPECT_DOUBLE_EQ(Parameters(kSettings)["problem_data"]["end_time"].GetDouble(), 1.0);  // int as double
  EXPECT_EQ(s["float_int"].GetInt(), 10);                                                // integral-valued float as int
  EXPECT_TRUE(s["flag"].GetBool());
  const Vector d = s["direction"].GetVector();
  ASSERT_EQ(d.size(), 3);
  EXPECT_EQ(d[0], 0.0);
  EXPECT_EQ(d[1], -1.0);
  const Matrix m = s["matrix"].GetMatrix();
  ASSERT_EQ(m.rows(), 2);
  ASSERT_EQ(m.cols(), 3);
  EXPECT_EQ(m(1, 2), 6.0);
  EXPECT_EQ(s["names"].GetStringArray(), (std::vector<std::string>{"A", "B"}));
  EXPECT_TRUE(s["direction"].IsVector());
  EXPECT_FALSE(s["mixed"].IsVector());
  EXPECT_TRUE(s["matrix"].IsMatrix());
  EXPECT_FALSE(s["ragged"].IsMatrix());
  EXPECT_TRUE(s["names"].IsStringArray());
  EXPECT_TRUE(s["half"].IsDouble());
  EXPECT_FALSE(s["half"].IsInt());
  EXPECT_TRUE(s["nothing"].IsNull());
  EXPECT_EQ(s.Keys().front(), "direction");  // objects are sorted by key
}

TEST(Parameters, SettersRoundTrip) {
  Parameters p;
  p.AddEmptyValue("v");
  Vector v(3);
  v << 1.5, -2.0, 3.25;
  p["v"].SetVector(v);
  EXPECT_EQ(p["v"].GetVector(), v);
  Matrix m(2, 2);
  m << 1, 2, 3, 4;
  p.AddMatrix("m", m);
  EXPECT_EQ(p["m"].GetMatrix(), m);
  p["v"].SetStringArray({"x", "y"});
  EXPECT_EQ(p["v"].GetStringArray(), (std::vector<std::string>{"x", "y"}));
  p.AddInt("i", -3);
  EXPECT_EQ(p["i"].GetInt(), -3);
}

TEST(Parameters, MissingKeyNamesPathAndNearestKey) {
  Parameters root(kSettings, "ProjectParameters.json");
  const std::string message = test::ErrorMessageOf([&] { root["solver_settings"]["max_iteratio"]; });
  EXPECT_NE(message.find("ProjectParameters.json: solver_settings.max_iteratio: missing key"), std::string::npos)
      << message;
  EXPECT_NE(message.find("'max_iteration'"), std::string::npos) << message;
  const std::string index = test::ErrorMessageOf([&] { root["solver_settings"]["names"][2]; });
  EXPECT_NE(index.find("solver_settings.names[2]"), std::string::npos) << index;
  EXPECT_NE(index.find("2 items"), std::string::npos) << index;
}

TEST(Parameters, EveryGetterRejectsTheWrongType) {
  Parameters s = Parameters(kSettings, "ProjectParameters.json")["solver_settings"];
  EXPECT_EQ(test::ErrorMessageOf([&] { s["max_iteration"].GetInt(); }),
            "ProjectParameters.json: solver_settings.max_iteration: expected an integer, found string \"ten\"");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["half"].GetInt(); }),
            "ProjectParameters.json: solver_settings.half: expected an integer, found number 2.5");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["max_iteration"].GetDouble(); }),
            "ProjectParameters.json: solver_settings.max_iteration: expected a number, found string \"ten\"");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["tolerance"].GetBool(); }),
            "ProjectParameters.json: solver_settings.tolerance: expected a boolean, found number 1e-06");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["flag"].GetString(); }),
            "ProjectParameters.json: solver_settings.flag: expected a string, found boolean true");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["flag"].GetVector(); }),
            "ProjectParameters.json: solver_settings.flag: expected an array of numbers, found boolean true");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["mixed"].GetVector(); }),
            "ProjectParameters.json: solver_settings.mixed[1]: expected a number, found string \"a\"");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["nothing"].GetMatrix(); }),
            "ProjectParameters.json: solver_settings.nothing: expected an array of equally long arrays of numbers, "
            "found null");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["ragged"].GetMatrix(); }),
            "ProjectParameters.json: solver_settings.ragged[1]: matrix row has 1 entries, the first row has 2");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["direction"].GetStringArray(); }),
            "ProjectParameters.json: solver_settings.direction[0]: expected a string, found number 0.0");
  EXPECT_EQ(test::ErrorMessageOf([&] { s["names"]["x"]; }),
            "ProjectParameters.json: solver_settings.names: expected an object, found array [\"A\",\"B\"]");
  EXPECT_EQ(test::ErrorMessageOf([] { Parameters("{\"big\": 3000000000}")["big"].GetInt(); }),
            "big: expected an integer from -2147483648 to 2147483647, found integer 3000000000");
}

TEST(Parameters, ParseErrorGivesLineAndColumn) {
  const std::string text = "{\n  \"a\": 1,\n  \"b\": [1, 2,,]\n}\n";
  const std::string message = test::ErrorMessageOf([&] { Parameters(text, "case.json"); });
  EXPECT_NE(message.find("case.json: line 3, column 14:"), std::string::npos) << message;
  EXPECT_NE(message.find("\"b\": [1, 2,,]"), std::string::npos) << message;
  const std::string missing_colon = test::ErrorMessageOf([] { Parameters("{\r\n\"a\" 1\r\n}", "x.json"); });
  EXPECT_NE(missing_colon.find("x.json: line 2, column 5:"), std::string::npos) << missing_colon;
}

// Found by fuzzing (issue 16): wrong-type errors on large documents serialized all of them to quote
// 60 characters (quadratic over a document's sub-views); the quote is the same, built from a prefix.
TEST(Parameters, WrongTypeOnALargeDocumentQuotesItsBeginning) {
  std::string text = "{\"a\": [";
  for (int i = 0; i < 200000; ++i) text += std::to_string(i) + ",";
  text += "0], \"b\": {\"c\": \"x\"}}";
  const Parameters root(text);
  const std::string dumped = root.Json().dump();
  const std::string message = test::ErrorMessageOf([&] { root.GetInt(); });
  EXPECT_EQ(message, "settings: expected an integer, found object " + dumped.substr(0, 60) + "...");
  EXPECT_EQ(test::ErrorMessageOf([&] { root["b"].GetInt(); }), "b: expected an integer, found object {\"c\":\"x\"}");
}

// Found by fuzzing (issue 16): nlohmann reports a number past the range of a double as
// out_of_range, not as a parse error; it escaped as an uncaught exception.
TEST(Parameters, NumberOutOfRangeIsAnInputErrorWithLineAndColumn) {
  const std::string message =
      test::ErrorMessageOf([] { Parameters("{\n  \"solver_settings\": {\"tolerance\": 1e400}\n}", "case.json"); });
  EXPECT_NE(
      message.find("case.json: line 2, column 36: invalid JSON: the number 1e400 is outside the range of a double"),
      std::string::npos)
      << message;
}

TEST(Parameters, FromFileWithBomAndCrlf) {
  const auto path = std::filesystem::temp_directory_path() / "mc_test_parameters_crlf.json";
  {
    std::ofstream out(path, std::ios::binary);
    out << "\xEF\xBB\xBF{\r\n  \"name\": \"crlf\",\r\n  // a comment\r\n  \"n\": 3\r\n}\r\n";
  }
  const Parameters p = Parameters::FromFile(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(p["name"].GetString(), "crlf");
  EXPECT_EQ(p["n"].GetInt(), 3);
  EXPECT_EQ(p.Origin(), path.string());
  const std::string message = test::ErrorMessageOf([] { Parameters::FromFile("/nonexistent/dir/p.json"); });
  EXPECT_NE(message.find("/nonexistent/dir/p.json"), std::string::npos) << message;
}

}  // namespace
}  // namespace mc
