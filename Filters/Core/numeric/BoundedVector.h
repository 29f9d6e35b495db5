// A vector whose capacity is held inline, for the corners of a triangle
// being clipped (ClippedCorners, ConvexPolygons.h): on the stack, so that
// clipping the hundreds of triangles of a cell's S_C (MeshCellError.h:
// 370 000 of them on armadillo at 1/64) takes no heap block per triangle.
// (Boost's static_vector does this; the core depends on nothing beyond the
// standard library, and the few members below are all the clipping uses.)
#pragma once

#include <cstddef>
#include <cstring>
#include <initializer_list>
#include <new>
#include <stdexcept>
#include <type_traits>

namespace tpc
{

template <typename T, std::size_t Capacity>
class BoundedVector
{
  // (Raw storage, copied only as far as it is used: a clipped triangle
  // mostly has 3 or 4 corners of the 32 it has room for.)
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
  BoundedVector() = default;
  BoundedVector(std::initializer_list<T> values)
  {
    for (const T& v : values)
    {
      this->push_back(v);
    }
  }
  BoundedVector(const BoundedVector& other) { *this = other; }
  BoundedVector& operator=(const BoundedVector& other)
  {
    this->Count = other.Count;
    std::memcpy(this->Storage, other.Storage, other.Count * sizeof(T));
    return *this;
  }

  /// Throws std::length_error past the capacity: each user states why its
  /// count stays within it, so this is a broken argument, never input data.
  void push_back(const T& value)
  {
    if (this->Count == Capacity)
    {
      throw std::length_error("tpc::BoundedVector: capacity exceeded");
    }
    new (this->Storage + this->Count++ * sizeof(T)) T(value);
  }
  void clear() { this->Count = 0; }

  std::size_t size() const { return this->Count; }
  bool empty() const { return this->Count == 0; }
  static constexpr std::size_t capacity() { return Capacity; }

  T* data() { return std::launder(reinterpret_cast<T*>(this->Storage)); }
  const T* data() const { return std::launder(reinterpret_cast<const T*>(this->Storage)); }
  T& operator[](std::size_t i) { return this->data()[i]; }
  const T& operator[](std::size_t i) const { return this->data()[i]; }
  const T& front() const { return this->data()[0]; }
  const T& back() const { return this->data()[this->Count - 1]; }
  T* begin() { return this->data(); }
  T* end() { return this->data() + this->Count; }
  const T* begin() const { return this->data(); }
  const T* end() const { return this->data() + this->Count; }

private:
  alignas(T) unsigned char Storage[Capacity * sizeof(T)];
  std::size_t Count = 0;
};

} // namespace tpc
