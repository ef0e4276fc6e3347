#include "io/hdf5.hpp"

#include "io/file_lock.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <numeric>
#include <optional>

#include <sys/resource.h>
#include <unistd.h>

namespace dem::h5 {

namespace {

// How close the process is to a limit on its memory (ulimit -v or -d), the only way an allocation
// fails on Linux short of being killed: the usage and the limit (MiB) of the
// tightest of the limits that are set; no value when no limit is set or /proc is unreadable.
struct MemoryHeadroom {
  double used_mib = 0, limit_mib = 0;
  double headroom_mib() const { return limit_mib - used_mib; }
};
std::optional<MemoryHeadroom> memory_headroom() {
  std::ifstream statm("/proc/self/statm");
  unsigned long long size_pages = 0, resident = 0, shared = 0, text = 0, lib = 0, data_pages = 0;
  if (!(statm >> size_pages >> resident >> shared >> text >> lib >> data_pages)) return std::nullopt;
  const double page_mib = static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
  std::optional<MemoryHeadroom> tightest;
  const auto consider = [&](int resource, unsigned long long pages) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
    const MemoryHeadroom h{static_cast<double>(pages) * page_mib, static_cast<double>(limit.rlim_cur) / (1024.0 * 1024.0)};
    if (!tightest || h.headroom_mib() < tightest->headroom_mib()) tightest = h;
  };
  consider(RLIMIT_AS, size_pages);
  consider(RLIMIT_DATA, data_pages);
  return tightest;
}

// A failed HDF5 call with no recorded reason, this near a memory limit, ran out of memory: HDF5's own
// allocations are small (metadata, a 1 MiB chunk cache), and the engine's large ones throw bad_alloc.
constexpr double out_of_memory_headroom_mib = 16.0;

std::string failed(const std::string& what) {
  const std::string why = last_error();
  return "HDF5: " + what + " failed" + (why.empty() ? "" : ": " + why);
}

void check(herr_t status, const std::string& what) {
  if (status < 0) throw Error(failed(what));
}

hid_t checked(hid_t id, const std::string& what) {
  if (id < 0) throw Error(failed(what));
  return id;
}

template <class T>
hid_t native_type();
template <> hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <> hid_t native_type<std::uint32_t>() { return H5T_NATIVE_UINT32; }
template <> hid_t native_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <> hid_t native_type<std::int64_t>() { return H5T_NATIVE_INT64; }

// Quiet HDF5's own error stack printing: errors are reported by our exceptions.
struct SilenceOnce {
  SilenceOnce() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
};
void silence() { static SilenceOnce once; }

}  // namespace

std::string last_error() {
  const int sys_errno = errno;  // before H5Ewalk2, which may change it
  struct Found {
    std::string innermost;
    int sys_errno = 0;
    bool memory = false;
  } found;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
    Found& f = *static_cast<Found*>(data);
    const std::string desc = e->desc ? e->desc : "";
    if (n == 0) f.innermost = desc;
    // The file drivers put the system's errno into the description of a failed read or write.
    const std::size_t at = desc.find("errno = ");
    if (at != std::string::npos && f.sys_errno == 0) f.sys_errno = std::atoi(desc.c_str() + at + 8);
    if (e->min_num == H5E_NOSPACE || desc.find("memory allocation failed") != std::string::npos)
      f.memory = true;
    return 0;
  }, &found);
  if (found.sys_errno > 0) return std::strerror(found.sys_errno);
  if (found.memory) return "out of memory (" + found.innermost + ")";
  // Out of memory, HDF5 may fail before it can record why (its error stack allocates too): a call
  // fails with an empty stack and malloc's ENOMEM is all that is left (a run at 34 MiB did so in
  // H5Acreate2).
  if (found.innermost.empty() && sys_errno == ENOMEM) return "out of memory (HDF5 recorded no reason; errno ENOMEM)";
  // Or it records only the outer call's failure ("unable to create dataset", a CI run at 34 MiB):
  // the memory limit's headroom then tells.
  if (const auto headroom = memory_headroom(); headroom && headroom->headroom_mib() < out_of_memory_headroom_mib) {
    char usage[160];
    std::snprintf(usage, sizeof usage, "; %.1f MiB of the process's %.1f MiB memory limit in use", headroom->used_mib,
                  headroom->limit_mib);
    return "out of memory (" + (found.innermost.empty() ? std::string("HDF5 recorded no reason") : found.innermost) +
           usage + ")";
  }
  return found.innermost;
}

