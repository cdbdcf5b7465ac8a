#include "cases.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cgfs::test {

std::string FunctionCase::Describe() const {
  return function + ", case " + std::to_string(number) + " of " + file + ": " + catches +
         "; args " + args.dump() + (given.is_null() ? "" : "; given " + given.dump());
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
                     each.at("args"),
                     each.at("expected"),
                     each.at("tolerance").get<double>()};
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
  return value.get<double>();
}

Vec3 ToVector(const nlohmann::json& value) {
  return {ToNumber(value.at(0)), ToNumber(value.at(1)), ToNumber(value.at(2))};
}

Color ToColor(const nlohmann::json& value) {
  return {ToNumber(value.at(0)), ToNumber(value.at(1)), ToNumber(value.at(2))};
}

bool Near(double actual, double expected, double tolerance) {
  if (std::isinf(expected)) {
    return actual == expected;
  }
  return std::abs(actual - expected) <= tolerance;
}

MatchesCase::MatchesCase(const FunctionCase& c) : tolerance_(c.tolerance) {
  if (c.expected.is_array()) {
    for (const nlohmann::json& each : c.expected) {
      expected_.push_back(ToNumber(each));
    }
  } else {
    expected_.push_back(ToNumber(c.expected));
  }
}

bool MatchesCase::match(const std::vector<double>& actual) const {
  if (actual.size() != expected_.size()) {
    return false;
  }
  for (std::size_t i = 0; i < actual.size(); ++i) {
    if (!Near(actual[i], expected_[i], tolerance_)) {
      return false;
    }
  }
  return true;
}

std::string MatchesCase::describe() const {
  std::ostringstream out;
  out.precision(10);
  out << "is within " << tolerance_ << " of {";
  for (std::size_t i = 0; i < expected_.size(); ++i) {
    out << (i > 0 ? ", " : " ") << expected_[i];
  }
  out << " } (expected)";
  return out.str();
}

}  // namespace cgfs::test
