#include "io/result_file.hpp"

#include <string>

#include "core/content_hash.hpp"
#include "version.hpp"

namespace dem {

namespace {

std::string checksum_of(const std::vector<double>& values) {
  return content_hash(std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double)));
}

// The names of the links in `group`, in name order.
std::vector<std::string> members(hid_t group) {
  std::vector<std::string> names;
  H5G_info_t info{};
  if (H5Gget_info(group, &info) < 0) throw h5::Error("HDF5: cannot list a group: " + h5::last_error());
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t len = H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (len < 0) throw h5::Error("HDF5: cannot list a group: " + h5::last_error());
    std::string name(static_cast<std::size_t>(len) + 1, '\0');
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(len));
    names.push_back(name);
  }
  return names;
}

}  // namespace

std::string result_problem(hid_t f) {
  const std::string status = h5::has_attribute(f, "status") ? h5::get_string_attribute(f, "status") : "";
  if (status != "complete") return "status '" + (status.empty() ? std::string("missing") : status) + "'";
  if (!h5::has_attribute(f, "wall_time_s"))
    return "status 'complete' but no wall_time_s, which a run writes as it completes: a killed run's .partial marked "
           "complete by hand?";
  if (!h5::has_attribute(f, "schema_version")) return "no schema_version: not a result of dem";
  const std::int64_t schema = h5::get_int_attribute(f, "schema_version");
  if (schema < 1 || schema > schema_version)
    return "schema_version " + std::to_string(schema) + ": this dem reads 1 to " + std::to_string(schema_version) +
           (schema > schema_version ? " (a result of a newer dem?)" : "");
  return "";
}

void check_complete_result(hid_t f, const std::string& path) {
  if (const std::string why = result_problem(f); !why.empty()) throw h5::Error(path + ": not a complete result (" + why + ")");
}

Table read_table(hid_t f, const std::string& group, const std::string& path) {
  Table out;
  if (!h5::exists(f, group)) return out;
  h5::Handle g = h5::open_group(f, group);
  std::map<std::string, std::string> checksums;  // of the columns that have one
  for (const std::string& name : members(g)) {
    std::size_t cols = 0;
    std::vector<double> values = h5::naming_file(path, [&] { return h5::read<double>(g, name, cols); });
    if (cols != 1) throw h5::Error(path + ": /" + group + "/" + name + " is not a column (" + std::to_string(cols) + " values a row)");
    const h5::Handle ds(H5Dopen2(g, name.c_str(), H5P_DEFAULT));
    if (h5::has_attribute(ds, "checksum")) checksums[name] = h5::get_string_attribute(ds, "checksum");
    out.emplace(name, std::move(values));
  }
  // Every column as long as `time` (or, in a table without one, as the first); then each as written.
  const auto first = out.count("time") ? out.find("time") : out.begin();
  for (const auto& [name, values] : out)
    if (values.size() != first->second.size())
      throw h5::Error(path + ": /" + group + "/" + name + " has " + std::to_string(values.size()) + " rows and /" + group + "/" +
                      first->first + " " + std::to_string(first->second.size()) +
                      ": a damaged result (every column of a table has one value per row)");
  for (const auto& [name, checksum] : checksums)
    if (checksum != checksum_of(out.at(name)))
      throw h5::Error(path + ": /" + group + "/" + name +
                      ": its values do not match its checksum (changed since the run wrote them: a damaged or edited file)");
  return out;
}

void write_table_checksums(hid_t f, const std::string& group) {
  if (!h5::exists(f, group)) return;
  h5::Handle g = h5::open_group(f, group);
  for (const std::string& name : members(g)) {
    std::size_t cols = 0;
    const std::vector<double> values = h5::read<double>(g, name, cols);
    h5::Handle ds(H5Dopen2(g, name.c_str(), H5P_DEFAULT));
    h5::set_attribute(ds, "checksum", checksum_of(values));
  }
}

}  // namespace dem