void flush_file(hid_t file, const std::string& path) {
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) throw Error(path + ": " + failed("writing the file"));
}

void close_file(Handle& file, const std::string& path) {
  const hid_t id = file.id();
  file.release();
  if (id >= 0 && H5Fclose(id) < 0) throw Error(path + ": " + failed("closing the file"));
}

void Handle::reset() {
  if (id_ < 0) return;
  switch (H5Iget_type(id_)) {
    case H5I_FILE: H5Fclose(id_); break;
    case H5I_GROUP: H5Gclose(id_); break;
    case H5I_DATASET: H5Dclose(id_); break;
    case H5I_DATASPACE: H5Sclose(id_); break;
    case H5I_ATTR: H5Aclose(id_); break;
    case H5I_DATATYPE: H5Tclose(id_); break;
    case H5I_GENPROP_LST: H5Pclose(id_); break;
    default: break;
  }
  id_ = -1;
}

Handle create_file(const std::string& path) {
  silence();
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (f < 0) throw Error(path + ": cannot create the HDF5 file (is the folder writable?)");
  return Handle(f);
}

namespace {

// The lock a dem run holds while it writes the family of OUT (OUT.partial, OUT.checkpoint): OUT.lock.
std::string writer_lock_of(const std::string& path) {
  for (const char* suffix : {".partial", ".checkpoint"}) {
    const std::string sfx = suffix;
    if (path.size() > sfx.size() && path.compare(path.size() - sfx.size(), sfx.size(), sfx) == 0)
      return path.substr(0, path.size() - sfx.size()) + ".lock";
  }
  return path + ".lock";
}

}  // namespace

Handle open_file_read(const std::string& path) {
  silence();
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw Error(path + ": " + ec.message());  // e.g. a link loop
  if (!regular) throw Error(path + ": no such file");
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f >= 0) return Handle(f);
  // A result still being written is not damaged: HDF5 refuses to open it while its writer has it.
  if (const std::string lock = writer_lock_of(path); FileLock::held_by_a_process(lock))
    throw Error(path + ": being written by a running dem run (it holds " + lock + "); read it when the run has ended");
  throw Error(path + ": not a readable HDF5 file (truncated or corrupt?)");
}

Handle open_file_write(const std::string& path) {
  silence();
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (f < 0) throw Error(path + ": cannot open the HDF5 file for writing");
  return Handle(f);
}

Handle create_group(hid_t parent, const std::string& name) {
  return Handle(checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "creating group " + name));
}

Handle open_group(hid_t parent, const std::string& name) {
  if (!exists(parent, name)) throw Error("HDF5: group '" + name + "' is missing");
  return Handle(checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), "opening group " + name));
}

bool exists(hid_t parent, const std::string& path) {
  std::string partial;
  for (std::size_t pos = 0; pos <= path.size();) {  // every prefix must exist (H5Lexists demands it)
    const std::size_t next = path.find('/', pos);
    partial = path.substr(0, next);
    if (H5Lexists(parent, partial.c_str(), H5P_DEFAULT) <= 0) return false;
    if (next == std::string::npos) break;
    pos = next + 1;
  }
  return true;
}

