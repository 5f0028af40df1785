// Vectors of a map's size (a cell array, a label or distance per cell),
// allocated so that the kernel may back them with huge pages.
//
// Why: arrays of tens of megabytes come from mmap, and Linux hands their
// pages out one 4 KiB fault (and page clearing) at a time unless asked for
// huge pages, which Debian's transparent huge pages ("madvise" by default)
// give only when asked. On a generated 8192 x 8192 office map those faults
// were 12 % of a decode and made the time per cell grow with the map.
// Asking costs one system call per array; arrays under 8 MiB are not worth
// it (and are mostly reused heap memory), and where the kernel says no
// nothing changes.
#ifndef LINEMAP_FORMAT_LARGE_VECTOR_H_
#define LINEMAP_FORMAT_LARGE_VECTOR_H_

#include <cstddef>
#include <vector>

namespace linemap {

// Advises the kernel to back the whole huge pages inside [data, data +
// bytes) with huge pages, if the array is large enough to gain.
void AdviseHugePages(const void* data, std::size_t bytes);

// *v = n copies of `value`, its storage advised before it is first touched
// when it had to grow.
template <typename T>
void AssignLarge(std::vector<T>* v, std::size_t n, const T& value) {
  const T fill = value;  // `value` may be an element of *v, freed below
  if (v->capacity() < n) {
    std::vector<T>().swap(*v);
    v->reserve(n);
    AdviseHugePages(v->data(), n * sizeof(T));
  }
  v->assign(n, fill);
}

// n copies of `value`, as AssignLarge.
template <typename T>
std::vector<T> LargeVector(std::size_t n, const T& value) {
  std::vector<T> v;
  AssignLarge(&v, n, value);
  return v;
}

}  // namespace linemap

#endif  // LINEMAP_FORMAT_LARGE_VECTOR_H_
