#pragma once
// Background threads of a process (the simulator's LiDAR, the mapper's OctoMap) run at a
// lower priority so that the process's loop thread runs as soon as it wakes on a busy machine.

namespace topay::procs {

/// Raises the calling thread's nice value by `increment` (at most to 19; allowed to any user).
/// False if the priority could not be read or set.
bool LowerThisThreadPriority(int increment);

}  // namespace topay::procs
