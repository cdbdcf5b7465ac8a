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
// SSE2 register on x86-64, one NEON register on ARM).
using Pair = double __attribute__((vector_size(16)));

inline Pair Load(const double* both) {
  Pair pair;
  std::memcpy(&pair, both, sizeof pair);
  return pair;
}

// std::max(a, b) and std::min(a, b), lane by lane, with the same answer when b is NaN: a.
inline Pair Max(Pair a, Pair b) {
  return a < b ? b : a;
}
inline Pair Min(Pair a, Pair b) {
  return b < a ? b : a;
}

// RayHitsBox for the four children of a packed node at once, in the same arithmetic
// with the slab bounds taken in the order the ray meets them instead of sorted after. A
// ray parallel to a slab (1/D = +-inf) gets -inf or +inf from it, or NaN exactly on its
// boundary, which Max and Min ignore: the same answers as RayHitsBox's test for D = 0.
// An unused child's box, from +inf to -inf, is never hit.
inline void RayHitsChildren(const double (&bounds)[2][3][4], const SlabRay& ray, double t_min,
                            double t_max, double (&enter)[4], bool (&hits)[4]) {
  for (int half = 0; half < 2; ++half) {
    Pair near = {t_min, t_min};
    Pair far = {t_max, t_max};
    for (int axis = 0; axis < 3; ++axis) {
      const int first = ray.first[axis];
      const Pair O = {ray.O[axis], ray.O[axis]};
      const Pair inv_D = {ray.inv_D[axis], ray.inv_D[axis]};
      near = Max(near, (Load(&bounds[first][axis][2 * half]) - O) * inv_D);
      far = Min(far, (Load(&bounds[1 - first][axis][2 * half]) - O) * inv_D);
    }
    for (int c = 0; c < 2; ++c) {
      enter[2 * half + c] = near[c];
      hits[2 * half + c] = near[c] <= far[c];
    }
  }
}

}  // namespace

// Appends node's subtree to packed_ (inner nodes) and leaves_; its child reference.
// An inner node takes up to four children: its own two, and in place of an inner one
// its two, the largest first.
int Bvh::Pack(int node) {
  if (nodes_[node].count > 0) {
    leaves_.push_back({nodes_[node].first, nodes_[node].count});
    return ~static_cast<int>(leaves_.size() - 1);
  }
  const int index = static_cast<int>(packed_.size());
  packed_.emplace_back();
  int children[4] = {node + 1, nodes_[node].second_child};
  int count = 2;
  while (count < 4) {
    int widest = -1;
    for (int c = 0; c < count; ++c) {
      const Node& child = nodes_[children[c]];
      if (child.count == 0 &&
          (widest < 0 || SurfaceArea(child.box) > SurfaceArea(nodes_[children[widest]].box))) {
        widest = c;
      }
    }
    if (widest < 0) {
      break;
    }
    const int inner = children[widest];
    children[widest] = inner + 1;
    children[count++] = nodes_[inner].second_child;
  }
  packed_[index].count = count;
  for (int c = 0; c < 4; ++c) {
    for (int axis = 0; axis < 3; ++axis) {
      packed_[index].bounds[0][axis][c] = c < count ? nodes_[children[c]].box.min[axis] : kFloatInf;
      packed_[index].bounds[1][axis][c] =
          c < count ? nodes_[children[c]].box.max[axis] : -kFloatInf;
    }
    // Pack may move packed_: index, not a reference.
    const int child = c < count ? Pack(children[c]) : 0;
    packed_[index].child[c] = child;
  }
  return index;
}

