// The heap settings of every holebench process that evaluates: large blocks are served from
// the heap and freed memory is kept, instead of glibc's default of mapping each large block
// anew and returning it when freed.
//
// The evaluation grows and frees large buffers many times per job (the distance searches'
// cell queues, the face maps of a repair the size of the model). By default glibc maps each
// block above its threshold (128 KiB, rising only to what was freed) and unmaps it when it is
// freed, so that the next one faults its pages in again; on this project's machines (virtual
// machines) a fault costs several microseconds, and on a 1.7M-triangle model these faults
// took more than the per-job evaluation's own work (EvaluationGrowth benchmark: 269 against
// 149 ms per job). Results do not change: only where the allocator's memory comes from.
#pragma once

namespace holebench::harness {

/// Serves blocks up to 256 MiB from the heap and keeps up to 1 GiB of freed memory (with a
/// 64 MiB pad at each growth). Call once, at the start of main().
void keep_freed_heap_memory();

}  // namespace holebench::harness
