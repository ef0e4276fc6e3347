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

// Rows [first, first + count) of an M x `cols` dataset (cols 0: 1-D), as an XDMF hyperslab.
std::string rows_slab(const std::string& file, const std::string& dataset, std::size_t first, std::size_t count,
                      std::size_t rows, std::size_t cols, const char* type = "Float", int precision = 8) {
  std::ostringstream x;
  const std::string in_dims = cols ? std::to_string(rows) + " " + std::to_string(cols) : std::to_string(rows);
  const std::string out_dims = cols ? std::to_string(count) + " " + std::to_string(cols) : std::to_string(count);
  x << "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << out_dims << "\" Type=\"HyperSlab\">\n"
    << "            <DataItem Dimensions=\"3 " << (cols ? 2 : 1) << "\" Format=\"XML\">" << first << (cols ? " 0  1 1  " : "  1  ")
    << count << (cols ? " " + std::to_string(cols) : std::string()) << "</DataItem>\n"
    << "            <DataItem Dimensions=\"" << in_dims << "\" NumberType=\"" << type << "\" Precision=\"" << precision
    << "\" Format=\"HDF\">" << file << ":" << dataset << "</DataItem>\n"
    << "          </DataItem>\n";
  return x.str();
}

}  // namespace

void write_xdmf(const std::string& result_path) {
  namespace fs = std::filesystem;
  const std::string all = "/particles/all";
  std::size_t n = 0, frames = 0, contact_rows = 0;
  std::vector<double> time;
  std::vector<std::int64_t> contacts_per_frame;  // empty: no contact network
  bool corners = false;
  std::vector<double> edges;  // F x 3: the cell's lengths, for a result without corners
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
    if (h5::exists(file, "frames/cell_corners")) {
      corners = true;
      frames = std::min<std::size_t>(frames, h5::shape(file, "frames/cell_corners").at(0));
    } else {
      edges = h5::read<double>(particles, "box/edges/value", cols);
      frames = std::min<std::size_t>(frames, edges.size() / 3);
    }
    if (h5::exists(file, "frames/contacts/count")) {
      contacts_per_frame = h5::read<std::int64_t>(file, "frames/contacts/count", cols);
      frames = std::min(frames, contacts_per_frame.size());
      contact_rows = static_cast<std::size_t>(h5::shape(file, "frames/contacts/ends").at(0));
    }
  }
  // Relative reference: the XDMF sits beside the result and keeps working if both are moved.
  const std::string h5_name = fs::path(result_path).filename().string();
  // The particles of frame f: one Polyvertex grid.
  const auto particle_grid = [&](std::ostringstream& x, std::size_t f) {
    x << "      <Grid Name=\"particles\" GridType=\"Uniform\">\n"
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
  };
  // The cell of frame f: its 12 edges as lines between its corners (corner k at (k & 1, k >> 1 & 1,
  // k >> 2 & 1) in cell coordinates), which ParaView draws as an outline that hides nothing. A result
  // written before /frames/cell_corners has the box's lengths only: the outline of those lengths,
  // written into the XML.
  const auto cell_grid = [&](std::ostringstream& x, std::size_t f) {
    x << "      <Grid Name=\"cell\" GridType=\"Uniform\">\n"
      << "        <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"12\">\n"
      << "          <DataItem Dimensions=\"12 2\" NumberType=\"Int\" Format=\"XML\">"
      << "0 1 2 3 4 5 6 7 0 2 1 3 4 6 5 7 0 4 1 5 2 6 3 7</DataItem>\n"
      << "        </Topology>\n        <Geometry GeometryType=\"XYZ\">\n";
    if (corners) {
      x << frame_slab(h5_name, "/frames/cell_corners", f, frames, 8);
    } else {
      x << "          <DataItem Dimensions=\"8 3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">";
      for (int k = 0; k < 8; ++k)
        for (int axis = 0; axis < 3; ++axis) x << (k || axis ? " " : "") << ((k >> axis) & 1 ? exact(edges[3 * f + axis]) : "0");
      x << "</DataItem>\n";
    }
    x << "        </Geometry>\n      </Grid>\n";
  };
  // The contacts of frame f, rows [first, first + m) of /frames/contacts: one line per contact.
  const auto contact_grid = [&](std::ostringstream& x, std::size_t first, std::size_t m) {
    x << "      <Grid Name=\"contacts\" GridType=\"Uniform\">\n"
      << "        <Topology TopologyType=\"Polyline\" NodesPerElement=\"2\" NumberOfElements=\"" << m << "\"/>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n"
      << "          <DataItem ItemType=\"HyperSlab\" Dimensions=\"" << m << " 2 3\" Type=\"HyperSlab\">\n"
      << "            <DataItem Dimensions=\"3 3\" Format=\"XML\">" << first << " 0 0  1 1 1  " << m << " 2 3</DataItem>\n"
      << "            <DataItem Dimensions=\"" << contact_rows << " 2 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
      << h5_name << ":/frames/contacts/ends</DataItem>\n          </DataItem>\n        </Geometry>\n";
    for (const char* force : {"normal_force", "tangential_force"})
      x << "        <Attribute Name=\"" << force << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << rows_slab(h5_name, std::string("/frames/contacts/") + force, first, m, contact_rows, 0) << "        </Attribute>\n";
    x << "      </Grid>\n";
  };
  std::ostringstream x;
  x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n  <Domain>\n"
    << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  std::size_t first_contact = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    // Each time a spatial collection: the particles, the cell and (if written) the contacts.
    x << "     <Grid Name=\"frame " << f << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
      << "      <Time Value=\"" << exact(time[f]) << "\"/>\n";
    particle_grid(x, f);
    cell_grid(x, f);
    if (!contacts_per_frame.empty()) {
      const std::size_t m = static_cast<std::size_t>(contacts_per_frame[f]);
      contact_grid(x, first_contact, m);
      first_contact += m;
    }
    x << "     </Grid>\n";
  }
  x << "    </Grid>\n  </Domain>\n</Xdmf>\n";

  write_file_atomically(xdmf_path_for(result_path), x.str());
}

}  // namespace dem
