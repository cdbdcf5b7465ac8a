// Building the bounding-volume hierarchy (bvh.h): which objects go together.
#include "bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <typeinfo>
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
constexpr int kLargeGroup = 4096;
constexpr double kBoxTestCost = 1;  // relative to one object test
constexpr double kObjectTestCost = 1;

using Int4 = int __attribute__((vector_size(16)));

// A float at or below v, and one at or above: the float box holds the double one.
float Down(double v) {
  const float f = static_cast<float>(v);
  return f > v ? std::nextafter(f, -HUGE_VALF) : f;
}

float Up(double v) {
  const float f = static_cast<float>(v);
  return f < v ? std::nextafter(f, HUGE_VALF) : f;
}

// The object as a prepared sphere, or a triangle, whose tests the leaves hold a copy
// of; nullptr for any other object. Sphere and Triangle are final: typeid names the
// exact type.
const Sphere* PreparedSphere(const Object& object) {
  const auto* sphere =
      typeid(object) == typeid(Sphere) ? static_cast<const Sphere*>(&object) : nullptr;
  return sphere != nullptr && sphere->cached ? sphere : nullptr;
}

const Triangle* AsTriangle(const Object& object) {
  return typeid(object) == typeid(Triangle) ? static_cast<const Triangle*>(&object) : nullptr;
}

// The float box around a double one: each bound rounded outwards.
FloatBox Rounded(const Box& box) {
  FloatBox rounded;
  for (int axis = 0; axis < 3; ++axis) {
    rounded.min[axis] = Down(box.min[axis]);
    rounded.max[axis] = Up(box.max[axis]);
  }
  return rounded;
}

Vec3 Size(const FloatBox& box) {
  const Float4 size = box.max - box.min;
  return {size[0], size[1], size[2]};
}

int LongestAxis(const Vec3& size) {
  if (size.x >= size.y && size.x >= size.z) {
    return 0;
  }
  return size.y >= size.z ? 1 : 2;
}

// Which of kBins equal slices of the centres' box a centre falls in, along x, y and z.
struct Binning {
  Float4 min;
  Float4 scale;  // kBins / extent; 0 along an axis where all centres coincide
  Int4 Of(const Float4& centre) const {
    const Int4 bin = __builtin_convertvector((centre - min) * scale, Int4);
    return bin < kBins - 1 ? bin : kBins - 1;
  }
};

// The objects whose centres fall in one slice, for the heuristic: their box and count.
struct Bin {
  FloatBox box;
  int count = 0;
};

struct Plane {
  double cost = cgfs::kInf;
  int index = 0;  // the first child takes bins [0, index)
};

// The plane between two bins of one axis that the surface area heuristic prefers.
template <typename Bins>
Plane CheapestPlane(const Bins& bins, double area) {
  // Right of plane p: bins [p, kBins), swept from the right first.
  double right_area[kBins] = {};
  int right_count[kBins] = {};
  FloatBox right;
  int n = 0;
  for (int p = kBins - 1; p > 0; --p) {
    right = Union(right, bins[p].box);
    n += bins[p].count;
    right_area[p] = SurfaceArea(right);
    right_count[p] = n;
  }
  Plane best;
  FloatBox left;
  n = 0;
  for (int p = 1; p < kBins; ++p) {
    left = Union(left, bins[p - 1].box);
    n += bins[p - 1].count;
    if (n == 0 || right_count[p] == 0) {
      continue;
    }
    const double cost = kBoxTestCost + (SurfaceArea(left) * n + right_area[p] * right_count[p]) /
                                           area * kObjectTestCost;
    if (cost < best.cost) {
      best = {cost, p};
    }
  }
  return best;
}

}  // namespace

