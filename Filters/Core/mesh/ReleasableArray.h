// A growable array of plain values in memory from malloc, whose ownership can
// be handed over with Release(): the extracted surface is written once, by
// the extraction, and its points and triangles become the output's data
// arrays without a copy (a VTK data array frees such memory with free()).
//
// Why not std::vector: a vector cannot give up its buffer, nor grow without
// writing every new value (resize_for_overwrite below). The interface is the
// part of std::vector the core uses; values must be trivially copyable (they
// are moved by memcpy and realloc).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tpc
{

template <typename T>
class ReleasableArray
{
  static_assert(std::is_trivially_copyable<T>::value, "values are moved by memcpy and realloc");

public:
  using value_type = T;
  using iterator = T*;
  using const_iterator = const T*;

  ReleasableArray() = default;
  ReleasableArray(std::initializer_list<T> values)
  {
    this->reserve(values.size());
    for (const T& v : values)
    {
      this->push_back(v);
    }
  }
  ReleasableArray(const ReleasableArray& other) { *this = other; }
  ReleasableArray(ReleasableArray&& other) noexcept { this->swap(other); }
  ReleasableArray& operator=(const ReleasableArray& other)
  {
    if (this != &other)
    {
      this->Size = 0;
      this->reserve(other.Size);
      if (other.Size > 0)
      {
        std::memcpy(this->Data, other.Data, other.Size * sizeof(T));
      }
      this->Size = other.Size;
    }
    return *this;
  }
  ReleasableArray& operator=(ReleasableArray&& other) noexcept
  {
    if (this != &other)
    {
      std::free(this->Data);
      this->Data = nullptr;
      this->Size = this->Capacity = 0;
      this->swap(other);
    }
    return *this;
  }
  ~ReleasableArray() { std::free(this->Data); }

  void swap(ReleasableArray& other) noexcept
  {
    std::swap(this->Data, other.Data);
    std::swap(this->Size, other.Size);
    std::swap(this->Capacity, other.Capacity);
  }

  /// The values' memory, for the caller to free() (null when empty); the
  /// array is left empty.
  T* Release() noexcept
  {
    T* data = this->Data;
    this->Data = nullptr;
    this->Size = this->Capacity = 0;
    return data;
  }

  std::size_t size() const { return this->Size; }
  bool empty() const { return this->Size == 0; }
  T* data() { return this->Data; }
  const T* data() const { return this->Data; }
  T& operator[](std::size_t i) { return this->Data[i]; }
  const T& operator[](std::size_t i) const { return this->Data[i]; }
  T& back() { return this->Data[this->Size - 1]; }
  const T& back() const { return this->Data[this->Size - 1]; }
  T* begin() { return this->Data; }
  T* end() { return this->Data + this->Size; }
  const T* begin() const { return this->Data; }
  const T* end() const { return this->Data + this->Size; }

  void reserve(std::size_t capacity)
  {
    if (capacity <= this->Capacity)
    {
      return;
    }
    void* grown = std::realloc(this->Data, capacity * sizeof(T));
    if (!grown)
    {
      throw std::bad_alloc();
    }
    this->Data = static_cast<T*>(grown);
    this->Capacity = capacity;
  }
  /// New values are value-initialized (zero for numbers and Vec3).
  void resize(std::size_t size)
  {
    this->reserve(size);
    for (std::size_t i = this->Size; i < size; ++i)
    {
      new (this->Data + i) T();
    }
    this->Size = size;
  }
  /// New values left unwritten, for a parallel loop to write every one of
  /// them before any is read: their pages are first touched by the threads
  /// that fill them. (resize writes zeros on the calling thread first, and a
  /// page first touched costs about 11 us on the benchmark machine - most of
  /// MeshSolid's index of an 18 000-triangle mesh, on one thread.)
  void resize_for_overwrite(std::size_t size)
  {
    this->reserve(size);
    this->Size = size;
  }
  void clear() { this->Size = 0; }
  void push_back(const T& value)
  {
    if (this->Size == this->Capacity)
    {
      const T copy = value; // (value may live in this array)
      this->reserve(std::max<std::size_t>(16, 2 * this->Capacity));
      this->Data[this->Size++] = copy;
      return;
    }
    this->Data[this->Size++] = value;
  }
  template <typename... Args>
  T& emplace_back(Args&&... args)
  {
    this->push_back(T{ std::forward<Args>(args)... });
    return this->back();
  }

  /// A copy as a std::vector.
  std::vector<T> ToVector() const { return std::vector<T>(this->begin(), this->end()); }

private:
  T* Data = nullptr;
  std::size_t Size = 0;
  std::size_t Capacity = 0;
};

} // namespace tpc