void set_attribute(hid_t obj, const std::string& name, const std::string& value) {
  if (H5Aexists(obj, name.c_str()) > 0) check(H5Adelete(obj, name.c_str()), "deleting attribute " + name);
  Handle type(H5Tcopy(H5T_C_S1));
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), "string type");
  Handle space(H5Screate(H5S_SCALAR));
  Handle attr(checked(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "attribute " + name));
  check(H5Awrite(attr, type, value.empty() ? "" : value.data()), "writing attribute " + name);
}

template <class T>
static void set_numeric_attribute(hid_t obj, const std::string& name, T value) {
  if (H5Aexists(obj, name.c_str()) > 0) check(H5Adelete(obj, name.c_str()), "deleting attribute " + name);
  Handle space(H5Screate(H5S_SCALAR));
  Handle attr(checked(H5Acreate2(obj, name.c_str(), native_type<T>(), space, H5P_DEFAULT, H5P_DEFAULT), "attribute " + name));
  check(H5Awrite(attr, native_type<T>(), &value), "writing attribute " + name);
}

void set_attribute(hid_t obj, const std::string& name, double value) { set_numeric_attribute(obj, name, value); }
void set_attribute(hid_t obj, const std::string& name, std::int64_t value) { set_numeric_attribute(obj, name, value); }

void set_attribute(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values) {
  if (H5Aexists(obj, name.c_str()) > 0) check(H5Adelete(obj, name.c_str()), "deleting attribute " + name);
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr));
  Handle attr(checked(H5Acreate2(obj, name.c_str(), H5T_NATIVE_INT64, space, H5P_DEFAULT, H5P_DEFAULT), "attribute " + name));
  check(H5Awrite(attr, H5T_NATIVE_INT64, values.data()), "writing attribute " + name);
}

void set_attribute(hid_t obj, const std::string& name, const std::vector<std::string>& values) {
  if (H5Aexists(obj, name.c_str()) > 0) check(H5Adelete(obj, name.c_str()), "deleting attribute " + name);
  std::size_t width = 1;
  for (const std::string& v : values) width = std::max(width, v.size());
  std::string packed(width * values.size(), '\0');  // fixed-length, NUL-padded strings side by side
  for (std::size_t k = 0; k < values.size(); ++k) packed.replace(k * width, values[k].size(), values[k]);
  Handle type(H5Tcopy(H5T_C_S1));
  check(H5Tset_size(type, width), "string type");
  check(H5Tset_strpad(type, H5T_STR_NULLPAD), "string padding");
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr));
  Handle attr(checked(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "attribute " + name));
  check(H5Awrite(attr, type, packed.data()), "writing attribute " + name);
}

bool has_attribute(hid_t obj, const std::string& name) { return H5Aexists(obj, name.c_str()) > 0; }

std::string get_string_attribute(hid_t obj, const std::string& name) {
  if (!has_attribute(obj, name)) throw Error("HDF5: attribute '" + name + "' is missing");
  Handle attr(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "opening attribute " + name));
  Handle type(H5Aget_type(attr));
  if (H5Tget_class(type) != H5T_STRING) throw Error("HDF5: attribute '" + name + "' is not a string");
  if (H5Tis_variable_str(type) > 0) throw Error("HDF5: attribute '" + name + "' is a variable-length string (unsupported)");
  std::string value(H5Tget_size(type), '\0');
  Handle mem(H5Tcopy(H5T_C_S1));
  check(H5Tset_size(mem, value.size()), "string type");
  check(H5Aread(attr, mem, value.data()), "reading attribute " + name);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

template <class T>
static T get_numeric_attribute(hid_t obj, const std::string& name) {
  if (!has_attribute(obj, name)) throw Error("HDF5: attribute '" + name + "' is missing");
  Handle attr(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "opening attribute " + name));
  T value{};
  check(H5Aread(attr, native_type<T>(), &value), "reading attribute " + name);
  return value;
}

double get_double_attribute(hid_t obj, const std::string& name) { return get_numeric_attribute<double>(obj, name); }
std::int64_t get_int_attribute(hid_t obj, const std::string& name) { return get_numeric_attribute<std::int64_t>(obj, name); }

