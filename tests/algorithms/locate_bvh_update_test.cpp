// FaceBvh refit and update after local edits, checked against an independent brute force over
// every fan triangle of every live face (exact equality, ties included).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "edits/random_edits.h"
#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "locate_reference.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace locate_test;

// ---- Refit and update. ----

TEST(FaceBvh, RefitAfterMovingVerticesMatchesBruteForceAgain) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  const FaceBvh stale = bvh;
  const float d = bounds(m).diagonal();
  std::mt19937 rng(23);
  std::normal_distribution<float> jitter(0.f, 0.02f * d);
  for (Vertex v : m.vertices()) {
    Vec3& p = m.position(v);
    p = Vec3{p.x * 1.3f + jitter(rng), p.y + 0.25f * d + jitter(rng), p.z * 0.7f + jitter(rng)};
  }
  bvh.refit();
  int stale_wrong = 0;
  const FanTriangles fans(m);
  for (const Vec3& p : query_points(m, 1500, 29)) {
    const auto want = brute_closest(fans, p);
    expect_same_closest(m, p, bvh.closest_point(p), want);
    const auto old = stale.closest_point(p);
    if (!old || old->squared_distance != want->squared_distance) ++stale_wrong;
  }
  EXPECT_GT(stale_wrong, 10) << "the motion must be large enough that stale boxes give wrong answers";
  for (const Ray& ray : query_rays(m, 800, 37))
    expect_same_hit(m, bvh.first_hit(ray.origin, ray.direction),
                    brute_first_hit(fans, ray.origin, ray.direction, kInf));
  EXPECT_EQ(bvh.stats().builds, 1u);
}

TEST(FaceBvh, UpdateAfterSplittingFacesWithoutRebuilding) {
  SurfaceMesh m = load("spot_triangulated.obj");
  FaceBvh bvh(m);
  std::mt19937 rng(43);
  std::vector<Face> changed;
  for (int i = 0; i < 60; ++i) {
    const Face f(static_cast<Index>(rng() % m.face_slots()));
    // Move the new vertex off the surface so that the new faces stick out and get hit.
    const Vec3 p = locate_test::centroid(m, f) + Vec3{0.02f, 0.03f, -0.01f};
    const auto faces = split_triangle(m, f, p);
    changed.assign(faces.begin(), faces.end());
    bvh.update(changed);
  }
  ASSERT_TRUE(m.validate().empty()) << m.validate().front();
  EXPECT_EQ(m.n_faces(), 5856u + 120u);
  const FaceBvh::Stats s = bvh.stats();
  EXPECT_EQ(s.builds, 1u) << "small updates must not rebuild the tree";
  EXPECT_EQ(s.live_faces, m.n_faces());
  EXPECT_GE(s.dead_slots, 60u);  // the replaced entries of the split faces
  EXPECT_GT(s.inserted_subtrees + s.merged_subtrees, 0u);
  expect_matches_brute_force(m, bvh, 47);
}

TEST(FaceBvh, UpdateAfterRemovingFaces) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  // Faces no two of which share a vertex, so that every hole is a separate boundary loop.
  std::vector<bool> used(m.vertex_slots(), false);
  std::vector<Face> removed;
  for (Face f : m.faces()) {
    if (f.idx() % 5 != 0) continue;
    const std::vector<Vertex> c = corners_of(m, f);
    bool free = true;
    for (Vertex v : c)
      for (Vertex w : m.vertices(v)) free = free && !used[v.idx()] && !used[w.idx()] && !m.is_boundary(v);
    if (!free) continue;
    for (Vertex v : c) used[v.idx()] = true;
    ASSERT_TRUE(remove_face(m, f));
    removed.push_back(f);
  }
  ASSERT_TRUE(m.validate().empty()) << m.validate().front();
  ASSERT_GT(removed.size(), 40u);
  bvh.update({}, removed);
  EXPECT_EQ(bvh.stats().builds, 1u);
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  expect_matches_brute_force(m, bvh, 53);
  // A point at a removed face's centre now finds a neighbour, never the removed face.
  SurfaceMesh original = load("anchor.off");
  for (Face f : removed) {
    const auto r = bvh.closest_point(locate_test::centroid(original, f));
    ASSERT_TRUE(r);
    EXPECT_NE(r->face, f);
    EXPECT_GT(r->squared_distance, 0.0);
  }
}

