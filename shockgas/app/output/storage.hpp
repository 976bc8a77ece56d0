#pragma once
// How a dataset's values are stored in result.h5, declared once beside its
// path, unit and meaning (declaration.hpp). Every value is computed in double
// precision; the declared storage says what the file keeps of it:
//   float64  the value itself (everything that is measured or compared);
//   float32  the value rounded to the nearest float32, for data that are only
//            drawn (a world line, an animation frame): half the bytes, and a
//            relative rounding of at most 2^-24 (6e-8), far below a pixel;
//   integer  a count, an index or a 0/1 mask, stored as a 64-bit integer (the
//            values are checked to be whole numbers when written).
#include <string>

namespace shockgas::app {

enum class Storage { float64, float32, integer };

// "float64", "float32", "int64": the name `shockgas info` and docs/output.md show,
// and the numpy dtype the Python module gives the dataset.
inline std::string storage_name(Storage s) {
  switch (s) {
    case Storage::float32:
      return "float32";
    case Storage::integer:
      return "int64";
    case Storage::float64:
      break;
  }
  return "float64";
}

}  // namespace shockgas::app
