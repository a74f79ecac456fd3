// The program's own malloc family, forwarding to glibc's (__libc_malloc and friends: the
// documented way to interpose on glibc's allocator) and counting calls while asked to.
#include "counting_malloc.hpp"

#include <atomic>
#include <cerrno>
#include <cstddef>

#if defined(__GLIBC__)
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
inline void count() {
  if (g_counting.load(std::memory_order_relaxed))
    g_allocations.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace

extern "C" {
void* malloc(std::size_t n) {
  count();
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t size) {
  count();
  return __libc_calloc(n, size);
}
void* realloc(void* p, std::size_t n) {
  count();
  return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
void* memalign(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
void* aligned_alloc(std::size_t alignment, std::size_t n) {
  count();
  return __libc_memalign(alignment, n);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t n) {
  count();
  void* p = __libc_memalign(alignment, n);
  if (p == nullptr && n != 0) return ENOMEM;
  *out = p;
  return 0;
}
}

namespace jelly::testing {
bool allocation_counting_available() { return true; }
void start_counting_allocations() {
  g_allocations = 0;
  g_counting = true;
}
long stop_counting_allocations() {
  g_counting = false;
  return g_allocations.load();
}
}  // namespace jelly::testing

#else
namespace jelly::testing {
bool allocation_counting_available() { return false; }
void start_counting_allocations() {}
long stop_counting_allocations() { return 0; }
}  // namespace jelly::testing
#endif