// An impact sequence as fracture makes one: find the face under a point, split it there, repeat.
TEST(FaceBvh, RepeatedSplitsInOnePlaceKeepTheTreeShallow) {
  IndexedMesh plate = test::grid(40, true);
  SurfaceMesh m = build(plate);
  FaceBvh bvh(m);
  std::mt19937 rng(59);
  std::normal_distribution<float> spread(0.f, 0.3f);
  for (int i = 0; i < 400; ++i) {
    const Vec2 p{20 + spread(rng), 20 + spread(rng)};
    const auto hit = bvh.face_containing(p);
    ASSERT_TRUE(hit);
    if (i % 8 == 0) {
      const auto want = brute_containing(FanTriangles(m), p);
      ASSERT_EQ(hit->face, want->face);
    }
    const auto faces = split_triangle(m, hit->face, {p.x, p.y, 0});
    bvh.update(std::vector<Face>(faces.begin(), faces.end()));
    const FaceBvh::Stats s = bvh.stats();
    EXPECT_LE(s.height, 2 * s.height_at_build + 16);
  }
  ASSERT_TRUE(m.validate().empty());
  const FaceBvh::Stats s = bvh.stats();
  EXPECT_GT(s.merged_subtrees, 100u) << "edits in one place merge into one small subtree";
  EXPECT_LE(s.builds, 5u) << "400 edits in one spot must not rebuild the tree every few edits";
  EXPECT_EQ(s.live_faces, m.n_faces());
  expect_matches_brute_force(m, bvh, 61, 600);
  std::uniform_real_distribution<float> u(18.f, 22.f);
  const FanTriangles final_fans(m);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p{u(rng), u(rng)};
    const auto got = bvh.face_containing(p);
    const auto want = brute_containing(final_fans, p);
    ASSERT_TRUE(got && want);
    EXPECT_EQ(got->face, want->face);
  }
}

TEST(FaceBvh, ManyUpdatesReclaimDeadSlotsAndStayCorrect) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m, {.rebuild_fraction = 0.1});
  std::mt19937 rng(67);
  const std::size_t n = m.n_faces();
  for (std::size_t i = 0; i < n / 3; ++i) {
    const Face f(static_cast<Index>(rng() % m.face_slots()));
    const auto faces = split_triangle(m, f, locate_test::centroid(m, f));
    bvh.update(std::vector<Face>(faces.begin(), faces.end()));
    const FaceBvh::Stats s = bvh.stats();
    EXPECT_LE(double(s.dead_slots), 0.1 * double(s.live_faces + s.dead_slots) + 1);
  }
  EXPECT_GT(bvh.stats().compactions, 1u);
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  expect_matches_brute_force(m, bvh, 71, 900);
}

