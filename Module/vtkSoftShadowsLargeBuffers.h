// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSoftShadowsLargeBuffers.h
 * @brief  Private: allocation of the mesh-topology filters' large buffers.
 *
 * On meshes of millions of faces these filters write hundreds of megabytes
 * (a default topology aware mesh is 252 bytes a face), and the first touch
 * of fresh memory then costs as much as the work itself: on the 2-core
 * virtual machine this module is benchmarked on, one 4 KiB page fault took
 * 12-14 us (meshbench prints the figure), i.e. 3 ms a megabyte. Buffers of
 * 4 MiB and more are therefore aligned to 2 MiB and, on Linux, advised as
 * transparent huge pages (madvise(MADV_HUGEPAGE), honoured when the system's
 * THP mode is "madvise" or "always"): one fault a 2 MiB page instead of 512.
 * The same advice shortens the silhouette hierarchy's walks (fewer TLB
 * misses). Elsewhere, or when the kernel declines, they are plain malloc
 * memory. Either way they are released with free(), so VTK arrays can own
 * them (VTK_DATA_ARRAY_FREE).
 *
 * Not installed, not wrapped.
 */

#ifndef vtkSoftShadowsLargeBuffers_h
#define vtkSoftShadowsLargeBuffers_h

#include "vtkAOSDataArrayTemplate.h"
#include "vtkType.h"

#include <cstddef> // for std::size_t
#include <cstdlib> // for std::malloc, std::free, posix_memalign
#include <memory>  // for std::allocator
#include <new>     // for std::bad_alloc
#include <utility> // for std::forward
#include <vector>  // for std::vector

#if defined(__linux__)
#include <sys/mman.h> // for madvise
#endif

namespace vtksoftshadows
{
/// Memory for `bytes` bytes, to be released with std::free(); nullptr on failure.
inline void* AllocateLarge(std::size_t bytes)
{
  constexpr std::size_t hugePage = std::size_t(2) << 20;
  if (bytes < 2 * hugePage)
  {
    return std::malloc(bytes > 0 ? bytes : 1);
  }
#if defined(__linux__)
  const std::size_t rounded = (bytes + hugePage - 1) / hugePage * hugePage;
  void* memory = nullptr;
  if (posix_memalign(&memory, hugePage, rounded) != 0)
  {
    return nullptr;
  }
#if defined(MADV_HUGEPAGE)
  madvise(memory, rounded, MADV_HUGEPAGE); // advice only: ignore a refusal
#endif
  return memory;
#else
  return std::malloc(bytes);
#endif
}

/**
 * A std::vector allocator for large buffers: AllocateLarge() memory, and
 * elements of trivial types left uninitialized on resize (buffers about to be
 * overwritten are not filled twice).
 */
template <typename T>
struct LargeAllocator
{
  using value_type = T;
  LargeAllocator() = default;
  template <typename U>
  LargeAllocator(const LargeAllocator<U>&)
  {
  }
  T* allocate(std::size_t n)
  {
    void* memory = AllocateLarge(n * sizeof(T));
    if (!memory)
    {
      throw std::bad_alloc();
    }
    return static_cast<T*>(memory);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }
  template <typename U>
  void construct(U* p)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const LargeAllocator<U>&) const
  {
    return true;
  }
  template <typename U>
  bool operator!=(const LargeAllocator<U>&) const
  {
    return false;
  }
};
template <typename T>
using RawVector = std::vector<T, LargeAllocator<T>>;

/**
 * Gives `array` (its components already set) `tuples` uninitialized tuples
 * in AllocateLarge() memory, which the array owns and frees.
 */
template <typename T>
void AllocateTuples(vtkAOSDataArrayTemplate<T>* array, vtkIdType tuples)
{
  const vtkIdType values = tuples * array->GetNumberOfComponents();
  void* memory = AllocateLarge(static_cast<std::size_t>(values) * sizeof(T));
  if (!memory)
  {
    throw std::bad_alloc();
  }
  array->SetArray(
    static_cast<T*>(memory), values, 0, vtkAOSDataArrayTemplate<T>::VTK_DATA_ARRAY_FREE);
}
}

#endif
// VTK-HeaderTest-Exclude: vtkSoftShadowsLargeBuffers.h
