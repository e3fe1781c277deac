#include "io/film_field_h5.hpp"

#include <stdexcept>

namespace centrec::io {

namespace {
// The film field's schema, written and read back from these lists alone.
// The case metadata of docs/coupling.md, as group attributes with their units.
struct Meta {
  const char* name;
  const char* units;
  double thermal::FilmField::*member;
};
const Meta kMeta[] = {{"drum_diameter", "m", &thermal::FilmField::drum_diameter},
                      {"length", "m", &thermal::FilmField::length},
                      {"omega", "rad/s", &thermal::FilmField::omega},
                      {"mdot", "kg/s", &thermal::FilmField::mdot},
                      {"particle_diameter", "m", &thermal::FilmField::particle_diameter}};
// The axes and the thickness over z.
struct Axis {
  const char* name;
  const char* units;
  std::vector<double> thermal::FilmField::*member;
  const char* scale;  // the axis it lies over ("" = itself an axis)
};
const Axis kAxes[] = {{"z", "m", &thermal::FilmField::z, ""},
                      {"eta", "m", &thermal::FilmField::eta, ""},
                      {"t", "m", &thermal::FilmField::t, "z"}};
// The fields on the [z, eta] grid; an optional one is absent when empty.
struct Field {
  const char* name;
  const char* units;
  std::vector<double> thermal::FilmField::*member;
  bool optional;
};
const Field kFields[] = {{"u", "m/s", &thermal::FilmField::u, false},
                         {"phi", "1", &thermal::FilmField::phi, false},
                         {"D", "m2/s", &thermal::FilmField::D, false},
                         {"u_std", "m/s", &thermal::FilmField::u_std, true},
                         {"phi_std", "1", &thermal::FilmField::phi_std, true},
                         {"D_std", "m2/s", &thermal::FilmField::D_std, true}};
}  // namespace

void write_film_field(H5File& file, const thermal::FilmField& f, const std::string& group) {
  file.create_group(group);
  const std::size_t nz = f.nz(), ne = f.neta();
  for (const Axis& a : kAxes) file.write(group + "/" + a.name, f.*a.member, a.units);
  for (const Field& q : kFields)
    if (!q.optional || !(f.*q.member).empty()) file.write(group + "/" + q.name, f.*q.member, {nz, ne}, q.units);
  for (const Axis& a : kAxes)
    if (*a.scale) file.attach_scale(group + "/" + a.name, 0, group + "/" + a.scale, a.scale);
  for (const Field& q : kFields)
    if (file.exists(group + "/" + q.name)) {
      file.attach_scale(group + "/" + q.name, 0, group + "/z", "z");
      file.attach_scale(group + "/" + q.name, 1, group + "/eta", "eta");
    }
  for (const Meta& m : kMeta) {
    file.set_attribute(group, m.name, f.*m.member);
    file.set_attribute(group, std::string(m.name) + "_units", m.units);
  }
  file.set_attribute(group, "scaling", f.scaling);
}

thermal::FilmField read_film_field(const H5File& file, const std::string& group) {
  if (!file.exists(group)) throw std::runtime_error(file.path() + ": no film field group '" + group + "'");
  thermal::FilmField f;
  for (const Axis& a : kAxes) f.*a.member = file.read(group + "/" + a.name);
  for (const Field& q : kFields) {
    const std::string p = group + "/" + q.name;
    if (q.optional && !file.exists(p)) continue;
    std::vector<std::size_t> dims;
    f.*q.member = file.read(p, &dims);
    if (dims.size() != 2 || dims[0] != f.z.size() || dims[1] != f.eta.size())
      throw std::runtime_error(file.path() + ": " + p + " must have shape [nz, neta] = [" + std::to_string(f.z.size()) +
                               ", " + std::to_string(f.eta.size()) + "]");
  }
  for (const Meta& m : kMeta)
    if (file.has_attribute(group, m.name)) f.*m.member = file.number_attribute(group, m.name);
  if (file.has_attribute(group, "scaling")) f.scaling = file.string_attribute(group, "scaling");
  try {
    f.check();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(file.path() + ":" + group + ": " + e.what());
  }
  return f;
}

}  // namespace centrec::io
