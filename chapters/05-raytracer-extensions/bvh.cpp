#include "bvh.h"

#include <algorithm>

namespace {

// The surface area heuristic: a ray that enters a box enters a child of it with
// probability (child's area) / (box's area), so a split costs one box test plus, for
// each child, that probability times its objects' tests. Of kBins - 1 planes along
// each axis the cheapest wins; a group of at most kMaxLeaf objects stays a leaf where
// no plane is cheaper than testing them all.
constexpr int kBins = 16;
constexpr int kMaxLeaf = 8;
// So few objects are a leaf whatever the heuristic says: a scene of a few objects is
// then one leaf, which PrepareScene does not keep (the plain loop does the same, with
// no box to test).
constexpr int kSmallLeaf = 4;
constexpr double kBoxTestCost = 1;  // relative to one object test
// Deeper than this (only objects nested like Russian dolls get there), groups are
// halved, so that the tree stays under 64 levels, the size of the walk's stack.
constexpr int kMaxSplitDepth = 40;

Vec3 Centre(const Box& box) {
  return (box.min + box.max) * 0.5;
}

double SurfaceArea(const Box& box) {
  const Vec3 size = box.max - box.min;
  return 2 * (size.x * size.y + size.y * size.z + size.z * size.x);
}

// Which of kBins equal slices of the centres' box, along `axis`, holds `centre`.
int BinOf(const Vec3& centre, const Box& centres, int axis) {
  const double extent = centres.max[axis] - centres.min[axis];
  const int bin = static_cast<int>((centre[axis] - centres.min[axis]) / extent * kBins);
  return std::min(bin, kBins - 1);
}

}  // namespace

Bvh::Bvh(const std::vector<std::shared_ptr<Object>>& objects) {
  std::vector<Box> boxes;
  for (const auto& object : objects) {
    order_.push_back(static_cast<int>(objects_.size()));
    objects_.push_back(object.get());
    boxes.push_back(object->Bounds());
  }
  if (!objects.empty()) {
    Build(0, static_cast<int>(objects.size()), boxes, 0);
  }
}

// Appends the node of the objects order_[first, first + count), then its subtree.
void Bvh::Build(int first, int count, const std::vector<Box>& boxes, int depth) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Box box;
  Box centres;
  for (int i = first; i < first + count; ++i) {
    box = Union(box, boxes[order_[i]]);
    const Vec3 centre = Centre(boxes[order_[i]]);
    centres = Union(centres, {centre, centre});
  }
  nodes_[index].box = box;
  const int split =
      count > kSmallLeaf ? Split(first, count, depth, box, centres, boxes, nodes_[index].axis) : 0;
  if (split == 0) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return;
  }
  Build(first, split, boxes, depth + 1);
  nodes_[index].second_child = static_cast<int>(nodes_.size());
  Build(first + split, count - split, boxes, depth + 1);
}

// Reorders order_[first, first + count) by the plane the surface area heuristic
// prefers, sets `split_axis` to its axis, and returns how many go to the first child
// (0: make a leaf). Objects whose centres all coincide cannot be split by any plane,
// and the tree must stay under 64 levels: then they are halved as they are.
int Bvh::Split(int first, int count, int depth, const Box& box, const Box& centres,
               const std::vector<Box>& boxes, int& split_axis) {
  if (depth >= kMaxSplitDepth) {
    return count / 2;
  }
  double best_cost = count <= kMaxLeaf ? count : cgfs::kInf;
  int best_plane = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(centres.max[axis] > centres.min[axis])) {
      continue;
    }
    Box bin_boxes[kBins];
    int bin_counts[kBins] = {};
    for (int i = first; i < first + count; ++i) {
      const int bin = BinOf(Centre(boxes[order_[i]]), centres, axis);
      bin_boxes[bin] = Union(bin_boxes[bin], boxes[order_[i]]);
      ++bin_counts[bin];
    }
    // The plane before bin p leaves bins [0, p) on its left: the right sides first.
    Box right;
    double right_area[kBins] = {};
    int right_count[kBins + 1] = {};
    for (int p = kBins - 1; p > 0; --p) {
      right = Union(right, bin_boxes[p]);
      right_area[p] = SurfaceArea(right);
      right_count[p] = right_count[p + 1] + bin_counts[p];
    }
    Box left;
    int left_count = 0;
    for (int p = 1; p < kBins; ++p) {
      left = Union(left, bin_boxes[p - 1]);
      left_count += bin_counts[p - 1];
      if (left_count == 0 || right_count[p] == 0) {
        continue;
      }
      const double cost =
          kBoxTestCost +
          (SurfaceArea(left) * left_count + right_area[p] * right_count[p]) / SurfaceArea(box);
      if (cost < best_cost) {
        best_cost = cost;
        best_plane = p;
        split_axis = axis;
      }
    }
  }
  if (best_plane < 0) {
    return count <= kMaxLeaf ? 0 : count / 2;
  }
  const auto middle = std::partition(
      order_.begin() + first, order_.begin() + first + count,
      [&](int i) { return BinOf(Centre(boxes[i]), centres, split_axis) < best_plane; });
  return static_cast<int>(middle - (order_.begin() + first));
}

// Walks the nodes whose box the ray enters within [t_min, best hit so far], testing
// the objects of each leaf reached. Of an inner node's two children the one on the
// ray's side of the split goes first, since its hits are likely the nearer ones, which
// then rule out the boxes of the other that lie beyond them; the other waits on the
// stack. With `any`, stops at the first hit.
Hit Bvh::Search(const Ray& ray, double t_min, double t_max, bool any, int& object) const {
  Hit best;
  best.t = t_max;  // what the boxes are tested against; narrows with each hit
  object = -1;
  // Tests a leaf's objects; true to stop (with `any`, at the first hit).
  const auto test_leaf = [&](const Node& leaf) {
    for (int i = leaf.first; i < leaf.first + leaf.count; ++i) {
      cgfs::Tally(kObjectTests);
      const int candidate = order_[i];
      const Hit hit = objects_[candidate]->Intersect(ray, t_min, best.t);
      // Within [t_min, best.t]: nearer, or as near and first in the scene (or the first).
      if (hit.primitive != nullptr && (hit.t < best.t || object < 0 || candidate < object)) {
        best = hit;
        object = candidate;
        if (any) {
          return true;
        }
      }
    }
    return false;
  };
  const Vec3 inv_D = 1.0 / ray.D;
  int stack[64];
  int size = 0;
  int node = 0;
  while (!nodes_.empty()) {
    const Node& current = nodes_[node];
    double t_enter = 0;
    cgfs::Tally(kBoxTests);
    if (RayHitsBox(current.box, ray.O, ray.D, inv_D, t_min, best.t, t_enter)) {
      if (current.count == 0) {
        const bool second_first = ray.D[current.axis] < 0;
        stack[size++] = second_first ? node + 1 : current.second_child;
        node = second_first ? current.second_child : node + 1;
        continue;
      }
      if (test_leaf(current)) {
        break;
      }
    }
    if (size == 0) {
      break;
    }
    node = stack[--size];
  }
  return object >= 0 ? best : Hit{};
}

Hit Bvh::Closest(const Ray& ray, double t_min, double t_max, int& object) const {
  return Search(ray, t_min, t_max, false, object);
}

bool Bvh::Any(const Ray& ray, double t_min, double t_max, int& object) const {
  return Search(ray, t_min, t_max, true, object).primitive != nullptr;
}