Bvh::Bvh(const std::vector<std::shared_ptr<Object>>& objects) {
  // The build reorders these in place, which keeps its passes over them in memory
  // order; order_ takes the objects' final order.
  std::vector<Bound> items;
  items.reserve(objects.size());
  objects_.reserve(objects.size());
  std::size_t spheres = 0;
  std::size_t triangles = 0;
  for (const auto& object : objects) {
    objects_.push_back(object.get());
    const FloatBox box = Rounded(object->Bounds());
    items.push_back({box, static_cast<float>(SurfaceArea(box)), static_cast<int>(items.size())});
    spheres += PreparedSphere(*object) != nullptr;
    triangles += AsTriangle(*object) != nullptr;
  }
  const int count = static_cast<int>(objects.size());
  nodes_.reserve(objects.size());
  if (count > 0) {
    Build(0, Summarise(0, count, items), items, 1);
    // Pack makes a leaf of each of the build's leaves and at most one node of each inner
    // node, of which a binary tree has one fewer than leaves.
    const auto leaves = std::count_if(nodes_.begin(), nodes_.end(),
                                      [](const Node& node) { return node.count > 0; });
    leaves_.reserve(leaves);
    packed_.reserve(leaves);
    root_ = Pack(0);
    const FloatBox& root = nodes_[0].box;
    root_box_ = {{root.min[0], root.min[1], root.min[2]}, {root.max[0], root.max[1], root.max[2]}};
  }
  // The leaves' copies of what the tests of prepared spheres and of triangles read, in
  // leaf order. Every array is sized before it is filled: an array grown as it is filled
  // is copied, and its memory asked for again, on the way (the README's "Building").
  order_.reserve(items.size());
  slot_of_.resize(items.size());
  slot_spheres_.reserve(items.size());
  spheres_.reserve(spheres);
  slot_triangles_.reserve(items.size());
  triangles_.reserve(triangles);
  for (const Bound& item : items) {
    slot_of_[item.object] = static_cast<int>(order_.size());
    order_.push_back(item.object);
    const Sphere* sphere = PreparedSphere(*objects_[item.object]);
    slot_spheres_.push_back(sphere != nullptr ? static_cast<int>(spheres_.size()) : -1);
    if (sphere != nullptr) {
      spheres_.push_back({sphere->center, sphere->cache});
    }
    const Triangle* triangle = AsTriangle(*objects_[item.object]);
    slot_triangles_.push_back(triangle != nullptr ? static_cast<int>(triangles_.size()) : -1);
    if (triangle != nullptr) {
      triangles_.push_back({triangle->A, triangle->B, triangle->C, triangle->N});
    }
  }
}

Bvh::Group Bvh::Summarise(int first, int count, const std::vector<Bound>& items) const {
  Group group;
  for (int i = first; i < first + count; ++i) {
    group.Add(items[i]);
  }
  return group;
}

// Appends the node of the group's objects, items[first, first + group.count), and its
// subtree: a leaf when few objects are left or splitting does not pay, else two
// children, with a very large object on its own or where the surface area heuristic
// says.
void Bvh::Build(int first, const Group& group, std::vector<Bound>& items, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  nodes_[index].box = group.box;
  depth_ = std::max(depth_, depth);
  Group children[2];
  int split = 0;
  if (group.count > kSmallLeaf) {
    // At most 24 levels of large objects, so that the depth, and the traversal stack
    // with it, stays under 64 even for objects nested like Russian dolls; deep down
    // (only nested objects get there), halves at the median centre.
    if (depth <= 24) {
      split = SplitOffLargest(first, group, items, children);
    }
    if (split == 0) {
      split = depth < 40 ? SplitBySurfaceArea(first, group, items, children)
                         : SplitAtMedian(first, group, items, children);
    }
  }
  if (split == 0) {
    nodes_[index].first = first;
    nodes_[index].count = group.count;
    return;
  }
  Build(first, children[0], items, depth + 1);
  nodes_[index].second_child = static_cast<int>(nodes_.size());
  Build(first + split, children[1], items, depth + 1);
}

