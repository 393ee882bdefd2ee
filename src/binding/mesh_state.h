// What every binding keeps per mesh besides the mesh: its picking tree, kept up to date through the
// mesh's change log, and the busy check that turns calls on one mesh from two threads at once into
// an error (HEDGE_ERROR_BUSY) instead of a race.
#pragma once

#include <atomic>
#include <memory>
#include <thread>
#include <utility>

#include "hedge/algorithms/locate.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::binding {

//! A binding's mesh object (a binding derives its own, adding what it keeps beside the mesh).
struct MeshState {
  SurfaceMesh mesh;
  //! The picking tree: made by the first picking_tree() and brought up to date by each later one.
  //! Declared after `mesh`: destroyed first, as it follows mesh's change log.
  std::unique_ptr<FaceBvh> bvh;
  //! The thread in a call on this mesh (none: the default id), and how many nested uses it holds
  //! (touched by that thread only). See MeshUse.
  std::atomic<std::thread::id> user{};
  int depth = 0;
};

//! The mesh's picking tree, up to date: built on first use, otherwise brought up to date with the
//! edits since its last use through the mesh's change log (FaceBvh::update(), which costs the
//! edited faces). Every picking call and every fracture of a binding goes through it, so a mesh has
//! one tree and no call builds a tree of its own.
FaceBvh& picking_tree(MeshState& state);
//! The memory of the mesh and its picking tree, in bytes.
std::size_t memory_bytes(const MeshState& state);

//! Claims the mesh for the calling thread (nested claims by one thread count). \throw BindingError
//! (HEDGE_ERROR_BUSY) at once if another thread holds it: one compare-and-swap per call.
void claim(MeshState& state);
//! Gives back one claim of claim().
void release(MeshState& state) noexcept;

//! A call's use of a mesh object (T derives from MeshState): while it lives, the mesh belongs to
//! the calling thread (claim()).
template <typename T>
class MeshUse {
 public:
  //! \throw BindingError (HEDGE_ERROR_BUSY) if another thread uses the mesh.
  explicit MeshUse(std::shared_ptr<T> object) : object_(std::move(object)) { claim(*object_); }
  MeshUse(MeshUse&& other) noexcept = default;
  MeshUse& operator=(MeshUse&&) = delete;
  ~MeshUse() {
    if (object_) release(*object_);
  }
  T* operator->() const { return object_.get(); }
  T& operator*() const { return *object_; }
  const std::shared_ptr<T>& shared() const { return object_; }

 private:
  std::shared_ptr<T> object_;
};

}  // namespace hedge::binding
