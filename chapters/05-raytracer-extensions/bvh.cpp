// Walking the bounding-volume hierarchy (bvh.h): the rays' side of it.
#include "bvh.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace {

// A ray as the packed nodes test it: per axis, 1/D and which bound of a slab the
// ray meets first (the max when D < 0).
struct SlabRay {
  Vec3 O;
  Vec3 inv_D;
  int first[3];
};

SlabRay MakeSlabRay(const Ray& ray) {
  SlabRay slab{ray.O, 1.0 / ray.D, {}};
  for (int axis = 0; axis < 3; ++axis) {
    slab.first[axis] = std::signbit(slab.inv_D[axis]) ? 1 : 0;
  }
  return slab;
}

// Two doubles, one per child, worked on together (a GCC and Clang vector type: one
// SSE2 register on x86-64, one NEON register on ARM), and two floats, as the packed
// node stores a bound of both children.
using Pair = double __attribute__((vector_size(16)));
using FloatPair = float __attribute__((vector_size(8)));

inline Pair Load(const float (&both)[2]) {
  FloatPair f;
  std::memcpy(&f, both, sizeof f);
  return __builtin_convertvector(f, Pair);
}

// std::max(a, b) and std::min(a, b), lane by lane, with the same answer when b is NaN: a.
inline Pair Max(Pair a, Pair b) {
  return a < b ? b : a;
}
inline Pair Min(Pair a, Pair b) {
  return b < a ? b : a;
}

// RayHitsBox for the two children of a packed node at once, on their float boxes, in
// the same double arithmetic with the slab bounds taken in the order the ray meets
// them instead of sorted after. A ray parallel to a slab (1/D = +-inf) gets -inf or
// +inf from it, or NaN exactly on its boundary, which Max and Min ignore: the same
// answers as RayHitsBox's test for D = 0.
inline void RayHitsChildren(const float (&bounds)[2][3][2], const SlabRay& ray, double t_min,
                            double t_max, double (&enter)[2], bool (&hits)[2]) {
  Pair near = {t_min, t_min};
  Pair far = {t_max, t_max};
  for (int axis = 0; axis < 3; ++axis) {
    const int first = ray.first[axis];
    const Pair O = {ray.O[axis], ray.O[axis]};
    const Pair inv_D = {ray.inv_D[axis], ray.inv_D[axis]};
    near = Max(near, (Load(bounds[first][axis]) - O) * inv_D);
    far = Min(far, (Load(bounds[1 - first][axis]) - O) * inv_D);
  }
  for (int c = 0; c < 2; ++c) {
    enter[c] = near[c];
    hits[c] = near[c] <= far[c];
  }
}

}  // namespace

// Appends node's subtree to packed_ (inner nodes) and leaves_; its child reference.
int Bvh::Pack(int node) {
  if (nodes_[node].count > 0) {
    leaves_.push_back({nodes_[node].first, nodes_[node].count});
    return ~static_cast<int>(leaves_.size() - 1);
  }
  const int index = static_cast<int>(packed_.size());
  packed_.emplace_back();
  const int children[2] = {node + 1, nodes_[node].second_child};
  for (int c = 0; c < 2; ++c) {
    const FloatBox& box = nodes_[children[c]].box;
    for (int axis = 0; axis < 3; ++axis) {
      packed_[index].bounds[0][axis][c] = box.min[axis];
      packed_[index].bounds[1][axis][c] = box.max[axis];
    }
    const int child = Pack(children[c]);  // may move packed_: index, not a reference
    packed_[index].child[c] = child;
  }
  return index;
}

