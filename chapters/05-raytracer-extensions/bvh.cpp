#include "bvh.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace {

// "Hierarchical Structures" with the surface area heuristic: a ray that enters a box
// enters a child of it with probability (child's area) / (box's area), so a split
// costs one more box test plus, for each child, that probability times its objects'
// tests. The build tries kBins planes along each axis, keeps the cheapest, and makes a
// leaf where no split is cheaper than testing every object (at most kMaxLeaf of them).
constexpr int kBins = 16;
// So few objects are a leaf whatever the heuristic says: a small scene is then one
// leaf, which Closest and Any loop over without any box test.
constexpr int kSmallLeaf = 4;
constexpr int kMaxLeaf = 8;
constexpr double kBoxTestCost = 1;  // relative to one object test
constexpr double kObjectTestCost = 1;

Vec3 Centre(const Box& box) {
  return (box.min + box.max) * 0.5;
}

double SurfaceArea(const Box& box) {
  const Vec3 size = box.max - box.min;
  return 2 * (size.x * size.y + size.y * size.z + size.z * size.x);
}

int LongestAxis(const Vec3& size) {
  if (size.x >= size.y && size.x >= size.z) {
    return 0;
  }
  return size.y >= size.z ? 1 : 2;
}

}  // namespace

Bvh::Bvh(const std::vector<std::shared_ptr<Object>>& objects) {
  const int count = static_cast<int>(objects.size());
  std::vector<Box> boxes;
  boxes.reserve(objects.size());
  for (const auto& object : objects) {
    objects_.push_back(object.get());
    boxes.push_back(object->Bounds());
  }
  order_.resize(objects.size());
  for (int i = 0; i < count; ++i) {
    order_[i] = i;
  }
  nodes_.reserve(objects.size());
  if (count > 0) {
    Build(0, count, boxes, 1);
    root_ = Pack(0);
  }
}

namespace {

// A float at or below v, and one at or above: the float box holds the double one.
float Down(double v) {
  const float f = static_cast<float>(v);
  return f > v ? std::nextafter(f, -HUGE_VALF) : f;
}

float Up(double v) {
  const float f = static_cast<float>(v);
  return f < v ? std::nextafter(f, HUGE_VALF) : f;
}

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

// RayHitsBox for the two children of a packed node at once, on their float boxes, in
// the same double arithmetic with the slab bounds taken in the order the ray meets
// them instead of sorted after. A ray parallel to a slab (1/D = +-inf) gets -inf or
// +inf from it, or NaN exactly on its boundary, which std::max and std::min as called
// here ignore: the same answers as RayHitsBox's test for D = 0.
inline void RayHitsChildren(const float (&bounds)[2][3][2], const SlabRay& ray, double t_min,
                            double t_max, double (&enter)[2], bool (&hits)[2]) {
  double near[2] = {t_min, t_min};
  double far[2] = {t_max, t_max};
  for (int axis = 0; axis < 3; ++axis) {
    const int first = ray.first[axis];
    for (int c = 0; c < 2; ++c) {
      near[c] = std::max(near[c], (bounds[first][axis][c] - ray.O[axis]) * ray.inv_D[axis]);
      far[c] = std::min(far[c], (bounds[1 - first][axis][c] - ray.O[axis]) * ray.inv_D[axis]);
    }
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
    const Box& box = nodes_[children[c]].box;
    for (int axis = 0; axis < 3; ++axis) {
      packed_[index].bounds[0][axis][c] = Down(box.min[axis]);
      packed_[index].bounds[1][axis][c] = Up(box.max[axis]);
    }
    const int child = Pack(children[c]);  // may move packed_: index, not a reference
    packed_[index].child[c] = child;
  }
  return index;
}

// Appends the node of order_[first, first + count) and its subtree: a leaf when few
// objects are left or splitting does not pay, else two children split where the
// surface area heuristic says (SplitBySurfaceArea).
void Bvh::Build(int first, int count, const std::vector<Box>& boxes, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  depth_ = std::max(depth_, depth);
  Box box;
  Box centres;
  for (int i = first; i < first + count; ++i) {
    box = Union(box, boxes[order_[i]]);
    const Vec3 centre = Centre(boxes[order_[i]]);
    centres = Union(centres, {centre, centre});
  }
  nodes_[index].box = box;
  if (count <= kSmallLeaf) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return;
  }
  // An object larger than all the others together (chapter 4's ground, a sphere of
  // radius 5000) would make every box above it as large as itself, and every ray
  // would enter them all: it gets a leaf of its own, beside the tree of the rest.
  int largest = first;
  for (int i = first; i < first + count; ++i) {
    if (SurfaceArea(boxes[order_[i]]) > SurfaceArea(boxes[order_[largest]])) {
      largest = i;
    }
  }
  Box others;
  for (int i = first; i < first + count; ++i) {
    if (i != largest) {
      others = Union(others, boxes[order_[i]]);
    }
  }
  // (At most 24 such levels, so that the depth, and the traversal stack with it,
  // stays under 64 even for objects nested like Russian dolls.)
  if (depth <= 24 && SurfaceArea(boxes[order_[largest]]) > SurfaceArea(others)) {
    std::swap(order_[first], order_[largest]);
    Build(first, 1, boxes, depth + 1);
    nodes_[index].second_child = static_cast<int>(nodes_.size());
    Build(first + 1, count - 1, boxes, depth + 1);
    return;
  }

