// Runs a task beside the caller when a thread can be had (the encoder
// extracts the walls beside the rooms, and the layers of two blocks of a
// large map at a time).
#ifndef LINEMAP_CODEC_LAYERS_START_TASK_H_
#define LINEMAP_CODEC_LAYERS_START_TASK_H_

#include <future>
#include <system_error>

namespace linemap {

// Runs `task` on a thread of its own when `own_thread` (and the system gives
// one), else when its result is asked for.
template <typename Task>
auto StartTask(bool own_thread, Task task) {
  if (own_thread) {
    try {
      return std::async(std::launch::async, task);
    } catch (const std::system_error&) {
      // No thread to be had: run it on the caller's.
    }
  }
  return std::async(std::launch::deferred, task);
}

}  // namespace linemap

#endif  // LINEMAP_CODEC_LAYERS_START_TASK_H_