std::string unit_of(hid_t parent, const std::string& name) {
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  for (const std::string& key : {unit_attribute, std::string("units")})
    if (has_attribute(ds, key)) return get_string_attribute(ds, key);
  return "";
}

template <class T>
void write(hid_t parent, const std::string& name, const std::vector<T>& data, std::size_t cols, const std::string& units) {
  const hsize_t dims[2] = {cols ? data.size() / cols : 0, cols};
  Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr));
  Handle ds(checked(H5Dcreate2(parent, name.c_str(), native_type<T>(), space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    "creating dataset " + name));
  if (!data.empty()) check(H5Dwrite(ds, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "writing " + name);
  set_attribute(ds, unit_attribute, units);
}

template <class T>
std::vector<T> read(hid_t parent, const std::string& name, std::size_t& cols) {
  if (!exists(parent, name)) throw Error("HDF5: dataset '" + name + "' is missing");
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle space(H5Dget_space(ds));
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 1 || rank > 2) throw Error("HDF5: dataset '" + name + "' has rank " + std::to_string(rank));
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  cols = static_cast<std::size_t>(dims[1]);
  std::vector<T> out(static_cast<std::size_t>(dims[0] * dims[1]));
  if (!out.empty()) check(H5Dread(ds, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "reading " + name);
  return out;
}

template void write(hid_t, const std::string&, const std::vector<double>&, std::size_t, const std::string&);
template void write(hid_t, const std::string&, const std::vector<std::uint32_t>&, std::size_t, const std::string&);
template void write(hid_t, const std::string&, const std::vector<std::uint8_t>&, std::size_t, const std::string&);
template void write(hid_t, const std::string&, const std::vector<std::int64_t>&, std::size_t, const std::string&);
template std::vector<double> read(hid_t, const std::string&, std::size_t&);
template std::vector<std::uint32_t> read(hid_t, const std::string&, std::size_t&);
template std::vector<std::uint8_t> read(hid_t, const std::string&, std::size_t&);
template std::vector<std::int64_t> read(hid_t, const std::string&, std::size_t&);

Column::Column(hid_t parent, const std::string& name, const std::string& units) {
  const hsize_t dims[1] = {0}, max_dims[1] = {H5S_UNLIMITED}, chunk[1] = {256};
  Handle space(H5Screate_simple(1, dims, max_dims));
  Handle props(H5Pcreate(H5P_DATASET_CREATE));
  check(H5Pset_chunk(props, 1, chunk), "chunking " + name);
  dataset_ = Handle(checked(H5Dcreate2(parent, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, props, H5P_DEFAULT),
                            "creating column " + name));
  set_attribute(dataset_, unit_attribute, units);
}

Column::Column(hid_t parent, const std::string& name) {
  dataset_ = Handle(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening column " + name));
  Handle space(H5Dget_space(dataset_));
  hsize_t dims[1] = {0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  size_ = static_cast<std::size_t>(dims[0]);
}

void Column::append(const std::vector<double>& values) {
  if (values.empty()) return;
  const hsize_t new_size[1] = {size_ + values.size()};
  check(H5Dset_extent(dataset_, new_size), "extending column");
  Handle file_space(H5Dget_space(dataset_));
  const hsize_t start[1] = {size_}, count[1] = {values.size()};
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr), "selecting rows");
  Handle mem_space(H5Screate_simple(1, count, nullptr));
  check(H5Dwrite(dataset_, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, values.data()), "appending rows");
  size_ += values.size();
}

template <class T>
FrameSeries<T>::FrameSeries(hid_t parent, const std::string& name, std::vector<hsize_t> frame_shape, hsize_t chunk_frames)
    : frame_shape_(std::move(frame_shape)) {
  std::vector<hsize_t> dims = {0}, max_dims = {H5S_UNLIMITED}, chunk = {1};
  for (hsize_t d : frame_shape_) dims.push_back(d), max_dims.push_back(d), chunk.push_back(d);
  // A frame of particles is one chunk (written and read whole); scalars per frame are batched.
  if (frame_shape_.empty()) chunk[0] = 64;
  if (chunk_frames > 0) chunk[0] = chunk_frames;
  Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max_dims.data()));
  Handle props(H5Pcreate(H5P_DATASET_CREATE));
  check(H5Pset_chunk(props, static_cast<int>(chunk.size()), chunk.data()), "chunking " + name);
  dataset_ = Handle(checked(H5Dcreate2(parent, name.c_str(), native_type<T>(), space, H5P_DEFAULT, props, H5P_DEFAULT),
                            "creating dataset " + name));
}

