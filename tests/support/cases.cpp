#include "cases.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cgfs::test {

std::string FunctionCase::Describe() const {
  return function + ", case " + std::to_string(number) + " of " + file + ": " + catches +
         (calls.empty() ? "; args " + args.dump() : "; calls " + calls.dump()) +
         (given.is_null() ? "" : "; given " + given.dump());
}

std::vector<FunctionCase> CasesOf(const std::string& file, const std::string& function) {
  const std::string path = std::string(CGFS_CASES_DIR) + "/" + file;
  std::ifstream in(path);
  if (!in) {
    throw std::runtime_error("cannot read the cases " + path);
  }
  const nlohmann::json cases = nlohmann::json::parse(in);
  std::vector<FunctionCase> found;
  for (const nlohmann::json& entry : cases.at("functions")) {
    if (entry.at("function") != function) {
      continue;
    }
    for (const nlohmann::json& each : entry.at("cases")) {
      FunctionCase c{file,
                     function,
                     static_cast<int>(found.size()) + 1,
                     each.at("catches").get<std::string>(),
                     each.value("given", nlohmann::json()),
                     each.value("args", nlohmann::json::object()),
                     each.value("calls", nlohmann::json::array()),
                     each.at("expected"),
                     each.at("tolerance").get<double>(),
                     each.value("compare", "")};
      found.push_back(c);
    }
  }
  if (found.empty()) {
    throw std::runtime_error(path + " has no cases of " + function);
  }
  return found;
}

double ToNumber(const nlohmann::json& value) {
  if (value.is_string()) {
    if (value == "inf") {
      return cgfs::kInf;
    }
    if (value == "-inf") {
      return -cgfs::kInf;
    }
    throw std::runtime_error("not a number in the cases: " + value.dump());
  }
  if (value.is_boolean()) {
    return value.get<bool>() ? 1 : 0;
  }
  return value.get<double>();
}

Vec3 ToVector(const nlohmann::json& value) {
  return {ToNumber(value.at(0)), ToNumber(value.at(1)), ToNumber(value.at(2))};
}

Color ToColor(const nlohmann::json& value) {
  return {ToNumber(value.at(0)), ToNumber(value.at(1)), ToNumber(value.at(2))};
}

glm::dmat4 ToMatrix(const nlohmann::json& rows) {
  glm::dmat4 matrix(1.0);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      matrix[column][row] = ToNumber(rows.at(row).at(column));
    }
  }
  return matrix;
}

std::vector<double> AsNumbers(const glm::dmat4& value) {
  std::vector<double> numbers;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      numbers.push_back(value[column][row]);
    }
  }
  return numbers;
}

namespace {

// Whether `actual` is within `tolerance` of `expected` (infinities equal themselves).
bool Near(double actual, double expected, double tolerance) {
  if (std::isinf(expected)) {
    return actual == expected;
  }
  return std::abs(actual - expected) <= tolerance;
}

// Every number of a case's expected value, lists within lists flattened in order.
void Flatten(const nlohmann::json& value, std::vector<double>& numbers) {
  if (value.is_null()) {  // none: a function that returns nothing here
    return;
  }
  if (value.is_array()) {
    for (const nlohmann::json& each : value) {
      Flatten(each, numbers);
    }
  } else {
    numbers.push_back(ToNumber(value));
  }
}

}  // namespace

std::vector<double> DrawnPixelsAsNumbers(const Canvas& canvas) {
  const Rgb8 background{static_cast<std::uint8_t>(kCaseBackground.r),
                        static_cast<std::uint8_t>(kCaseBackground.g),
                        static_cast<std::uint8_t>(kCaseBackground.b)};
  std::vector<double> pixels;
  for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
    for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
      const Rgb8 pixel = canvas.GetPixel(x, y);
      if (!(pixel == background)) {
        pixels.insert(pixels.end(),
                      {static_cast<double>(x), static_cast<double>(y), static_cast<double>(pixel.r),
                       static_cast<double>(pixel.g), static_cast<double>(pixel.b)});
      }
    }
  }
  return pixels;
}

MatchesCase::MatchesCase(const FunctionCase& c)
    : tolerance_(c.tolerance), truncated_(c.compare == "truncated") {
  Flatten(c.expected, expected_);
}

bool MatchesCase::match(const std::vector<double>& actual) const {
  if (actual.size() != expected_.size()) {
    return false;
  }
  for (std::size_t i = 0; i < actual.size(); ++i) {
    if (!Near(truncated_ ? std::trunc(actual[i]) : actual[i], expected_[i], tolerance_)) {
      return false;
    }
  }
  return true;
}

std::string MatchesCase::describe() const {
  std::ostringstream out;
  out.precision(10);
  out << (truncated_ ? "truncated toward zero, is within " : "is within ") << tolerance_ << " of {";
  for (std::size_t i = 0; i < expected_.size(); ++i) {
    out << (i > 0 ? ", " : " ") << expected_[i];
  }
  out << " } (expected)";
  return out.str();
}

}  // namespace cgfs::test
