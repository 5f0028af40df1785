// linemap.DecodeLimits: the decoder's limits (DecodeLimits in
// linemap/codec.h) as a Python class, and the limits a reading function
// takes from its `max_cells` and `limits` arguments.
#ifndef LINEMAP_PYTHON_DECODE_LIMITS_H_
#define LINEMAP_PYTHON_DECODE_LIMITS_H_

#include <pybind11/pybind11.h>

#include "linemap/codec.h"

namespace linemap::python {

// Adds the class DecodeLimits to `module`.
void BindDecodeLimits(pybind11::module_& module);

// The limits of a call given `limits` (a DecodeLimits or None: the
// defaults) and `max_cells` (an int or None). Both naming the cell limit
// raise ValueError: one would silently override the other.
DecodeLimits LimitsArgument(const pybind11::object& limits, const pybind11::object& max_cells);

}  // namespace linemap::python

#endif  // LINEMAP_PYTHON_DECODE_LIMITS_H_
