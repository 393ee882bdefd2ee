#include "binding/mesh_state.h"

#include "binding/errors.h"

namespace hedge::binding {

FaceBvh& picking_tree(MeshState& state) {
  if (!state.bvh)
    state.bvh = std::make_unique<FaceBvh>(state.mesh);
  else
    state.bvh->update();
  return *state.bvh;
}

std::size_t memory_bytes(const MeshState& state) {
  return state.mesh.memory_bytes() + (state.bvh ? state.bvh->memory_bytes() : 0);
}

void claim(MeshState& state) {
  const std::thread::id me = std::this_thread::get_id();
  std::thread::id user{};
  if (state.user.compare_exchange_strong(user, me, std::memory_order_acquire)) {
    state.depth = 1;
  } else if (user == me) {
    ++state.depth;  // a nested use on the same thread
  } else {
    fail(HEDGE_ERROR_BUSY,
         "the mesh is in a call on another thread; a mesh, and what belongs to it, takes calls from one "
         "thread at a time");
  }
}

void release(MeshState& state) noexcept {
  if (--state.depth == 0) state.user.store(std::thread::id{}, std::memory_order_release);
}

}  // namespace hedge::binding