template <class T>
FrameSeries<T>::FrameSeries(hid_t parent, const std::string& name) {
  dataset_ = Handle(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle space(H5Dget_space(dataset_));
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(1, H5Sget_simple_extent_ndims(space))), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  frames_ = static_cast<std::size_t>(dims[0]);
  frame_shape_.assign(dims.begin() + 1, dims.end());
}

template <class T>
void FrameSeries<T>::append(const std::vector<T>& frame) {
  const hsize_t per_frame = std::accumulate(frame_shape_.begin(), frame_shape_.end(), hsize_t{1}, std::multiplies<>());
  if (frame.size() != per_frame) throw Error("HDF5: a frame of " + std::to_string(frame.size()) + " values, expected " +
                                             std::to_string(per_frame));
  append_frames(frame);
}

template <class T>
void FrameSeries<T>::append_frames(const std::vector<T>& values) {
  const hsize_t per_frame = std::accumulate(frame_shape_.begin(), frame_shape_.end(), hsize_t{1}, std::multiplies<>());
  if (values.size() % per_frame != 0)
    throw Error("HDF5: " + std::to_string(values.size()) + " values are not whole frames of " + std::to_string(per_frame));
  const hsize_t n = values.size() / per_frame;
  if (n == 0) return;
  std::vector<hsize_t> size = {frames_ + n}, start = {frames_}, count = {n};
  for (hsize_t d : frame_shape_) size.push_back(d), start.push_back(0), count.push_back(d);
  check(H5Dset_extent(dataset_, size.data()), "extending dataset");
  Handle file_space(H5Dget_space(dataset_));
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), "selecting a frame");
  Handle mem_space(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr));
  check(H5Dwrite(dataset_, native_type<T>(), mem_space, file_space, H5P_DEFAULT, values.data()), "appending a frame");
  frames_ += n;
}

template class FrameSeries<double>;
template class FrameSeries<std::int64_t>;

void write_text(hid_t parent, const std::string& name, const std::string& text) {
  if (exists(parent, name)) check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT), "replacing dataset " + name);
  Handle type(checked(H5Tcopy(H5T_C_S1), "string type"));
  check(H5Tset_size(type, std::max<std::size_t>(1, text.size())), "string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "string type");
  Handle space(checked(H5Screate(H5S_SCALAR), "dataspace of " + name));
  Handle ds(checked(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "creating dataset " + name));
  std::string padded = text;
  padded.resize(std::max<std::size_t>(1, text.size()), '\0');
  check(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()), "writing dataset " + name);
}

bool has_text(hid_t parent, const std::string& name) { return exists(parent, name) || has_attribute(parent, name); }

std::string read_text(hid_t parent, const std::string& name) {
  if (!exists(parent, name)) {
    if (has_attribute(parent, name)) return get_string_attribute(parent, name);  // schema 2
    throw Error("HDF5: dataset '" + name + "' is missing");
  }
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle type(checked(H5Dget_type(ds), "type of " + name));
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
    throw Error("HDF5: dataset '" + name + "' is not a fixed-length string");
  Handle space(H5Dget_space(ds));
  if (H5Sget_simple_extent_type(space) != H5S_SCALAR) throw Error("HDF5: dataset '" + name + "' is not a scalar");
  std::string value(H5Tget_size(type), '\0');
  // Read as the file's own type: no conversion (which would put a terminator in the last byte).
  check(H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data()), "reading dataset " + name);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

