#include "hedge/core/threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "hedge/algorithms/distance.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// Restores the default thread count when a test ends, whatever it set.
class ThreadsTest : public ::testing::Test {
 protected:
  void TearDown() override { set_max_threads(0); }
};

// The threads a parallel loop over n elements ran its ranges on, and whether the ranges covered
// [0, n) exactly once.
struct RangeRun {
  std::set<std::thread::id> threads;
  bool covered = true;
};
RangeRun run_ranges(std::size_t n, std::size_t grain) {
  std::vector<std::atomic<int>> hits(n);
  std::mutex mutex;
  RangeRun r;
  detail::parallel_ranges(
      n,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) hits[i].fetch_add(1);
        const std::lock_guard<std::mutex> lock(mutex);
        r.threads.insert(std::this_thread::get_id());
      },
      grain);
  for (const std::atomic<int>& h : hits) r.covered = r.covered && h.load() == 1;
  return r;
}

TEST_F(ThreadsTest, DefaultIsTheUsableCores) {
  set_max_threads(0);
  EXPECT_GE(max_threads(), 1u);
  EXPECT_LE(max_threads(), std::max(1u, std::thread::hardware_concurrency()));
  set_max_threads(3);
  EXPECT_EQ(max_threads(), 3u);
  set_max_threads(0);
  EXPECT_GE(max_threads(), 1u);
}

// One thread runs everything on the calling thread; two split the range between two, the calling
// thread one of them.
TEST_F(ThreadsTest, TheRangeSplitsBetweenAsManyThreadsAsSetTheCallingThreadAmongThem) {
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(testing::Message() << threads << " thread(s)");
    set_max_threads(threads);
    EXPECT_EQ(detail::parallel_parts(1'000'000, 1), threads);
    const RangeRun r = run_ranges(100'000, 1);
    EXPECT_TRUE(r.covered);
    EXPECT_EQ(r.threads.size(), threads);
    EXPECT_TRUE(r.threads.count(std::this_thread::get_id()));
  }
}

TEST_F(ThreadsTest, PartsRespectTheGrainAndTheCap) {
  set_max_threads(16);
  EXPECT_EQ(detail::parallel_parts(0, 100), 1u);
  EXPECT_EQ(detail::parallel_parts(99, 100), 1u);
  EXPECT_EQ(detail::parallel_parts(350, 100), 3u);
  EXPECT_EQ(detail::parallel_parts(1'000'000, 100), 16u);
  EXPECT_EQ(detail::parallel_parts(1'000'000, 100, 8), 8u);
  EXPECT_EQ(detail::parallel_parts(1'000'000, 0), 16u);  // a grain of 0 counts as 1
}

TEST_F(ThreadsTest, ThePartIndexNamesEachRangeOnce) {
  set_max_threads(4);
  const std::size_t parts = detail::parallel_parts(40, 10);
  ASSERT_EQ(parts, 4u);
  std::vector<std::size_t> begin_of(parts, ~std::size_t(0));
  detail::parallel_ranges(
      40, [&](std::size_t begin, std::size_t, std::size_t part) { begin_of[part] = begin; }, 10);
  EXPECT_EQ(begin_of, (std::vector<std::size_t>{0, 10, 20, 30}));
}

// Tasks are taken in turn by whichever thread is free: each runs once, on a worker named in
// [0, threads), and while a long first task holds one thread the others run on the other.
TEST_F(ThreadsTest, TasksRunOnceAndBesideALongFirstTask) {
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(testing::Message() << threads << " thread(s)");
    set_max_threads(threads);
    constexpr std::size_t n = 50;
    std::vector<std::atomic<int>> hits(n);
    std::vector<std::size_t> worker_of(n, ~std::size_t(0));
    std::atomic<std::size_t> done{0};
    bool waited = true;
    const std::thread::id caller = std::this_thread::get_id();
    std::thread::id first_on;
    detail::parallel_tasks(n, [&](std::size_t task, std::size_t worker) {
      hits[task].fetch_add(1);
      worker_of[task] = worker;
      if (task == 0) first_on = std::this_thread::get_id();
      if (task == 0 && threads > 1) {
        // Holds its thread until the other tasks are done (bounded, so wrong code fails, not hangs).
        for (int i = 0; i < 20'000 && done.load() < n - 1; ++i)
          std::this_thread::sleep_for(std::chrono::milliseconds(1));
        waited = done.load() == n - 1;
      }
      if (task != 0) done.fetch_add(1);
    });
    for (std::size_t t = 0; t < n; ++t) {
      EXPECT_EQ(hits[t].load(), 1) << "task " << t;
      EXPECT_LT(worker_of[t], threads) << "task " << t;
      if (threads > 1 && t > 0) EXPECT_NE(worker_of[t], worker_of[0]) << "task " << t;
    }
    EXPECT_TRUE(waited);
    // Task 0 on the calling thread, where its thread-local scratch outlives the call.
    EXPECT_EQ(first_on, caller);
    EXPECT_EQ(worker_of[0], 0u);
  }
}

// A wavy grid, big enough that each subdivision pass splits between two threads.
SurfaceMesh wavy_grid() {
  IndexedMesh in = test::grid(200, false);
  for (Vec3& p : in.positions) p.z = 0.25f * float((int(p.x) * 7 + int(p.y) * 13) % 5);
  return build(in);
}

TEST_F(ThreadsTest, SubdivisionGivesTheSameMeshOnOneThreadAsOnTwo) {
  for (Subdivision scheme : {Subdivision::catmull_clark, Subdivision::split_faces}) {
    set_max_threads(1);
    SurfaceMesh one = wavy_grid();
    subdivide(one, scheme, 1);
    set_max_threads(2);
    SurfaceMesh two = wavy_grid();
    subdivide(two, scheme, 1);
    ASSERT_EQ(one.vertex_slots(), two.vertex_slots());
    ASSERT_EQ(one.halfedge_slots(), two.halfedge_slots());
    for (Vertex v : one.vertices()) ASSERT_EQ(one.position(v), two.position(v)) << v.idx();
    for (Halfedge h : one.halfedges()) {
      ASSERT_EQ(one.next(h), two.next(h)) << h.idx();
      ASSERT_EQ(one.to_vertex(h), two.to_vertex(h)) << h.idx();
    }
    EXPECT_EQ(one.validate(), std::vector<std::string>{});
    EXPECT_EQ(two.validate(), std::vector<std::string>{});
  }
}

TEST_F(ThreadsTest, DistanceIsTheSameOnOneThreadAsOnTwo) {
  const SurfaceMesh a = wavy_grid();
  const SurfaceMesh b = build(test::grid(200, true));
  DistanceOptions o;
  o.samples = 20000;
  o.threads = 8;
  set_max_threads(1);
  const HausdorffDistance one = hausdorff_distance(a, b, o);
  set_max_threads(2);
  const HausdorffDistance two = hausdorff_distance(a, b, o);
  EXPECT_EQ(one.distance, two.distance);
  EXPECT_EQ(one.mean, two.mean);
  EXPECT_EQ(one.a_to_b.farthest, two.a_to_b.farthest);
}

}  // namespace
}  // namespace hedge
