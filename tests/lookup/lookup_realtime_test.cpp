// SPDX-License-Identifier: Apache-2.0
// Real-time properties: no allocation in queries (counting malloc in this binary), concurrent queries from
// several std::threads equal sequential ones bit for bit.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/lookup/blob.hpp"
#include "synthetic_table.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer the allocator is the sanitizer's: replacing malloc here would hand it foreign pointers.
// Its allocation hook sees every allocation of this process instead.
// Declared as in the sanitizer runtime's allocator_interface.h (not every Debian toolchain ships that header).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace {
void count_allocation(const volatile void*, std::size_t) { g_allocations.fetch_add(1, std::memory_order_relaxed); }
void ignore_free(const volatile void*) {}
[[maybe_unused]] const int g_hooks_installed = __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free);
}  // namespace
#else
// glibc's own allocator entry points; every allocation of this process (operator new included) passes here.
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* __libc_calloc(std::size_t n, std::size_t size);
extern "C" void* __libc_realloc(void* p, std::size_t size);
extern "C" void* __libc_memalign(std::size_t alignment, std::size_t size);

extern "C" void* malloc(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(p, size);
}
extern "C" void* aligned_alloc(std::size_t alignment, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
extern "C" int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  *out = __libc_memalign(alignment, size);
  return *out ? 0 : 12;
}
#endif

namespace ctab::lookup {
namespace {

ctab_table* open_synthetic(ctab_interpolation interpolation, bool single, std::size_t n_second) {
  const std::vector<unsigned char> blob =
      write_blob(test::make_synthetic({.n_second = n_second, .failed_case = true}), single);
  const ctab_open_options options{interpolation, single ? 1 : 0};
  ctab_table* table = nullptr;
  EXPECT_EQ(ctab_table_open_memory(blob.data(), blob.size(), &options, &table), CTAB_OK);
  return table;
}

TEST(LookupRealtime, CountingAllocatorSeesLoadsButNoQueries) {
  const long before_load = g_allocations.load();
  ctab_table* table = open_synthetic(CTAB_PCHIP, false, 3);
  ASSERT_NE(table, nullptr);
  EXPECT_GT(g_allocations.load(), before_load) << "the counter works: loading allocates";
  std::vector<double> dys(2000);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-14e-3, 14e-3);
  for (double& dy : dys) dy = uniform(random);
  ctab_result result;
  ctab_location where;
  ctab_creep_result creep_result;
  double s[16], a[16], p0[16];
  std::uint32_t count = 0;
  const long before = g_allocations.load();
  for (const double dy : dys) {
    ctab_query(table, dy, 75e3, 0, &result);
    ctab_prelookup(table, dy, 1e9, &where);
    ctab_query_prelooked(table, &where, 1, &result);
    ctab_strip_profile(table, &where, 1, 0, s, a, p0, 16, &count);
    for (const int32_t method :
         {CTAB_CREEP_STRIPS_CARTER, CTAB_CREEP_FASTSIM_ELLIPSE, CTAB_CREEP_LINEAR, CTAB_CREEP_STRIPS}) {
      const ctab_creep_input creep{dy * 0.1, -dy * 0.1, 0.5, 0.3, 0.0, 0.0, method, 0};
      ctab_creep_prelooked(table, &where, 1, &creep, &creep_result);
    }
  }
  const ctab_creep_input bad{std::nan(""), 0.0, 0.0, 0.3, 0.0, 0.0, CTAB_CREEP_STRIPS, 0};
  ctab_creep_prelooked(table, &where, 0, &bad, &creep_result);
  ctab_query(table, std::nan(""), 0.0, 0, &result);
  ctab_query(nullptr, 0.0, 0.0, 0, &result);
  EXPECT_EQ(g_allocations.load(), before) << "a query or a creep call allocated";
  ctab_table_close(table);
}

// Located jumps on an adaptive axis: the index search and the jump bands between rows allocate nothing either.
TEST(LookupRealtime, LocatedJumpsAllocateNothing) {
  const std::vector<unsigned char> blob = write_blob(test::make_located(), false);
  for (const ctab_interpolation interpolation : {CTAB_LINEAR, CTAB_PCHIP}) {
    const ctab_open_options options{interpolation, 0};
    ctab_table* table = nullptr;
    ASSERT_EQ(ctab_table_open_memory(blob.data(), blob.size(), &options, &table), CTAB_OK);
    std::vector<double> dys(4000), loads(4000);
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> dy(-3.5e-3, 2.5e-3), load(55e3, 105e3);
    for (std::size_t i = 0; i < dys.size(); ++i) dys[i] = dy(random), loads[i] = load(random);
    ctab_result result;
    ctab_location where;
    double a[4];
    std::uint32_t count = 0;
    const long before = g_allocations.load();
    for (std::size_t i = 0; i < dys.size(); ++i) {
      ctab_query(table, dys[i], loads[i], static_cast<std::int32_t>(i % 2), &result);
      ctab_prelookup(table, dys[i], loads[i], &where);
      ctab_strip_profile(table, &where, 0, 1, nullptr, a, nullptr, 4, &count);
    }
    EXPECT_EQ(g_allocations.load(), before) << "a query allocated";
    ctab_table_close(table);
  }
}

TEST(LookupRealtime, ConcurrentQueriesEqualSequentialOnes) {
  for (const bool single : {false, true}) {
    ctab_table* table = open_synthetic(CTAB_LINEAR, single, 3);
    ASSERT_NE(table, nullptr);
    constexpr std::size_t kThreads = 4, kQueries = 3000;
    std::vector<double> dys(kQueries), loads(kQueries);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> dy(-12.5e-3, 12.5e-3), load(50e3, 110e3);
    for (std::size_t i = 0; i < kQueries; ++i) dys[i] = dy(random), loads[i] = load(random);
    std::vector<ctab_result> sequential(kQueries);
    for (std::size_t i = 0; i < kQueries; ++i)
      ctab_query(table, dys[i], loads[i], static_cast<std::int32_t>(i % 2), &sequential[i]);
    std::vector<std::vector<ctab_result>> parallel(kThreads, std::vector<ctab_result>(kQueries));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        for (std::size_t i = 0; i < kQueries; ++i)
          ctab_query(table, dys[i], loads[i], static_cast<std::int32_t>(i % 2), &parallel[t][i]);
      });
    for (std::thread& thread : threads) thread.join();
    for (std::size_t t = 0; t < kThreads; ++t)
      for (std::size_t i = 0; i < kQueries; ++i)
        ASSERT_EQ(std::memcmp(&parallel[t][i], &sequential[i], sizeof(ctab_result)), 0)
            << "thread " << t << " query " << i;
    ctab_table_close(table);
  }
}

}  // namespace
}  // namespace ctab::lookup