namespace {
Handle variable_string_type() {
  Handle type(checked(H5Tcopy(H5T_C_S1), "string type"));
  check(H5Tset_size(type, H5T_VARIABLE), "string type");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "string type");
  return type;
}
}  // namespace

void append_texts(hid_t parent, const std::string& name, const std::vector<std::string>& items) {
  if (items.empty()) return;
  Handle type = variable_string_type();
  Handle ds;
  hsize_t old_size = 0;
  if (exists(parent, name)) {
    ds = Handle(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
    Handle space(H5Dget_space(ds));
    H5Sget_simple_extent_dims(space, &old_size, nullptr);
  } else {
    const hsize_t zero = 0, unlimited = H5S_UNLIMITED, chunk = 64;
    Handle space(checked(H5Screate_simple(1, &zero, &unlimited), "dataspace of " + name));
    Handle props(checked(H5Pcreate(H5P_DATASET_CREATE), "properties of " + name));
    check(H5Pset_chunk(props, 1, &chunk), "chunking " + name);
    ds = Handle(checked(H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, props, H5P_DEFAULT), "creating dataset " + name));
  }
  const hsize_t count = items.size(), new_size = old_size + count;
  check(H5Dset_extent(ds, &new_size), "extending dataset " + name);
  Handle file_space(checked(H5Dget_space(ds), "dataspace of " + name));
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &old_size, nullptr, &count, nullptr), "selecting in " + name);
  Handle mem_space(checked(H5Screate_simple(1, &count, nullptr), "dataspace of " + name));
  std::vector<const char*> pointers;
  for (const std::string& item : items) pointers.push_back(item.c_str());
  check(H5Dwrite(ds, type, mem_space, file_space, H5P_DEFAULT, pointers.data()), "writing dataset " + name);
}

std::vector<std::string> read_texts(hid_t parent, const std::string& name) {
  std::vector<std::string> out;
  if (!exists(parent, name)) {
    if (!has_attribute(parent, name)) throw Error("HDF5: dataset '" + name + "' is missing");
    const std::string text = get_string_attribute(parent, name);  // schema 2: one warning per line
    std::size_t from = 0;
    for (std::size_t nl; (nl = text.find('\n', from)) != std::string::npos; from = nl + 1) out.push_back(text.substr(from, nl - from));
    if (from < text.size()) out.push_back(text.substr(from));
    return out;
  }
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle file_type(checked(H5Dget_type(ds), "type of " + name));
  if (H5Tget_class(file_type) != H5T_STRING || H5Tis_variable_str(file_type) <= 0)
    throw Error("HDF5: dataset '" + name + "' is not a list of variable-length strings");
  Handle space(H5Dget_space(ds));
  if (H5Sget_simple_extent_ndims(space) != 1) throw Error("HDF5: dataset '" + name + "' is not 1-D");
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  if (n == 0) return out;
  Handle type = variable_string_type();
  std::vector<char*> pointers(n, nullptr);
  check(H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "reading dataset " + name);
  for (char* p : pointers) out.emplace_back(p ? p : "");
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, pointers.data());
  return out;
}

namespace {

struct Fnv {
  std::uint64_t h = 14695981039346656037ULL;
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
  }
  void add(const std::string& s) {
    const std::uint64_t n = s.size();
    add(&n, sizeof n);  // the length first: "ab"+"c" and "a"+"bc" differ
    add(s.data(), s.size());
  }
};

// The bytes of a dataset or an attribute of `type` and `space`, read by `read(memtype, buf)`.
template <class Read>
void add_values(Fnv& d, hid_t type, hid_t space, Read read, const std::string& what) {
  const hssize_t points = H5Sget_select_npoints(space);
  if (points < 0) throw Error(failed("size of " + what));
  if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) {
    std::vector<char*> strings(static_cast<std::size_t>(points), nullptr);
    if (points > 0) check(read(type, strings.data()), "reading " + what);
    for (char* p : strings) d.add(std::string(p ? p : ""));
    if (points > 0) H5Dvlen_reclaim(type, space, H5P_DEFAULT, strings.data());
    return;
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(points) * H5Tget_size(type));
  if (!bytes.empty()) check(read(type, bytes.data()), "reading " + what);
  d.add(std::string(bytes.begin(), bytes.end()));
}

