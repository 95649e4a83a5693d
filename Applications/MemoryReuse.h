// Tells the C library to keep freed memory for the program's next allocations.
#ifndef MemoryReuse_h
#define MemoryReuse_h

/// The pipeline allocates and frees arrays of a mesh's size at every stage and flow step
/// (half-edge lists, sparse matrices, right-hand sides, point copies). By default glibc
/// hands blocks above 128 KB to mmap and gives the heap's free top back to the kernel, so
/// each such array is fresh memory again, paid for by one page fault per 4 KB page on first
/// touch. Raising both thresholds (to 32 MB and 1 GB) keeps those pages in the process for
/// reuse: fewer page faults, which cost a noticeable share of the CPU time (README,
/// Performance), for a slightly larger peak resident size. Memory goes back to the system
/// when the program ends. Does nothing with another C library.
void KeepFreedMemoryForReuse();

#endif
