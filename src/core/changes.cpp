#include "hedge/core/changes.h"

#include <algorithm>

namespace hedge {

template <typename H>
void ChangeLog::record(H h, ChangeEvent events, std::vector<std::uint32_t>& stamps, std::vector<H>& log) {
  unnotified_ |= events;
  for (Consumer& c : consumers_) c.events |= events;
  if (consumers_.empty() || !h.is_valid()) return;
  const std::size_t i = h.idx();
  if (i >= stamps.size()) stamps.resize(std::max<std::size_t>(i + 1, stamps.size() * 3 / 2 + 16), 0);
  if (stamps[i] == generation_) return;  // logged already since the last read
  stamps[i] = generation_;
  log.push_back(h);
}

template void ChangeLog::record(Vertex, ChangeEvent, std::vector<std::uint32_t>&, std::vector<Vertex>&);
template void ChangeLog::record(Face, ChangeEvent, std::vector<std::uint32_t>&, std::vector<Face>&);

void ChangeLog::advance_generation() {
  if (++generation_ == 0) {
    std::fill(vertex_stamp_.begin(), vertex_stamp_.end(), 0);
    std::fill(face_stamp_.begin(), face_stamp_.end(), 0);
    generation_ = 1;
  }
}

void ChangeLog::mark_reset() {
  if (!active()) return;
  unnotified_ |= ChangeEvent::reset;
  // Nothing logged so far matters any more to anyone: every consumer rebuilds.
  for (Consumer& c : consumers_) {
    c.reset = true;
    c.events |= ChangeEvent::reset;
    c.vertex_cursor = vertices_.size();
    c.face_cursor = faces_.size();
  }
  compact_log();
}

void ChangeLog::notify() {
  if (transaction_depth_ > 0 || !any(unnotified_)) return;
  const ChangeEvent events = unnotified_;
  unnotified_ = ChangeEvent::none;
  // A callback may subscribe or unsubscribe; iterate over a copy of the ids.
  std::vector<SubscriptionId> ids;
  ids.reserve(subscribers_.size());
  for (const Subscriber& s : subscribers_) ids.push_back(s.id);
  for (SubscriptionId id : ids) {
    auto it = std::find_if(subscribers_.begin(), subscribers_.end(),
                           [&](const Subscriber& s) { return s.id == id; });
    if (it == subscribers_.end() || !any(it->mask & events)) continue;
    Callback fn = it->fn;  // the subscriber may remove itself while running
    fn(events & it->mask);
  }
}

bool ChangeLog::commit() {
  if (transaction_depth_ == 0) return false;
  if (--transaction_depth_ > 0) return false;
  notify();
  return true;
}

void ChangeLog::begin(ConsumerId id) {
  for (Consumer& c : consumers_) {
    if (c.id != id) continue;
    ++c.transactions;
    begin();
    return;
  }
}

bool ChangeLog::commit(ConsumerId id) {
  for (Consumer& c : consumers_) {
    if (c.id != id || c.transactions == 0) continue;
    --c.transactions;
    const bool outermost = c.transactions == 0;
    commit();  // may run callbacks that attach or detach consumers: c is not used after it
    return outermost;
  }
  return false;
}

bool ChangeLog::in_transaction(ConsumerId id) const {
  for (const Consumer& c : consumers_)
    if (c.id == id) return c.transactions > 0;
  return false;
}

ChangeLog::ConsumerId ChangeLog::attach() {
  Consumer c;
  c.id = next_id_++;
  c.vertex_cursor = vertices_.size();
  c.face_cursor = faces_.size();
  consumers_.push_back(c);
  // Marks made before this consumer existed must not suppress marks it needs to see.
  advance_generation();
  return c.id;
}

ChangeLog::ConsumerId ChangeLog::attach_copy(ConsumerId other) {
  const ConsumerId id = attach();
  for (const Consumer& c : consumers_) {
    if (c.id != other) continue;
    // attach() started a generation, so marks from now on reach the copy like the original.
    Consumer& copy = consumers_.back();
    copy = c;
    copy.id = id;
    break;
  }
  return id;
}

void ChangeLog::detach(ConsumerId id) {
  // Nobody could close the transactions of a consumer that is gone; they end here.
  int open = 0;
  for (const Consumer& c : consumers_)
    if (c.id == id) open = c.transactions;
  std::erase_if(consumers_, [&](const Consumer& c) { return c.id == id; });
  compact_log();
  if (consumers_.empty()) {
    vertices_.clear();
    faces_.clear();
    std::vector<std::uint32_t>().swap(vertex_stamp_);
    std::vector<std::uint32_t>().swap(face_stamp_);
  }
  for (; open > 0; --open) commit();
}

ChangeLog::Pending ChangeLog::pending(ConsumerId id) const {
  Pending p;
  for (const Consumer& c : consumers_) {
    if (c.id != id) continue;
    p.reset = c.reset;
    p.events = c.events;
    if (!c.reset) {
      p.vertices = std::span<const Vertex>(vertices_).subspan(c.vertex_cursor);
      p.faces = std::span<const Face>(faces_).subspan(c.face_cursor);
    }
  }
  return p;
}

bool ChangeLog::reset_pending(ConsumerId id) const {
  for (const Consumer& c : consumers_)
    if (c.id == id) return c.reset;
  return false;
}

void ChangeLog::consume(ConsumerId id) {
  for (Consumer& c : consumers_) {
    if (c.id != id) continue;
    c.vertex_cursor = vertices_.size();
    c.face_cursor = faces_.size();
    c.events = ChangeEvent::none;
    c.reset = false;
  }
  // New marks must be logged again even if they were logged before this read.
  advance_generation();
  compact_log();
}

void ChangeLog::compact_log() {
  if (consumers_.empty()) return;
  std::size_t vmin = vertices_.size(), fmin = faces_.size();
  for (const Consumer& c : consumers_) {
    vmin = std::min(vmin, c.vertex_cursor);
    fmin = std::min(fmin, c.face_cursor);
  }
  if (vmin > 0) {
    vertices_.erase(vertices_.begin(), vertices_.begin() + static_cast<std::ptrdiff_t>(vmin));
    for (Consumer& c : consumers_) c.vertex_cursor -= vmin;
  }
  if (fmin > 0) {
    faces_.erase(faces_.begin(), faces_.begin() + static_cast<std::ptrdiff_t>(fmin));
    for (Consumer& c : consumers_) c.face_cursor -= fmin;
  }
}

ChangeLog::SubscriptionId ChangeLog::subscribe(ChangeEvent mask, Callback fn) {
  const SubscriptionId id = next_id_++;
  subscribers_.push_back({id, mask, std::move(fn)});
  return id;
}

void ChangeLog::unsubscribe(SubscriptionId id) {
  std::erase_if(subscribers_, [&](const Subscriber& s) { return s.id == id; });
}

}  // namespace hedge
