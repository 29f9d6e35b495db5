// Scratch objects for the ranges of a parallel loop, kept for the run that
// owns the pool: a range takes one, uses it for each of its items, and gives
// it back, so a buffer grown for one cell is reused by the next instead of
// being freed and allocated again.
//
// Why: where one mesh is the surface, every cell a prediction examines builds
// S_C (MeshCellError.h), up to a few megabytes for the large cells of the
// first levels. Allocated and freed per cell, such buffers go back to the
// system and come back as fresh pages, and a page fault costs about 15 us on
// the virtual machines this runs on (armadillo at 1/64: about 3 500 more
// faults in the first two levels than with the buffers reused). Thread-local buffers would outlive the run in the
// threads of VTK's pool (ParaView keeps them); the pool's objects are freed
// with it.
#pragma once

#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace tpc
{

template <typename T>
class ScratchPool
{
public:
  /// An object of the pool, the caller's alone until the lease ends.
  class Lease
  {
  public:
    explicit Lease(ScratchPool& pool)
      : Pool(&pool)
      , Item(pool.Take())
    {
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() { this->Pool->Give(std::move(this->Item)); }
    T& operator*() { return *this->Item; }
    T* operator->() { return this->Item.get(); }

  private:
    ScratchPool* Pool;
    std::unique_ptr<T> Item;
  };

private:
  std::unique_ptr<T> Take()
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    if (this->Free.empty())
    {
      return std::make_unique<T>();
    }
    std::unique_ptr<T> item = std::move(this->Free.back());
    this->Free.pop_back();
    return item;
  }
  void Give(std::unique_ptr<T> item)
  {
    const std::lock_guard<std::mutex> lock(this->Mutex);
    this->Free.push_back(std::move(item));
  }

  std::mutex Mutex;
  std::vector<std::unique_ptr<T>> Free;
};

} // namespace tpc
