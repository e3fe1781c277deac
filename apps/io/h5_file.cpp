#include "io/h5_file.hpp"

#include <hdf5_hl.h>

#include <cstdio>
#include <stdexcept>

namespace centrec::io {

namespace {
// Silences the HDF5 error stack printer; failures become exceptions with our own text.
void quiet_hdf5() {
  static bool done = false;
  if (!done) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    done = true;
  }
}

[[noreturn]] void fail(const std::string& what, const std::string& file) {
  throw std::runtime_error("HDF5: " + what + " (" + file + ")");
}

// RAII for one HDF5 handle closed with the given function.
struct Handle {
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle() {
    if (id >= 0) close(id);
  }
};

void write_string_attribute(hid_t obj, const std::string& name, const std::string& value, const std::string& file) {
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  // Variable-length UTF-8: h5py reads it as str (fixed-length strings come back as bytes).
  Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);
  Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  Handle attr{H5Acreate2(obj, name.c_str(), type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  const char* text = value.c_str();
  if (attr.id < 0 || H5Awrite(attr.id, type.id, &text) < 0) fail("cannot write attribute '" + name + "'", file);
}
}  // namespace

H5File::H5File(hid_t id, std::string path, std::string tmp_path)
    : id_(id), path_(std::move(path)), tmp_path_(std::move(tmp_path)) {}

H5File::H5File(H5File&& o) noexcept : id_(o.id_), path_(std::move(o.path_)), tmp_path_(std::move(o.tmp_path_)) {
  o.id_ = -1;
  o.tmp_path_.clear();
}

H5File H5File::create(const std::string& path) {
  quiet_hdf5();
  const std::string tmp = path + ".tmp";
  const hid_t id = H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) fail("cannot create file", tmp);
  return H5File(id, path, tmp);
}

H5File H5File::open_read(const std::string& path) {
  quiet_hdf5();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) fail("cannot open file for reading (missing, not HDF5, truncated or corrupted)", path);
  return H5File(id, path, "");
}

H5File::~H5File() {
  if (id_ >= 0) H5Fclose(id_);
  // An uncommitted writer leaves nothing behind.
  if (!tmp_path_.empty()) std::remove(tmp_path_.c_str());
}

void H5File::create_group(const std::string& path) {
  if (exists(path)) return;
  Handle lcpl{H5Pcreate(H5P_LINK_CREATE), H5Pclose};
  H5Pset_create_intermediate_group(lcpl.id, 1);
  Handle g{H5Gcreate2(id_, path.c_str(), lcpl.id, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
  if (g.id < 0) fail("cannot create group '" + path + "'", path_);
}

void H5File::write(const std::string& path, const std::vector<double>& data, const std::vector<std::size_t>& dims,
                   const std::string& units) {
  write_typed(path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), dims, units);
}

void H5File::write_int64(const std::string& path, const std::vector<std::int64_t>& data,
                         const std::vector<std::size_t>& dims, const std::string& units) {
  write_typed(path, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), data.size(), dims, units);
}

void H5File::write_int8(const std::string& path, const std::vector<std::int8_t>& data, const std::string& units) {
  write_typed(path, H5T_STD_I8LE, H5T_NATIVE_INT8, data.data(), data.size(), {data.size()}, units);
}

