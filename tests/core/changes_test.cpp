#include "hedge/core/changes.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "hedge/algorithms/split_all_faces.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "test_meshes.h"

namespace hedge {
namespace {

template <typename H>
bool contains(std::span<const H> s, H h) {
  return std::find(s.begin(), s.end(), h) != s.end();
}

TEST(ChangeLog, RecordsNothingWithoutConsumers) {
  ChangeLog log;
  EXPECT_FALSE(log.active());
  log.mark(Vertex(3), ChangeEvent::vertices_moved);
  const auto id = log.attach();
  EXPECT_TRUE(log.pending(id).empty());
}

TEST(ChangeLog, EachElementOncePerRead) {
  ChangeLog log;
  const auto id = log.attach();
  log.mark(Vertex(3), ChangeEvent::vertices_moved);
  log.mark(Vertex(3), ChangeEvent::vertices_moved);
  log.mark(Face(1), ChangeEvent::faces_changed);
  log.mark(Vertex(5), ChangeEvent::vertex_data_changed);
  auto p = log.pending(id);
  ASSERT_EQ(p.vertices.size(), 2u);
  EXPECT_EQ(p.vertices[0], Vertex(3));
  EXPECT_EQ(p.vertices[1], Vertex(5));
  ASSERT_EQ(p.faces.size(), 1u);
  EXPECT_EQ(p.events,
            ChangeEvent::vertices_moved | ChangeEvent::vertex_data_changed | ChangeEvent::faces_changed);
  log.consume(id);
  EXPECT_TRUE(log.pending(id).empty());
  // After a read, the same element is logged again.
  log.mark(Vertex(3), ChangeEvent::vertices_moved);
  EXPECT_EQ(log.pending(id).vertices.size(), 1u);
}

TEST(ChangeLog, ConsumersReadIndependently) {
  ChangeLog log;
  const auto a = log.attach();
  const auto b = log.attach();
  log.mark(Vertex(1), ChangeEvent::vertices_moved);
  log.consume(a);
  log.mark(Vertex(1), ChangeEvent::vertices_moved);  // a has read; it must see this mark
  log.mark(Vertex(2), ChangeEvent::vertices_moved);
  auto pa = log.pending(a);
  auto pb = log.pending(b);
  EXPECT_TRUE(contains(pa.vertices, Vertex(1)));
  EXPECT_TRUE(contains(pa.vertices, Vertex(2)));
  EXPECT_TRUE(contains(pb.vertices, Vertex(1)));
  EXPECT_TRUE(contains(pb.vertices, Vertex(2)));
  log.consume(b);
  EXPECT_TRUE(log.pending(b).empty());
  EXPECT_FALSE(log.pending(a).empty());
  // A consumer attached later sees only later marks, including elements logged before.
  const auto c = log.attach();
  EXPECT_TRUE(log.pending(c).empty());
  log.mark(Vertex(2), ChangeEvent::vertices_moved);
  EXPECT_TRUE(contains(log.pending(c).vertices, Vertex(2)));
  log.detach(a);
  log.detach(b);
  log.detach(c);
  EXPECT_FALSE(log.active());
}

TEST(ChangeLog, SubscribersHearOncePerNotifyAndOncePerTransaction) {
  ChangeLog log;
  std::vector<ChangeEvent> heard;
  const auto s = log.subscribe(ChangeEvent::vertices_moved | ChangeEvent::faces_removed,
                               [&](ChangeEvent e) { heard.push_back(e); });
  for (int i = 0; i < 100; ++i) log.mark(Vertex(i), ChangeEvent::vertices_moved);
  log.mark(Face(0), ChangeEvent::faces_added);  // not in the mask
  log.notify();
  ASSERT_EQ(heard.size(), 1u);
  EXPECT_EQ(heard[0], ChangeEvent::vertices_moved);
  log.notify();  // nothing new
  EXPECT_EQ(heard.size(), 1u);

  log.begin();
  log.begin();
  log.mark(Vertex(1), ChangeEvent::vertices_moved);
  log.notify();
  log.mark(Face(2), ChangeEvent::faces_removed);
  log.notify();
  EXPECT_FALSE(log.commit());  // inner
  EXPECT_EQ(heard.size(), 1u);
  EXPECT_TRUE(log.commit());  // outermost
  ASSERT_EQ(heard.size(), 2u);
  EXPECT_EQ(heard[1], ChangeEvent::vertices_moved | ChangeEvent::faces_removed);
  log.unsubscribe(s);
  log.mark(Vertex(1), ChangeEvent::vertices_moved);
  log.notify();
  EXPECT_EQ(heard.size(), 2u);
}

TEST(ChangeLog, ResetClearsListsAndCopiesStartEmpty) {
  ChangeLog log;
  const auto id = log.attach();
  log.mark(Vertex(1), ChangeEvent::vertices_moved);
  log.mark_reset();
  auto p = log.pending(id);
  EXPECT_TRUE(p.reset);
  EXPECT_TRUE(p.vertices.empty());
  ChangeLog copy(log);
  EXPECT_FALSE(copy.active());
  log.consume(id);
  EXPECT_FALSE(log.pending(id).reset);
}

TEST(ChangeLog, ConsumersStayWithTheMeshObjectAcrossCopiesAndAssignments) {
  SurfaceMesh a = build(test::grid(2, true));
  const SurfaceMesh b = build(test::grid(3, true));
  const auto id = a.changes().attach();
  int heard = 0;
  a.changes().subscribe(ChangeEvent::reset, [&](ChangeEvent) { ++heard; });
  SurfaceMesh copy(a);  // a new object: nobody watches it
  EXPECT_FALSE(copy.changes().active());
  a = b;  // a's watchers stay and learn that everything changed
  EXPECT_TRUE(a.changes().active());
  EXPECT_TRUE(a.changes().pending(id).reset);
  EXPECT_EQ(heard, 1);
  a.changes().consume(id);
  SurfaceMesh moved(std::move(a));  // the data leaves a: a's watchers see a reset, moved has none
  EXPECT_FALSE(moved.changes().active());
  EXPECT_TRUE(a.changes().pending(id).reset);
  EXPECT_TRUE(moved.validate().empty());
}

TEST(ChangeLog, AttachCopyStartsWithTheUnreadChangesOfAnother) {
  ChangeLog log;
  const auto a = log.attach();
  log.mark(Vertex(1), ChangeEvent::vertices_moved);
  log.mark(Face(2), ChangeEvent::faces_added);
  const auto b = log.attach_copy(a);
  const auto pb = log.pending(b);
  EXPECT_TRUE(contains(pb.vertices, Vertex(1)));
  EXPECT_TRUE(contains(pb.faces, Face(2)));
  EXPECT_EQ(pb.events, ChangeEvent::vertices_moved | ChangeEvent::faces_added);
  // From then on each reads on its own, and later marks reach both.
  log.consume(a);
  EXPECT_TRUE(log.pending(a).empty());
  EXPECT_TRUE(contains(log.pending(b).faces, Face(2)));
  log.mark(Face(2), ChangeEvent::faces_changed);
  EXPECT_TRUE(contains(log.pending(a).faces, Face(2)));
  log.consume(b);
  const auto c = log.attach_copy(a);
  log.mark(Vertex(4), ChangeEvent::vertices_moved);
  for (auto id : {a, b, c}) EXPECT_TRUE(contains(log.pending(id).vertices, Vertex(4)));
  log.mark_reset();
  EXPECT_TRUE(log.pending(log.attach_copy(c)).reset);
  const auto plain = log.attach_copy(999);  // not attached: a plain attach
  EXPECT_TRUE(log.pending(plain).empty());
}

// A reader holding a const mesh watches its changes without a mutable mesh.
TEST(ChangeLog, AConstMeshLendsItsConsumerSide) {
  SurfaceMesh m = build(test::grid(2, true));
  const SurfaceMesh& reader = m;
  const ChangeWatch watch = reader.watch_changes();
  const auto id = watch.attach();
  EXPECT_TRUE(m.changes().active());
  Vec3 centre{0, 0, 0};
  for (Vertex v : m.vertices(Face(0))) centre += m.position(v) / 3.f;
  ASSERT_TRUE(split_face(m, Face(0), centre).is_valid());
  EXPECT_TRUE(contains(watch.pending(id).faces, Face(0)));
  EXPECT_TRUE(any(watch.pending(id).events & ChangeEvent::faces_added));
  const auto copy = watch.attach_copy(id);
  watch.consume(id);
  EXPECT_TRUE(watch.pending(id).empty());
  EXPECT_TRUE(contains(watch.pending(copy).faces, Face(0)));
  watch.detach(id);
  watch.detach(copy);
  EXPECT_FALSE(m.changes().active());
  EXPECT_TRUE(m.validate().empty());
}

// The operations mark what they touch.
TEST(ChangeLog, OperationsMarkTheFacesTheyTouch) {
  SurfaceMesh m = build(test::grid(4, true));
  const auto id = m.changes().attach();
  int notified = 0;
  m.changes().subscribe(ChangeEvent::all, [&](ChangeEvent) { ++notified; });

  const Edge e = test::first_edge(m, [&](Edge c) { return can_flip(m, c); });
  ASSERT_TRUE(e.is_valid());
  const Face f0 = m.face(e, 0), f1 = m.face(e, 1);
  flip(m, e);
  auto p = m.changes().pending(id);
  EXPECT_EQ(notified, 1);
  EXPECT_EQ(p.faces.size(), 2u);
  EXPECT_TRUE(contains(p.faces, f0));
  EXPECT_TRUE(contains(p.faces, f1));
  m.changes().consume(id);

  const Vertex v = split_edge(m, e, 0.5f * (m.position(m.vertex(e, 0)) + m.position(m.vertex(e, 1))));
  p = m.changes().pending(id);
  EXPECT_EQ(p.faces.size(), 4u);
  for (Face f : m.faces(v)) EXPECT_TRUE(contains(p.faces, f));
  EXPECT_TRUE(any(p.events & ChangeEvent::faces_added));
  m.changes().consume(id);

  const Halfedge h = m.halfedge(v);
  ASSERT_TRUE(can_collapse(m, h));
  const Face gone = m.face(h);
  const Vertex s = collapse(m, h);
  p = m.changes().pending(id);
  EXPECT_TRUE(contains(p.faces, gone));
  for (Face f : m.faces(s)) EXPECT_TRUE(contains(p.faces, f));
  EXPECT_TRUE(any(p.events & ChangeEvent::faces_removed));
  m.changes().consume(id);

  m.set_position(Vertex(0), Vec3{-1, -1, 0});
  p = m.changes().pending(id);
  ASSERT_EQ(p.vertices.size(), 1u);
  EXPECT_EQ(p.vertices[0], Vertex(0));
  m.changes().consume(id);

  const int before = notified;
  split_all_faces(m);  // one notification for the pass
  EXPECT_EQ(notified, before + 1);
  EXPECT_EQ(m.changes().pending(id).faces.size(), m.n_faces());
  m.changes().consume(id);

  m.garbage_collection();
  EXPECT_TRUE(m.changes().pending(id).reset);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge
