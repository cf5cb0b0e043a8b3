//! [`TraceBuffer`]: the read-only storage of the node and block arrays the CPU tracer walks,
//! aligned to 2 MiB and advised to the kernel as transparent-huge-page memory.
//!
//! Input: a slice (usually a `accel::Blas`'s or a scene's freshly built vectors).
//! Output: a copy that dereferences to the same slice type. Any thread; the only `unsafe` is the
//! allocation, the advice and the copies below. Must not: be written while shared (the tracers
//! share it across threads; [`TraceBuffer::write_range`] needs `&mut`).
//!
//! Why (measured, peer benchmark dragon, 202,520 triangles, 3.4 MB of nodes and 11.4 MB of
//! blocks): with 4 KiB pages a ray's walk touches a new page at almost every node and block, and
//! the second-level TLB (2,048 entries) covers only 8 MiB; with 2 MiB pages the whole tree needs
//! eight entries. See `accel/mod.rs` for the figures. Linux only does this for memory that asks
//! for it (`/sys/kernel/mm/transparent_hugepage/enabled` = `madvise` on most distributions);
//! elsewhere, or when the kernel has no huge page to give, the buffer is ordinary memory and
//! only the speed differs. Buffers under [`HUGE_MIN_BYTES`] are allocated normally.

use std::alloc::{Layout, alloc_zeroed, dealloc, handle_alloc_error};
use std::ptr::NonNull;

use bytemuck::Pod;

/// Size of a transparent huge page on x86-64 and the alignment of large buffers.
const HUGE_PAGE: usize = 2 << 20;

/// Buffers at least this large are rounded up to whole huge pages and advised; smaller ones fit
/// the TLB anyway and would waste up to 2 MiB each.
pub const HUGE_MIN_BYTES: usize = 1 << 20;

/// An array of `T`, read-only while shared, 2 MiB-aligned and huge-page-advised when large (see module docs).
pub struct TraceBuffer<T: Pod> {
    ptr: NonNull<T>,
    /// Elements in use (the slice it dereferences to).
    len: usize,
    /// Elements allocated (`len..capacity` is zeroed room to grow into).
    capacity: usize,
    storage: Storage,
}

/// Where the elements live.
#[derive(Clone, Copy, Debug)]
enum Storage {
    /// Nothing allocated (empty buffer, dangling pointer).
    None,
    /// The global allocator, with this layout.
    Heap(Layout),
    /// An anonymous mapping of this many bytes at `ptr` (Linux, large buffers).
    Mapped(usize),
}

// SAFETY: the buffer owns its elements exclusively and never mutates them after construction;
// `T: Pod` has no interior mutability, so shared references may cross threads.
unsafe impl<T: Pod + Send> Send for TraceBuffer<T> {}
// SAFETY: as above (read only).
unsafe impl<T: Pod + Sync> Sync for TraceBuffer<T> {}

impl<T: Pod> TraceBuffer<T> {
    /// A copy of `data`.
    pub fn from_slice(data: &[T]) -> Self {
        Self::with_capacity(data, data.len())
    }

    /// A copy of `data` with room for `capacity` elements (at least `data.len()`), the rest zeroed.
    fn with_capacity(data: &[T], capacity: usize) -> Self {
        let capacity = capacity.max(data.len());
        let Some(bytes) = capacity.checked_mul(size_of::<T>()) else {
            panic!("TraceBuffer: {capacity} elements exceed the address space");
        };
        if bytes == 0 {
            return Self {
                ptr: NonNull::dangling(),
                len: data.len(),
                capacity,
                storage: Storage::None,
            };
        }
        let (ptr, storage) = if bytes >= HUGE_MIN_BYTES
            && let Some((ptr, mapped)) = map_huge(bytes)
        {
            (ptr, Storage::Mapped(mapped))
        } else {
            let Ok(layout) = Layout::from_size_align(bytes, align_of::<T>().max(64)) else {
                panic!("TraceBuffer: {bytes} bytes exceed the address space");
            };
            // SAFETY: `layout` has a non-zero size.
            let Some(ptr) = NonNull::new(unsafe { alloc_zeroed(layout) }) else {
                handle_alloc_error(layout)
            };
            (ptr, Storage::Heap(layout))
        };
        let ptr = ptr.cast::<T>();
        // SAFETY: `ptr` is a fresh, zeroed allocation (anonymous mappings are zeroed too) of
        // `capacity` elements, aligned for `T` (64 B or 2 MiB), that does not overlap `data`.
        unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), ptr.as_ptr(), data.len()) };
        Self {
            ptr,
            len: data.len(),
            capacity,
            storage,
        }
    }

    /// Copies `data` over elements `first..first + data.len()`, growing the buffer with zeroed
    /// elements first when it is shorter. Growing past the allocation reallocates to at least
    /// twice the size and copies (amortised O(1) per element, like `Vec`); other writes are plain
    /// copies. Exclusive access (`&mut self`) keeps the read-only contract of shared buffers.
    pub fn write_range(&mut self, first: usize, data: &[T]) {
        let end = first + data.len();
        if end > self.capacity {
            *self = Self::with_capacity(self, end.max(2 * self.capacity));
        }
        // Elements `len..capacity` are zeroed, so growing within the allocation is a length change.
        self.len = self.len.max(end);
        // SAFETY: `ptr` points to `capacity >= len` initialised elements owned by `self`, and
        // `&mut self` guarantees no other reference to them exists.
        let all = unsafe { std::slice::from_raw_parts_mut(self.ptr.as_ptr(), self.len) };
        all[first..end].copy_from_slice(data);
    }

    /// Whether this buffer lives in memory advised for huge pages (large enough, on Linux).
    pub fn huge_page_advised(&self) -> bool {
        matches!(self.storage, Storage::Mapped(_))
    }
}