void H5File::write_typed(const std::string& path, hid_t file_type, hid_t mem_type, const void* data, std::size_t size,
                         const std::vector<std::size_t>& dims, const std::string& units) {
  std::size_t n = 1;
  std::vector<hsize_t> hd;
  for (std::size_t d : dims) {
    n *= d;
    hd.push_back(d);
  }
  if (dims.empty() || dims.size() > 2 || n != size)
    fail("dataset '" + path + "': shape does not match the data size", path_);
  const std::size_t slash = path.rfind('/');
  if (slash != std::string::npos && slash > 0) create_group(path.substr(0, slash));
  Handle space{H5Screate_simple(static_cast<int>(hd.size()), hd.data(), nullptr), H5Sclose};
  Handle lcpl{H5Pcreate(H5P_LINK_CREATE), H5Pclose};
  H5Pset_create_intermediate_group(lcpl.id, 1);
  Handle ds{H5Dcreate2(id_, path.c_str(), file_type, space.id, lcpl.id, H5P_DEFAULT, H5P_DEFAULT), H5Dclose};
  if (ds.id < 0) fail("cannot create dataset '" + path + "'", path_);
  if (n > 0 && H5Dwrite(ds.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail("cannot write dataset '" + path + "'", path_);
  write_string_attribute(ds.id, "units", units, path_);
}

void H5File::attach_scale(const std::string& dataset, int dim, const std::string& scale, const std::string& name) {
  Handle sc{H5Dopen2(id_, scale.c_str(), H5P_DEFAULT), H5Dclose};
  Handle ds{H5Dopen2(id_, dataset.c_str(), H5P_DEFAULT), H5Dclose};
  if (sc.id < 0 || ds.id < 0) fail("no dataset '" + (sc.id < 0 ? scale : dataset) + "' for a dimension scale", path_);
  if (H5DSis_scale(sc.id) <= 0 && H5DSset_scale(sc.id, name.c_str()) < 0)
    fail("cannot make '" + scale + "' a dimension scale", path_);
  if (H5DSattach_scale(ds.id, sc.id, static_cast<unsigned>(dim)) < 0)
    fail("cannot attach scale '" + scale + "' to '" + dataset + "'", path_);
}

void H5File::set_attribute(const std::string& object_path, const std::string& name, const std::string& value) {
  Handle obj{H5Oopen(id_, object_path.c_str(), H5P_DEFAULT), H5Oclose};
  if (obj.id < 0) fail("no object '" + object_path + "' for attribute '" + name + "'", path_);
  write_string_attribute(obj.id, name, value, path_);
}

void H5File::set_attribute(const std::string& object_path, const std::string& name, double value) {
  Handle obj{H5Oopen(id_, object_path.c_str(), H5P_DEFAULT), H5Oclose};
  if (obj.id < 0) fail("no object '" + object_path + "' for attribute '" + name + "'", path_);
  if (H5Aexists(obj.id, name.c_str()) > 0) H5Adelete(obj.id, name.c_str());
  Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  Handle attr{H5Acreate2(obj.id, name.c_str(), H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  if (attr.id < 0 || H5Awrite(attr.id, H5T_NATIVE_DOUBLE, &value) < 0)
    fail("cannot write attribute '" + name + "'", path_);
}

bool H5File::exists(const std::string& path) const {
  if (path == "/") return true;
  // Check each prefix: H5Lexists fails on a missing intermediate group.
  std::size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(id_, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(id_, path.c_str(), H5P_DEFAULT) > 0;
}

std::vector<double> H5File::read(const std::string& path, std::vector<std::size_t>* dims) const {
  if (!exists(path)) fail("no dataset '" + path + "'", path_);
  Handle ds{H5Dopen2(id_, path.c_str(), H5P_DEFAULT), H5Dclose};
  if (ds.id < 0) fail("cannot open dataset '" + path + "'", path_);
  Handle space{H5Dget_space(ds.id), H5Sclose};
  const int rank = H5Sget_simple_extent_ndims(space.id);
  std::vector<hsize_t> hd(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space.id, hd.data(), nullptr);
  std::size_t n = 1;
  if (dims) dims->clear();
  for (hsize_t d : hd) {
    n *= d;
    if (dims) dims->push_back(d);
  }
  std::vector<double> out(n);
  if (n > 0 && H5Dread(ds.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail("cannot read dataset '" + path + "' as double", path_);
  return out;
}

bool H5File::has_attribute(const std::string& object_path, const std::string& name) const {
  if (!exists(object_path)) return false;
  return H5Aexists_by_name(id_, object_path.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::string H5File::string_attribute(const std::string& object_path, const std::string& name) const {
  if (!has_attribute(object_path, name)) fail("no attribute '" + name + "' on '" + object_path + "'", path_);
  Handle attr{H5Aopen_by_name(id_, object_path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  Handle type{H5Aget_type(attr.id), H5Tclose};
  if (H5Tget_class(type.id) != H5T_STRING) fail("attribute '" + name + "' is not a string", path_);
  if (H5Tis_variable_str(type.id) > 0) {
    char* s = nullptr;
    Handle mem{H5Tget_native_type(type.id, H5T_DIR_ASCEND), H5Tclose};
    if (H5Aread(attr.id, mem.id, &s) < 0) fail("cannot read attribute '" + name + "'", path_);
    std::string out = s ? s : "";
    H5free_memory(s);
    return out;
  }
  std::string out(H5Tget_size(type.id), '\0');
  if (H5Aread(attr.id, type.id, out.data()) < 0) fail("cannot read attribute '" + name + "'", path_);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

double H5File::number_attribute(const std::string& object_path, const std::string& name) const {
  if (!has_attribute(object_path, name)) fail("no attribute '" + name + "' on '" + object_path + "'", path_);
  Handle attr{H5Aopen_by_name(id_, object_path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  double v = 0.0;
  if (H5Aread(attr.id, H5T_NATIVE_DOUBLE, &v) < 0) fail("attribute '" + name + "' is not a number", path_);
  return v;
}

void H5File::commit() {
  if (tmp_path_.empty()) fail("commit() on a file opened for reading", path_);
  if (H5Fclose(id_) < 0) fail("cannot close file", tmp_path_);
  id_ = -1;
  if (std::rename(tmp_path_.c_str(), path_.c_str()) != 0) fail("cannot rename " + tmp_path_ + " onto", path_);
  tmp_path_.clear();
}

}  // namespace centrec::io
