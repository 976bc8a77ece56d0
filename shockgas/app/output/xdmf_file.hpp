#pragma once
// result.xdmf: a description of result.h5 in XDMF 3 (XML; www.xdmf.org, "XDMF
// Model and Format") that ParaView, VisIt and other tools of the field open
// directly; the values stay in result.h5, which it names by its file name.
//
//   continuum   one temporal collection per solver, each time a 1-D
//               rectilinear grid (a 2DRectMesh one cell high: XDMF has no 1-D
//               mesh) with its cell centres x and the node attributes v and
//               rho: the animation's frames (/animation/fields/{solver}) and
//               the fields at t_end (/continuum/{solver})
//   particles   one temporal collection of the stored states of realization
//               0 (/initial, /particles/snapshots/{k}, /particles/final), each
//               a Polyvertex of its bodies placed at (x, v, 0) in phase space,
//               with the node attributes v and m
#include <string>

#include "shockgas/app/output/result_reader.hpp"

namespace shockgas::app {

// The XML describing the file `h5` (its datasets, attributes and /animation/t), its
// data named by `h5_name` (the file's name beside the .xdmf, "result.h5").
std::string xdmf_text(const ResultContents& h5, const std::string& h5_name);

// Writes <dir>/result.xdmf for <dir>/result.h5, whose contents are `h5`
// (written_contents, with the values of /animation/t).
void write_xdmf(const std::string& dir, const ResultContents& h5);

}  // namespace shockgas::app
