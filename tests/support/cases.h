// The function cases of tests/cases/<chapter>.json: for one book function, each case's
// inputs, the output expected, its tolerance and what mistake it catches. Our equation
// tests read them, and so do the runners for other languages (tools/check-functions):
// one set of cases for both.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/math.h"

namespace cgfs::test {

struct FunctionCase {
  std::string file;      // e.g. "02-basic-rays.json"
  std::string function;  // the book's name, e.g. "CanvasToViewport"
  int number = 0;        // from 1, in the file's order
  std::string catches;   // the mistake it catches, in one sentence
  nlohmann::json given;  // the book's globals the function reads: canvas, viewport, scene
  nlohmann::json args;   // its parameters, by the book's names
  // Or, for a function whose effect builds up (a depth buffer): its arguments for each
  // call in turn, all on one canvas and buffer; args is then empty.
  nlohmann::json calls;
  nlohmann::json expected;
  double tolerance = 0;
  // "truncated": yours truncated toward zero before comparing, as a canvas truncates
  // pixel coordinates; empty: as they are.
  std::string compare;

  // "CanvasToViewport, case 4 of 02-basic-rays.json: <catches>; args {...}": what a
  // failure prints first (Catch's INFO).
  std::string Describe() const;
};

// Every case of `function` in tests/cases/<file>; throws with one line when the file
// cannot be read or has no such function.
std::vector<FunctionCase> CasesOf(const std::string& file, const std::string& function);

// A number of a case: a JSON number, "inf" / "-inf" (JSON has no infinity), or true / false
// (1 / 0: what a yes-or-no function such as IsBackFacing is expected to say).
double ToNumber(const nlohmann::json& value);
// [x, y, z].
Vec3 ToVector(const nlohmann::json& value);
// [r, g, b], 0 to 255.
Color ToColor(const nlohmann::json& value);
// [[row 0], [row 1], [row 2], [row 3]]: a 4x4 matrix as the book writes it, row by row.
glm::dmat4 ToMatrix(const nlohmann::json& rows);

// What a function returned, as the list of numbers the case expects.
inline std::vector<double> AsNumbers(const Vec3& value) {
  return {value.x, value.y, value.z};
}
inline std::vector<double> AsNumbers(const std::pair<double, double>& value) {
  return {value.first, value.second};
}
inline std::vector<double> AsNumbers(double value) {
  return {value};
}
inline std::vector<double> AsNumbers(const std::vector<double>& values) {
  return values;
}
// A 4x4 matrix row by row, as the cases write it (GLM keeps it column by column).
std::vector<double> AsNumbers(const glm::dmat4& value);
// None (an empty optional) is no numbers, as the cases write it (null).
inline std::vector<double> AsNumbers(const std::optional<Vec3>& value) {
  return value ? AsNumbers(*value) : std::vector<double>{};
}

// The background of a canvas that a case's function draws on: a colour no case draws.
inline constexpr Color kCaseBackground{1, 2, 3};
// The pixels drawn on such a canvas, as the cases list them: [x, y, r, g, b] in canvas
// coordinates, sorted by x, then y; flattened.
std::vector<double> DrawnPixelsAsNumbers(const Canvas& canvas);

// CHECK_THAT(AsNumbers(yours), MatchesCase(c)): each number within the case's
// tolerance of the one expected; a failure prints both lists.
class MatchesCase : public Catch::MatcherBase<std::vector<double>> {
 public:
  explicit MatchesCase(const FunctionCase& c);
  bool match(const std::vector<double>& actual) const override;
  std::string describe() const override;

 private:
  std::vector<double> expected_;
  double tolerance_;
  bool truncated_;
};

}  // namespace cgfs::test
