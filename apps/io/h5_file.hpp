#pragma once
// A small RAII HDF5 file over the C API (docs/outputs.md): groups, double datasets
// (1D/2D) with a `units` attribute, string and number attributes. Writing goes to
// "<path>.tmp" and commit() renames it onto <path>, so a failed run never leaves a
// half-written file under the final name. Paths are absolute inside the file ("/a/b").
#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace centrec::io {

class H5File {
 public:
  // Creates <path>.tmp for writing (truncating it); commit() moves it to <path>.
  static H5File create(const std::string& path);
  // Opens an existing file read-only.
  static H5File open_read(const std::string& path);
  ~H5File();
  H5File(H5File&& other) noexcept;
  H5File& operator=(H5File&&) = delete;
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;

  // Creates the group and any missing parents.
  void create_group(const std::string& path);
  // Writes a dataset of doubles with shape dims ({n} or {rows, cols}; row-major data) and
  // its units as an attribute ("1" for dimensionless).
  void write(const std::string& path, const std::vector<double>& data, const std::vector<std::size_t>& dims,
             const std::string& units);
  void write(const std::string& path, const std::vector<double>& data, const std::string& units) {
    write(path, data, {data.size()}, units);
  }
  // Integer datasets (ids, counts, flags, cell connectivity), same shapes as write().
  void write_int64(const std::string& path, const std::vector<std::int64_t>& data, const std::vector<std::size_t>& dims,
                   const std::string& units);
  void write_int8(const std::string& path, const std::vector<std::int8_t>& data, const std::string& units);
  // HDF5 dimension scales: makes the 1D dataset `scale` a scale named `name` and attaches it
  // to dimension `dim` of `dataset` (h5py: ds.dims[dim][0]; ParaView and xarray read them).
  void attach_scale(const std::string& dataset, int dim, const std::string& scale, const std::string& name);
  void set_attribute(const std::string& object_path, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object_path, const std::string& name, double value);

  bool exists(const std::string& path) const;
  // Reads a double dataset; dims receives its shape.
  std::vector<double> read(const std::string& path, std::vector<std::size_t>* dims = nullptr) const;
  std::string string_attribute(const std::string& object_path, const std::string& name) const;
  double number_attribute(const std::string& object_path, const std::string& name) const;
  bool has_attribute(const std::string& object_path, const std::string& name) const;

  // Flushes, closes and renames the temporary file onto the final path (writers only).
  void commit();
  const std::string& path() const { return path_; }

 private:
  H5File(hid_t id, std::string path, std::string tmp_path);
  void write_typed(const std::string& path, hid_t file_type, hid_t mem_type, const void* data, std::size_t size,
                   const std::vector<std::size_t>& dims, const std::string& units);
  hid_t id_ = -1;
  std::string path_, tmp_path_;  // tmp_path_ empty for readers
};

}  // namespace centrec::io
