// Change tracking: edits mark what they touched through the mesh, and consumers (RenderBuffers, a BVH,
// an engine's own caches) read what changed since they last looked.
//
//  - Marks are recorded only while at least one consumer is attached, so a mesh nobody watches
//    pays one branch per mark.
//  - Each consumer has its own cursor into one shared log; an element marked twice between two
//    reads of any consumer is logged once. The log is cleared when every consumer has read it.
//  - Coarse events (vertices moved, faces added or removed, ...) reach subscribers once per
//    operation, or once per transaction: there is no callback per vertex.
//
// Every operation of core/operations.h marks what it changes. Code that edits through the
// low-level setters of SurfaceMesh, or writes a property directly, calls mark() itself
// (SurfaceMesh::set_position does it for positions).
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "hedge/core/handles.h"

namespace hedge {

//! Coarse change events. They combine as bits: `ChangeEvent::faces_added | ChangeEvent::faces_removed`,
//! and any(e) tests for a non-empty set.
enum class ChangeEvent : std::uint32_t {
  none = 0,
  vertices_moved = 1u << 0,       //!< positions changed
  vertex_data_changed = 1u << 1,  //!< other vertex properties changed
  faces_added = 1u << 2,
  faces_removed = 1u << 3,
  faces_changed = 1u << 4,  //!< corners, corner properties or face properties changed
  vertices_added = 1u << 5,
  vertices_removed = 1u << 6,
  reset = 1u << 7,  //!< every index may have changed (garbage collection, rebuild)
  all = 0xffu,
};
constexpr ChangeEvent operator|(ChangeEvent a, ChangeEvent b) {
  return ChangeEvent(static_cast<std::uint32_t>(a) | static_cast<std::uint32_t>(b));
}
constexpr ChangeEvent operator&(ChangeEvent a, ChangeEvent b) {
  return ChangeEvent(static_cast<std::uint32_t>(a) & static_cast<std::uint32_t>(b));
}
constexpr ChangeEvent& operator|=(ChangeEvent& a, ChangeEvent b) { return a = a | b; }
//! True if the set holds at least one event.
constexpr bool any(ChangeEvent e) { return e != ChangeEvent::none; }

class ChangeLog {
 public:
  using ConsumerId = std::uint32_t;
  using SubscriptionId = std::uint32_t;
  using Callback = std::function<void(ChangeEvent events)>;

  //! What a consumer has not read yet. Elements may repeat and may be deleted by now; after a
  //! reset, the element lists are empty and everything must be rebuilt.
  struct Pending {
    std::span<const Vertex> vertices;
    std::span<const Face> faces;
    ChangeEvent events = ChangeEvent::none;
    bool reset = false;
    bool empty() const { return vertices.empty() && faces.empty() && !any(events) && !reset; }
  };

  // Consumers and subscribers watch one mesh object, so they never travel with its data: a mesh
  // made by copy or move starts with none, and a mesh assigned to (or moved from) keeps its own and
  // marks a reset, because all its contents changed.
  ChangeLog() = default;
  ChangeLog(const ChangeLog&) {}
  ChangeLog(ChangeLog&& other) noexcept { other.mark_reset(); }
  ChangeLog& operator=(const ChangeLog&) {
    mark_reset();
    return *this;
  }
  ChangeLog& operator=(ChangeLog&& other) noexcept {
    if (this != &other) {
      mark_reset();
      other.mark_reset();
    }
    return *this;
  }

  // ---- Recording (called by edits). ----
  bool active() const { return !consumers_.empty() || !subscribers_.empty(); }
  void mark(Vertex v, ChangeEvent events) {
    if (active()) record(v, events, vertex_stamp_, vertices_);
  }
  void mark(Face f, ChangeEvent events) {
    if (active()) record(f, events, face_stamp_, faces_);
  }
  //! Everything changed: consumers rebuild from scratch.
  void mark_reset();
  //! The end of one edit: subscribers hear the events gathered since the last notify, unless a
  //! transaction is open, in which case they hear them once at commit().
  void notify();

  // ---- Transactions: notifications wait until the outermost commit(). They nest. ----
  void begin() { ++transaction_depth_; }
  //! Ends a transaction; the outermost one notifies. Returns true if that was the outermost.
  bool commit();
  bool in_transaction() const { return transaction_depth_ > 0; }
  //! Opens a transaction on behalf of consumer `id`: an ordinary one, also counted for `id`, so
  //! that the consumer can defer its own reads until it closes it while other consumers read as
  //! usual. detach(id) closes the ones still open. Opens nothing for an unknown id. O(consumers).
  void begin(ConsumerId id);
  //! Closes one transaction opened by begin(id), as commit() does. Returns true if that was the
  //! outermost of `id`'s; false, closing nothing, if `id` has none open. O(consumers).
  bool commit(ConsumerId id);
  //! True while a transaction opened by begin(id) is open. O(consumers).
  bool in_transaction(ConsumerId id) const;