// A strike of solid fracture, repeated: the faces in a ball are removed and a few new ones added.
// The leaves that lose faces are refitted at once, the dead slots are reclaimed by compactions,
// and the tree is not rebuilt; bounds() keeps its box until a compaction makes it tight.
TEST(FaceBvh, RemovalsInBallsRefitTheirLeavesAndCompactWithoutARebuild) {
  SurfaceMesh m = load("spot_triangulated.obj");
  FaceBvh bvh(m, {.rebuild_fraction = 0.1});
  const BoundingBox box = bounding_box(m);
  std::mt19937 rng(89);
  std::size_t compactions = 0;
  for (int strike = 0; strike < 10; ++strike) {
    const Face hit(static_cast<Index>(rng() % m.face_slots()));
    if (m.is_deleted(hit)) continue;
    const Vec3 c = locate_test::centroid(m, hit);
    std::vector<Face> removed;
    for (Face f : m.faces())
      if (norm(to_double(locate_test::centroid(m, f) - c)) < 0.1 * norm(to_double(box.size())))
        removed.push_back(f);
    const BoundingBox before = bvh.bounds();
    detach_faces(m, removed);
    // New faces where the old ones were: triangles near the ball's centre.
    for (int k = 0; k < 20; ++k) {
      const Vec3 o = c + Vec3{0.01f * float(k), 0, 0};
      const Vertex a = m.add_vertex(o), b = m.add_vertex(o + Vec3{0.02f, 0, 0}),
                   d = m.add_vertex(o + Vec3{0, 0.02f, 0});
      ASSERT_TRUE(add_face(m, std::vector<Vertex>{a, b, d}).is_valid());
    }
    bvh.update();  // from the change log: detach_faces() may split a vertex it leaves pinched
    const FaceBvh::Stats s = bvh.stats();
    EXPECT_EQ(s.builds, 1u) << "strike " << strike;
    EXPECT_EQ(s.live_faces, m.n_faces());
    if (s.compactions == compactions) {
      // No compaction: the box kept what it had (it may grow by the new faces, never shrink).
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(bvh.bounds().min[a], before.min[a]);
        EXPECT_GE(bvh.bounds().max[a], before.max[a]);
      }
    } else {
      // A compaction: the dead slots are gone and the box is the faces' own, which needs every
      // leaf that lost faces refitted.
      EXPECT_EQ(s.dead_slots, 0u);
      Vec3 lo = bvh.bounds().max, hi = bvh.bounds().min;
      for (Face f : m.faces())
        for (Vertex v : m.vertices(f))
          for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], m.position(v)[a]);
            hi[a] = std::max(hi[a], m.position(v)[a]);
          }
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(bvh.bounds().min[a], lo[a]) << "strike " << strike << " axis " << a;
        EXPECT_EQ(bvh.bounds().max[a], hi[a]) << "strike " << strike << " axis " << a;
      }
    }
    compactions = s.compactions;
    expect_matches_brute_force(m, bvh, 90 + unsigned(strike), 200);
  }
  EXPECT_GE(compactions, 2u);
  ASSERT_TRUE(m.validate().empty()) << m.validate().front();
}

// The library's local operations, each followed by update() with the faces it touched.
TEST(FaceBvh, UpdateAfterSplitFlipAndCollapseOperations) {
  SurfaceMesh m = load("spot_triangulated.obj");
  FaceBvh bvh(m);
  std::mt19937 rng(79);
  auto random_live = [&](std::size_t size, auto is_deleted) {
    for (;;) {
      const Index i = static_cast<Index>(rng() % size);
      if (!is_deleted(i)) return i;
    }
  };
  auto faces_around = [&](Vertex v, std::vector<Face>& out) {
    for (Face f : m.faces(v)) out.push_back(f);
  };
  int done[4] = {0, 0, 0, 0};
  for (int i = 0; i < 400; ++i) {
    std::vector<Face> changed, removed;
    switch (i % 4) {
      case 0: {  // split a face at a point a little off the surface
        const Face f(random_live(m.face_slots(), [&](Index x) { return m.is_deleted(Face(x)); }));
        const Vertex v = split_face(m, f, locate_test::centroid(m, f) + Vec3{0.01f, -0.01f, 0.01f});
        ASSERT_TRUE(v.is_valid());
        faces_around(v, changed);
        break;
      }
      case 1: {  // split an edge at its midpoint
        const Edge e(random_live(m.edge_slots(), [&](Index x) { return m.is_deleted(Edge(x)); }));
        const Vec3 mid = (m.position(m.vertex(e, 0)) + m.position(m.vertex(e, 1))) * 0.5f;
        const Vertex v = split_edge(m, e, mid);
        ASSERT_TRUE(v.is_valid());
        faces_around(v, changed);
        break;
      }
      case 2: {  // flip an edge: its two faces change corners
        const Edge e(random_live(m.edge_slots(), [&](Index x) { return m.is_deleted(Edge(x)); }));
        if (!can_flip(m, e)) continue;
        for (Face f : m.faces(e)) changed.push_back(f);
        ASSERT_TRUE(flip(m, e).is_valid());
        break;
      }
      case 3: {  // collapse an edge to its midpoint: the triangles on it vanish
        const Halfedge h(random_live(m.halfedge_slots(), [&](Index x) { return m.is_deleted(Halfedge(x)); }));
        if (!can_collapse(m, h)) continue;
        std::vector<Face> before;
        faces_around(m.from_vertex(h), before);
        faces_around(m.to_vertex(h), before);
        const Vec3 mid = (m.position(m.from_vertex(h)) + m.position(m.to_vertex(h))) * 0.5f;
        const Vertex v = collapse(m, h);
        ASSERT_TRUE(v.is_valid());
        m.position(v) = mid;
        faces_around(v, changed);
        for (Face f : before)
          if (m.is_deleted(f)) removed.push_back(f);
        EXPECT_FALSE(removed.empty());
        break;
      }
    }
    ++done[i % 4];
    bvh.update(changed, removed);
  }
  ASSERT_TRUE(m.validate().empty()) << m.validate().front();
  for (int k = 0; k < 4; ++k) EXPECT_GT(done[k], 20) << "operation " << k;
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  expect_matches_brute_force(m, bvh, 83);
}

