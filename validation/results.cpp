#include "results.hpp"

#include <filesystem>

#include "io/hdf5.hpp"

namespace validation {

namespace {

bool complete(const dem::h5::Handle& f) {
  return dem::h5::has_attribute(f, "status") && dem::h5::get_string_attribute(f, "status") == "complete";
}

Columns read_group(hid_t file, const std::string& group) {
  Columns out;
  if (!dem::h5::exists(file, group)) return out;
  dem::h5::Handle g = dem::h5::open_group(file, group);
  H5G_info_t info{};
  H5Gget_info(g, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256] = {0};
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    std::size_t cols = 0;
    out[name] = dem::h5::read<double>(g, name, cols);
  }
  return out;
}

}  // namespace

Columns read_columns(const std::string& file, const std::string& group) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  return read_group(f, group);
}

bool is_complete(const std::string& file) {
  try {
    return complete(dem::h5::open_file_read(file));
  } catch (const std::exception&) {
    return false;
  }
}

std::map<std::string, DensityResults> load_results(const std::string& dir, const std::vector<std::string>& densities,
                                                   std::vector<std::string>& missing) {
  namespace fs = std::filesystem;
  std::map<std::string, DensityResults> all;
  for (const std::string& d : densities) {
    DensityResults& r = all[d];
    const std::string prep = (fs::path(dir) / (d + "_prepare.h5")).string();
    try {
      dem::h5::Handle f = dem::h5::open_file_read(prep);
      if (!complete(f)) throw std::runtime_error("not complete");
      for (const auto& [name, values] : read_group(f, "timeseries"))
        if (!values.empty()) r.sample[name] = values.back();
      r.prepared = true;
    } catch (const std::exception&) {
      missing.push_back(prep);
    }
    for (int n = 1; n <= 5; ++n) {
      const std::string file = (fs::path(dir) / (d + "_test" + std::to_string(n) + ".h5")).string();
      try {
        dem::h5::Handle f = dem::h5::open_file_read(file);
        if (!complete(f)) throw std::runtime_error("not complete");
        r.tests.push_back({n, read_group(f, "timeseries"), read_group(f, "legs")});
      } catch (const std::exception&) {
        missing.push_back(file);
      }
    }
  }
  return all;
}

}  // namespace validation
