// "Hierarchical Structures": a ray that misses a volume around a group of objects
// misses every object in it. Nesting such groups gives a tree, a bounding-volume
// hierarchy, and a ray visits only the branches whose volume it enters.
//
// The volumes are axis-aligned boxes rather than the book's spheres: the box of two
// boxes is tight, where the sphere around two spheres is loose and gets looser up
// the tree, and a box test is a handful of multiplications with no square root
// (the chapter's README compares the two).
#pragma once

#include <memory>
#include <vector>

#include "objects.h"

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
  int Depth() const { return depth_; }

 private:
  // Nodes are stored depth first: an inner node's first child follows it.
  struct Node {
    Box box;
    int first = 0;  // a leaf: the objects order_[first, first + count)
    int count = 0;  // 0 for an inner node
    int second_child = 0;
  };
  void Build(int first, int count, const std::vector<Box>& boxes, int depth);

  std::vector<const Object*> objects_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  int depth_ = 0;
};

// Whether O + tD, t in [t_min, t_max], passes through the box; sets t_enter to the
// smallest such t. inv_D holds 1/D per axis.
bool RayHitsBox(const Box& box, const Vec3& O, const Vec3& D, const Vec3& inv_D, double t_min,
                double t_max, double& t_enter);
