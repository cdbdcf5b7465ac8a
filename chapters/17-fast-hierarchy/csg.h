// "Constructive Solid Geometry": solids made of other solids with set operations,
// worked out along each ray on the spans of t where the ray is inside each operand.
#pragma once

#include <memory>
#include <vector>

#include "objects.h"

enum class CsgOperation {
  kUnion,         // inside A or inside B
  kIntersection,  // inside A and inside B (the book's lens: two spheres)
  kDifference,    // inside A and not inside B (the book's "Death Star")
};

class CsgSolid final : public Solid {
 public:
  CsgSolid(CsgOperation op, std::shared_ptr<Solid> first, std::shared_ptr<Solid> second)
      : operation(op), a(std::move(first)), b(std::move(second)) {}

  void Spans(const Ray& ray, std::vector<Span>& spans) const override;
  Vec3 Normal(const Vec3& P) const override;  // never asked: hits name the part they are on
  Box Bounds() const override;
  std::shared_ptr<Object> Prepared(const Vec3& camera_position) const override;

  CsgOperation operation;
  std::shared_ptr<Solid> a;
  std::shared_ptr<Solid> b;
};

// The spans of `operation` applied to two sorted span lists. A boundary that comes
// from B in a difference is where the ray leaves (or enters) the hole, so its
// normal is turned around: it must point out of the result, into B.
std::vector<Span> CombineSpans(CsgOperation operation, const std::vector<Span>& a,
                               const std::vector<Span>& b);
