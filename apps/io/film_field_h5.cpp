#include "io/film_field_h5.hpp"

#include <stdexcept>

namespace centrec::io {

namespace {
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
}  // namespace

void write_film_field(H5File& file, const thermal::FilmField& f, const std::string& group) {
  file.create_group(group);
  const std::size_t nz = f.nz(), ne = f.neta();
  file.write(group + "/z", f.z, "m");
  file.write(group + "/eta", f.eta, "m");
  file.write(group + "/t", f.t, "m");
  file.write(group + "/u", f.u, {nz, ne}, "m/s");
  file.write(group + "/phi", f.phi, {nz, ne}, "1");
  file.write(group + "/D", f.D, {nz, ne}, "m2/s");
  if (!f.u_std.empty()) file.write(group + "/u_std", f.u_std, {nz, ne}, "m/s");
  if (!f.phi_std.empty()) file.write(group + "/phi_std", f.phi_std, {nz, ne}, "1");
  if (!f.D_std.empty()) file.write(group + "/D_std", f.D_std, {nz, ne}, "m2/s");
  file.attach_scale(group + "/t", 0, group + "/z", "z");
  for (const char* name : {"u", "phi", "D", "u_std", "phi_std", "D_std"})
    if (file.exists(group + "/" + name)) {
      file.attach_scale(group + "/" + name, 0, group + "/z", "z");
      file.attach_scale(group + "/" + name, 1, group + "/eta", "eta");
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
  std::vector<std::size_t> dims;
  f.z = file.read(group + "/z");
  f.eta = file.read(group + "/eta");
  f.t = file.read(group + "/t");
  auto field = [&](const char* name, std::vector<double>& out, bool optional) {
    const std::string p = group + "/" + name;
    if (optional && !file.exists(p)) return;
    out = file.read(p, &dims);
    if (dims.size() != 2 || dims[0] != f.z.size() || dims[1] != f.eta.size())
      throw std::runtime_error(file.path() + ": " + p + " must have shape [nz, neta] = [" + std::to_string(f.z.size()) +
                               ", " + std::to_string(f.eta.size()) + "]");
  };
  field("u", f.u, false);
  field("phi", f.phi, false);
  field("D", f.D, false);
  field("u_std", f.u_std, true);
  field("phi_std", f.phi_std, true);
  field("D_std", f.D_std, true);
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
