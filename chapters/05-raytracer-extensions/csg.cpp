#include "csg.h"

#include <algorithm>

namespace {

bool Inside(CsgOperation operation, bool in_a, bool in_b) {
  switch (operation) {
    case CsgOperation::kUnion:
      return in_a || in_b;
    case CsgOperation::kIntersection:
      return in_a && in_b;
    case CsgOperation::kDifference:
      return in_a && !in_b;
  }
  return false;
}

// A boundary of an operand along the ray: where the ray enters or leaves it.
struct Event {
  Hit hit;
  bool from_a = true;
  bool entering = true;
};

}  // namespace

// Walks along the ray through every boundary of both operands in order of t,
// keeping track of whether the ray is inside A and inside B; the result's spans
// begin and end where the combination changes.
std::vector<Span> CombineSpans(CsgOperation operation, const std::vector<Span>& a,
                               const std::vector<Span>& b) {
  std::vector<Event> events;
  for (const Span& span : a) {
    events.push_back({span.in, true, true});
    events.push_back({span.out, true, false});
  }
  for (const Span& span : b) {
    events.push_back({span.in, false, true});
    events.push_back({span.out, false, false});
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& x, const Event& y) { return x.hit.t < y.hit.t; });

  std::vector<Span> result;
  bool in_a = false;
  bool in_b = false;
  bool inside = false;
  Span current;
  for (const Event& event : events) {
    (event.from_a ? in_a : in_b) = event.entering;
    const bool now_inside = Inside(operation, in_a, in_b);
    if (now_inside == inside) {
      continue;
    }
    Hit boundary = event.hit;
    if (operation == CsgOperation::kDifference && !event.from_a) {
      boundary.flip_normal = !boundary.flip_normal;
    }
    if (now_inside) {
      current.in = boundary;
    } else {
      current.out = boundary;
      result.push_back(current);
    }
    inside = now_inside;
  }
  // Where operands touch, the walk can end a span and start the next at the same t
  // (the union of [4, 6] and [6, 8]), or make a span of no length (their
  // intersection). Neither has a surface a ray could meet: join the first, drop the second.
  std::vector<Span> joined;
  for (const Span& span : result) {
    if (!joined.empty() && joined.back().out.t == span.in.t) {
      joined.back().out = span.out;
    } else {
      joined.push_back(span);
    }
  }
  std::erase_if(joined, [](const Span& span) { return span.in.t == span.out.t; });
  return joined;
}

void CsgSolid::Spans(const Ray& ray, std::vector<Span>& spans) const {
  std::vector<Span> spans_a;
  std::vector<Span> spans_b;
  a->Spans(ray, spans_a);
  b->Spans(ray, spans_b);
  const std::vector<Span> combined = CombineSpans(operation, spans_a, spans_b);
  spans.insert(spans.end(), combined.begin(), combined.end());
}

Vec3 CsgSolid::Normal(const Vec3& P) const {
  return a->Normal(P);
}

Box CsgSolid::Bounds() const {
  switch (operation) {
    case CsgOperation::kUnion:
      return Union(a->Bounds(), b->Bounds());
    case CsgOperation::kIntersection:
      return Intersection(a->Bounds(), b->Bounds());
    case CsgOperation::kDifference:
      return a->Bounds();
  }
  return a->Bounds();
}

void CsgSolid::Prepare(const Vec3& camera_position) {
  a->Prepare(camera_position);
  b->Prepare(camera_position);
}
