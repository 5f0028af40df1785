#include "python/decode_limits.h"

#include <pybind11/operators.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "python/arrays.h"
#include "python/pickling.h"

namespace linemap::python {
namespace {

namespace py = pybind11;

// One limit as a read-write property of the class, checked when set.
template <typename T>
void AddLimit(py::class_<DecodeLimits>& cls, const char* name, T DecodeLimits::*field,
              std::uint64_t min, std::uint64_t max, const char* doc) {
  cls.def_property(
      name, [field](const DecodeLimits& l) { return l.*field; },
      [field, name, min, max](DecodeLimits& l, const py::object& value) {
        l.*field = static_cast<T>(WholeNumberArgument(value, name, min, max));
      },
      doc);
}

constexpr int kMaxThreads = 4096;

// The limits that count bytes or items (whole numbers from 1), in the
// order of the C++ struct; max_threads, an int from 0, follows them.
struct CountLimit {
  Limit limit;
  std::uint64_t DecodeLimits::*field;
  const char* doc;
  // The keyword and property: the library's name of the field, which a
  // MemoryError's .limit gives too.
  const char* name() const { return LimitFieldName(limit); }
};
constexpr CountLimit kCountLimits[] = {
    {Limit::kFileBytes, &DecodeLimits::max_file_bytes,
     "Bytes of an .lmap file read from a path (default 2^31)."},
    {Limit::kCells, &DecodeLimits::max_cells, "Cells of the map, width x height (default 2^30)."},
    {Limit::kChunkBytes, &DecodeLimits::max_chunk_bytes,
     "Bytes of one chunk's payload (default 2^30)."},
    {Limit::kInflatedBytes, &DecodeLimits::max_inflated_bytes,
     "Bytes of one inflated (zlib) payload (default 2^28)."},
    {Limit::kSegments, &DecodeLimits::max_segments,
     "Wall segments per chunk, or per band of layer sections read together (spec 7.3; default "
     "2^24, what a 2^30-cell SLAM map may need)."},
    {Limit::kChainLength, &DecodeLimits::max_chain_length,
     "Cells of one room or furniture chain, and of all the rooms' chains (and apart, all the "
     "objects') (default 2^26)."},
    {Limit::kObjects, &DecodeLimits::max_objects,
     "Rooms per file, and furniture objects per file (apart) (default 2^20)."},
};
constexpr const char* kThreadsName = "max_threads";

// Every property's name, in the order of the C++ struct (for keywords and
// repr).
std::vector<const char*> LimitNames() {
  std::vector<const char*> names;
  for (const CountLimit& limit : kCountLimits) names.push_back(limit.name());
  names.push_back(kThreadsName);
  return names;
}

}  // namespace

void BindDecodeLimits(py::module_& module) {
  const DecodeLimits d;
  py::class_<DecodeLimits> cls(module, "DecodeLimits", R"doc(
What a reading function (load, decode, vectors, room_at, eval) accepts
before it allocates: an .lmap file over a limit raises MemoryError naming
the limit, before the memory is taken. The defaults take the largest maps
nav2 users report (a 282-Mcell map); lower them for files from elsewhere:

  limits = linemap.DecodeLimits(max_cells=4_000_000, max_segments=100_000)
  m = linemap.load("upload.lmap", limits=limits)

A file within the limits is still checked against the bytes it holds. Every
limit is a whole number of at least 1 (max_threads: 0 to 4096).
)doc");
  // Keyword-only, each through its property's checks.
  cls.def(py::init([](const py::object& max_file_bytes, const py::object& max_cells,
                      const py::object& max_chunk_bytes, const py::object& max_inflated_bytes,
                      const py::object& max_segments, const py::object& max_chain_length,
                      const py::object& max_objects, const py::object& max_threads) {
            py::object self = py::cast(DecodeLimits{});
            const py::object values[] = {max_file_bytes,     max_cells,    max_chunk_bytes,
                                         max_inflated_bytes, max_segments, max_chain_length,
                                         max_objects,        max_threads};
            const std::vector<const char*> names = LimitNames();
            for (std::size_t i = 0; i < names.size(); ++i) self.attr(names[i]) = values[i];
            return self.cast<DecodeLimits>();
          }),
          py::kw_only(), py::arg("max_file_bytes") = d.max_file_bytes,
          py::arg("max_cells") = d.max_cells, py::arg("max_chunk_bytes") = d.max_chunk_bytes,
          py::arg("max_inflated_bytes") = d.max_inflated_bytes,
          py::arg("max_segments") = d.max_segments,
          py::arg("max_chain_length") = d.max_chain_length, py::arg("max_objects") = d.max_objects,
          py::arg("max_threads") = d.max_threads,
          "The defaults, with the limits given as keywords set.");
  for (const CountLimit& limit : kCountLimits) {
    AddLimit(cls, limit.name(), limit.field, 1, UINT64_MAX, limit.doc);
  }
  AddLimit(cls, kThreadsName, &DecodeLimits::max_threads, 0, kMaxThreads,
           "Threads decoding the tiles of a 2.0 file, the calling one included; 0 (the "
           "default) is one per core. The result does not depend on it.");
  cls.def(py::self == py::self);
  // Pickled as {name: value} of every limit; unpickling sets each through its
  // property's checks, and a limit the state lacks (pickled by a version
  // without it) keeps its default.
  cls.def(py::pickle(
      [](const DecodeLimits& limits) {
        py::dict state;
        for (const CountLimit& limit : kCountLimits) state[limit.name()] = limits.*limit.field;
        state[kThreadsName] = limits.max_threads;
        return state;
      },
      [](const py::dict& state) {
        py::object self = py::cast(DecodeLimits{});
        const std::vector<const char*> names = LimitNames();
        for (const auto& [key, value] : state) {
          const std::string name = py::str(key);
          if (std::find_if(names.begin(), names.end(),
                           [&name](const char* known) { return name == known; }) == names.end()) {
            throw py::value_error("DecodeLimits has no limit '" + name + "' to unpickle");
          }
          self.attr(key) = value;
        }
        return self.cast<DecodeLimits>();
      }));
  ReduceAsProtocolTwoAtLeast(cls);
  cls.def("__repr__", [](const py::object& self) {
    std::string text = "linemap.DecodeLimits(";
    for (const char* name : LimitNames()) {
      text += std::string(text.back() == '(' ? "" : ", ") + name + "=" +
              std::string(py::str(self.attr(name)));
    }
    return text + ")";
  });
}

DecodeLimits LimitsArgument(const py::object& limits, const py::object& max_cells) {
  DecodeLimits out;
  if (!limits.is_none()) {
    if (!py::isinstance<DecodeLimits>(limits)) {
      throw py::type_error("limits must be a linemap.DecodeLimits or None");
    }
    if (!max_cells.is_none()) {
      throw py::value_error(
          "give max_cells or limits (with its max_cells), not both: one would override the other");
    }
    out = limits.cast<DecodeLimits>();
  }
  out.max_cells = MaxCellsArgument(max_cells, out.max_cells);
  return out;
}

}  // namespace linemap::python