// Walks the nodes whose box the ray enters within [t_min, min(t_max, best)], the
// nearest child first, so that the farther ones are often skipped, and calls
// visit(leaf) for each leaf reached; stops when visit returns true. `best` is read at
// every step: Closest narrows it as it finds hits. The build's tree is under 64
// levels deep (Build) for any scene that fits in memory, so this one is too, and each
// level leaves at most three children on the stack.
template <typename Visit>
void Bvh::Walk(const Ray& ray, double t_min, double t_max, const double& best, Visit visit) const {
  const SlabRay slab = MakeSlabRay(ray);
  double t_root = 0;
  cgfs::Tally(kBoxTests);
  if (!RayHitsBox(root_box_, ray.O, ray.D, slab.inv_D, t_min, t_max, t_root)) {
    return;
  }
  struct Entry {
    int child;
    double t_enter;
  };
  Entry stack[3 * 64];
  int size = 0;
  stack[size++] = {root_, t_root};
  while (size > 0) {
    Entry entry = stack[--size];
    // Down the nearest child, the others left on the stack nearest on top, until a leaf.
    while (entry.child >= 0 && entry.t_enter <= best) {
      const PackedNode& node = packed_[entry.child];
      cgfs::Tally(kBoxTests, node.count);
      double enter[4];
      bool hits[4];
      RayHitsChildren(node.bounds, slab, t_min, std::min(t_max, best), enter, hits);
      // The children hit, farthest first.
      Entry order[4];
      int n = 0;
      for (int c = 0; c < 4; ++c) {
        if (hits[c]) {
          int k = n++;
          for (; k > 0 && order[k - 1].t_enter < enter[c]; --k) {
            order[k] = order[k - 1];
          }
          order[k] = {node.child[c], enter[c]};
        }
      }
      if (n == 0) {
        entry.t_enter = cgfs::kInf;  // no child: back to the stack
        break;
      }
      for (int k = 0; k < n - 1; ++k) {
        stack[size++] = order[k];
      }
      entry = order[n - 1];
    }
    // A leaf the ray enters before the best hit so far (it may have got nearer since
    // the leaf was put on the stack).
    if (entry.child < 0 && entry.t_enter <= best && visit(leaves_[~entry.child])) {
      return;
    }
  }
}

template <typename Test>
bool Bvh::InSceneOrder(Test test) const {
  for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
    cgfs::Tally(kObjectTests);
    if (test(candidate)) {
      return true;
    }
  }
  return false;
}

Hit Bvh::Closest(const Ray& ray, double t_min, double t_max, int& object) const {
  Hit best;
  object = -1;
  if (order_.empty()) {
    return best;
  }
  const auto test = [&](int slot) {
    cgfs::Tally(kObjectTests);
    const int candidate = order_[slot];
    // Only as far as the best hit so far (a tie there still counts).
    const Hit hit = IntersectSlot(slot, ray, t_min, std::min(t_max, best.t));
    // On a tie the lower index wins, as in the plain loop, which keeps the first.
    if (hit.t < best.t || (hit.t == best.t && hit.t < cgfs::kInf && candidate < object)) {
      best = hit;
      object = candidate;
    }
  };
  if (root_ < 0) {  // all in one leaf: without a box test
    InSceneOrder([&](int candidate) {
      const Hit hit = objects_[candidate]->Intersect(ray, t_min, t_max);
      if (hit.t < best.t) {
        best = hit;
        object = candidate;
      }
      return false;
    });
    return best;
  }
  Walk(ray, t_min, t_max, best.t, [&](const Leaf& leaf) {
    for (int slot = leaf.first; slot < leaf.first + leaf.count; ++slot) {
      test(slot);
    }
    return false;
  });
  return best;
}

bool Bvh::Any(const Ray& ray, double t_min, double t_max, int& object) const {
  object = -1;
  if (root_ < 0) {  // all in one leaf: without a box test
    return InSceneOrder([&](int candidate) {
      const bool hit = objects_[candidate]->Intersect(ray, t_min, t_max).t < cgfs::kInf;
      object = hit ? candidate : object;
      return hit;
    });
  }
  if (order_.empty()) {
    return false;
  }
  Walk(ray, t_min, t_max, t_max, [&](const Leaf& leaf) {
    for (int slot = leaf.first; slot < leaf.first + leaf.count; ++slot) {
      cgfs::Tally(kObjectTests);
      if (IntersectSlot(slot, ray, t_min, t_max).t < cgfs::kInf) {
        object = order_[slot];
        return true;
      }
    }
    return false;
  });
  return object >= 0;
}