TEST(FaceBvh, UpdateRejectsForeignHandlesAndGarbageCollectionNeedsABuild) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  EXPECT_THROW(bvh.update(std::vector<Face>{Face(Index(m.face_slots()))}), InvalidInputError);
  EXPECT_THROW(bvh.update({}, std::vector<Face>{Face()}), InvalidInputError);
  // Deleted faces in the changed list count as removed; unknown removed faces are ignored.
  ASSERT_TRUE(remove_face(m, Face(10)));
  bvh.update(std::vector<Face>{Face(10)}, std::vector<Face>{Face(10)});
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  m.garbage_collection();
  EXPECT_THROW(bvh.closest_point({0, 0, 0}), InvalidInputError);
  EXPECT_THROW(bvh.refit(), InvalidInputError);
  EXPECT_THROW(bvh.update(std::vector<Face>{Face(0)}), InvalidInputError);
  bvh.build(m);
  expect_matches_brute_force(m, bvh, 73, 600);
  ASSERT_TRUE(m.validate().empty());
}

// ---- FaceBvh as a consumer of the mesh's change log. ----

// Every operation of the random-edit driver, then update() with no arguments: the tree finds the
// touched faces in the change log, and answers as the brute force does.
TEST(FaceBvh, UpdateFromTheChangeLogFollowsRandomEdits) {
  SurfaceMesh m = load("spot_triangulated.obj");
  FaceBvh bvh(m);
  EXPECT_TRUE(bvh.up_to_date());
  RandomEditor editor(m, 97);
  std::size_t applied = 0;
  for (int round = 0; round < 12; ++round) {
    for (int i = 0; i < 40; ++i) applied += editor.step().applied;
    EXPECT_FALSE(bvh.up_to_date());
    bvh.update();
    EXPECT_TRUE(bvh.up_to_date());
    EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
    if (round % 4 == 3) expect_matches_brute_force(m, bvh, 101 + round, 400);
  }
  EXPECT_GT(applied, 300u);
  ASSERT_TRUE(m.validate().empty()) << m.validate().front();
}

// One operation at a time, so that a face missing from the log shows up at once.
TEST(FaceBvh, UpdateFromTheChangeLogAfterEachOperation) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  RandomEditor editor(m, 5);
  for (int i = 0; i < 150; ++i) {
    const RandomEditor::Step step = editor.step();
    bvh.update();
    EXPECT_EQ(bvh.stats().live_faces, m.n_faces()) << "after " << edit_name(step.kind);
    if (step.applied && i % 10 == 0) expect_matches_brute_force(m, bvh, 200 + i, 60);
  }
  expect_matches_brute_force(m, bvh, 7, 600);
  ASSERT_TRUE(m.validate().empty());
}

TEST(FaceBvh, UpdateFromTheChangeLogSeesMovedVertices) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  // A few vertices: their faces are re-inserted.
  for (Index i = 0; i < 5; ++i)
    m.set_position(Vertex(i * 7), m.position(Vertex(i * 7)) + Vec3{0.2f, 0.3f, -0.1f});
  const std::size_t builds = bvh.stats().builds;
  bvh.update();
  EXPECT_GT(bvh.stats().dead_slots, 0u);
  expect_matches_brute_force(m, bvh, 31, 600);
  // Every vertex, as a smoothing pass would: the tree is refitted rather than re-inserted.
  for (Vertex v : m.vertices()) m.set_position(v, m.position(v) * 1.5f + Vec3{1, 0, 0});
  bvh.update();
  EXPECT_EQ(bvh.stats().builds, builds);
  expect_matches_brute_force(m, bvh, 37, 600);
  ASSERT_TRUE(m.validate().empty());
}

