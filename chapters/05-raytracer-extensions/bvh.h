// "Hierarchical Structures": a ray that misses a volume around a group of objects
// misses every object in it. Nesting such groups gives a tree, a bounding-volume
// hierarchy, and a ray visits only the branches whose volume it enters.
//
// The volumes are axis-aligned boxes rather than the book's spheres: the box of two
// boxes is tight, where the sphere around two spheres is loose and gets looser up
// the tree, and a box test is a handful of multiplications with no square root
// (the chapter's README compares the two).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "cgfs/tally.h"
#include "objects.h"

// Whether O + tD, t in [t_min, t_max], passes through the box; sets t_enter to the
// smallest such t. inv_D holds 1/D per axis. The slabs are intersected one axis after
// the other; the answer only needs checking at the end, since each axis can only
// narrow [t_min, t_max]. Inline: a ray tests dozens of boxes.
inline bool RayHitsBox(const Box& box, const Vec3& O, const Vec3& D, const Vec3& inv_D,
                       double t_min, double t_max, double& t_enter) {
  for (int axis = 0; axis < 3; ++axis) {
    if (D[axis] == 0) {  // parallel to the slab: inside it or never
      if (O[axis] < box.min[axis] || O[axis] > box.max[axis]) {
        return false;
      }
      continue;
    }
    const double t0 = (box.min[axis] - O[axis]) * inv_D[axis];
    const double t1 = (box.max[axis] - O[axis]) * inv_D[axis];
    t_min = std::max(t_min, std::min(t0, t1));
    t_max = std::min(t_max, std::max(t0, t1));
  }
  t_enter = t_min;
  return t_min <= t_max;
}

// The work of a search, counted box by box and object by object: the cost view of the
// tests per camera ray (cost.h), the tests, and the chapter's README's numbers.
inline constexpr cgfs::Counter kBoxTests{"box tests"};
inline constexpr cgfs::Counter kObjectTests{"object tests"};

class Bvh {
 public:
  // Built once per scene over its objects, which it refers to by index.
  explicit Bvh(const std::vector<std::shared_ptr<Object>>& objects);

  // The nearest hit in [t_min, t_max], as the loop over every object finds it: on a
  // tie in t, the object that comes first in the scene. `object` is the index of
  // the scene object hit, or -1.
  Hit Closest(const Ray& ray, double t_min, double t_max, int& object) const;
  // Whether anything is hit in [t_min, t_max]; stops at the first hit found.
  bool Any(const Ray& ray, double t_min, double t_max, int& object) const;

  int NodeCount() const { return static_cast<int>(nodes_.size()); }

 private:
  // The nodes in depth-first order: an inner node's first child comes right after it.
  struct Node {
    Box box;
    int first = 0;  // a leaf: the objects order_[first, first + count)
    int count = 0;  // 0 for an inner node
    int second_child = 0;
    int axis = 0;  // the axis its children were split along
  };
  void Build(int first, int count, const std::vector<Box>& boxes, int depth);
  int Split(int first, int count, int depth, const Box& box, const Box& centres,
            const std::vector<Box>& boxes, int& split_axis);
  Hit Search(const Ray& ray, double t_min, double t_max, bool any, int& object) const;

  std::vector<const Object*> objects_;  // the scene's, in its order
  std::vector<int> order_;              // their indices, grouped leaf by leaf
  std::vector<Node> nodes_;
};
