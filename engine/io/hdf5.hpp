#pragma once
// A thin RAII layer over the HDF5 C API: handles, attributes, whole datasets and extendable
// columns. Every dataset written here carries a unit attribute (`units`, or H5MD's `unit`).
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace dem::h5 {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Owns one HDF5 identifier and closes it with the right H5?close.
class Handle {
 public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(Handle&& o) noexcept : id_(o.id_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) { reset(); id_ = o.id_; o.id_ = -1; }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t id() const { return id_; }
  operator hid_t() const { return id_; }
  void reset();  // closes, ignoring errors (see close_file for a file whose close must be checked)
  // Forgets the identifier without closing it (after a close that failed: HDF5 must not see it again).
  void release() { id_ = -1; }

 private:
  hid_t id_ = -1;
};

// Why the last HDF5 call failed, from the library's error stack: the system's message when a read
// or write failed (e.g. "No space left on device", "File too large"), "out of memory" when an
// allocation failed (or the stack is empty and errno is ENOMEM, or the process is within 16 MiB of
// its memory limit), else HDF5's innermost description ("" if the stack is empty).
std::string last_error();

Handle create_file(const std::string& path);     // truncates
Handle open_file_read(const std::string& path);  // throws h5::Error naming the file if it cannot be opened
Handle open_file_write(const std::string& path);
// Writes everything HDF5 holds in memory for `file` (data, metadata) to the file; throws h5::Error
// naming `path` and the reason. It does not fsync: see io/atomic_file.hpp.
void flush_file(hid_t file, const std::string& path);
// Closes a file whose other objects are closed, checked: a failed close (a full disk) throws
// h5::Error naming `path` and the reason. Either way `file` is empty afterwards: HDF5 1.10 cannot
// close a file whose close failed, and touching it again (or at exit) crashes the library; `dem`
// therefore calls H5dont_atexit, and such a file is left to the operating system.
void close_file(Handle& file, const std::string& path);
Handle create_group(hid_t parent, const std::string& name);
Handle open_group(hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& path);

void set_attribute(hid_t obj, const std::string& name, const std::string& value);
void set_attribute(hid_t obj, const std::string& name, double value);
void set_attribute(hid_t obj, const std::string& name, std::int64_t value);
void set_attribute(hid_t obj, const std::string& name, const std::vector<std::int64_t>& values);  // 1-D array
void set_attribute(hid_t obj, const std::string& name, const std::vector<std::string>& values);   // 1-D, fixed length
std::string get_string_attribute(hid_t obj, const std::string& name);
double get_double_attribute(hid_t obj, const std::string& name);
std::int64_t get_int_attribute(hid_t obj, const std::string& name);
bool has_attribute(hid_t obj, const std::string& name);

// Text of any size, as a dataset: an attribute's object header holds at most 64 KiB, which a long
// resolved scene or many warnings exceed. write_text writes (or replaces) a scalar
// fixed-length string dataset; read_text reads it, or, in a file written before schema 3, the
// attribute of that name on `parent`. append_texts grows a 1-D dataset of variable-length
// strings (chunked, unlimited: one item per call's element, nothing rewritten); read_texts reads
// it, or splits at newlines such an older attribute.
void write_text(hid_t parent, const std::string& name, const std::string& text);
std::string read_text(hid_t parent, const std::string& name);
bool has_text(hid_t parent, const std::string& name);  // a dataset or (schema 2) an attribute of that name
void append_texts(hid_t parent, const std::string& name, const std::vector<std::string>& items);
std::vector<std::string> read_texts(hid_t parent, const std::string& name);

// A digest (FNV-1a 64, core/content_hash.hpp) of everything in an open file: every object's
// path, every attribute's name and bytes and every dataset's bytes (variable-length strings by
// their text), in name order; the attribute `skip_attribute` of the object `skip_object` is left
// out (it holds the digest). Any value changed changes it.
std::string digest(hid_t file, const std::string& skip_object, const std::string& skip_attribute);

// The attribute that holds a dataset's unit, in every group: H5MD's name (H5MD 1.1 requires
// `unit`). Results written before 2026-11-27 named it `units` outside the H5MD groups; unit_of
// reads either.
inline const std::string unit_attribute = "unit";
// The unit of dataset `name` under `parent`: its `unit` attribute, else an older file's `units`;
// "" if it has neither.
std::string unit_of(hid_t parent, const std::string& name);

// A whole dataset of rows x cols values (cols = 1 writes a 1-D dataset), its unit in `unit`.
template <class T>
void write(hid_t parent, const std::string& name, const std::vector<T>& data, std::size_t cols, const std::string& units);
// Reads a dataset written by write(); `cols` receives the second dimension (1 for 1-D).
template <class T>
std::vector<T> read(hid_t parent, const std::string& name, std::size_t& cols);

// A 1-D dataset of doubles that grows by appending (chunked, unlimited).
class Column {
 public:
  Column(hid_t parent, const std::string& name, const std::string& units);
  // Reopens an existing column for appending.
  Column(hid_t parent, const std::string& name);
  void append(const std::vector<double>& values);
  std::size_t size() const { return size_; }
  hid_t id() const { return dataset_; }

 private:
  Handle dataset_;
  std::size_t size_ = 0;
};

// A dataset that grows along its first dimension one frame at a time, each frame holding
// `frame_shape` values (empty: one value per frame). Chunked, unlimited; T is double or int64.
template <class T>
class FrameSeries {
 public:
  FrameSeries() = default;
  // `chunk_frames` frames per chunk (0: one frame of particles, or 64 scalars).
  FrameSeries(hid_t parent, const std::string& name, std::vector<hsize_t> frame_shape, hsize_t chunk_frames = 0);
  // Reopens an existing series for appending.
  FrameSeries(hid_t parent, const std::string& name);
  void append(const std::vector<T>& frame);
  // Appends values.size() / (values per frame) frames at once (a whole number of them).
  void append_frames(const std::vector<T>& values);
  std::size_t frames() const { return frames_; }
  hid_t id() const { return dataset_; }

 private:
  Handle dataset_;
  std::vector<hsize_t> frame_shape_;
  std::size_t frames_ = 0;
};

// The extent of a dataset, outermost dimension first.
std::vector<hsize_t> shape(hid_t parent, const std::string& name);
// Rows [first, first + rows) along the first dimension of a dataset of any rank, every value of
// each row (row-major); throws h5::Error naming the dataset if they are not all there.
template <class T>
std::vector<T> read_rows(hid_t parent, const std::string& name, hsize_t first, hsize_t rows);

// Runs `read` and makes every h5::Error it throws start with `file` (readers of whole files).
template <class F>
auto naming_file(const std::string& file, F read) {
  try {
    return read();
  } catch (const Error& e) {
    const std::string what = e.what();
    if (what.rfind(file, 0) == 0) throw;
    throw Error(file + ": " + what);
  }
}

}  // namespace dem::h5
