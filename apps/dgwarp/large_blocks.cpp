// The command's large arrays on transparent huge pages (issue #33).
//
// A mesh of a million nodes lives in a few arrays of 20-300 MB (the file's
// text, the cells' node ids, per-cell qualities). glibc maps each with 4 KiB
// pages, so the first write to it takes one page fault per 4 KiB: 65,000
// faults for a 256 MB array, 0.2 s on bare metal and 0.8 s measured in a
// virtual machine whose page faults trap into the hypervisor (AMD EPYC guest,
// 3.2 us a fault), for every such array, at every run. On 2 MiB pages the same
// array takes 128 faults.
//
// So the command (the executable, and the benchmarks that time what it does:
// this file is not in the library, which leaves allocation to its host)
// replaces the global operator new/delete:
// blocks of `large` bytes or more are mapped 2 MiB-aligned and advised to the
// kernel as huge-page memory (madvise MADV_HUGEPAGE: honoured where the
// kernel's transparent_hugepage setting is "madvise" or "always", ignored where
// it is "never"); smaller ones go to malloc as before. Large blocks are listed
// in a small table, so operator delete tells one from a malloc'd pointer for
// certain (an address test first, then the table).
//
// Not under the sanitizers, which replace operator new themselves (large_blocks.hpp).
#include "large_blocks.hpp"

#if DGWARP_LARGE_BLOCKS

#include <sys/mman.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t huge_page = std::size_t{2} << 20;
// Blocks from 2 MiB up: at 8 MiB the arrays of one id per node (3.5 MB at
// 865k nodes, a dozen of them in a run) stayed on malloc's 4 KiB pages and,
// freed, in its heap: `deform`'s peak at 865k nodes went 416 -> 395 MB.
constexpr std::size_t large = std::size_t{2} << 20;
constexpr std::size_t table_size = 1024;             // large blocks alive at once; beyond, malloc takes them

// Every live large block: its start (2 MiB-aligned, 0 for a free slot) and
// its mapped length. Nothing is written into a block (its first page is
// touched when its owner first writes there, not before).
std::atomic<std::uintptr_t> live[table_size];
std::atomic<std::size_t> lengths[table_size];

std::size_t round_up(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

bool claim_slot(std::uintptr_t base, std::size_t length) {
    for (std::size_t i = 0; i < table_size; ++i) {
        std::uintptr_t expected = 0;
        if (live[i].load(std::memory_order_relaxed) == 0 &&
            live[i].compare_exchange_strong(expected, base, std::memory_order_acq_rel)) {
            lengths[i].store(length, std::memory_order_release);
            return true;
        }
    }
    return false;
}

/// Releases the slot holding `base` and returns its length; 0 when no slot
/// holds it (not a large block).
std::size_t release_slot(std::uintptr_t base) {
    for (std::size_t i = 0; i < table_size; ++i) {
        if (live[i].load(std::memory_order_acquire) != base) continue;
        const std::size_t length = lengths[i].load(std::memory_order_acquire);
        std::uintptr_t expected = base;
        if (live[i].compare_exchange_strong(expected, 0, std::memory_order_acq_rel)) return length;
    }
    return 0;
}

/// A large block of at least n bytes, or nullptr when it cannot be mapped
/// or listed (the caller then falls back to malloc).
void* map_large(std::size_t n) {
    if (n > (std::size_t{1} << 46)) return nullptr;
    const std::size_t length = round_up(n, huge_page);
    // One huge page more than needed, so that a 2 MiB-aligned start fits; the
    // ends beyond it are given back at once.
    const std::size_t mapped = length + huge_page;
    void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) return nullptr;
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t base = round_up(start, huge_page);
    if (base > start) munmap(raw, base - start);
    if (const std::uintptr_t end = base + length; start + mapped > end)
        munmap(reinterpret_cast<void*>(end), start + mapped - end);
    madvise(reinterpret_cast<void*>(base), length, MADV_HUGEPAGE);
    if (!claim_slot(base, length)) {
        munmap(reinterpret_cast<void*>(base), length);
        return nullptr;
    }
    return reinterpret_cast<void*>(base);
}

/// Unmaps p when it is a large block's; false for any other pointer.
bool unmap_large(void* p) {
    const auto at = reinterpret_cast<std::uintptr_t>(p);
    if (at % huge_page != 0) return false;  // most pointers: not even a candidate
    const std::size_t length = release_slot(at);
    if (length == 0) return false;
    munmap(p, length);
    return true;
}

void* allocate(std::size_t n) {
    if (n >= large)
        if (void* p = map_large(n)) return p;
    for (;;) {
        if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
        const std::new_handler handler = std::get_new_handler();
        if (!handler) throw std::bad_alloc();
        handler();
    }
}

void deallocate(void* p) noexcept {
    if (!p || unmap_large(p)) return;
    std::free(p);
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept { deallocate(p); }
void operator delete[](void* p) noexcept { deallocate(p); }
void operator delete(void* p, std::size_t) noexcept { deallocate(p); }
void operator delete[](void* p, std::size_t) noexcept { deallocate(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { deallocate(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { deallocate(p); }

#endif
