#pragma once
// An XDMF 2 description of a result's H5MD particle frames (io/h5md.hpp), so that ParaView opens
// the particles over time: per frame one Polyvertex grid, with radius, mass, velocity and
// angular velocity as point attributes (Glyph filter, sphere, scale by radius), the cell's 12
// edges as lines and, if the result has them, the contacts as lines. The XML holds no
// data of its own; it points into the result by its file name, so the two must stay side by side.
#include <string>

namespace dem {

// "R.h5" -> "R.xdmf"; any other name gets ".xdmf" appended.
std::string xdmf_path_for(const std::string& result_path);

// Writes xdmf_path_for(result_path) from the frames found in the (closed, complete) result,
// through <xdmf>.tmp, fsync and a rename (io/atomic_file.hpp), so that it is either whole or absent.
void write_xdmf(const std::string& result_path);

}  // namespace dem
