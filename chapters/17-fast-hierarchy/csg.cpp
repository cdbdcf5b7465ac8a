#include "csg.h"

#include <algorithm>
#include <cstddef>
#include <memory>

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

namespace {

// Walks along the ray through every boundary of both operands in order of t,
// keeping track of whether the ray is inside A and inside B; the result's spans
// begin and end where the combination changes. Appends them to `out`; `events` is
// scratch space, kept by the caller so that a ray allocates nothing.
void CombineSpansInto(CsgOperation operation, const std::vector<Span>& a,
                      const std::vector<Span>& b, std::vector<Event>& events,
                      std::vector<Span>& out) {
  events.clear();
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

  const std::size_t first = out.size();
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
    inside = now_inside;
    if (now_inside) {
      current.in = boundary;
      continue;
    }
    current.out = boundary;
    // Where operands touch, the walk can end a span and start the next at the same t
    // (the union of [4, 6] and [6, 8]), or make a span of no length (their
    // intersection). Neither has a surface a ray could meet: join the first, drop the
    // second (once joining is done: a joined span may have length).
    if (out.size() > first && out.back().out.t == current.in.t) {
      out.back().out = current.out;
    } else {
      out.push_back(current);
    }
  }
  out.erase(std::remove_if(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(),
                           [](const Span& span) { return span.in.t == span.out.t; }),
            out.end());
}

}  // namespace

std::vector<Span> CombineSpans(CsgOperation operation, const std::vector<Span>& a,
                               const std::vector<Span>& b) {
  std::vector<Event> events;
  std::vector<Span> combined;
  CombineSpansInto(operation, a, b, events, combined);
  return combined;
}

namespace {

// Each thread's scratch space for CSG, one set per level of nesting of the solid
// being tested, kept from ray to ray: once its vectors have grown, a ray's CSG tests
// allocate nothing.
struct CsgScratch {
  std::vector<Span> a;
  std::vector<Span> b;
  std::vector<Event> events;
};

thread_local std::vector<std::unique_ptr<CsgScratch>> scratch_sets;
thread_local std::size_t nesting = 0;

// The scratch set of the next level, released when it goes out of scope.
class ScratchLevel {
 public:
  ScratchLevel() {
    if (scratch_sets.size() <= nesting) {
      scratch_sets.push_back(std::make_unique<CsgScratch>());
    }
    set_ = scratch_sets[nesting++].get();
    set_->a.clear();
    set_->b.clear();
  }
  ~ScratchLevel() { --nesting; }
  ScratchLevel(const ScratchLevel&) = delete;
  ScratchLevel& operator=(const ScratchLevel&) = delete;
  CsgScratch& operator*() const { return *set_; }

 private:
  CsgScratch* set_;
};

}  // namespace

void CsgSolid::Spans(const Ray& ray, std::vector<Span>& spans) const {
  const ScratchLevel level;
  CsgScratch& scratch = *level;
  a->Spans(ray, scratch.a);
  b->Spans(ray, scratch.b);
  CombineSpansInto(operation, scratch.a, scratch.b, scratch.events, spans);
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

std::shared_ptr<Object> CsgSolid::Prepared(const Vec3& camera_position) const {
  auto prepared = std::make_shared<CsgSolid>(*this);
  for (std::shared_ptr<Solid>* part : {&prepared->a, &prepared->b}) {
    if (std::shared_ptr<Object> copy = (*part)->Prepared(camera_position)) {
      *part = std::static_pointer_cast<Solid>(copy);  // a solid's copy is a solid
    }
  }
  return prepared;
}