/// A fresh anonymous mapping of `bytes` rounded up to whole huge pages, 2 MiB-aligned and
/// advised `MADV_HUGEPAGE` before anything touches it (so the first writes fault in huge pages
/// directly): `(start, mapped bytes)`. `None` if the mapping fails (the caller falls back to
/// the heap). A mapping of its own rather than the allocator's memory, which may already be
/// faulted in with small pages.
#[cfg(target_os = "linux")]
fn map_huge(bytes: usize) -> Option<(NonNull<u8>, usize)> {
    let size = bytes.checked_next_multiple_of(HUGE_PAGE)?;
    let reserve = size.checked_add(HUGE_PAGE)?;
    // SAFETY: a new private anonymous mapping; no existing memory is affected.
    let base = unsafe {
        libc::mmap(
            std::ptr::null_mut(),
            reserve,
            libc::PROT_READ | libc::PROT_WRITE,
            libc::MAP_PRIVATE | libc::MAP_ANONYMOUS,
            -1,
            0,
        )
    };
    if base == libc::MAP_FAILED {
        return None;
    }
    let head = (base as usize).next_multiple_of(HUGE_PAGE) - base as usize;
    // SAFETY: `head <= HUGE_PAGE`, so `start..start + size` lies inside the mapping; the head
    // and tail pieces unmapped here are parts of the same fresh mapping that nothing uses.
    // MADV_HUGEPAGE changes only how the range is backed, never its contents; if it fails
    // (a kernel without THP) the range stays ordinary memory.
    unsafe {
        let start = base.cast::<u8>().add(head);
        if head > 0 {
            libc::munmap(base, head);
        }
        if HUGE_PAGE - head > 0 {
            libc::munmap(start.add(size).cast(), HUGE_PAGE - head);
        }
        libc::madvise(start.cast(), size, libc::MADV_HUGEPAGE);
        NonNull::new(start).map(|p| (p, size))
    }
}

#[cfg(not(target_os = "linux"))]
fn map_huge(_bytes: usize) -> Option<(NonNull<u8>, usize)> {
    None
}

impl<T: Pod> Drop for TraceBuffer<T> {
    fn drop(&mut self) {
        match self.storage {
            Storage::None => {}
            // SAFETY: allocated in `from_slice` with exactly this layout; dropped once.
            Storage::Heap(layout) => unsafe { dealloc(self.ptr.as_ptr().cast(), layout) },
            // SAFETY: the mapping `map_huge` returned, unmapped once.
            #[cfg(target_os = "linux")]
            Storage::Mapped(size) => unsafe {
                libc::munmap(self.ptr.as_ptr().cast(), size);
            },
            #[cfg(not(target_os = "linux"))]
            Storage::Mapped(_) => {}
        }
    }
}

impl<T: Pod> std::ops::Deref for TraceBuffer<T> {
    type Target = [T];
    fn deref(&self) -> &[T] {
        // SAFETY: `ptr` points to `len` initialised elements (copied in `from_slice`), or is
        // dangling with `len == 0`; the memory lives as long as `self` and is never mutated.
        unsafe { std::slice::from_raw_parts(self.ptr.as_ptr(), self.len) }
    }
}

impl<T: Pod> Clone for TraceBuffer<T> {
    fn clone(&self) -> Self {
        Self::from_slice(self)
    }
}

impl<T: Pod> Default for TraceBuffer<T> {
    fn default() -> Self {
        Self::from_slice(&[])
    }
}

impl<T: Pod> From<Vec<T>> for TraceBuffer<T> {
    fn from(data: Vec<T>) -> Self {
        Self::from_slice(&data)
    }
}

impl<T: Pod + std::fmt::Debug> std::fmt::Debug for TraceBuffer<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TraceBuffer")
            .field("len", &self.len)
            .field("huge_page_advised", &self.huge_page_advised())
            .finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_small_large_and_empty() {
        for n in [0usize, 1, 1000, HUGE_MIN_BYTES / 4 + 3] {
            let data: Vec<u32> = (0..n as u32)
                .map(|i| i.wrapping_mul(2_654_435_761))
                .collect();
            let buffer = TraceBuffer::from_slice(&data);
            assert_eq!(&*buffer, &data[..]);
            assert_eq!(&*buffer.clone(), &data[..]);
            let large = n * 4 >= HUGE_MIN_BYTES;
            assert_eq!(
                buffer.huge_page_advised(),
                large && cfg!(target_os = "linux")
            );
            if large {
                assert_eq!(buffer.as_ptr() as usize % HUGE_PAGE, 0);
            }
        }
    }

    #[test]
    fn write_range_overwrites_and_grows_like_a_vec() {
        let mut buffer = TraceBuffer::from_slice(&[1u32, 2, 3]);
        let mut reference = vec![1u32, 2, 3];
        for (first, data) in [
            (1usize, vec![9u32]),
            (5, vec![7, 8]),
            (0, vec![4; 300_000]),
            (2, vec![]),
        ] {
            buffer.write_range(first, &data);
            if reference.len() < first + data.len() {
                reference.resize(first + data.len(), 0);
            }
            reference[first..first + data.len()].copy_from_slice(&data);
            assert_eq!(&*buffer, &reference[..]);
        }
        assert!(buffer.huge_page_advised() == cfg!(target_os = "linux"));
    }
}
