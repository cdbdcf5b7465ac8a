#include "bvh.h"

#include <algorithm>
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
  }
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

// Visits the nodes whose box the ray enters no later than the best hit so far, the
// nearer child first, so that the farther one is often skipped. The tree's depth,
// and so the stack, stays under 64 (Build) for any scene that fits in memory.
Hit Bvh::Closest(const Ray& ray, double t_min, double t_max, int& object) const {
  Hit best;
  object = -1;
  if (nodes_.size() == 1) {  // all in one leaf: a box around a list only costs a test
    for (int candidate = 0; candidate < static_cast<int>(objects_.size()); ++candidate) {
      const Hit hit = objects_[candidate]->Intersect(ray, t_min, t_max);
      if (hit.t < best.t) {
        best = hit;
        object = candidate;
      }
    }
    return best;
  }
  const Vec3 inv_D = 1.0 / ray.D;
  struct Entry {
    int node;
    double t_enter;
  };
  Entry stack[64];
  int size = 0;
  double t_root = 0;
  if (!order_.empty() && RayHitsBox(nodes_[0].box, ray.O, ray.D, inv_D, t_min, t_max, t_root)) {
    stack[size++] = {0, t_root};
  }
  while (size > 0) {
    const Entry entry = stack[--size];
    if (entry.t_enter > best.t) {
      continue;  // a nearer hit was found since this node was pushed
    }
    const Node& node = nodes_[entry.node];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const int candidate = order_[i];
        const Hit hit = objects_[candidate]->Intersect(ray, t_min, t_max);
        // On a tie the lower index wins, as in the plain loop, which keeps the first.
        if (hit.t < best.t || (hit.t == best.t && hit.t < cgfs::kInf && candidate < object)) {
          best = hit;
          object = candidate;
        }
      }
      continue;
    }
    const int children[2] = {entry.node + 1, node.second_child};
    double enter[2] = {cgfs::kInf, cgfs::kInf};
    bool hits[2] = {false, false};
    for (int c = 0; c < 2; ++c) {
      hits[c] = RayHitsBox(nodes_[children[c]].box, ray.O, ray.D, inv_D, t_min,
                           std::min(t_max, best.t), enter[c]);
    }
    const int near = (hits[1] && (!hits[0] || enter[1] < enter[0])) ? 1 : 0;
    for (const int c : {1 - near, near}) {
      if (hits[c]) {
        stack[size++] = {children[c], enter[c]};
      }
    }
  }
  return best;
}

bool Bvh::Any(const Ray& ray, double t_min, double t_max, int& object) const {
  object = -1;
  if (nodes_.size() == 1) {
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
  const Vec3 inv_D = 1.0 / ray.D;
  int stack[64];
  int size = 0;
  stack[size++] = 0;
  while (size > 0) {
    const int index = stack[--size];
    const Node& node = nodes_[index];
    double t_enter = 0;
    if (!RayHitsBox(node.box, ray.O, ray.D, inv_D, t_min, t_max, t_enter)) {
      continue;
    }
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        if (objects_[order_[i]]->Intersect(ray, t_min, t_max).t < cgfs::kInf) {
          object = order_[i];
          return true;
        }
      }
      continue;
    }
    stack[size++] = node.second_child;
    stack[size++] = index + 1;
  }
  return false;
}