  // ---- Consumers. ----
  ConsumerId attach();
  void detach(ConsumerId id);
  //! Attaches a consumer that starts with what `other` has not read yet: a copy of a consumer.
  //! A plain attach() if `other` is not attached.
  ConsumerId attach_copy(ConsumerId other);
  Pending pending(ConsumerId id) const;
  //! Marks everything pending for `id` as read.
  void consume(ConsumerId id);
  //! True if a reset reached `id` since it last consumed: pending(id).reset without the lists.
  //! False for an unknown id. O(consumers).
  bool reset_pending(ConsumerId id) const;

  // ---- Coarse event subscribers. ----
  //! Calls `fn` with the events of each notify that intersect `mask`.
  SubscriptionId subscribe(ChangeEvent mask, Callback fn);
  void unsubscribe(SubscriptionId id);

 private:
  struct Consumer {
    ConsumerId id;
    std::size_t vertex_cursor = 0, face_cursor = 0;
    ChangeEvent events = ChangeEvent::none;
    bool reset = false;
    int transactions = 0;  // opened by begin(id), not yet committed
  };
  struct Subscriber {
    SubscriptionId id;
    ChangeEvent mask;
    Callback fn;
  };
  template <typename H>
  void record(H h, ChangeEvent events, std::vector<std::uint32_t>& stamps, std::vector<H>& log);
  //! Starts a new generation, so that elements are logged again (stamps cleared on wrap-around).
  void advance_generation();
  void compact_log();

  std::vector<Vertex> vertices_;
  std::vector<Face> faces_;
  // Generation stamps: an element already logged in the current generation is not logged again.
  // The generation advances whenever a consumer reads, so every consumer sees later marks.
  std::vector<std::uint32_t> vertex_stamp_, face_stamp_;
  std::uint32_t generation_ = 1;
  std::vector<Consumer> consumers_;
  std::vector<Subscriber> subscribers_;
  std::uint32_t next_id_ = 1;
  ChangeEvent unnotified_ = ChangeEvent::none;
  int transaction_depth_ = 0;
};

//! The consumer side of a ChangeLog, which a mesh lends when const (SurfaceMesh::watch_changes()):
//! attaching, reading and consuming change what the log keeps for a consumer, never the mesh, so a
//! reader holding a const mesh (FaceBvh) may watch it. Marking needs the mutable log,
//! SurfaceMesh::changes(). Like the log, it is not thread-safe: attach, detach and consume need the
//! log to themselves, as edits do; pending() and reset_pending() may run alongside each other.
class ChangeWatch {
 public:
  //! Watches nothing; only a watch from a mesh may be used.
  ChangeWatch() = default;
  explicit ChangeWatch(ChangeLog& log) : log_(&log) {}
  explicit operator bool() const { return log_ != nullptr; }
  ChangeLog::ConsumerId attach() const { return log_->attach(); }
  ChangeLog::ConsumerId attach_copy(ChangeLog::ConsumerId other) const { return log_->attach_copy(other); }
  void detach(ChangeLog::ConsumerId id) const { log_->detach(id); }
  ChangeLog::Pending pending(ChangeLog::ConsumerId id) const { return log_->pending(id); }
  bool reset_pending(ChangeLog::ConsumerId id) const { return log_->reset_pending(id); }
  void consume(ChangeLog::ConsumerId id) const { log_->consume(id); }

 private:
  ChangeLog* log_ = nullptr;
};

//! One consumer of a mesh's change log, held by value: it attaches when made from a watch and
//! detaches when destroyed. A copy is attached too and starts with what the original has not read
//! (ChangeLog::attach_copy); a move hands the attachment over. A default-made one watches nothing:
//! pending() is empty and reset_pending() false.
//! \pre The mesh outlives every consumer attached to it.
class ChangeConsumer {
 public:
  ChangeConsumer() = default;
  explicit ChangeConsumer(ChangeWatch watch) : watch_(watch), id_(watch ? watch.attach() : 0) {}
  ChangeConsumer(const ChangeConsumer& other)
      : watch_(other.watch_), id_(other.watch_ ? other.watch_.attach_copy(other.id_) : 0) {}
  ChangeConsumer(ChangeConsumer&& other) noexcept : watch_(other.watch_), id_(other.id_) {
    other.watch_ = ChangeWatch();
    other.id_ = 0;
  }
  ChangeConsumer& operator=(ChangeConsumer other) noexcept {
    std::swap(watch_, other.watch_);
    std::swap(id_, other.id_);
    return *this;
  }
  ~ChangeConsumer() {
    if (watch_) watch_.detach(id_);
  }

  bool attached() const { return static_cast<bool>(watch_); }
  ChangeLog::ConsumerId id() const { return id_; }
  ChangeLog::Pending pending() const { return watch_ ? watch_.pending(id_) : ChangeLog::Pending{}; }
  bool reset_pending() const { return watch_ && watch_.reset_pending(id_); }
  void consume() const {
    if (watch_) watch_.consume(id_);
  }

 private:
  ChangeWatch watch_;
  ChangeLog::ConsumerId id_ = 0;
};

}  // namespace hedge