// An object larger than all the others together (chapter 4's ground, a sphere of radius
// 5000) would make every box above it as large as itself, and every ray would enter
// them all: it gets a leaf of its own, beside the tree of the rest. Only a group whose
// box the largest object fills at least half of (by area) is gone over.
int Bvh::SplitOffLargest(int first, const Group& group, std::vector<Bound>& items,
                         Group (&children)[2]) {
  if (!(2 * group.largest > SurfaceArea(group.box))) {
    return 0;
  }
  int largest = first;
  for (int i = first; i < first + group.count; ++i) {
    if (items[i].area > items[largest].area) {
      largest = i;
    }
  }
  FloatBox others;
  for (int i = first; i < first + group.count; ++i) {
    if (i != largest) {
      others = Union(others, items[i].box);
    }
  }
  if (!(group.largest > SurfaceArea(others))) {
    return 0;
  }
  std::swap(items[first], items[largest]);
  children[0] = Summarise(first, 1, items);
  children[1] = Summarise(first + 1, group.count - 1, items);
  return 1;
}

// Reorders the group around the median centre along the axis where the centres spread
// most.
int Bvh::SplitAtMedian(int first, const Group& group, std::vector<Bound>& items,
                       Group (&children)[2]) {
  const int axis = LongestAxis(Size(group.centres));
  const int half = group.count / 2;
  std::nth_element(items.begin() + first, items.begin() + first + half,
                   items.begin() + first + group.count, [&](const Bound& a, const Bound& b) {
                     const float ca = Centre(a.box)[axis];
                     const float cb = Centre(b.box)[axis];
                     return ca < cb || (ca == cb && a.object < b.object);
                   });
  children[0] = Summarise(first, half, items);
  children[1] = Summarise(first + half, group.count - half, items);
  return half;
}

// The best place to split the group, by the surface area heuristic over kBins bins of
// the centres along each axis, filled in one pass over the objects; the bins on each
// side of the plane chosen are the children's groups. Objects whose centres coincide
// cannot be split by any plane: they are halved in scene order.
int Bvh::SplitBySurfaceArea(int first, const Group& group, std::vector<Bound>& items,
                            Group (&children)[2]) {
  // A large group is binned only along the axis where its centres spread most: a third
  // of the work, where the cuts are all much the same.
  const int longest = LongestAxis(Size(group.centres));
  Binning binning{group.centres.min, Float4{}};
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = group.centres.max[axis] - group.centres.min[axis];
    const bool binned = group.count <= kLargeGroup || axis == longest;
    binning.scale[axis] = extent > 0 && binned ? kBins / extent : 0;
  }
  std::array<std::array<Bin, kBins>, 3> bins;
  for (int i = first; i < first + group.count; ++i) {
    const Bound& bound = items[i];
    const Int4 bin = binning.Of(Centre(bound.box));
    for (int axis = 0; axis < 3; ++axis) {
      if (binning.scale[axis] > 0) {
        Bin& each = bins[axis][bin[axis]];
        each.box = Union(each.box, bound.box);
        ++each.count;
      }
    }
  }
  Plane best;
  best.cost = group.count <= kMaxLeaf ? group.count * kObjectTestCost : cgfs::kInf;
  int best_axis = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (binning.scale[axis] > 0) {
      const Plane plane = CheapestPlane(bins[axis], SurfaceArea(group.box));
      if (plane.cost < best.cost) {
        best = plane;
        best_axis = axis;
      }
    }
  }
  if (best_axis < 0) {
    if (group.count <= kMaxLeaf) {
      return 0;
    }
    std::sort(items.begin() + first, items.begin() + first + group.count,
              [](const Bound& a, const Bound& b) { return a.object < b.object; });
    const int half = group.count / 2;
    children[0] = Summarise(first, half, items);
    children[1] = Summarise(first + half, group.count - half, items);
    return half;
  }
  // Partitions the items as std::partition would, summing up each side on the way.
  Group sides[2];
  int left = first;
  int right = first + group.count - 1;
  while (left <= right) {
    const Bound& bound = items[left];
    if (binning.Of(Centre(bound.box))[best_axis] < best.index) {
      sides[0].Add(bound);
      ++left;
    } else {
      sides[1].Add(bound);
      std::swap(items[left], items[right--]);
    }
  }
  children[0] = sides[0];
  children[1] = sides[1];
  return children[0].count;
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