// Walks the nodes whose box the ray enters within [t_min, min(t_max, best)], the
// nearer child first, so that the farther one is often skipped, and calls visit(leaf)
// for each leaf reached; stops when visit returns true. `best` is read at every step:
// Closest narrows it as it finds hits. The tree's depth, and so the stack, stays
// under 64 (Build) for any scene that fits in memory.
template <typename Visit, typename Count>
void Bvh::Walk(const Ray& ray, double t_min, double t_max, const double& best, Visit visit,
               Count& count) const {
  const SlabRay slab = MakeSlabRay(ray);
  double t_root = 0;
  count.Boxes(1);
  if (!RayHitsBox(root_box_, ray.O, ray.D, slab.inv_D, t_min, t_max, t_root)) {
    return;
  }
  struct Entry {
    int child;
    double t_enter;
  };
  Entry stack[64];
  int size = 0;
  stack[size++] = {root_, t_root};
  while (size > 0) {
    Entry entry = stack[--size];
    // Down the nearer child, the farther one left on the stack, until a leaf.
    while (entry.child >= 0 && entry.t_enter <= best) {
      const PackedNode& node = packed_[entry.child];
      count.Boxes(2);
      double enter[2];
      bool hits[2];
      RayHitsChildren(node.bounds, slab, t_min, std::min(t_max, best), enter, hits);
      const int near = (hits[1] && (!hits[0] || enter[1] < enter[0])) ? 1 : 0;
      if (!hits[near]) {
        entry.t_enter = cgfs::kInf;  // neither child: back to the stack
        break;
      }
      if (hits[1 - near]) {
        stack[size++] = {node.child[1 - near], enter[1 - near]};
      }
      entry = {node.child[near], enter[near]};
    }
    // A leaf the ray enters before the best hit so far (it may have got nearer since
    // the leaf was put on the stack).
    if (entry.child < 0 && entry.t_enter <= best && visit(leaves_[~entry.child])) {
      return;
    }
  }
}

Hit Bvh::Closest(const Ray& ray, double t_min, double t_max, int& object) const {
  NoCount none;
  return FindClosest(ray, t_min, t_max, object, none);
}

Bvh::Tests Bvh::CountClosest(const Ray& ray, double t_min, double t_max) const {
  struct Counter {
    Tests tests;
    void Boxes(int n) { tests.boxes += n; }
    void Object() { ++tests.objects; }
  } counter;
  int object = -1;
  FindClosest(ray, t_min, t_max, object, counter);
  return counter.tests;
}

template <typename Count>
Hit Bvh::FindClosest(const Ray& ray, double t_min, double t_max, int& object, Count& count) const {
  Hit best;
  object = -1;
  if (order_.empty()) {
    return best;
  }
  const auto test = [&](int slot) {
    count.Object();
    const int candidate = order_[slot];
    const Hit hit = IntersectSlot(slot, ray, t_min, t_max);
    // On a tie the lower index wins, as in the plain loop, which keeps the first.
    if (hit.t < best.t || (hit.t == best.t && hit.t < cgfs::kInf && candidate < object)) {
      best = hit;
      object = candidate;
    }
  };
  if (root_ < 0) {  // all in one leaf: the plain loop, in scene order, without a box test
    for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
      count.Object();
      const Hit hit = objects_[candidate]->Intersect(ray, t_min, t_max);
      if (hit.t < best.t) {
        best = hit;
        object = candidate;
      }
    }
    return best;
  }
  Walk(
      ray, t_min, t_max, best.t,
      [&](const Leaf& leaf) {
        for (int slot = leaf.first; slot < leaf.first + leaf.count; ++slot) {
          test(slot);
        }
        return false;
      },
      count);
  return best;
}

bool Bvh::Any(const Ray& ray, double t_min, double t_max, int& object) const {
  object = -1;
  if (root_ < 0) {  // all in one leaf: the plain loop, in scene order
    for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
      if (objects_[candidate]->Intersect(ray, t_min, t_max).t < cgfs::kInf) {
        object = candidate;
        return true;
      }
    }
    return false;
  }
  if (order_.empty()) {
    return false;
  }
  NoCount none;
  Walk(
      ray, t_min, t_max, t_max,
      [&](const Leaf& leaf) {
        for (int slot = leaf.first; slot < leaf.first + leaf.count; ++slot) {
          if (IntersectSlot(slot, ray, t_min, t_max).t < cgfs::kInf) {
            object = order_[slot];
            return true;
          }
        }
        return false;
      },
      none);
  return object >= 0;
}
