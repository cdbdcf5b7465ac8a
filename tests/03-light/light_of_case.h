// A light of the cases in tests/cases/03-light.json and later: {"type": "ambient" |
// "point" | "directional", "intensity", "position" or "direction"}.
#pragma once

#include <string>

#include "cases.h"
#include "raytracer.h"

inline Light LightOfCase(const nlohmann::json& light) {
  const std::string type = light.at("type");
  const auto vector = [&](const char* name) {
    return light.contains(name) ? cgfs::test::ToVector(light.at(name)) : Vec3(0, 0, 0);
  };
  return {type == "ambient" ? LightType::kAmbient
          : type == "point" ? LightType::kPoint
                            : LightType::kDirectional,
          cgfs::test::ToNumber(light.at("intensity")), vector("position"), vector("direction")};
}