  // Deep down (only objects nested inside one another get there), halves at the
  // median centre keep the depth, and the traversal's stack, under 64.
  const int split = depth < 40 ? SplitBySurfaceArea(first, count, box, centres, boxes)
                               : SplitAtMedian(first, count, centres, boxes);
  if (split == 0) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return;
  }
  const int half = split;
  Build(first, half, boxes, depth + 1);
  nodes_[index].second_child = static_cast<int>(nodes_.size());
  Build(first + half, count - half, boxes, depth + 1);
}

// Reorders order_[first, first + count) around the median centre along the axis where
// the centres spread most; the first half's size.
int Bvh::SplitAtMedian(int first, int count, const Box& centres, const std::vector<Box>& boxes) {
  const int axis = LongestAxis(centres.max - centres.min);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count, [&](int a, int b) {
                     const double ca = Centre(boxes[a])[axis];
                     const double cb = Centre(boxes[b])[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  return half;
}

// The best place to split order_[first, first + count), by the surface area
// heuristic over kBins bins of the centres along each axis: the number of objects that
// go to the first child, after reordering them; 0 to make a leaf instead. Objects whose
// centres coincide cannot be split by any plane: they are halved in scene order.
int Bvh::SplitBySurfaceArea(int first, int count, const Box& box, const Box& centres,
                            const std::vector<Box>& boxes) {
  struct Bin {
    Box box;
    int count = 0;
  };
  const double area = SurfaceArea(box);
  double best_cost = count <= kMaxLeaf ? count * kObjectTestCost : cgfs::kInf;
  int best_axis = -1;
  int best_plane = 0;
  const auto bin_of = [&](int object, int axis) {
    const double extent = centres.max[axis] - centres.min[axis];
    const double at = (Centre(boxes[object])[axis] - centres.min[axis]) / extent;
    return std::min(kBins - 1, static_cast<int>(at * kBins));
  };
  for (int axis = 0; axis < 3; ++axis) {
    if (!(centres.max[axis] > centres.min[axis])) {
      continue;
    }
    Bin bins[kBins];
    for (int i = first; i < first + count; ++i) {
      Bin& bin = bins[bin_of(order_[i], axis)];
      bin.box = Union(bin.box, boxes[order_[i]]);
      ++bin.count;
    }
    // Left of plane p: bins [0, p); right: [p, kBins).
    double right_area[kBins] = {};
    int right_count[kBins] = {};
    Box right;
    int n = 0;
    for (int p = kBins - 1; p > 0; --p) {
      right = Union(right, bins[p].box);
      n += bins[p].count;
      right_area[p] = SurfaceArea(right);
      right_count[p] = n;
    }
    Box left;
    n = 0;
    for (int p = 1; p < kBins; ++p) {
      left = Union(left, bins[p - 1].box);
      n += bins[p - 1].count;
      if (n == 0 || right_count[p] == 0) {
        continue;
      }
      const double cost = kBoxTestCost + (SurfaceArea(left) * n + right_area[p] * right_count[p]) /
                                             area * kObjectTestCost;
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_plane = p;
      }
    }
  }
  if (best_axis < 0) {
    if (count <= kMaxLeaf) {
      return 0;
    }
    std::sort(order_.begin() + first, order_.begin() + first + count);
    return count / 2;
  }
  const auto middle =
      std::stable_partition(order_.begin() + first, order_.begin() + first + count,
                            [&](int object) { return bin_of(object, best_axis) < best_plane; });
  return static_cast<int>(middle - (order_.begin() + first));
}

double Bvh::SurfaceAreaCost() const {
  if (nodes_.empty()) {
    return 0;
  }
  const double root = SurfaceArea(nodes_.front().box);
  double cost = 0;
  for (const Node& node : nodes_) {
    const double chance = SurfaceArea(node.box) / root;
    cost += chance * (node.count > 0 ? node.count * kObjectTestCost : 2 * kBoxTestCost);
  }
  return cost;
}

// Walks the nodes whose box the ray enters within [t_min, min(t_max, best)], the
// nearer child first, so that the farther one is often skipped, and calls visit(leaf)
// for each leaf reached; stops when visit returns true. `best` is read at every step:
// Closest narrows it as it finds hits. The tree's depth, and so the stack, stays
// under 64 (Build) for any scene that fits in memory.
template <typename Visit>
void Bvh::Walk(const Ray& ray, double t_min, double t_max, const double& best, Visit visit) const {
  const SlabRay slab = MakeSlabRay(ray);
  double t_root = 0;
  if (!RayHitsBox(nodes_[0].box, ray.O, ray.D, slab.inv_D, t_min, t_max, t_root)) {
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
  Hit best;
  object = -1;
  if (order_.empty()) {
    return best;
  }
  const auto test = [&](int candidate) {
    const Hit hit = objects_[candidate]->Intersect(ray, t_min, t_max);
    // On a tie the lower index wins, as in the plain loop, which keeps the first.
    if (hit.t < best.t || (hit.t == best.t && hit.t < cgfs::kInf && candidate < object)) {
      best = hit;
      object = candidate;
    }
  };
  if (root_ < 0) {  // all in one leaf: a box around a list only costs a test
    for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
      test(candidate);
    }
    return best;
  }
  Walk(ray, t_min, t_max, best.t, [&](const Leaf& leaf) {
    for (int i = leaf.first; i < leaf.first + leaf.count; ++i) {
      test(order_[i]);
    }
    return false;
  });
  return best;
}

bool Bvh::Any(const Ray& ray, double t_min, double t_max, int& object) const {
  object = -1;
  const auto hits = [&](int candidate) {
    if (objects_[candidate]->Intersect(ray, t_min, t_max).t < cgfs::kInf) {
      object = candidate;
      return true;
    }
    return false;
  };
  if (root_ < 0) {
    for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
      if (hits(candidate)) {
        return true;
      }
    }
    return false;
  }
  if (order_.empty()) {
    return false;
  }
  Walk(ray, t_min, t_max, t_max, [&](const Leaf& leaf) {
    for (int i = leaf.first; i < leaf.first + leaf.count; ++i) {
      if (hits(order_[i])) {
        return true;
      }
    }
    return false;
  });
  return object >= 0;
}
