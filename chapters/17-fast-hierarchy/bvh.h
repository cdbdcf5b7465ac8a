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
#include <limits>
#include <memory>
#include <vector>

#include "cgfs/tally.h"
#include "objects.h"

// The build's boxes (bvh_build.cpp): in single precision, rounded outwards from the
// objects' own boxes (so that each holds its object), with x, y and z in the first
// three lanes of a vector of four floats (a GCC and Clang vector type: one SSE
// register on x86-64, one NEON register on ARM), so that the box around two boxes is
// two instructions. The fourth lane is 0.
using Float4 = float __attribute__((vector_size(16)));
inline constexpr float kFloatInf = std::numeric_limits<float>::infinity();
struct FloatBox {
  Float4 min = {kFloatInf, kFloatInf, kFloatInf, 0};
  Float4 max = {-kFloatInf, -kFloatInf, -kFloatInf, 0};
};
// The box around both, the centre of a box and its surface area (inline: the build
// takes millions).
inline FloatBox Union(const FloatBox& a, const FloatBox& b) {
  return {a.min < b.min ? a.min : b.min, a.max > b.max ? a.max : b.max};
}
inline Float4 Centre(const FloatBox& box) {
  return (box.min + box.max) * 0.5F;
}
inline double SurfaceArea(const FloatBox& box) {
  const Float4 size = box.max - box.min;
  const double x = size[0], y = size[1], z = size[2];
  return 2 * (x * y + y * z + z * x);
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
  // Whether scene object `object` is hit in [t_min, t_max]; a prepared sphere is tested
  // on the hierarchy's copy of what its test reads, which lies beside its neighbours'.
  bool Hits(int object, const Ray& ray, double t_min, double t_max) const {
    return IntersectSlot(slot_of_[object], ray, t_min, t_max).t < cgfs::kInf;
  }

  int NodeCount() const { return static_cast<int>(nodes_.size()); }
  int Depth() const { return depth_; }
  // The tree's expected cost for a ray that enters the root, by the surface area
  // heuristic: each node's box tests and each leaf's object tests, weighted by the
  // chance that a ray through the root enters the node (its area over the root's).
  double SurfaceAreaCost() const;

 private:
  // Nodes are stored depth first: an inner node's first child follows it.
  struct Node {
    FloatBox box;
    int first = 0;  // a leaf: the objects order_[first, first + count)
    int count = 0;  // 0 for an inner node
    int second_child = 0;
  };
  // What the build needs of each object, computed once (bvh_build.cpp).
  struct Bound {
    FloatBox box;
    float area;
    int object;  // its index in objects_
  };
  // A group of objects as the build sees it: their box, the box of their centres, how
  // many, and the area of the largest. The build gets a node's group from the split
  // of its parent, without going over its objects again.
  struct Group {
    FloatBox box;
    FloatBox centres;
    int count = 0;
    float largest = 0;
    void Add(const Bound& bound) {
      box = Union(box, bound.box);
      const Float4 centre = Centre(bound.box);
      centres = Union(centres, {centre, centre});
      ++count;
      largest = std::max(largest, bound.area);
    }
  };
  Group Summarise(int first, int count, const std::vector<Bound>& items) const;
  void Build(int first, const Group& group, std::vector<Bound>& items, int depth);
  // Each reorders the items from `first` on and returns how many objects go to the first
  // child (0: none, make a leaf), with both children's groups.
  int SplitOffLargest(int first, const Group& group, std::vector<Bound>& items,
                      Group (&children)[2]);
  int SplitBySurfaceArea(int first, const Group& group, std::vector<Bound>& items,
                         Group (&children)[2]);
  int SplitAtMedian(int first, const Group& group, std::vector<Bound>& items, Group (&children)[2]);

  // The tree as the rays walk it, four children to a node (as Embree's is): a node of
  // the build's binary tree with, in place of each inner child, that child's own two
  // (the larger first), so that a ray goes down half as many levels. A node holds its
  // children's boxes side by side: the build's float boxes, rounded outwards (a box can
  // only grow, so no hit is lost), held as doubles, which the slab test takes without
  // converting them (the conversions cost more than the memory the floats save), in
  // four 64-byte lines. A child is an inner node's index, or ~i for leaves_[i]; the
  // unused ones (count < 4) have an empty box, which no ray enters.
  struct alignas(64) PackedNode {
    double bounds[2][3][4];  // [min or max][axis][child]
    int child[4];
    int count;
  };
  struct Leaf {
    int first = 0;  // the objects order_[first, first + count)
    int count = 0;
  };
  int Pack(int node);
  template <typename Visit>
  void Walk(const Ray& ray, double t_min, double t_max, const double& t_best, Visit visit) const;
  // All in one leaf (no root): test(object) for every object in scene order, as the
  // plain loop tests them, each test counted (kObjectTests); stops when test returns
  // true, and says whether it did.
  template <typename Test>
  bool InSceneOrder(Test test) const;

  // The hit of the object in leaf slot `slot`, order_[slot]. Prepared spheres and
  // triangles, the usual leaves, are tested inline, from the hierarchy's copy of what
  // their test reads.
  Hit IntersectSlot(int slot, const Ray& ray, double t_min, double t_max) const {
    const int sphere = slot_spheres_[slot];
    const Object* object = objects_[order_[slot]];
    double t = cgfs::kInf;
    if (sphere >= 0) {
      const LeafSphere& leaf = spheres_[sphere];
      t = NearestRoot(IntersectRaySphere(ray, leaf.center, leaf.cache), t_min, t_max);
    } else if (const int triangle = slot_triangles_[slot]; triangle >= 0) {
      const LeafTriangle& leaf = triangles_[triangle];
      t = IntersectRayTriangle(ray.O, ray.D, leaf.A, leaf.B, leaf.C, leaf.N, t_min, t_max);
    } else {
      return object->Intersect(ray, t_min, t_max);
    }
    return t < cgfs::kInf ? Hit{t, object} : Hit{};
  }

  std::vector<const Object*> objects_;
  // What the test of each prepared sphere reads (40 bytes, where a whole Sphere takes
  // 120), in leaf order, so that a leaf's spheres lie side by side in memory instead of
  // wherever the scene's are; slot_spheres_[slot] is the one of objects_[order_[slot]],
  // or -1 for any other object.
  struct LeafSphere {
    Vec3 center;
    SphereCache cache;
  };
  std::vector<LeafSphere> spheres_;
  std::vector<int> slot_spheres_;
  // The same for triangles: their corners and normal (96 bytes, where a whole Triangle
  // takes 160).
  struct LeafTriangle {
    Vec3 A, B, C, N;
  };
  std::vector<LeafTriangle> triangles_;
  std::vector<int> slot_triangles_;
  std::vector<Node> nodes_;
  std::vector<int> order_;
  std::vector<int> slot_of_;  // the inverse of order_: each object's slot
  std::vector<PackedNode> packed_;
  std::vector<Leaf> leaves_;
  Box root_box_;  // the root node's box, for the walk's first test
  int root_ = 0;  // the root as a child reference: 0, or ~0 when the root is a leaf
  int depth_ = 0;
};

// Whether O + tD, t in [t_min, t_max], passes through the box; sets t_enter to the
// smallest such t. inv_D holds 1/D per axis. The slabs are intersected one axis after
// the other; the answer only needs checking at the end, since each axis can only
// narrow [t_min, t_max]. Inline: a ray tests hundreds of boxes.
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
