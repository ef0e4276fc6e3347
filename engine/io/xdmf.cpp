#include "io/xdmf.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"

namespace dem {

std::string xdmf_path_for(const std::string& result_path) {
  const std::string ext = ".h5";
  const bool h5 = result_path.size() > ext.size() && result_path.compare(result_path.size() - ext.size(), ext.size(), ext) == 0;
  return (h5 ? result_path.substr(0, result_path.size() - ext.size()) : result_path) + ".xdmf";
}

namespace {

std::string exact(double x) {  // round-trips a double
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// Frame `f` of an F x N x 3 dataset: an XDMF hyperslab (start, stride, count per dimension).
std::string frame_slab(const std::string& file, const std::string& dataset, std::size_t f, std::size_t frames,
                       std::size_t n) {
  std::ostringstream x;
  x << "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"1 " << n << " 3\" Type=\"HyperSlab\">\n"
    << "            <DataItem Dimensions=\"3 3\" Format=\"XML\">" << f << " 0 0  1 1 1  1 " << n << " 3</DataItem>\n"
    << "            <DataItem Dimensions=\"" << frames << " " << n << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
    << file << ":" << dataset << "</DataItem>\n"
    << "          </DataItem>\n";
  return x.str();
}

}  // namespace

void write_xdmf(const std::string& result_path) {
  namespace fs = std::filesystem;
  const std::string all = "/particles/all";
  std::size_t n = 0, frames = 0;
  std::vector<double> time;
  {
    h5::Handle file = h5::open_file_read(result_path);
    h5::Handle particles = h5::open_group(file, "particles/all");
    n = static_cast<std::size_t>(h5::shape(particles, "radius").at(0));
    std::size_t cols = 0;
    time = h5::read<double>(particles, "position/time", cols);
    // Only frames present in every dataset are described.
    frames = time.size();
    for (const std::string element : {"position", "velocity", "angular_velocity"})
      frames = std::min<std::size_t>(frames, h5::shape(particles, element + "/value").at(0));
  }
  // Relative reference: the XDMF sits beside the result and keeps working if both are moved.
  const std::string h5_name = fs::path(result_path).filename().string();
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n  <Domain>\n"
    << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t f = 0; f < frames; ++f) {
    x << "      <Grid Name=\"frame " << f << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << exact(time[f]) << "\"/>\n"
      << "        <Topology TopologyType=\"Polyvertex\" NodesPerElement=\"" << n << "\"/>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << frame_slab(h5_name, all + "/position/value", f, frames, n) << "        </Geometry>\n";
    for (const char* scalar : {"radius", "mass"})
      x << "        <Attribute Name=\"" << scalar << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        << "          <DataItem Dimensions=\"" << n << "\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5_name
        << ":" << all << "/" << scalar << "</DataItem>\n"
        << "        </Attribute>\n";
    for (const char* vector : {"velocity", "angular_velocity"})
      x << "        <Attribute Name=\"" << vector << "\" AttributeType=\"Vector\" Center=\"Node\">\n"
        << frame_slab(h5_name, all + "/" + vector + "/value", f, frames, n) << "        </Attribute>\n";
    x << "      </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";

  write_file_atomically(xdmf_path_for(result_path), x.str());
}

}  // namespace dem