struct DigestWalk {
  Fnv d;
  std::string skip_object, skip_attribute;
  std::vector<std::string> paths;
};

herr_t collect_path(hid_t, const char* name, const H5L_info_t*, void* data) {
  static_cast<DigestWalk*>(data)->paths.emplace_back(name);
  return 0;
}

void add_object(DigestWalk& w, hid_t file, const std::string& path) {
  Handle obj(checked(H5Oopen(file, path.c_str(), H5P_DEFAULT), "opening " + path));
  w.d.add(path);
  // Attributes, in name order.
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  hsize_t at = 0;
  check(H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &at, collect, &names), "listing the attributes of " + path);
  for (const std::string& name : names) {
    if (path == w.skip_object && name == w.skip_attribute) continue;
    Handle attr(checked(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "opening attribute " + name));
    Handle type(checked(H5Aget_type(attr), "type of attribute " + name));
    Handle space(checked(H5Aget_space(attr), "dataspace of attribute " + name));
    w.d.add(name);
    add_values(w.d, type, space, [&](hid_t t, void* buf) { return H5Aread(attr, t, buf); }, "attribute " + name + " of " + path);
  }
  if (H5Iget_type(obj) != H5I_DATASET) return;
  Handle type(checked(H5Dget_type(obj), "type of " + path));
  Handle space(checked(H5Dget_space(obj), "dataspace of " + path));
  add_values(w.d, type, space, [&](hid_t t, void* buf) { return H5Dread(obj, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf); }, path);
}

}  // namespace

std::string digest(hid_t file, const std::string& skip_object, const std::string& skip_attribute) {
  DigestWalk w;
  w.skip_object = skip_object, w.skip_attribute = skip_attribute;
  check(H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, collect_path, &w), "listing the file's objects");
  add_object(w, file, "/");
  for (const std::string& p : w.paths) add_object(w, file, p);
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(w.d.h));
  return buf;
}

std::vector<hsize_t> shape(hid_t parent, const std::string& name) {
  if (!exists(parent, name)) throw Error("HDF5: dataset '" + name + "' is missing");
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle space(H5Dget_space(ds));
  std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(0, H5Sget_simple_extent_ndims(space))));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  return dims;
}

template <class T>
std::vector<T> read_rows(hid_t parent, const std::string& name, hsize_t first, hsize_t rows) {
  std::vector<hsize_t> dims = shape(parent, name);
  if (dims.empty() || first + rows > dims[0])
    throw Error("HDF5: dataset '" + name + "' has " + std::to_string(dims.empty() ? 0 : dims[0]) + " rows, not rows " +
                std::to_string(first) + " to " + std::to_string(first + rows));
  Handle ds(checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), "opening dataset " + name));
  Handle space(H5Dget_space(ds));
  std::vector<hsize_t> start(dims.size(), 0);
  start[0] = first, dims[0] = rows;
  hsize_t values = 1;
  for (hsize_t d : dims) values *= d;
  std::vector<T> out(static_cast<std::size_t>(values));
  if (out.empty()) return out;
  check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr, dims.data(), nullptr), "selecting rows of " + name);
  Handle memory(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr));
  check(H5Dread(ds, native_type<T>(), memory, space, H5P_DEFAULT, out.data()), "reading " + name);
  return out;
}
template std::vector<double> read_rows(hid_t, const std::string&, hsize_t, hsize_t);
template std::vector<std::int64_t> read_rows(hid_t, const std::string&, hsize_t, hsize_t);

}  // namespace dem::h5