// A collection renumbers; edits after it may grow the mesh past its old size again, so only the
// change log's reset tells the tree that its indices are stale.
TEST(FaceBvh, GarbageCollectionIsSeenEvenAfterTheMeshGrewBack) {
  SurfaceMesh m = load("anchor.off");
  FaceBvh bvh(m);
  const std::size_t slots[3] = {m.vertex_slots(), m.halfedge_slots(), m.face_slots()};
  ASSERT_TRUE(remove_face(m, Face(3)));
  m.garbage_collection();  // renumbers
  EXPECT_THROW(bvh.update(std::vector<Face>{}, std::vector<Face>{}), InvalidInputError);
  for (Face f = Face(0); m.face_slots() <= slots[2] || m.vertex_slots() <= slots[0]; f = Face(f.idx() + 1))
    ASSERT_TRUE(split_face(m, f, locate_test::centroid(m, f)).is_valid());
  ASSERT_GT(m.halfedge_slots(), slots[1]);
  m.garbage_collection();  // nothing deleted since: the indices stay, nothing to tell
  EXPECT_FALSE(bvh.up_to_date());
  EXPECT_THROW(bvh.closest_point({0, 0, 0}), InvalidInputError);
  EXPECT_THROW(bvh.first_hit({0, 0, 0}, {1, 0, 0}), InvalidInputError);
  const std::size_t builds = bvh.stats().builds;
  bvh.update();  // rebuilds
  EXPECT_EQ(bvh.stats().builds, builds + 1);
  EXPECT_TRUE(bvh.up_to_date());
  expect_matches_brute_force(m, bvh, 41, 300);
  // So is an assignment to the mesh.
  m = load("spot_triangulated.obj");
  EXPECT_THROW(bvh.closest_point({0, 0, 0}), InvalidInputError);
  bvh.update();
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  expect_matches_brute_force(m, bvh, 43, 300);
  // Garbage collection in the middle of the random edits.
  RandomEditor editor(m, 3);
  for (int i = 0; i < 200; ++i) {
    editor.step();
    if (i % 50 == 49) m.garbage_collection();
    if (i % 30 == 0) bvh.update();
  }
  bvh.update();
  expect_matches_brute_force(m, bvh, 47, 300);
  ASSERT_TRUE(m.validate().empty());
}

TEST(FaceBvh, CopiesFollowTheLogOnTheirOwnAndDetachWhenDestroyed) {
  SurfaceMesh m = load("anchor.off");
  EXPECT_FALSE(m.changes().active());
  {
    FaceBvh a(m);
    EXPECT_TRUE(m.changes().active());
    ASSERT_TRUE(remove_face(m, Face(3)));
    FaceBvh b = a;  // b starts with what a has not read: the removal
    EXPECT_FALSE(b.up_to_date());
    b.update();
    EXPECT_TRUE(b.up_to_date());
    EXPECT_FALSE(a.up_to_date());
    EXPECT_EQ(b.stats().live_faces, m.n_faces());
    EXPECT_EQ(a.stats().live_faces, m.n_faces() + 1);
    FaceBvh c = std::move(a);  // c takes a's place in the log
    EXPECT_FALSE(c.up_to_date());
    c.update();
    expect_matches_brute_force(m, c, 53, 300);
    expect_matches_brute_force(m, b, 59, 300);
    b = c;
    EXPECT_TRUE(b.up_to_date());
  }
  // Every tree detached: the mesh records nothing any more.
  EXPECT_FALSE(m.changes().active());
  ASSERT_TRUE(m.validate().empty());
}

TEST(FaceBvh, UpdateOnATreeNeverBuiltDoesNothing) {
  FaceBvh bvh;
  bvh.update();
  EXPECT_TRUE(bvh.up_to_date());
  EXPECT_FALSE(bvh.closest_point({0, 0, 0}));
}

}  // namespace
}  // namespace hedge
