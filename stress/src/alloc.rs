//! A counting allocator for the `rtnav` binary and the test binaries that fuzz and soak: it
//! passes every call to the system allocator and counts, per thread, the bytes live, their
//! peak and the largest single request (the fuzzer's allocation bound), and in total the
//! bytes live in the process (the soak's memory figure).
//!
//! A binary installs it with
//! `#[global_allocator] static A: rtnav_stress::alloc::Counting = rtnav_stress::alloc::Counting;`;
//! without that, [`installed`] is false and the figures stay zero.
// The `GlobalAlloc` contract needs `unsafe`; every call goes straight to `System`.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicBool, AtomicI64, Ordering};

thread_local! {
    static LIVE: Cell<i64> = const { Cell::new(0) };
    static PEAK: Cell<i64> = const { Cell::new(0) };
    static LARGEST: Cell<usize> = const { Cell::new(0) };
}

static TOTAL_LIVE: AtomicI64 = AtomicI64::new(0);
static INSTALLED: AtomicBool = AtomicBool::new(false);

/// The counting allocator (see the module documentation).
#[derive(Debug, Clone, Copy, Default)]
pub struct Counting;

fn note_alloc(size: usize) {
    INSTALLED.store(true, Ordering::Relaxed);
    TOTAL_LIVE.fetch_add(size as i64, Ordering::Relaxed);
    let _ = LARGEST.try_with(|l| l.set(l.get().max(size)));
    let _ = LIVE.try_with(|live| {
        let now = live.get() + size as i64;
        live.set(now);
        let _ = PEAK.try_with(|p| p.set(p.get().max(now)));
    });
}

fn note_free(size: usize) {
    TOTAL_LIVE.fetch_sub(size as i64, Ordering::Relaxed);
    let _ = LIVE.try_with(|live| live.set(live.get() - size as i64));
}

// SAFETY: every call is passed to the system allocator with the caller's arguments. The
// counters are atomics and thread-local `Cell`s with const initialisers, which never allocate
// (and are skipped, not touched, while a thread's locals are being torn down).
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        note_alloc(layout.size());
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        note_free(layout.size());
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        note_free(layout.size());
        note_alloc(new_size);
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

/// Whether the running binary counts (it installed [`Counting`] and allocated since).
pub fn installed() -> bool {
    INSTALLED.load(Ordering::Relaxed)
}

/// Bytes live in the whole process now (0 without the counting allocator).
pub fn total_live() -> i64 {
    TOTAL_LIVE.load(Ordering::Relaxed)
}

/// What a piece of code allocated on this thread ([`measure`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Usage {
    /// The largest single request \[bytes\].
    pub largest: usize,
    /// The peak of live bytes above those live at the start \[bytes\].
    pub peak: i64,
}

/// Runs `f` and returns what it allocated on this thread (zeros without the counting
/// allocator).
pub fn measure<T>(f: impl FnOnce() -> T) -> (T, Usage) {
    let base = LIVE.with(Cell::get);
    PEAK.with(|p| p.set(base));
    LARGEST.with(|l| l.set(0));
    let out = f();
    let usage = Usage {
        largest: LARGEST.with(Cell::get),
        peak: PEAK.with(Cell::get) - base,
    };
    (out, usage)
}
